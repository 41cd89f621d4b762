//! What the commands print, shared by them: a solve's JSON object, the rolling friction as
//! text, a failed solve, the per-cycle progress of one solve and a target's summary line.

use repro::paper::mastercurve::fit::{eq13_mu_bar, PAPER_C};
use repro::paper::TargetReport;
use repro::physics::case::Physics;
use repro::solver::output::{
    Film, Friction, Info, LadderStop, Output, OutputErrors, Progress, SolveError, Step,
};
use repro::solver::richardson::ErrorEstimate;
use serde_json::{json, Map, Value};

/// What every solve reports, point or line contact: the keys of `repro solve --json`.
pub struct SolveReport<'a> {
    /// The case's groups and anything else that names the contact (`contact` for a line).
    pub case: Value,
    /// The physics the problem composes.
    pub physics: Physics,
    /// Film thickness.
    pub film: &'a Film,
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
        match e.stopped {
            Some(LadderStop::FilmClosed { level }) => {
                levels += &format!(", level {level} not read: its film closes at the centre")
            }
            Some(LadderStop::NotConverged { level }) => {
                levels += &format!(", level {level} not read: it did not converge")
            }
            None => {}
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
        (true, Some(p)) => format!("order {p:.2}"),
        (false, _) if x.oscillating => "oscillating, bound".into(),
        (false, Some(p)) => format!("order {p:.2} not trusted, bound"),
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

/// Prints why a solve failed, with its residual history, on stderr (`repro solve`, `solve
/// --line`, `predict --solve`).
pub fn print_failure(e: &SolveError) {
    eprintln!("solve failed: {e}");
    eprintln!("residual history: {:?}", e.residual_history());
}

/// Prints one progress line per solver step (point-contact cycle or Newton-Krylov step,
/// line-contact Newton iteration) to stderr; nothing when `quiet`.
pub fn solve_progress(quiet: bool) -> impl FnMut(&Progress) {
    move |p: &Progress| {
        if quiet {
            return;
        }
        let (what, krylov) = match p.step {
            Step::Cycle => ("cycle ", String::new()),
            Step::NewtonKrylov { krylov_iterations } => {
                ("newton", format!(", {krylov_iterations} GMRES iterations"))
            }
            Step::Newton => ("newton", String::new()),
        };
        eprintln!(
            "  level {:>2} {what} {:>3}: residual {:.3e} (largest at X {:+.3}, Y {:+.3}), dP {:.1e}, load error {:.1e}, Hc {:.5e}{krylov}",
            p.level, p.count, p.residual, p.worst_at.0, p.worst_at.1, p.pressure_change, p.load_error, p.h_central
        );
    }
}

/// One line per built target: cases, solved, level, time, fit, files.
pub fn summary_line(b: &TargetReport) -> String {
    let mut line = format!("{}: {} cases", b.name, b.cases);
    if let (Some(s), Some(c)) = (b.solved, b.cached) {
        line.push_str(&format!(", {s} solved, {c} cached"));
    }
    if let Some(l) = b.level {
        line.push_str(&format!(", level {l}"));
    }
    line.push_str(&format!(", {:.1} s", b.seconds));
    if let Some(h) = &b.headline {
        line.push_str(&format!(", {h}"));
    }
    line.push_str(&format!(" -> {}", b.files.join(", ")));
    line
}
