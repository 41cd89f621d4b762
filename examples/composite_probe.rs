//! Prototype of issue 39: a composite grid (the whole domain at `LEVEL`, one patch at twice
//! its resolution, coupled both ways; `solver::point::composite`) against the uniform levels.
//!
//! `cargo run --release --example composite_probe -- CASE LEVEL X_START PATCH_LEVEL ROUNDS [MARGIN [BAND]]`
//!
//! `CASE` as `nested_probe`. The domain and edge are the rule's (`PROBE_EDGE_ZERO`: `P = 0`); the patch's inlet
//! is the grid line nearest `X_START`, and it spans `2^PATCH_LEVEL` cells of the level in each
//! direction, about `Y = PROBE_Y_CENTRE` (default 0). Prints the uniform solutions at `LEVEL` and `LEVEL + 1`
//! and the composite's outputs after each round.
mod common;

use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::output::Output;
use repro::solver::point::composite::{solve_composite, Patch, PatchSet, PatchSpec};
use repro::solver::point::{self, Edge, Params};
use std::time::Instant;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let problem = Problem::from_case(&common::case_of(&a[1]), &LubricantTable::table1()).unwrap();
    let level: u32 = a[2].parse().unwrap();
    let x_start: f64 = a[3].parse().unwrap();
    let patch_level: u32 = a[4].parse().unwrap();
    let rounds: usize = a[5].parse().unwrap();
    let margin: usize = a.get(6).map_or(1, |m| m.parse().unwrap());
    let band: usize = a.get(7).map_or(8, |m| m.parse().unwrap());
    let mut params = Params::for_problem(&problem, level).level_alone();
    // PROBE_EDGE_ZERO: the P = 0 edge instead of the rule's far field.
    if std::env::var_os("PROBE_EDGE_ZERO").is_some() {
        params.edge = Edge::Zero;
    }
    // PROBE_OUTTOL: the cycles' output tolerance (the rounds converge to about it).
    if let Some(t) = std::env::var_os("PROBE_OUTTOL") {
        params.stopping.output_tolerance = t.to_str().unwrap().parse().unwrap();
    }
    // PROBE_LOADTOL: the force balance's tolerance.
    if let Some(t) = std::env::var_os("PROBE_LOADTOL") {
        params.stopping.load_tolerance = t.to_str().unwrap().parse().unwrap();
    }
    // PROBE_Y_CENTRE: the patch's middle across the rolling direction (0: about the axis).
    let y_centre = std::env::var("PROBE_Y_CENTRE").map_or(0.0, |v| v.parse().unwrap());
    let spec = PatchSpec {
        x_start,
        y_centre,
        cells_level: patch_level,
        margin,
        band,
    };
    let (patch, _) = spec.rectangle(&params.domain, level);
    // PROBE_SET: the product's patches (`inlet`, `lobes`, `inlet-and-lobes`) at LEVEL instead
    // of the one given.
    let set = match std::env::var("PROBE_SET").as_deref() {
        Ok("inlet") => Patch::Inlet.set(level),
        Ok("lobes") => Patch::Lobes.set(level),
        Ok("inlet-and-lobes") => Patch::InletAndLobes.set(level),
        Ok(other) => panic!("PROBE_SET {other}: inlet, lobes or inlet-and-lobes"),
        Err(_) => PatchSet::fixed(vec![spec]),
    };
    println!(
        "domain {:?}\npatches {set:?} (given: {patch:?})",
        params.domain
    );
    // PROBE_NO_UNIFORM skips the uniform solves (a heavy contact's level 9 takes most of an hour).
    let uniform = if std::env::var_os("PROBE_NO_UNIFORM").is_some() {
        vec![]
    } else {
        vec![level, level + 1]
    };
    for l in uniform {
        let t = Instant::now();
        let s = point::solve(
            &problem,
            &Params {
                level: l,
                ..params.clone()
            },
            None,
        )
        .unwrap();
        println!(
            "uniform L{l}: Hc {:.5} Hmin {:.5} mu {:.5} delta {:.6} ({:?}, {:.1} s)",
            s.film.hc_moes,
            s.film.hmin_moes,
            s.friction.sliding,
            s.delta,
            s.info.method,
            t.elapsed().as_secs_f64()
        );
    }
    match solve_composite(&problem, &params, &set, rounds) {
        Ok(rs) => {
            for (n, r) in rs.iter().enumerate() {
                println!(
                    "round {}: Hc {:.5} Hmin {:.5} (patch {:.5}) mu {:.5} delta {:.6} dP {:.2e} residual {:.1e} ({:.1} s)",
                    n + 1,
                    r.hc_moes,
                    r.hmin_moes,
                    r.patch_hmin_moes,
                    r.friction.sliding,
                    r.delta,
                    r.patch_change,
                    r.residual,
                    r.seconds
                );
            }
        }
        Err(e) => println!("composite failed: {e}"),
    }
    // PROBE_ESTIMATE: the product's composite solve (`Params::patch`) with its error
    // estimate over the composites at the two levels below.
    if std::env::var_os("PROBE_ESTIMATE").is_some() {
        let mut with_patch = params.clone();
        with_patch.patch = Some(set);
        with_patch.accuracy.error_levels = 2;
        match point::solve(&problem, &with_patch, None) {
            Ok(s) => {
                let errors = s.errors.as_ref().expect("estimated");
                for (name, output, value) in [
                    ("Hc", Output::HCentral, s.film.h_central),
                    ("mu", Output::MuBarSliding, s.friction.sliding),
                ] {
                    if let Some(e) = errors.estimate(output) {
                        println!(
                            "estimate {name}: {value:.6} error {:.3} % order {:?} extrapolated {:.6}",
                            100.0 * e.relative(value),
                            e.order,
                            e.extrapolated
                        );
                    }
                }
                println!(
                    "estimated composite: Hc {:.5} (Moes), {:.1} s",
                    s.film.hc_moes, s.info.seconds
                );
            }
            Err(e) => println!("estimate failed: {e}"),
        }
    }
}
