//! What the commands print, shared by them: a solve's JSON object, the rolling friction as
//! text, a failed solve, the per-cycle progress of one solve and a target's summary line.

use repro::paper::mastercurve::fit::{eq13_mu_bar, PAPER_C};
use repro::paper::TargetReport;
use repro::physics::case::Physics;
use repro::solver::output::{Film, Friction, Info, Progress, SolveError, Step};
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
        Value::Object(out)
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
