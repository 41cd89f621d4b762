//! The error ladder's coarser levels against their oracle: each is its own problem's
//! solution, whatever the start it is converged from.

use crate::point_contact::{physical, problem, rel};
use repro::solver::point::{solve, Params};

#[test]
fn a_cold_newton_krylov_cases_ladder_reads_its_levels_own_solutions() {
    // 5P4E at 40 C, 2 GPa, 7 m/s (Fig. 6's family finished by Newton-Krylov; M 57): its cycles
    // fail, the grid sequence converges levels 5-7, and the ladder starts its levels 6 and 5
    // from the sequence's solutions of them (point-30; from the full-multigrid states before,
    // level 6 took 65 Newton-Krylov steps). The ladder's level 6 is level 6 solved on its own
    // (`--exact-level --level 6`) within the two solves' algebraic tolerance: the outputs'
    // stopping rule's 5e-4, and measured 1.2e-6 in Hc and 7e-7 in friction between the two
    // starts.
    let c = physical("5p4e", 40.0, 2e9, 7.0, 0.005, 6e6, 1.0);
    let p = problem(&c);
    let at = |level: u32, ladder: bool| {
        let mut params = Params::for_problem(&p, level);
        params.accuracy.target = None;
        params.accuracy.refinement_levels = 0;
        if !ladder {
            params.accuracy.error_levels = 0;
        }
        solve(&p, &params, None).unwrap()
    };
    let seven = at(7, true);
    let errors = seven.errors.as_ref().expect("the rule's ladder");
    let ladder_six = errors
        .levels
        .iter()
        .find(|l| l.level == 6)
        .expect("level 6 read");
    let six = at(6, false);
    for (got, own, what) in [
        (ladder_six.h_central, six.film.h_central, "Hc"),
        (ladder_six.h_min, six.film.h_min, "Hmin"),
        (ladder_six.mu_bar_sliding, six.friction.sliding, "mu-bar"),
    ] {
        assert!(rel(got, own) < 5e-4, "{what}: ladder {got} vs own {own}");
    }
}
