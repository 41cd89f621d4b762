//! Continuation (issue 30): a case solved from its base's solution agrees with the same case
//! solved cold and tightly converged, on every path a warm start can take: cycles,
//! Newton-Krylov, a base the film refined to the next level, a limited case from its Eyring
//! twin, and a Figs. 1-3 family across its two decades of S-bar.
//!
//! The tolerance, 5e-4 relative on the central and minimum film and the sliding friction, is
//! the stopping rule's bound on a solve's algebraic error (`OUTPUT_TOLERANCE`): the warm
//! solve stops on it, the reference is solved with the rule off (to the residual tolerance,
//! or by Newton-Krylov), so the two differ by the warm solve's algebraic error alone. Levels
//! 5 and 6 keep each solve under a few seconds; the paths are the same at every level.

use crate::support::physical;
use repro::paper::cases::shipped_sweep;
use repro::physics::case::{Case, CaseForm, DimensionlessCase, Physics, Problem};
use repro::physics::lubricant::LubricantTable;
use repro::physics::rheology::{LimitingShearStress, Rheology};
use repro::pipeline::base::{base_of, BASE_S_BAR};
use repro::solver::output::{Method, StartKind};
use repro::solver::point::{self, Params, PointSolution, Start};
use std::collections::BTreeMap;

const TOLERANCE: f64 = 5e-4;

fn problem(case: &Case) -> Problem {
    Problem::from_case(case, &LubricantTable::table1()).expect("a valid case")
}

/// The base's solution, solved as a sweep solves it (from its own base where it has one).
fn base_start(case: &Case, level: u32) -> (Start, PointSolution) {
    let base = base_of(case).expect("a member, not a base");
    let bp = problem(&base);
    let params = Params::for_problem(&bp, level);
    let s = match base_of(&base) {
        Some(_) => {
            let (below, _) = base_start(&base, level);
            point::solve_from(&bp, &params, &below, None)
        }
        None => point::solve(&bp, &params, None),
    }
    .expect("the base converges");
    (Start::of(&s), s)
}

/// Solves `case` warm from its base and cold with the output rule off; checks the warm
/// start was taken and agrees; returns the warm and the base's solutions.
fn warm_agrees(case: &Case, level: u32, what: &str) -> (PointSolution, PointSolution) {
    let p = problem(case);
    let (start, base) = base_start(case, level);
    let params = Params::for_problem(&p, level);
    let warm = point::solve_from(&p, &params, &start, None).expect("warm converges");
    let tight = {
        let mut params = params.clone();
        params.stopping.output_tolerance = 0.0;
        params
    };
    let cold = point::solve(&p, &tight, None).expect("cold converges");
    assert_eq!(warm.info.start, StartKind::Warm, "{what}: {:?}", warm.info);
    assert_eq!(
        warm.info.level, cold.info.level,
        "{what}: the level solved on"
    );
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    for (name, w, c) in [
        ("Hc", warm.film.h_central, cold.film.h_central),
        ("Hmin", warm.film.h_min, cold.film.h_min),
        ("mu-bar", warm.friction.sliding, cold.friction.sliding),
    ] {
        assert!(
            rel(w, c) < TOLERANCE,
            "{what}: {name} warm {w} vs tight cold {c} ({:.1e})",
            rel(w, c)
        );
    }
    (warm, base)
}

#[test]
fn a_member_converged_by_cycles_starts_from_its_base() {
    // Mineral oil A, 40 C, 3 GPa, 12 m/s (the Appendix family), S 2 %, tau0 4 MPa, level 6.
    let case = physical("mineral-oil-a", 40.0, 3.0, 12.0, 0.02, 4.0);
    let (warm, base) = warm_agrees(&case, 6, "cycles");
    assert_eq!(base.info.method, Method::Cycles);
    assert_eq!(warm.info.method, Method::Cycles);
    // Fewer cycles than the base's cold solve: the point of starting warm.
    assert!(warm.info.cycles < base.info.cycles, "{:?}", warm.info);
}

#[test]
fn a_member_starts_its_top_refined_across_from_its_bases() {
    // The same family at level 7, where its minimum film misses 10 % (21 %): the base and the
    // member add the top refined across the rolling direction (256 x 512), the member's
    // square level from the base's and its top and the 6y rung under it from the base's.
    let case = physical("mineral-oil-a", 40.0, 3.0, 12.0, 0.02, 4.0);
    let (warm, base) = warm_agrees(&case, 7, "across");
    for s in [&base, &warm] {
        assert!(s.grid.is_refined_y(), "{:?}", s.grid);
        let across = s.errors.as_ref().and_then(|e| e.across);
        assert!(across.is_some_and(|a| a.below.is_some()), "{across:?}");
    }
    assert_eq!(warm.info.level, 7);
    assert!(warm.info.cycles < base.info.cycles, "{:?}", warm.info);
}

#[test]
fn a_member_of_a_newton_krylov_family_starts_newton_from_its_base() {
    // 5P4E, 40 C, 3 GPa, 12 m/s, S 0.1 %, tau0 8 MPa, level 5: the hard case's family,
    // converged by Newton-Krylov.
    let case = physical("5p4e", 40.0, 3.0, 12.0, 0.001, 8.0);
    let (warm, base) = warm_agrees(&case, 5, "Newton-Krylov");
    assert_eq!(base.info.method, Method::NewtonKrylov);
    assert_eq!(warm.info.method, Method::NewtonKrylov);
    assert!(
        warm.info.newton_steps < base.info.newton_steps,
        "{:?}",
        warm.info
    );
}

#[test]
fn a_member_of_a_refined_family_is_solved_on_its_bases_level() {
    // Traction fluid, 60 C, 3 GPa, 7 m/s (M 1 840) at level 5: the film closes at level 5
    // and the base is refined to level 6 (as M 11 070 is from level 7 to 8); its members
    // start there.
    let case = physical("traction-fluid", 60.0, 3.0, 7.0, 0.02, 8.0);
    let (warm, base) = warm_agrees(&case, 5, "refined");
    assert_eq!(base.info.level, 6, "{:?}", base.info);
    assert_eq!(warm.info.level, 6, "{:?}", warm.info);
}

#[test]
fn a_limited_case_starts_from_its_eyring_twin() {
    // Mineral oil A, 60 C, 3 GPa, 7 m/s, S 2 %, tau0 4 MPa with the `lss` target's limit at
    // Lambda-bar 10: tau_L = tau0 + Lambda p, Lambda = 10 tau0 / p_H; level 6. Its twin
    // starts from the family's base in turn.
    let mut case = physical("mineral-oil-a", 60.0, 3.0, 7.0, 0.02, 4.0);
    case.physics.rheology = Rheology::EyringLss(LimitingShearStress {
        lambda: 10.0 * 4e6 / 3e9,
        tau_l0_pa: 4e6,
    });
    let twin = base_of(&case).expect("the Eyring twin");
    assert_eq!(twin.physics.rheology, Rheology::Eyring);
    warm_agrees(&case, 6, "limited from its Eyring twin");
}

#[test]
fn a_figs_1_to_3_family_starts_from_s_bar_0_1_across_two_decades() {
    // M 1000, L 10 (Barus, incompressible, Eyring), tau0_hat 2: S-bar 0.01 and 1 from the
    // base at 0.1, level 6.
    for s_bar in [0.01, 1.0] {
        let case = Case {
            spec: CaseForm::Dimensionless(DimensionlessCase {
                m: 1000.0,
                l: 10.0,
                s_bar,
                d: 1.0,
                slip: 2.0 * s_bar,
                eta0_pa_s: None,
                ph_pa: None,
            }),
            physics: Physics::default(),
        };
        warm_agrees(&case, 6, &format!("Figs. 1-3, S-bar {s_bar}"));
    }
}

#[test]
fn a_start_that_does_not_fit_the_grid_solves_cold() {
    // A level-5 start for a level-6 solve: coarser than asked, so the solve starts cold
    // (5P4E, 40 C, 1 GPa, 7 m/s: a light family, whose base is not refined).
    let case = physical("5p4e", 40.0, 1.0, 7.0, 0.02, 4.0);
    let p = problem(&case);
    let (start, _) = base_start(&case, 5);
    let s = point::solve_from(&p, &Params::for_problem(&p, 6), &start, None).expect("converges");
    assert_eq!(s.info.start, StartKind::Cold);
    let cold = point::solve(&p, &Params::for_problem(&p, 6), None).expect("converges");
    assert_eq!(s.film.h_central.to_bits(), cold.film.h_central.to_bits());
}

// The base of a case, on the shipped sweeps.

#[test]
fn every_table_2_family_has_its_base_among_its_nine_members() {
    for fig in ["fig4", "fig5", "fig6"] {
        let cases = shipped_sweep(fig).unwrap().cases;
        let mut families: BTreeMap<String, Vec<&Case>> = BTreeMap::new();
        for c in &cases {
            let key = match base_of(c) {
                Some(b) => serde_json::to_string(&b).unwrap(),
                None => serde_json::to_string(c).unwrap(),
            };
            families.entry(key).or_default().push(c);
        }
        assert_eq!(families.len(), 27, "{fig}: 27 families");
        for (base, members) in &families {
            assert_eq!(members.len(), 9, "{fig}: {base}");
            let own = members.iter().filter(|c| base_of(c).is_none()).count();
            assert_eq!(own, 1, "{fig}: one member is the base: {base}");
        }
    }
}

#[test]
fn figs_1_to_3_families_keep_m_l_and_the_eyring_stress() {
    let cases = shipped_sweep("fig1-3").unwrap().cases;
    let mut bases = 0;
    for c in &cases {
        let CaseForm::Dimensionless(d) = &c.spec else {
            panic!("Figs. 1-3 are in Moes groups")
        };
        match base_of(c) {
            None => {
                assert_eq!(d.s_bar, BASE_S_BAR);
                bases += 1;
            }
            Some(b) => {
                let CaseForm::Dimensionless(db) = &b.spec else {
                    panic!()
                };
                assert_eq!((db.m, db.l, db.d, db.s_bar), (d.m, d.l, d.d, BASE_S_BAR));
                // The dimensionless Eyring stress S / S-bar is kept (2 in Figs. 1-3).
                assert!((db.slip / db.s_bar - d.slip / d.s_bar).abs() < 1e-12);
            }
        }
    }
    assert_eq!(bases, 25, "one base per (M, L)");
}

#[test]
fn a_limited_case_has_its_eyring_twin_for_base() {
    let mut c = shipped_sweep("fig4").unwrap().cases[0].clone();
    c.physics.rheology = Rheology::EyringLss(LimitingShearStress {
        lambda: 0.08,
        tau_l0_pa: 5e6,
    });
    let twin = base_of(&c).unwrap();
    assert_eq!(twin.physics.rheology, Rheology::Eyring);
    assert_eq!(twin.spec, c.spec);
}
