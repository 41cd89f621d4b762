//! Prototype of issue 39: a nested domain inside the whole domain's solution.
//!
//! `cargo run --release --example nested_probe -- CASE WIDE_LEVEL INNER_LEVEL X0:X1:YH...`
//!
//! `CASE`: `case23`, `d:M:L:SBAR` (as `order_probe`) or
//! `p:LUBRICANT:T_C:PH_PA:UM:SLIP:TAU0_PA` (circular, the Figs. 4-7 physics). The whole domain is the rule's with
//! the far field, solved at `WIDE_LEVEL`; each nested rectangle `X0..X1 x -YH..YH` is snapped
//! outward to the grid lines of the solution around it and solved at `INNER_LEVEL` with that
//! solution as its surroundings. Prints both solutions' central and minimum film (Moes), the sliding
//! `mu-bar` (nested: its own loaded film plus the wide solution's outside it) and the times.
mod common;

use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::grid::{Domain, Grid};
use repro::solver::output::Output;
use repro::solver::point::chain::snap;
use repro::solver::point::nested::Surround;
use repro::solver::point::{self, Params, LOADED_FILM_FACTOR};
use std::sync::Arc;
use std::time::Instant;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let problem = Problem::from_case(&common::case_of(&a[1]), &LubricantTable::table1()).unwrap();
    let (wl, il): (u32, u32) = (a[2].parse().unwrap(), a[3].parse().unwrap());
    let mut wide_params = Params::for_problem(&problem, wl);
    wide_params.accuracy.error_levels = 0;
    // The whole domain alone: the rectangles are this probe's own.
    wide_params.nested = false;
    let t = Instant::now();
    let wide = point::solve(&problem, &wide_params, None).expect("wide solve");
    let wide_s = t.elapsed().as_secs_f64();
    println!(
        "wide  L{wl} {:?} hx {:.4}: Hc {:.5} Hmin {:.5} mu {:.5} delta {:.5} ({:?}, {:.1} s)",
        wide_params.domain,
        wide.grid.hx,
        wide.film.hc_moes,
        wide.film.hmin_moes,
        wide.friction.sliding,
        wide.delta,
        wide.info.method,
        wide_s
    );
    // Each further rectangle is nested in the solution of the one before; the friction
    // outside each rectangle comes from the solution around it.
    let mut outer = wide;
    let mut outside_friction: Vec<Arc<Surround>> = Vec::new();
    for rect in &a[4..] {
        let r: Vec<f64> = rect.split(':').map(|s| s.parse().unwrap()).collect();
        let g = outer.grid;
        let inner = snap(
            &Domain {
                x_start: r[0],
                x_end: r[1],
                y_half: r[2],
                y_centre: 0.0,
            },
            &g,
        );
        let fine = Grid::level(&inner, il);
        let surround = Arc::new(Surround::new(
            &problem,
            &g,
            (&outer.p, &outer.h, outer.delta),
            &inner,
            (fine.hx, fine.hy),
        ));
        let mut params = Params::for_problem(&problem, il);
        params.domain = inner;
        // PROBE_ERROR_LEVELS: the coarser levels of the nested solve's error estimate.
        params.accuracy.error_levels = std::env::var("PROBE_ERROR_LEVELS")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(0);
        let t = Instant::now();
        let nested = point::solve_nested(&problem, &params, &surround, None).expect("nested solve");
        let nested_s = t.elapsed().as_secs_f64();
        outside_friction.push(surround.clone());
        let limit = LOADED_FILM_FACTOR * nested.film.h_central;
        let outside: f64 = outside_friction
            .iter()
            .map(|s| s.outside_sliding(&problem, limit))
            .sum();
        let mut edge_loaded = 0;
        for j in 0..=fine.ny {
            for i in 0..=fine.nx {
                let on_edge = i == 0 || j == 0 || i == fine.nx || j == fine.ny;
                let k = fine.idx(i, j);
                if on_edge && nested.p[k] > 0.0 && nested.h[k] <= limit {
                    edge_loaded += 1;
                }
            }
        }
        println!(
            "nest  L{il} {inner:?} hx {:.4}: Hc {:.5} Hmin {:.5} mu {:.5} (inside {:.5} + outside {:.5}) delta {:.5} outside load {:.4} edge loaded nodes {edge_loaded} ({:?}, {:.1} s)",
            fine.hx,
            nested.film.hc_moes,
            nested.film.hmin_moes,
            nested.friction.sliding + outside,
            nested.friction.sliding,
            outside,
            nested.delta,
            surround.outside_load(),
            nested.info.method,
            nested_s
        );
        if let Some(errors) = &nested.errors {
            for (name, output) in [("Hc", Output::HCentral), ("mu", Output::MuBarSliding)] {
                if let Some(e) = errors.estimate(output) {
                    let finest = errors.levels[errors.levels.len() - 1].get(output);
                    println!(
                        "      {name} levels {:?}: error {:.2} % (order {:?}, used {:.2}), extrapolated {:.6}",
                        errors.levels.iter().map(|v| v.get(output)).collect::<Vec<_>>(),
                        100.0 * e.error / finest.abs(),
                        e.order,
                        e.order_used,
                        e.extrapolated
                    );
                }
            }
        }
        outer = nested;
    }
}
