//! The data behind "Tau-extrapolation, measured" (docs/ACCURACY_NOTES.md): each case named on
//! the command line solved cold at one level (`--level N`, default 7) by the rule's parameters
//! but for the target, the refinement and the error ladder, with its outputs tau-extrapolated
//! ([`repro::solver::point::AccuracyParams::tau_extrapolation`]). One JSON object per case on
//! stdout; `python3 docs/tau_study.py docs/estimate-study.jsonl OUT.jsonl` holds them against
//! the estimate study's finest levels.
//!
//! `cargo run --release --example tau_study -- [--level N] [--plain] CASE...` (`--plain`: the
//! same solves without the extrapolation, whose outputs stand in for it, to time its cost) (cases as
//! `common::case_of` names them: `case23`, `d:M:L:SBAR`, `p:LUBRICANT:T_C:PH_PA:UM:SLIP:TAU0_PA`).
mod common;

use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::point;
use std::time::Instant;

fn main() {
    let lubricants = LubricantTable::table1();
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut level = 7;
    // `--plain`: the same solves without the extrapolation, for its cost.
    let plain = args.iter().any(|a| a == "--plain");
    args.retain(|a| a != "--plain");
    if let Some(at) = args.iter().position(|a| a == "--level") {
        level = args[at + 1].parse().expect("--level N");
        args.drain(at..at + 2);
    }
    for name in args {
        let case = common::case_of(&name);
        let problem = Problem::from_case(&case, &lubricants).expect("a valid case");
        let mut params = common::level_alone(&problem, level);
        params.accuracy.tau_extrapolation = !plain;
        let clock = Instant::now();
        let line = match point::solve(&problem, &params, None) {
            Ok(s) => {
                // Without the extrapolation (`--plain`) the plain outputs stand in for it.
                let (film, friction) = s
                    .tau
                    .as_ref()
                    .map_or((s.film, s.friction), |t| (t.film, t.friction));
                serde_json::json!({
                    "case": name,
                    "level": s.info.level,
                    "method": format!("{:?}", s.info.method),
                    "nested": params.nested,
                    "seconds": clock.elapsed().as_secs_f64(),
                    "h_central": s.film.h_central,
                    "h_min": s.film.h_min,
                    "mu_bar_sliding": s.friction.sliding,
                    "tau_h_central": film.h_central,
                    "tau_h_min": film.h_min,
                    "tau_mu_bar_sliding": friction.sliding,
                })
            }
            Err(e) => serde_json::json!({ "case": name, "level": level, "error": e.to_string() }),
        };
        println!("{line}");
    }
}
