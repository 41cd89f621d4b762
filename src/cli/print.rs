//! What the commands print, shared by them: a failed solve, the per-cycle progress of one
//! solve and a target's summary line (a solve's JSON object and summary are the library's,
//! [`repro::report::solve`]).

use repro::paper::TargetReport;
pub use repro::report::solve::rolling_text;
use repro::solver::output::{Progress, SolveError, Step};

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
