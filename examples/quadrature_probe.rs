//! Whether a level's friction error is its quadrature's or its solution's
//! (docs/ACCURACY_NOTES.md, "The friction's error is in the solution"): each case named on the
//! command line solved cold at level N (the first argument) and at the two levels below, on
//! the same domain, by the rule's parameters without target, refinement or ladder. The sliding
//! `mu-bar` of Eq. 8 is summed over the finest solution's nodes that are also a coarser
//! level's (every second or fourth node, with that level's cell area and loaded-film region):
//! the coarser quadrature of the fine solution. Where it lies next to the fine friction and
//! the coarser level's own friction does not, the coarser level's error is in its pressure and
//! film, not in the sum. One line per case on stdout.
//!
//! `cargo run --release --example quadrature_probe -- N CASE...` (cases as `common::case_of`
//! names them).
mod common;
use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::point::{self, mean_shear_stress, PointSolution, LOADED_FILM_FACTOR};

fn solve(problem: &Problem, level: u32) -> Option<PointSolution> {
    point::solve(problem, &common::level_alone(problem, level), None).ok()
}

/// Sliding mu-bar of `s` summed at every `stride`-th node (the coarser grid's quadrature).
fn quadrature(problem: &Problem, s: &PointSolution, stride: usize) -> f64 {
    let tau = mean_shear_stress(problem, s);
    let g = &s.grid;
    let limit = LOADED_FILM_FACTOR * g.at_centre(&s.h);
    let mut sum = 0.0;
    let (nx, ny) = (g.nx / stride, g.ny / stride);
    for j in 1..ny {
        for i in 1..nx {
            let k = g.idx(i * stride, j * stride);
            if s.p[k] > 0.0 && s.h[k] <= limit {
                sum += tau[k];
            }
        }
    }
    let cell = g.hx * g.hy * (stride * stride) as f64;
    sum * cell / repro::physics::hertz::DIMENSIONLESS_LOAD
}

fn main() {
    let lubricants = LubricantTable::table1();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let fine: u32 = args[0].parse().unwrap();
    for name in &args[1..] {
        let problem = Problem::from_case(&common::case_of(name), &lubricants).expect("a case");
        let s9 = solve(&problem, fine).expect("the finest level converges");
        let mut line = format!(
            "{name}: fine {fine} mu {:.6} Q(self) {:.6}",
            s9.friction.sliding,
            quadrature(&problem, &s9, 1)
        );
        for (lv, stride) in [(fine - 1, 2usize), (fine - 2, 4)] {
            let mu = solve(&problem, lv).map_or(f64::NAN, |s| s.friction.sliding);
            line += &format!(
                " | level {lv}: mu {mu:.6} Q{lv}(u_fine) {:.6}",
                quadrature(&problem, &s9, stride)
            );
        }
        println!("{line}");
    }
}
