//! `repro solve --line`: the line contact (Fig. 7) from the same flags as the point contact,
//! printed with the same keys.

use crate::cli::SolveArgs;
use crate::report::{flag_error, rolling_text};
use anyhow::{bail, Context as _, Result};
use repro::artefacts::csv;
use repro::physics::case::Spec;
use repro::physics::line_contact::{LineDimensionlessCase, LinePhysicalCase, LineProblem};
use repro::physics::lubricant::LubricantTable;
use repro::solver::line::{solve, LineSolution, Params, Progress, MAX_LEVEL, MIN_LEVEL};
use serde_json::json;

/// Flags of the elliptical contact that a line contact cannot take.
fn reject_point_flags(args: &SolveArgs) -> Result<()> {
    if args.ry.is_some() {
        bail!("--ry: a line contact has no Ry (it is infinite); drop --ry with --line");
    }
    if args.d.is_some() {
        bail!("--d: a line contact has D = Rx/Ry = 0; drop --d with --line");
    }
    if !matches!(args.domain, crate::cli::DomainArg::Auto) {
        bail!("--domain: the line contact has its own domain (-4.5 <= X <= 1.5); drop --domain with --line");
    }
    Ok(())
}

/// The line-contact problem the flags describe.
pub fn problem(args: &SolveArgs) -> Result<LineProblem> {
    reject_point_flags(args)?;
    let case = args.case()?;
    match &case.spec {
        Spec::Physical(ph) => {
            let line = LinePhysicalCase::from_point_case(ph, &LubricantTable::table1())
                .map_err(flag_error)?;
            LineProblem::from_physical(&line, case.physics).map_err(flag_error)
        }
        Spec::Dimensionless(d) => {
            let line = LineDimensionlessCase {
                m: d.m,
                l: d.l,
                s_bar: d.s_bar,
                slip: d.slip,
                eta0_pa_s: d.eta0_pa_s,
                ph_pa: d.ph_pa,
            };
            LineProblem::from_dimensionless(&line, case.physics).map_err(flag_error)
        }
    }
}

/// Solver parameters from the numerics flags (default level 8).
pub fn params(args: &SolveArgs) -> Result<Params> {
    let level = args.level.unwrap_or(Params::default().level);
    if !(MIN_LEVEL..=MAX_LEVEL).contains(&level) {
        bail!("--level: level {level} outside the line-contact range {MIN_LEVEL}..={MAX_LEVEL}");
    }
    Ok(Params {
        level,
        max_iterations: args.max_cycles,
        rolling_friction: !args.no_rolling,
        ..Params::default()
    })
}

/// `repro solve --line`: false when the solve failed (after printing why).
pub fn solve_line(args: &SolveArgs) -> Result<bool> {
    let problem = problem(args)?;
    let params = params(args)?;
    let quiet = args.quiet;
    let mut printer = move |p: &Progress| {
        if !quiet {
            eprintln!(
                "level {:>2} iteration {:>3}: residual {:.3e}, load error {:.2e}, H(0) {:.5e}",
                p.level, p.cycle, p.residual, p.load_error, p.h_central
            );
        }
    };
    let s = match solve(&problem, &params, Some(&mut printer)) {
        Ok(s) => s,
        Err(e) => {
            crate::report::print_failure(&e);
            return Ok(false);
        }
    };
    if let Some(path) = &args.fields {
        csv::write_atomic(path, &fields_csv(&s))
            .with_context(|| format!("--fields: cannot write {}", path.display()))?;
    }
    if args.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&summary_json(&problem, params.level, &s))?
        );
    } else {
        print!("{}", summary_text(&problem, &s));
    }
    Ok(true)
}

/// The point contact's keys; `d` and `kappa` are 0 for a line contact (`Ry`, `b` infinite).
fn summary_json(problem: &LineProblem, level: u32, s: &LineSolution) -> serde_json::Value {
    let g = &problem.groups;
    let ph = problem.physics();
    let tau_c = problem.tau_c();
    json!({
        "contact": "line",
        "level": level,
        "m": g.m, "l": g.l, "s_bar": g.s_bar, "d": 0.0, "slip": g.slip,
        "alpha_bar": g.alpha_bar, "lambda": g.lambda, "kappa": 0.0, "n": g.n,
        "viscosity": ph.viscosity, "density": ph.density, "rheology": ph.rheology,
        "h_central": s.film.h_central, "h_min": s.film.h_min,
        "hc_moes": s.film.hc_moes, "hmin_moes": s.film.hmin_moes,
        "mu_bar_sliding": s.friction.sliding, "mu_bar_rolling": s.friction.rolling, "mu_bar_total": s.friction.total(),
        "tau_c": tau_c, "tau_c_film": "moes-line", "mu_bar_eq13": (tau_c / 5.0).asinh(),
        "cycles": s.info.cycles, "residual": s.info.residual(), "load_error": s.info.load_error,
        "residual_history": s.info.residual_history, "seconds": s.info.seconds,
    })
}

fn summary_text(problem: &LineProblem, s: &LineSolution) -> String {
    let g = &problem.groups;
    let tau_c = problem.tau_c();
    let rolling = rolling_text(s.friction.rolling);
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
        repro::physics::line_contact::LineFilmFormula::Moes.hc(g.m, g.l),
        s.friction.sliding, rolling, s.friction.total(),
        tau_c, (tau_c / 5.0).asinh(),
        s.info.cycles, s.info.residual(), s.info.load_error, s.info.seconds,
    )
}

fn fields_csv(s: &LineSolution) -> String {
    let mut out = String::from("X,P,H\n");
    for ((x, p), h) in s.x.iter().zip(&s.p).zip(&s.h) {
        out.push_str(&format!(
            "{},{},{}\n",
            csv::num(*x),
            csv::num(*p),
            csv::num(*h)
        ));
    }
    out
}
