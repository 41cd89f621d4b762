//! A chain of nested domains by the rule of `solver::point::chain` (issue 39 prototype): the
//! case's rectangles, the chain's outputs at `LEVEL` and their error estimate over the chains
//! at the two levels below, and the time.
//!
//! `cargo run --release --example chain_probe -- CASE LEVEL` (`CASE` as `nested_probe`).
mod common;

use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::output::Output;
use repro::solver::point::chain::{rectangles, solve_chain_estimated};
use repro::solver::point::Params;
use std::time::Instant;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let problem = Problem::from_case(&common::case_of(&a[1]), &LubricantTable::table1()).unwrap();
    let level: u32 = a[2].parse().unwrap();
    let params = Params::for_problem(&problem, level);
    println!("domain {:?}", params.domain);
    for r in rectangles(&params.domain) {
        println!("  rectangle {r:?}");
    }
    let t = Instant::now();
    let (chain, errors) = solve_chain_estimated(&problem, &params, 2).expect("chain");
    let seconds = t.elapsed().as_secs_f64();
    let finest = errors.levels.last().expect("the chain's own level");
    for (name, output) in [
        ("Hc", Output::HCentral),
        ("Hmin", Output::HMin),
        ("mu", Output::MuBarSliding),
    ] {
        // The estimate is in the solver's units (`H = h/c`): relative, as in Moes units.
        let value = finest.get(output);
        match errors.estimate(output) {
            Some(e) => println!(
                "{name} {value:.6}: error {:.3} % (order {:?}), extrapolated {:.6}",
                100.0 * e.error / value.abs(),
                e.order,
                e.extrapolated
            ),
            None => println!("{name} {value:.6}: no estimate"),
        }
    }
    let [hc, hmin, mu] = chain.outputs(&problem);
    println!("Moes Hc {hc:.6}, Moes Hmin {hmin:.6}, mu-bar {mu:.6}");
    println!(
        "level {level}, {} grids, {seconds:.1} s with the estimate",
        chain.solutions.len()
    );
}
