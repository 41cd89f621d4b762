//! What a solve reports, point or line contact: the keys of `repro solve --json` and the
//! lines of its summary.

use crate::paper::eq13::{eq13_mu_bar, PAPER_C};
use crate::paper::figures::estimate::ladder_stop_words;
use crate::physics::case::{Physics, Problem};
use crate::physics::line_contact::{LineFilmFormula, LineProblem};
use crate::physics::rheology::ShearLaw;
use crate::solver::grid::Domain;
use crate::solver::line::LineSolution;
use crate::solver::output::{Film, Friction, Info, Output, OutputErrors};
use crate::solver::point::PointSolution;
use crate::solver::richardson::ErrorEstimate;
use serde_json::{json, Map, Value};

/// What every solve reports, point or line contact: the keys of `repro solve --json`.
pub struct SolveReport<'a> {
    /// The case's groups and anything else that names the contact (`contact` for a line).
    pub case: Value,
    /// The physics the problem composes.
    pub physics: Physics,
    /// Film thickness, as the solve reports it (the central film tau-extrapolated where the
    /// rule extrapolates it).
    pub film: &'a Film,
    /// The grid's own central film, `H` at X = Y = 0 (`film.h_central` where not
    /// extrapolated): what the fields show.
    pub h_central_grid: f64,
    /// Reduced friction.
    pub friction: &'a Friction,
    /// How the solve went: every field of [`Info`] becomes a key of its own, so a field the
    /// solver adds is printed without a change here.
    pub info: &'a Info,
    /// Characteristic shear stress, Eq. (12).
    pub tau_c: f64,
    /// The outputs' discretisation error, where the solve estimated it.
    pub errors: Option<&'a OutputErrors>,
}

impl SolveReport<'_> {
    /// One flat JSON object.
    pub fn json(&self) -> Value {
        let mut out = Map::new();
        let mut add = |v: Value| {
            if let Value::Object(m) = v {
                out.extend(m);
            }
        };
        add(self.case.clone());
        add(to_json(self.film));
        add(to_json(self.info));
        add(json!({
            "viscosity": self.physics.viscosity,
            "density": self.physics.density,
            "rheology": self.physics.rheology,
            "h_central_grid": self.h_central_grid,
            "mu_bar_sliding": self.friction.sliding,
            "mu_bar_rolling": self.friction.rolling,
            "mu_bar_total": self.friction.total(),
            "tau_c": self.tau_c,
            "mu_bar_eq13": eq13_mu_bar(self.tau_c, PAPER_C),
            "residual": self.info.residual(),
        }));
        if let Some(e) = self.errors {
            add(self.error_json(e));
        }
        Value::Object(out)
    }

    /// The discretisation error's keys: each output's absolute error and extrapolated value
    /// in the unit of its key (`hc_moes_error`, `hc_moes_extrapolated`, ...), and the whole
    /// estimate (levels, orders, time) under `discretisation_error`.
    fn error_json(&self, e: &OutputErrors) -> Value {
        let mut out = Map::new();
        for (key, estimate, scale) in self.estimates(e) {
            let (error, extrapolated) = match estimate {
                Some(x) => (json!(x.error * scale), json!(x.extrapolated * scale)),
                None => (Value::Null, Value::Null),
            };
            out.insert(format!("{key}_error"), error);
            out.insert(format!("{key}_extrapolated"), extrapolated);
        }
        let mut whole = to_json(e);
        if let Value::Object(m) = &mut whole {
            for (key, output) in [
                ("h_central", Output::HCentral),
                ("h_min", Output::HMin),
                ("mu_bar_sliding", Output::MuBarSliding),
                ("mu_bar_total", Output::MuBarTotal),
            ] {
                m.insert(key.into(), to_json(&e.estimate(output)));
            }
        }
        out.insert("discretisation_error".into(), whole);
        Value::Object(out)
    }

    /// The three estimated outputs: their key, estimate and the factor from the solver's
    /// unit to the key's (Moes units for the films).
    fn estimates(&self, e: &OutputErrors) -> [(&'static str, Option<ErrorEstimate>, f64); 3] {
        let moes = self.film.hc_moes / self.film.h_central;
        [
            ("hc_moes", e.estimate(Output::HCentral), moes),
            ("hmin_moes", e.estimate(Output::HMin), moes),
            ("mu_bar_sliding", e.estimate(Output::MuBarSliding), 1.0),
        ]
    }

    /// The discretisation error as one line of text: each output's relative error, the
    /// order it rests on, and the extrapolated values.
    pub fn error_text(&self) -> String {
        let Some(e) = self.errors else {
            return String::new();
        };
        let values = [
            self.film.hc_moes,
            self.film.hmin_moes,
            self.friction.sliding,
        ];
        let names = ["Hc", "Hmin", "mu-bar"];
        let parts: Vec<String> = self
            .estimates(e)
            .iter()
            .zip(values.iter().zip(names))
            .map(|((_, estimate, scale), (value, name))| match estimate {
                // A zero output (a pure rolling contact's sliding mu-bar) has an absolute error.
                Some(x) if *value == 0.0 => format!(
                    "{name} {:.4} +- {:.1e} ({})",
                    x.extrapolated * scale,
                    x.error * scale,
                    order_text(x)
                ),
                Some(x) => format!(
                    "{name} {:.4} +- {:.2} % ({})",
                    x.extrapolated * scale,
                    100.0 * x.error * scale / value.abs(),
                    order_text(x)
                ),
                None => format!("{name} not estimated"),
            })
            .collect();
        let mut levels = match (e.levels.first(), e.levels.last()) {
            (Some(a), Some(b)) => format!("levels {}-{}", a.level, b.level),
            _ => "no levels".into(),
        };
        if let Some(top) = e.across {
            levels += &format!(
                " under the top {}y refined across the rolling direction",
                top.top.level
            );
        }
        if let Some(stop) = e.stopped {
            levels += &format!(", {}", ladder_stop_words(stop));
        }
        format!(
            "grid error  {} [extrapolated, Moes; {levels}, {:.2} s]\n",
            parts.join(", "),
            e.seconds
        )
    }
}

/// How an estimate was made, in a few words.
fn order_text(x: &ErrorEstimate) -> String {
    match (x.trusted(), x.order) {
        (true, Some(p)) if p == x.order_used => format!("order {p:.2}"),
        (true, Some(p)) => format!("order {p:.2}, read at {:.0}", x.order_used),
        (false, _) if x.oscillating => "oscillating, bound".into(),
        (false, Some(p)) => format!("order {p:.2} beyond a power law, bound"),
        (false, None) if x.levels == 2 => format!("two levels, order {:.0}", x.order_used),
        _ => "bound".into(),
    }
}

/// A plain data struct of the solver as JSON (its fields are numbers and lists of them, which
/// serialise without error).
fn to_json<T: serde::Serialize>(v: &T) -> Value {
    serde_json::to_value(v).unwrap_or(Value::Null)
}

/// The rolling part of the friction as printed: four decimals, or "not computed" when the
/// solve was asked to skip it.
pub fn rolling_text(rolling: Option<f64>) -> String {
    rolling
        .map(|r| format!("{r:.4}"))
        .unwrap_or_else(|| "not computed".into())
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
        h_central_grid: s.grid_h_central(),
        friction: &s.friction,
        info: &s.info,
        tau_c: problem.tau_c(),
        errors: s.errors.as_ref(),
    }
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

pub(super) fn point_text(problem: &Problem, s: &PointSolution) -> String {
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
        + &patch_text(s)
        + &point_report(problem, s).error_text()
        + &limit
}

/// The innermost grid's and the case-sized domain's `(domain, mesh)` of a solve on nested
/// domains (`None` on a single domain).
fn nested_domains(s: &PointSolution) -> Option<[(Domain, f64); 2]> {
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
    let describe = |(d, h): (Domain, f64)| {
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

/// The composite grid's lines of a summary (none without a patch): each patch's rectangle
/// and mesh inside the whole domain's.
fn patch_text(s: &PointSolution) -> String {
    let whole = s.grid.domain();
    s.patches
        .iter()
        .map(|(d, h)| {
            format!(
                "patch       X {:.3}..{:.3}, Y {:.3}..{:.3} (mesh {:.4}) inside X {:.3}..{:.3}, |Y| <= {:.3} (mesh {:.4}), coupled both ways\n",
                d.x_start,
                d.x_end,
                d.y_start(),
                d.y_end(),
                h,
                whole.x_start,
                whole.x_end,
                whole.y_half,
                s.grid.hx
            )
        })
        .collect()
}

/// The same for `--json`: one `{"x_start", "x_end", "y_start", "y_end", "mesh"}` per patch
/// (`None` without a patch).
pub(super) fn patches_json(s: &PointSolution) -> Option<serde_json::Value> {
    (!s.patches.is_empty()).then(|| {
        s.patches
            .iter()
            .map(|(d, h)| {
                json!({"x_start": d.x_start, "x_end": d.x_end, "y_start": d.y_start(),
                       "y_end": d.y_end(), "mesh": h})
            })
            .collect()
    })
}

/// The same for `--json`: `{"innermost": {...}, "case_domain": {...}}`.
pub(super) fn nested_json(s: &PointSolution) -> Option<serde_json::Value> {
    let [inner, outer] = nested_domains(s)?;
    let describe = |(d, h): (Domain, f64)| json!({"x_start": d.x_start, "x_end": d.x_end, "y_half": d.y_half, "mesh": h});
    Some(json!({"innermost": describe(inner), "case_domain": describe(outer)}))
}

/// The point contact's keys; `d` and `kappa` are 0 for a line contact (`Ry`, `b` infinite).
pub fn line_report<'a>(problem: &LineProblem, s: &'a LineSolution) -> SolveReport<'a> {
    let g = &problem.groups;
    SolveReport {
        case: json!({
            "contact": "line", "tau_c_film": "moes-line",
            "m": g.m, "l": g.l, "s_bar": g.s_bar, "d": 0.0, "slip": g.slip,
            "alpha_bar": g.alpha_bar, "lambda": g.lambda, "kappa": 0.0, "n": g.n,
        }),
        physics: problem.physics(),
        film: &s.film,
        h_central_grid: s.film.h_central,
        friction: &s.friction,
        info: &s.info,
        tau_c: problem.tau_c(),
        errors: s.errors.as_ref(),
    }
}

pub(super) fn line_text(problem: &LineProblem, s: &LineSolution) -> String {
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
