//! The heaviest Table 2 load (M = 19 205): the longest integration test, a level-8
//! Newton-Krylov solve audited for subnormal numbers (about 2.5 minutes on 2 cores). libtest
//! starts the tests in the order of their names, so this module is named to sort first: named
//! `point_contact::...` it started last and ran alone for 138 s of the 561 s of a fresh-clone
//! CI's integration tests, where first it runs beside the others.

use crate::point_contact::{assert_sound, physical, problem};
use repro::solver::grid::Domain;
use repro::solver::point::{solve, Params};
use repro::solver::subnormal;

#[test]
fn the_film_opens_at_level_8_on_the_heavy_load_domain() {
    // Mineral oil A at 100 C, 3 GPa, 2 m/s (M = 19 205, the Fig. 4 cases whose film stayed
    // closed at level 8 on the paper's domain): on the domain the sweeps choose for this load
    // (Domain::heavy, a 3/4 mesh) the level-7 film still closes and the solver's refinement
    // opens it at level 8.
    let c = physical("mineral-oil-a", 100.0, 3e9, 2.0, 0.005, 6e6, 1.0);
    let p = problem(&c);
    assert!(p.groups.m > 19_000.0, "M = {}", p.groups.m);
    let params = Params::for_problem(&p, 7);
    assert_eq!(params.domain, Domain::heavy());
    // The solve audited for subnormal numbers, in the processor's default arithmetic (the
    // solver sets flush-to-zero only inside the preconditioner's factorisation and solves):
    // its factor's fill decays through f32's subnormal range, 2.7 % of the 100 million
    // entries of a level-8 factor without the flag, which slowed an Intel core 5-fold
    // (src/solver/subnormal.rs). Any subnormal entry of a factor or of a GMRES vector fails.
    assert!(
        !subnormal::flushes_to_zero(),
        "the test thread's default arithmetic"
    );
    let (s, counts) = subnormal::audit(|| solve(&p, &params, None));
    let s = s.unwrap_or_else(|e| panic!("M 19 205: {e}"));
    assert!(
        !subnormal::flushes_to_zero(),
        "the solver restores the caller's arithmetic"
    );
    assert_sound(&s, "M 19 205");
    assert_eq!(s.info.level, 8);
    // The level-8 factors were examined: 201 000 active nodes, about 1e8 entries (at least
    // 2e7 tells a level-8 factor from a level-7 one, 1.9e7).
    assert!(counts.largest_factor > 20_000_000, "{counts:?}");
    assert!(counts.vectors > 100, "{counts:?}");
    assert_eq!(
        (counts.factor_subnormals, counts.vector_subnormals),
        (0, 0),
        "{counts:?}"
    );
}
