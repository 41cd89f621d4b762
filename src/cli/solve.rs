//! `repro solve`: one elliptical contact (multigrid) or, with `--line`, one line contact
//! (Newton), printed as a summary or as one JSON object with the same keys.

use super::args::SolveArgs;
use super::config::flag_error;
use super::print::{print_failure, rolling_text, solve_progress, SolveReport};
use super::thermal;
use anyhow::{Context as _, Result};
use repro::paper::prediction::heat::HeatCorrection;
use repro::physics::case::{Case, Problem};
use repro::physics::line_contact::{LineFilmFormula, LineProblem};
use repro::physics::lubricant::LubricantTable;
use repro::physics::rheology::ShearLaw;
use repro::pipeline::base::solve_case;
use repro::pipeline::csv::{rows, write_atomic};
use repro::pipeline::error::PipelineError;
use repro::pipeline::label::case_label;
use repro::solver::line::{self, LineSolution};
use repro::solver::point::{self, PointSolution};
use serde::Serialize;
use serde_json::json;
use std::path::Path;

/// `repro solve`: false when the solve failed (after printing why).
pub fn run(args: &SolveArgs) -> Result<bool> {
    if args.line {
        return run_line(args);
    }
    let case = args.case()?;
    let problem = Problem::from_case(&case, &LubricantTable::table1()).map_err(flag_error)?;
    let params = args.params(&problem)?;
    let inputs = args.thermal.inputs()?;
    let mut printer = solve_progress(args.quiet);
    let solved = if args.cold {
        point::solve(&problem, &params, Some(&mut printer)).map_err(PipelineError::from)
    } else {
        let quiet = args.quiet || args.json;
        let mut said = |b: &Case| {
            if !quiet {
                eprintln!("solving its base first: {}", case_label(b, params.level));
            }
        };
        solve_case(
            &case,
            &problem,
            &params,
            &LubricantTable::table1(),
            &mut said,
            Some(&mut printer),
        )
    };
    let s = match solved {
        Ok(s) => s,
        Err(PipelineError::Solve(e)) => {
            print_failure(&e);
            return Ok(false);
        }
        Err(e) => return Err(e.into()),
    };
    if let Some(path) = &args.fields {
        let (g, p, h) = (&s.grid, &s.p, &s.h);
        let nodes = (0..g.py()).flat_map(|j| {
            (0..g.px()).map(move |i| {
                let k = g.idx(i, j);
                PointNode {
                    x: g.x(i),
                    y: g.y(j),
                    p: p[k],
                    h: h[k],
                }
            })
        });
        write_fields(path, &rows(nodes))?;
    }
    let heat = HeatCorrection::of_solution(&case, &problem, &s, &inputs);
    let (line, warning) = thermal::describe(&heat);
    if args.json {
        let mut v = point_report(&problem, &s).json();
        v["thermal"] = thermal::json_of(&heat);
        if let Some(nested) = nested_json(&s) {
            v["nested"] = nested;
        }
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        print!("{}{line}", point_text(&problem, &s));
        if let Some(w) = warning {
            eprintln!("warning: {w}");
        }
    }
    Ok(true)
}

/// What a point-contact solve reports (`repro solve`, `repro predict --solve`).
pub fn point_report<'a>(problem: &Problem, s: &'a PointSolution) -> SolveReport<'a> {
    let g = &problem.groups;
    SolveReport {
        case: json!({
            "m": g.m, "l": g.l, "s_bar": g.s_bar, "d": g.d, "slip": g.slip,
            "alpha_bar": g.alpha_bar, "lambda": g.lambda, "kappa": g.kappa, "n": g.n,
        }),
        physics: problem.physics(),
        film: &s.film,
        friction: &s.friction,
        info: &s.info,
        tau_c: problem.tau_c(),
        errors: s.errors.as_ref(),
    }
}

/// A node of the point contact's fields (`--fields`).
#[derive(Default, Serialize)]
#[serde(rename_all = "UPPERCASE")]
struct PointNode {
    x: f64,
    y: f64,
    p: f64,
    h: f64,
}

/// A node of the line contact's fields (`--fields`).
#[derive(Default, Serialize)]
#[serde(rename_all = "UPPERCASE")]
struct LineNode {
    x: f64,
    p: f64,
    h: f64,
}

/// Writes the pressure and film fields (`--fields`), one row per node.
fn write_fields(path: &Path, text: &str) -> Result<()> {
    write_atomic(path, text).with_context(|| format!("--fields: cannot write {}", path.display()))
}

/// The limiting shear stress's line of a summary (empty without one): the dimensionless
/// limit and the friction bound it sets on the Hertzian contact (`A / W` the area over the
/// load: 3/2 for an ellipse, `4 / pi` for a line).
fn limit_text(law: ShearLaw, area_over_load: f64) -> String {
    match (law, law.friction_bound(area_over_load)) {
        (
            ShearLaw::EyringLss {
                tau_l0_bar,
                lambda_bar,
            },
            Some(bound),
        ) => format!(
            "limit       tau_L/tau0 = {} + {} P; saturated Hertzian contact: mu-bar = {}\n",
            short(tau_l0_bar),
            short(lambda_bar),
            short(bound)
        ),
        _ => String::new(),
    }
}

/// Four decimals, or four significant digits in exponent form beyond 1e6.
fn short(v: f64) -> String {
    if v.abs() < 1e6 {
        format!("{v:.4}")
    } else {
        format!("{v:.4e}")
    }
}

fn point_text(problem: &Problem, s: &PointSolution) -> String {
    let g = &problem.groups;
    let ph = problem.physics();
    let tau_c = problem.tau_c();
    let limit = limit_text(problem.shear, 1.5);
    format!(
        "case        M = {:.4}, L = {:.4}, S-bar = {:.4e}, D = {:.4}, S = {}\n\
         groups      alpha-bar = {:.4}, lambda = {:.4e}, kappa = {:.4}, N = {:.4e}\n\
         physics     {:?}, {:?}, {:?}\n\
         grid        {} x {}, {} cycles{}, residual {:.2e}, load error {:.1e}, {:.2} s\n\
         film        Hc = {:.5e} (Moes {:.4}), Hmin = {:.5e} (Moes {:.4})  [H = h/c]\n\
         friction    mu-bar sliding = {:.4}, rolling = {}, total = {:.4}\n\
         mastercurve tau_c = {:.4e}, Eq. (13) asinh(tau_c/5) = {:.4}\n",
        g.m,
        g.l,
        g.s_bar,
        g.d,
        g.slip,
        g.alpha_bar,
        g.lambda,
        g.kappa,
        g.n,
        ph.viscosity,
        ph.density,
        ph.rheology,
        s.grid.nx,
        s.grid.ny,
        s.info.cycles,
        match s.info.newton_steps {
            0 => String::new(),
            n => format!(
                " + {n} Newton-Krylov steps ({} GMRES iterations)",
                s.info.krylov_iterations
            ),
        },
        s.info.residual(),
        s.info.load_error,
        s.info.seconds,
        s.film.h_central,
        s.film.hc_moes,
        s.film.h_min,
        s.film.hmin_moes,
        s.friction.sliding,
        rolling_text(s.friction.rolling),
        s.friction.total(),
        tau_c,
        (tau_c / 5.0).asinh(),
    ) + &nested_text(s)
        + &point_report(problem, s).error_text()
        + &limit
}

/// The innermost grid's and the case-sized domain's `(domain, mesh)` of a solve on nested
/// domains (`None` on a single domain).
fn nested_domains(s: &PointSolution) -> Option<[(repro::solver::grid::Domain, f64); 2]> {
    let outer = s.surroundings.as_ref()?;
    Some([
        (s.grid.domain(), s.grid.hx),
        (outer.grid.domain(), outer.grid.hx),
    ])
}

/// The nested domains' line of a summary (empty on a single domain): the innermost grid's
/// rectangle and mesh inside the case-sized domain's.
fn nested_text(s: &PointSolution) -> String {
    let Some([inner, outer]) = nested_domains(s) else {
        return String::new();
    };
    let describe = |(d, h): (repro::solver::grid::Domain, f64)| {
        format!(
            "X {:.3}..{:.3}, |Y| <= {:.3} (mesh {:.4})",
            d.x_start, d.x_end, d.y_half, h
        )
    };
    format!(
        "nested      {} inside {}\n",
        describe(inner),
        describe(outer)
    )
}

/// The same for `--json`: `{"innermost": {...}, "case_domain": {...}}`.
fn nested_json(s: &PointSolution) -> Option<serde_json::Value> {
    let [inner, outer] = nested_domains(s)?;
    let describe = |(d, h): (repro::solver::grid::Domain, f64)| json!({"x_start": d.x_start, "x_end": d.x_end, "y_half": d.y_half, "mesh": h});
    Some(json!({"innermost": describe(inner), "case_domain": describe(outer)}))
}

/// `repro solve --line`: the line contact (Fig. 7) from the same flags.
fn run_line(args: &SolveArgs) -> Result<bool> {
    let problem = args.line_problem()?;
    let params = args.line_params(&problem)?;
    let mut printer = solve_progress(args.quiet);
    let s = match line::solve(&problem, &params, Some(&mut printer)) {
        Ok(s) => s,
        Err(e) => {
            print_failure(&e);
            return Ok(false);
        }
    };
    if let Some(path) = &args.fields {
        let nodes = s.x.iter().zip(&s.p).zip(&s.h).map(|((x, p), h)| LineNode {
            x: *x,
            p: *p,
            h: *h,
        });
        write_fields(path, &rows(nodes))?;
    }
    if args.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&line_report(&problem, &s).json())?
        );
    } else {
        print!("{}", line_text(&problem, &s));
    }
    Ok(true)
}

/// The point contact's keys; `d` and `kappa` are 0 for a line contact (`Ry`, `b` infinite).
fn line_report<'a>(problem: &LineProblem, s: &'a LineSolution) -> SolveReport<'a> {
    let g = &problem.groups;
    SolveReport {
        case: json!({
            "contact": "line", "tau_c_film": "moes-line",
            "m": g.m, "l": g.l, "s_bar": g.s_bar, "d": 0.0, "slip": g.slip,
            "alpha_bar": g.alpha_bar, "lambda": g.lambda, "kappa": 0.0, "n": g.n,
        }),
        physics: problem.physics(),
        film: &s.film,
        friction: &s.friction,
        info: &s.info,
        tau_c: problem.tau_c(),
        errors: s.errors.as_ref(),
    }
}

fn line_text(problem: &LineProblem, s: &LineSolution) -> String {
    let g = &problem.groups;
    let tau_c = problem.tau_c();
    let rolling = rolling_text(s.friction.rolling);
    let limit = limit_text(problem.shear, 4.0 / std::f64::consts::PI);
    format!(
        "line case   M = {:.4}, L = {:.4}, S-bar = {:.4e}, S = {}\n\
         groups      alpha-bar = {:.4}, lambda = {:.4e}, N = {:.4e}\n\
         film        H(0) = {:.5e} (h Rx / a^2), Moes Hc = {:.4}, Hmin = {:.4} (Moes formula Hc = {:.4})\n\
         friction    mu-bar sliding = {:.4}, rolling = {}, total = {:.4}\n\
         tau_c       {:.4e} (Moes line film); Eq. (13) asinh(tau_c/5) = {:.4}\n\
         solve       {} Newton iterations, residual {:.2e}, load error {:.1e}, {:.3} s\n",
        g.m, g.l, g.s_bar, g.slip,
        g.alpha_bar, g.lambda, g.n,
        s.film.h_central, s.film.hc_moes, s.film.hmin_moes,
        LineFilmFormula::Moes.hc(g.m, g.l),
        s.friction.sliding, rolling, s.friction.total(),
        tau_c, (tau_c / 5.0).asinh(),
        s.info.cycles, s.info.residual(), s.info.load_error, s.info.seconds,
    ) + &line_report(problem, s).error_text()
        + &limit
}
