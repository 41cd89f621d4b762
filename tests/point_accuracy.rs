//! The point-contact solver's accuracy machinery against its oracles: the refinement of a
//! closed film and of a missed accuracy target, the stopping rule's bound on the algebraic
//! error, the fitted far field against the a-priori one, and the chain of nested domains
//! (the error estimate against level 9: `error_bracket.rs`).

use crate::point_contact::{assert_sound, case_214_family, dimensionless, physical, problem, rel};
use crate::support::appendix_problem;
use repro::physics::rheology::Rheology;
use repro::solver::output::{LadderStop, Method, Output, SolveError};
use repro::solver::point::chain::solve_chain_estimated;
use repro::solver::point::{solve, solve_from, AccuracyTarget, Params, PointSolution, Start};

#[test]
fn a_closed_film_is_refined_to_the_next_level() {
    // Mineral oil A at 60 C, 3 GPa, 2 m/s (M = 11 070, a Fig. 4 case): at level 7 the
    // converged film closes at the side lobes (min H = -4e-4); the solver adds level 8,
    // where it is open, and says so.
    let c = physical("mineral-oil-a", 60.0, 3e9, 2.0, 0.001, 4e6, 1.0);
    let p = problem(&c);
    let s = solve(&p, &Params::at_level(7), None).unwrap();
    assert_eq!(s.info.level, 8);
    assert_eq!(s.grid.nx, 512);
    assert_sound(&s, "M 11 070 refined");
    // Level 8 is cycled first (19 cycles from the interpolated level 7), and its residual
    // then stands at 3-4e-5 in a period-2 oscillation while the film still creeps: since
    // revision point-10 (stopping::residual_falls) two Newton-Krylov steps finish it (13 s
    // in all, against 6.6 s for the cycles' stop 2e-4 off in Hc). Revision point-4's
    // Newton-Krylov refinement (7 steps from level 7 to a residual of 1.4e-8) gave
    // Hc 2.754665e-3, Hmin 2.377924e-4 (h/c) and mu-bar 30.940073: two solutions of the same
    // discrete equations to a residual below 1e-6 agree within 1e-4 (measured: 1e-5).
    assert!(s.info.newton_steps > 0 && s.info.residual() < 1e-6);
    for (got, newton, what) in [
        (s.film.h_central, 2.754665e-3, "Hc"),
        (s.film.h_min, 2.377924e-4, "Hmin"),
        (s.friction.sliding, 30.940073, "mu-bar"),
    ] {
        assert!(rel(got, newton) < 1e-4, "{what}: {got} vs {newton}");
    }
    let closed = solve(
        &p,
        &{
            let mut params = Params::at_level(7);
            params.accuracy.refinement_levels = 0;
            params
        },
        None,
    );
    // Without the refinement the error says which level would resolve the film: level 8,
    // which does (the estimate from the film's second-order grid error could say 9, one
    // level of margin; anything else is a wrong estimate).
    assert!(
        matches!(
            closed,
            Err(SolveError::FilmCollapse {
                level: 7,
                level_needed: Some(8 | 9),
                ..
            })
        ),
        "{closed:?}"
    );
}

#[test]
fn a_case_whose_estimate_misses_the_accuracy_target_is_refined_to_the_next_level() {
    // M 200, L 2, S-bar 0.3 (Figs. 1-3's physics): at level 7 its sliding mu-bar is 1.9471,
    // levels 5-7 converging at order 2.45 (read at 2), estimated 1.57 % off; level 9 puts it
    // 1.06 % off (examples/estimate_study.rs, docs/ACCURACY_NOTES.md): a target of 1 % in
    // friction takes it, converged by cycles, to level 8, whose levels 6-8 converge at
    // order 2.15 (0.36 %).
    let c = dimensionless(200.0, 2.0, 0.3, Rheology::Eyring);
    let p = problem(&c);
    let rule = Params::for_problem(&p, 7);
    assert_eq!(
        rule.accuracy.target,
        Some(AccuracyTarget::RULE),
        "the rule's target"
    );
    let s = solve(&p, &rule, None).unwrap();
    assert_eq!(s.info.level, 8);
    assert_sound(&s, "M 200 refined");
    let e = s.errors.as_ref().unwrap();
    assert_eq!(e.levels.len(), 3);
    let mu = e.estimate(Output::MuBarSliding).unwrap();
    assert!(
        mu.trusted() && mu.relative(s.friction.sliding) < 0.01,
        "{mu:?}"
    );
    // The same discrete solution as level 8 solved directly: two solves of the same
    // equations stopped by the output rule agree within its tolerance (5e-4).
    let direct = {
        let mut params = Params::for_problem(&p, 8);
        params.accuracy.target = None;
        params
    };
    let d = solve(&p, &direct, None).unwrap();
    for (got, want, what) in [
        (s.film.h_central, d.film.h_central, "Hc"),
        (s.friction.sliding, d.friction.sliding, "mu-bar"),
    ] {
        assert!(rel(got, want) < 5e-4, "{what}: {got} vs {want}");
    }
    // Without the target the solve stays on level 7, its estimate above 1 % and at least its
    // distance to level 8.
    let plain = solve(
        &p,
        &{
            let mut params = rule;
            params.accuracy.target = None;
            params
        },
        None,
    )
    .unwrap();
    assert_eq!(plain.info.level, 7);
    let estimate = plain
        .errors
        .unwrap()
        .estimate(Output::MuBarSliding)
        .unwrap();
    assert!(
        estimate.relative(plain.friction.sliding) > 0.01,
        "{estimate:?}"
    );
    assert!(estimate.error >= (plain.friction.sliding - d.friction.sliding).abs());
}

#[test]
fn a_level_outside_the_asymptotic_range_is_not_read_and_does_not_refine() {
    // Fig. 4 case 214 (mineral oil A, 100 C, 2 GPa, 12 m/s, S 2 %; M 1 484, L 7.4). Its level
    // 5's central film is 5 % of level 7's (under RESOLVED_FILM_SHARE, half) and its
    // mu-bar 12.0 against 16.5 and 16.2 at levels 6 and 7 (tau0 6 MPa): read, the levels
    // alternate and the first-order bound puts level 7 42 % off, which refined it. Levels 6-7
    // alone, read at the scheme's second order, put it 0.68 % off; level 8 is 0.36 % away
    // and its own levels 6-8 (order 2.17) extrapolate to 0.49 %: it stays on level 7.
    let c = physical("mineral-oil-a", 100.0, 2e9, 12.0, 0.02, 4e6, 1.0);
    let p = problem(&c);
    let s = solve(&p, &Params::for_problem(&p, 7), None).unwrap();
    assert_eq!(s.info.level, 7);
    let e = s.errors.as_ref().unwrap();
    assert_eq!(e.stopped, Some(LadderStop::FilmUnresolved { level: 5 }));
    let mu = e.estimate(Output::MuBarSliding).unwrap();
    assert_eq!((mu.levels, mu.order_used), (2, 2.0));
    assert!(mu.relative(s.friction.sliding) < 0.01, "{mu:?}");
    let fine = {
        let mut params = Params::for_problem(&p, 8);
        params.accuracy.target = None;
        solve(&p, &params, None).unwrap()
    };
    let extrapolated = fine
        .errors
        .as_ref()
        .unwrap()
        .estimate(Output::MuBarSliding)
        .unwrap()
        .extrapolated;
    assert!(
        mu.error >= (s.friction.sliding - extrapolated).abs(),
        "{mu:?}"
    );
}

#[test]
fn the_output_rule_stops_within_its_bound_of_the_converged_solution() {
    // The default cycles stop where the estimated algebraic error of film and friction is
    // below 5e-4 (solver::point::stopping); the same case iterated to a residual of 1e-6 is
    // the converged solution. The true error must stay within twice the bound: the tail
    // estimate assumes a constant convergence factor, which varies by about 10 % between
    // cycles (0.60-0.68 on this case).
    for level in [6, 7] {
        let p = appendix_problem();
        let fast = solve(&p, &Params::at_level(level), None).unwrap();
        let tight = solve(
            &p,
            &{
                let mut params = Params::at_level(level);
                params.stopping.output_tolerance = 0.0;
                params
            },
            None,
        )
        .unwrap();
        assert!(
            fast.info.cycles < tight.info.cycles,
            "the rule saves cycles"
        );
        for (what, a, b) in [
            ("Hc", fast.film.h_central, tight.film.h_central),
            ("Hmin", fast.film.h_min, tight.film.h_min),
            ("mu-bar", fast.friction.sliding, tight.friction.sliding),
        ] {
            assert!(rel(a, b) < 1e-3, "level {level} {what}: {a} vs {b}");
        }
    }
}

#[test]
fn the_cycles_do_not_stop_on_a_fixed_point_that_is_not_a_solution() {
    // Fig. 5's traction fluid at 40 C, 3 GPa, 12 m/s, S 2 % (4 MPa) at level 6: the cycles'
    // outputs settle while the residual stands at 7.7e-4, a fixed point of the cavitation
    // projection (solver::point::stopping::residual_falls). Stopped there (revision point-9)
    // the rolling friction was 6 % and Hc 2e-3 off the solution. The solver must hand that
    // state to Newton-Krylov and end at a solution of the discrete equations: a residual
    // below the tolerance, and the outputs of a Newton-Krylov solve started from the level-5
    // grid sequence (one cycle allowed) within 1e-4, two solutions of the same equations to a
    // residual of 1e-6 (the rolling friction, a thousandth of the sliding, within 1e-3).
    let p = problem(&physical("traction-fluid", 40.0, 3e9, 12.0, 0.02, 4e6, 1.0));
    let params = Params::at_level(6);
    let s = solve(&p, &params, None).unwrap();
    assert!(
        s.info.residual() < params.stopping.tolerance,
        "residual {} at the end ({:?})",
        s.info.residual(),
        s.info.method
    );
    let newton = solve(
        &p,
        &{
            let mut params = params.clone();
            params.multigrid.max_cycles = 1;
            params
        },
        None,
    )
    .unwrap();
    let rolling = |s: &PointSolution| s.friction.rolling.expect("rolling friction computed");
    for (what, a, b, bound) in [
        ("Hc", s.film.h_central, newton.film.h_central, 1e-4),
        ("Hmin", s.film.h_min, newton.film.h_min, 1e-4),
        ("mu-bar", s.friction.sliding, newton.friction.sliding, 1e-4),
        ("rolling mu-bar", rolling(&s), rolling(&newton), 1e-3),
    ] {
        assert!(rel(a, b) < bound, "{what}: {a} vs {b}");
    }
}

/// The loaded-film friction region (`H <= 4 Hc`, over the applied load) against the whole
/// domain on a heavy case whose inlet carries no friction to speak of: the Figs. 1-3 corner
/// M 1000, L 15, S-bar 0.1 at level 5. The Table 4 case at level 7 moves 4e-6 between them
/// (docs/DOMAIN_NOTES.md); 1e-4 leaves room for level 5's coarser cavitation boundary (the
/// load balance itself is held to 1e-4). On the paper's `P = 0` edge, so that the domain
/// carries the whole load and only the region differs (with the far field the domain's
/// share of the load is 5e-4 less than the applied load the loaded film divides by).
#[test]
fn the_loaded_film_region_leaves_a_heavy_contact_unchanged() {
    use repro::solver::point::{Edge, FrictionRegion};
    let p = problem(&dimensionless(1000.0, 15.0, 0.1, Rheology::Eyring));
    let at = |region| {
        let params = {
            let mut params = Params::for_problem(&p, 5);
            params.friction.region = region;
            params.edge = Edge::Zero;
            params
        };
        solve(&p, &params, None).expect("converges")
    };
    let (domain, film) = (at(FrictionRegion::Domain), at(FrictionRegion::LoadedFilm));
    // The same solve: only the friction's integral differs.
    assert_eq!(domain.film.h_central, film.film.h_central);
    let rel = (film.friction.sliding / domain.friction.sliding - 1.0).abs();
    assert!(
        rel < 1e-4,
        "sliding {} vs {}",
        film.friction.sliding,
        domain.friction.sliding
    );
}

#[test]
fn a_light_member_at_small_slip_converges_on_its_nested_domains() {
    // Fig. 6 case 19 (case 23 at S 0.1 %, tau0 4 MPa): with the core's outlet edge at X = 1.0,
    // inside its pressurised outlet (cavitation at X = 1.16), the innermost rectangle did not
    // converge and the case fell back to its case-sized domain, friction estimated 6.4 % off
    // at level 7 (about 14 % at level 6 by its order 1.16). Asked at level 5, the chain misses
    // the rule's 1 % in friction and is refined to level 6, where it is 1.8 % off by its
    // estimate (order 1.31): 3 % separates the two with room either way.
    let c = physical("5p4e", 40.0, 1e9, 12.0, 0.001, 4e6, 1.0);
    let p = problem(&c);
    let s = solve(&p, &Params::for_problem(&p, 5), None).expect("case 19 at level 5");
    let wide = s
        .surroundings
        .as_ref()
        .expect("solved on its nested domains");
    assert_eq!(s.info.level, 6, "refined one level");
    // The members start from the case-sized domain at the level asked, not the refined one:
    // a member's result does not depend on whether its base refined.
    assert_eq!(wide.info.level, 5);
    let e = s.errors.as_ref().expect("an error estimate");
    let mu = e
        .estimate(Output::MuBarSliding)
        .expect("a friction estimate");
    assert!(
        mu.relative(s.friction.sliding) < 0.03,
        "mu-bar {} +- {:.2} %",
        s.friction.sliding,
        100.0 * mu.relative(s.friction.sliding)
    );
    // The oracle: the chain solved at level 6 directly, its estimate over the chains at 4
    // and 5 solved afresh. The refined chain is solved cold, and its ladder reads the
    // level-5 solve's chains: the same bits.
    let at_6 = Params::for_problem(&p, 6);
    let (chain, direct) = solve_chain_estimated(&p, &at_6, 2).unwrap();
    let inner = chain.innermost();
    assert_eq!(
        (s.film.h_central, s.film.h_min),
        (inner.film.h_central, inner.film.h_min)
    );
    assert_eq!(s.friction.sliding, chain.friction(&p).sliding);
    assert_eq!(e.levels, direct.levels);
}

#[test]
fn a_members_ladder_stops_where_its_bases_found_a_level_outside_the_range() {
    // Fig. 4 case 214's family (mineral oil A, 100 C, 2 GPa, 12 m/s; M 1 484): its base (S
    // 0.5 %, 6 MPa) finds level 5 outside the asymptotic range at level 7, and so does the
    // member at S 2 %, 4 MPa when it converges that level itself (its film is its base's
    // within 1e-4). From its base's start the member does not solve level 5 again: it reads
    // the same levels 6-7, converged from the same starts, so the same bits, and says whose
    // finding stopped it.
    let (base, member) = case_214_family();
    let params = Params::for_problem(&base, 7);
    let b = solve(&base, &params, None).unwrap();
    let start = Start::of(&b);
    assert_eq!(start.outside, Some(LadderStop::FilmUnresolved { level: 5 }));
    let inherited = solve_from(&member, &params, &start, None).unwrap();
    let own = {
        let start = Start {
            outside: None,
            ..start.clone()
        };
        solve_from(&member, &params, &start, None).unwrap()
    };
    let (e, own_e) = (inherited.errors.unwrap(), own.errors.unwrap());
    assert_eq!(e.stopped, Some(LadderStop::OutsideAtBase { level: 5 }));
    assert_eq!(own_e.stopped, Some(LadderStop::FilmUnresolved { level: 5 }));
    assert_eq!(e.levels, own_e.levels);
    for o in [Output::HCentral, Output::HMin, Output::MuBarSliding] {
        assert_eq!(e.level_estimate(o), own_e.level_estimate(o), "{o:?}");
    }
    // The central film tau-extrapolated on both: their coarse problems start from coarse
    // levels converged apart, and stop where the film still to come is below 1e-4 of it
    // (src/solver/point/tau.rs), so the films agree within twice that.
    let (a, b) = (e.value(Output::HCentral), own_e.value(Output::HCentral));
    assert!((a / b - 1.0).abs() < 2e-4, "tau-extrapolated Hc {a} vs {b}");
}

/// The far field with its amplitude refitted to the solution (`Edge::FittedFarField`, the
/// studies' option, reached by no command) against the rule's a-priori amplitude on the light
/// contact M 5, L 10, S-bar 0.1, Eyring, whose domain the light inlet sizes. The amplitude
/// moves the outputs through the load outside the domain (at most 8 % of the load by the
/// domain rule): at level 6 the two differ by 1.5e-4 in `Hc` and 2.2e-3 in friction (at level
/// 7, docs/DOMAIN_NOTES.md, 5e-5 and 9e-4), a small part of level 6's own friction error (16 %
/// estimated). The bounds, 1e-3 and 5e-3, leave twice the measured difference and stay far
/// below that error: a refit loop that drifted or stopped on a stale edge would exceed them.
#[test]
fn the_fitted_far_field_agrees_with_the_a_priori_one_on_a_light_contact() {
    use repro::solver::point::Edge;
    let p = problem(&dimensionless(5.0, 10.0, 0.1, Rheology::Eyring));
    let at = |edge| {
        let params = Params {
            edge,
            ..Params::for_problem(&p, 6)
        };
        solve(&p, &params, None).expect("converges")
    };
    let (a_priori, fitted) = (at(Edge::FarField), at(Edge::FittedFarField));
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    let hc = rel(fitted.film.h_central, a_priori.film.h_central);
    let mu = rel(fitted.friction.sliding, a_priori.friction.sliding);
    // The refits ran: the fitted amplitude is not the a-priori one bit for bit.
    assert!(hc > 0.0, "the fit left the edge as it was");
    assert!(
        hc < 1e-3 && mu < 5e-3,
        "fitted against a priori: Hc {} / {} ({hc:e}), mu-bar {} / {} ({mu:e})",
        fitted.film.h_central,
        a_priori.film.h_central,
        fitted.friction.sliding,
        a_priori.friction.sliding
    );
}

/// The chain of nested domains (issue 39 prototype, `solver::point::chain`) on M 5, L 10
/// (S-bar 0.1, Barus, Eyring; case-sized domain `-12.5..7 x 12.5`, two rectangles) at level 6.
/// Reference: the grid-converged values of docs/ACCURACY_NOTES.md ("Resolution where the
/// contact needs it"): sliding `mu-bar` 0.22749, Moes `Hc` 3.6863, extrapolated from two
/// rectangles at levels 6-8 and agreeing with the uniform levels' extrapolation (0.2274).
#[test]
fn a_chain_of_nested_domains_brings_a_light_contact_within_the_targets() {
    let problem = problem(&dimensionless(5.0, 10.0, 0.1, Rheology::Eyring));
    let params = Params::for_problem(&problem, 6);
    let (chain, errors) = solve_chain_estimated(&problem, &params, 2).unwrap();
    let (hc, mu) = (
        errors.estimate(Output::HCentral),
        errors.estimate(Output::MuBarSliding),
    );
    assert_eq!(chain.solutions.len(), 3, "the domain and two rectangles");
    let [hc_value, _, mu_value] = chain.outputs(&problem);
    // Issue 39's targets: friction within 1 % (measured 0.57 %; the uniform level 6 is
    // 8.9 % off), film within 2 % (measured 0.01 %).
    let (mu_error, hc_error) = ((mu_value - 0.22749).abs(), (hc_value - 3.6863).abs());
    assert!(mu_error < 0.01 * 0.22749, "mu-bar {mu_value}");
    assert!(hc_error < 0.02 * 3.6863, "Hc {hc_value}");
    // The estimate over the chains at levels 4-6 brackets the friction's error (0.76 %
    // estimated against 0.57 %).
    let mu = mu.expect("three levels give an estimate");
    assert!(
        mu.error >= mu_error,
        "estimate {} against {mu_error}",
        mu.error
    );
    assert!(hc.is_some());
}

#[test]
fn a_refined_level_whose_cycles_alternate_converges_by_cycles() {
    // Fig. 5 case 5 (traction fluid, 40 C, 1 GPa, 2 m/s, S 0.5 %, 6 MPa; M 98, L 17.1):
    // refined to level 8 for a friction target of 0.1 % (its level-7 estimate is 0.54 %;
    // the rule's 1 % keeps it on level 7), where its cycles lock into a period-two
    // oscillation at the side of the pressure spike (solver::point::cycles::DAMPED_CORRECTION)
    // and, at point-22, stalled after 22 cycles and took 4 Newton-Krylov steps (11.7 s user
    // against 4.1 s). With the correction weighted they converge; the outputs of that
    // Newton-Krylov solution (a residual of 5.5e-8: Hc 0.19600971, Hmin 0.11306471, mu-bar
    // 14.630654) must be met within the output rule's 5e-4 (measured 1.0e-6, 1.7e-5, 5e-7).
    let p = problem(&physical("traction-fluid", 40.0, 1e9, 2.0, 0.005, 6e6, 1.0));
    let mut params = Params::for_problem(&p, 7);
    params.accuracy.target = Some(AccuracyTarget {
        mu_bar_sliding: 0.001,
        h_central: None,
        h_min: None,
    });
    let s = solve(&p, &params, None).unwrap();
    assert_eq!((s.info.level, s.info.method), (8, Method::Cycles));
    assert_sound(&s, "Fig. 5 case 5");
    for (what, got, want) in [
        ("Hc", s.film.h_central, 0.19600971),
        ("Hmin", s.film.h_min, 0.11306471),
        ("mu-bar", s.friction.sliding, 14.630654),
    ] {
        assert!(rel(got, want) < 5e-4, "{what}: {got} vs {want}");
    }
}
