//! The adopted error estimate evaluated by the crate itself on the estimate study's data
//! (`docs/estimate-study.jsonl`, from `examples/estimate_study.rs`): for each case and each
//! finest level 7 and 8 below the case's finest, the ladder read as a solve at that level
//! reads it (levels down to two below, a level outside the asymptotic range or not converged
//! ending it: [`LadderStop::outside`], the study's own `stopped`) and the estimate of the
//! central film, minimum film and sliding `mu-bar` ([`OutputErrors::estimate`]). One JSON
//! object per case and level on stdout; `docs/estimate_designs.py` reads them for the adopted
//! design's row and checks its own twin of the estimator against them.
//!
//! `cargo run --release --example estimate_adopted -- docs/estimate-study.jsonl`

use repro::solver::output::{LadderStop, LevelValues, Output, OutputErrors};
use std::io::BufRead;

/// The record a solve at `fine` makes from the study's `levels` (coarse to fine) and the
/// study's own stop (the level it names, and those below it, are not in `levels`).
fn ladder(levels: &[LevelValues], stopped: Option<LadderStop>, fine: u32) -> Option<OutputErrors> {
    let finest = *levels.iter().find(|v| v.level == fine)?;
    let mut read = vec![finest];
    let mut stop = None;
    for level in (fine.saturating_sub(2)..fine).rev() {
        // A level the study's ladder did not read ended it there, for the reason it gives.
        let Some(v) = levels.iter().find(|v| v.level == level) else {
            stop = stopped.filter(|s| s.level() == level);
            break;
        };
        if let Some(s) = LadderStop::outside(v, &finest) {
            stop = Some(s);
            break;
        }
        read.insert(0, *v);
    }
    Some(OutputErrors {
        stopped: stop,
        ..OutputErrors::of(read, 0.0)
    })
}

fn main() {
    let path = std::env::args().nth(1).expect("the study's JSON lines");
    let file = std::fs::File::open(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    for line in std::io::BufReader::new(file).lines() {
        let line = line.expect("a line");
        if line.trim().is_empty() {
            continue;
        }
        let row: serde_json::Value = serde_json::from_str(&line).expect("a JSON object");
        let Some(levels) = row.get("levels").filter(|l| l.is_array()) else {
            continue;
        };
        let levels: Vec<LevelValues> =
            serde_json::from_value(levels.clone()).expect("the study's levels");
        let stopped: Option<LadderStop> =
            serde_json::from_value(row["stopped"].clone()).expect("the study's stop");
        let top = levels.last().map_or(0, |v| v.level);
        for fine in [7, 8].into_iter().filter(|&f| f < top) {
            let Some(errors) = ladder(&levels, stopped, fine) else {
                continue;
            };
            let estimate = |o: Output| errors.estimate(o).map(|e| e.error);
            println!(
                "{}",
                serde_json::json!({
                    "case": row["case"],
                    "fine": fine,
                    "h_central": estimate(Output::HCentral),
                    "h_min": estimate(Output::HMin),
                    "mu_bar_sliding": estimate(Output::MuBarSliding),
                })
            );
        }
    }
}
