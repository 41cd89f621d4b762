//! The tau-extrapolation's pressure change as a local indicator of where a level's error is
//! (docs/ACCURACY_NOTES.md, "Tau-extrapolation, measured"): each case named on the command
//! line solved cold at level N (`--level N`, default 7) with its tau-extrapolation, and at
//! level N + 2 on the same domain, both by the rule's parameters without target, refinement or
//! ladder. On the level-N nodes, the indicator `P_tau - P_N` is held against the error
//! `P_(N+2) - P_N` (the finer pressure at the same points), and likewise the film `H` (and
//! its part inside the Hertzian circle less its mean there, the film constant's share): their
//! cosine, the ratio of their norms, how concentrated the error is (the share of nodes that
//! holds 80 % of its square), and how much of the error's square the indicator's largest
//! nodes of that number hold. One JSON object per case on stdout; `--fields DIR` writes
//! `DIR/CASE.csv` (x, y, the pressure's error and indicator) too.
//!
//! `cargo run --release --example tau_indicator -- [--level N] [--fields DIR] CASE...` (cases as
//! `common::case_of` names them).
mod common;

use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::point::{self, PointSolution};
use std::fmt::Write;
use std::time::Instant;

fn solve(problem: &Problem, level: u32, tau: bool) -> PointSolution {
    let mut params = common::level_alone(problem, level);
    params.accuracy.tau_extrapolation = tau;
    point::solve(problem, &params, None).expect("a converged solve")
}

/// The share of `weights`' total that its largest `count` entries of `order` hold.
fn share(weights: &[f64], order: &[usize], count: usize) -> f64 {
    let total: f64 = weights.iter().sum();
    order[..count].iter().map(|&k| weights[k]).sum::<f64>() / total
}

/// How `indicator` agrees with `error` over the same nodes: cosine, ratio of norms, the share
/// of nodes that holds 80 % of the error's square, and what share of it the indicator's
/// largest nodes of that number hold.
fn agreement(error: &[f64], indicator: &[f64]) -> serde_json::Value {
    let dot: f64 = error.iter().zip(indicator).map(|(a, b)| a * b).sum();
    let norm = |v: &[f64]| v.iter().map(|a| a * a).sum::<f64>().sqrt();
    let (ne, ni) = (norm(error), norm(indicator));
    let squares: Vec<f64> = error.iter().map(|e| e * e).collect();
    let by = |v: &[f64]| {
        let mut order: Vec<usize> = (0..v.len()).collect();
        order.sort_by(|&a, &b| v[b].abs().total_cmp(&v[a].abs()));
        order
    };
    let (error_order, indicator_order) = (by(error), by(indicator));
    let total: f64 = squares.iter().sum();
    let (mut count, mut held) = (0, 0.0);
    while held < 0.8 * total {
        held += squares[error_order[count]];
        count += 1;
    }
    serde_json::json!({
        "cosine": dot / (ne * ni),
        "norm_ratio": ni / ne,
        "error_nodes_share_80": count as f64 / error.len() as f64,
        "indicator_top_holds": share(&squares, &indicator_order, count),
    })
}

fn main() {
    let lubricants = LubricantTable::table1();
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut take = |flag: &str| {
        let at = args.iter().position(|a| a == flag)?;
        let value = args[at + 1].clone();
        args.drain(at..at + 2);
        Some(value)
    };
    let level: u32 = take("--level").map_or(7, |v| v.parse().expect("--level N"));
    let fields = take("--fields");
    for name in args {
        let problem = Problem::from_case(&common::case_of(&name), &lubricants).expect("a case");
        let clock = Instant::now();
        let coarse = solve(&problem, level, true);
        let fine = solve(&problem, level + 2, false);
        let (g, gf) = (coarse.grid, fine.grid);
        assert!(
            gf.nx == 4 * g.nx && (gf.x0 - g.x0).abs() < 1e-12,
            "the same domain"
        );
        let tau = coarse.tau.as_ref().expect("asked for");
        let mut at = Vec::new();
        let (mut p_error, mut p_indicator, mut h_error, mut h_indicator) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for j in 1..g.ny {
            for i in 1..g.nx {
                let (k, kf) = (g.idx(i, j), gf.idx(4 * i, 4 * j));
                p_error.push(fine.p[kf] - coarse.p[k]);
                p_indicator.push(tau.p[k] - coarse.p[k]);
                h_error.push(fine.h[kf] - coarse.h[k]);
                h_indicator.push(tau.h[k] - coarse.h[k]);
                at.push((g.x(i), g.y(j)));
            }
        }
        // The film's error less its mean over the Hertzian circle (the film constant's error,
        // which shifts the whole film): what a local refinement would have to reduce.
        let inside: Vec<usize> = (0..at.len())
            .filter(|&n| at[n].0 * at[n].0 + at[n].1 * at[n].1 < 1.0)
            .collect();
        let local = |v: &[f64]| {
            let mean = inside.iter().map(|&n| v[n]).sum::<f64>() / inside.len() as f64;
            inside.iter().map(|&n| v[n] - mean).collect::<Vec<f64>>()
        };
        let line = serde_json::json!({
            "case": name,
            "level": level,
            "pressure": agreement(&p_error, &p_indicator),
            "film": agreement(&h_error, &h_indicator),
            "film_local": agreement(&local(&h_error), &local(&h_indicator)),
            "seconds": clock.elapsed().as_secs_f64(),
        });
        println!("{line}");
        let (error, indicator) = (p_error, p_indicator);
        if let Some(dir) = &fields {
            let mut csv = String::from("x,y,pressure_error,pressure_indicator\n");
            for ((x, y), (e, t)) in at.iter().zip(error.iter().zip(&indicator)) {
                writeln!(csv, "{x},{y},{e},{t}").unwrap();
            }
            let file = format!("{dir}/{}.csv", name.replace(':', "_"));
            std::fs::write(&file, csv).expect("the fields file");
        }
    }
}
