//! The data behind the error estimate's design (docs/ACCURACY_NOTES.md, "The estimate,
//! measured"): each case named on the command line solved cold by the rule's parameters at
//! the finest level the solver reaches for it (9 on one domain, 8 on a chain of nested
//! domains, whose contact mesh is then finer than a uniform level 9's), with the error ladder
//! run down to level 5, so that every level's central film, minimum film and sliding
//! `mu-bar` come from one solve of the finest; no accuracy target (the finest level is the
//! one asked for). One JSON object per case on stdout.
//!
//! `cargo run --release --example estimate_study -- CASE...` (cases as `common::case_of`
//! names them: `case23`, `d:M:L:SBAR`, `p:LUBRICANT:T_C:PH_PA:UM:SLIP:TAU0_PA`).
mod common;

use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::point::{self, Params};
use std::time::Instant;

fn main() {
    let lubricants = LubricantTable::table1();
    for name in std::env::args().skip(1) {
        let case = common::case_of(&name);
        let problem = Problem::from_case(&case, &lubricants).expect("a valid case");
        let nested = Params::for_problem(&problem, 7).nested;
        let top = if nested { 8 } else { point::MAX_LEVEL };
        let mut params = Params::for_problem(&problem, top);
        params.accuracy.target = None;
        params.accuracy.error_levels = top - 5;
        let clock = Instant::now();
        let line = match point::solve(&problem, &params, None) {
            Ok(s) => serde_json::json!({
                "case": name,
                "m": problem.groups.m,
                "l": problem.groups.l,
                "nested": nested,
                "level": s.info.level,
                "method": format!("{:?}", s.info.method),
                "seconds": clock.elapsed().as_secs_f64(),
                "levels": s.errors.as_ref().map(|e| &e.levels),
                "stopped": s.errors.as_ref().and_then(|e| e.stopped),
            }),
            Err(e) => serde_json::json!({ "case": name, "error": e.to_string() }),
        };
        println!("{line}");
    }
}
