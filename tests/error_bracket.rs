//! The discretisation error estimates against the truth they claim to bound: each estimate
//! of a sample of point and line contacts brackets its distance to the next finer level (the
//! error of a level is at least that distance, up to the finer level's own error), and does
//! not overstate it by more than a small factor (the rule spends time where the estimate
//! says the error is); and a level-7 solve's estimate on the light, middle and heavy contacts
//! brackets its distance to level 9 without overstating it more than 3 times.

use crate::point_contact::{dimensionless, physical, problem};
use repro::paper::figures::line::table3_line_cases;
use repro::paper::table4::Table4Case;
use repro::physics::case::Case;
use repro::physics::line_contact::LineProblem;
use repro::physics::rheology::Rheology;
use repro::solver::line;
use repro::solver::output::{LadderStop, Output, OutputErrors};
use repro::solver::point::{self, Params, PointSolution};

/// The outputs checked: the central film and the sliding friction (the figures' `y` and
/// their film).
const OUTPUTS: [(Output, &str); 2] = [(Output::HCentral, "Hc"), (Output::MuBarSliding, "mu")];

/// Each reported output's estimated error ([`OutputErrors::value`], the central film
/// tau-extrapolated where the solve reports it so) over its distance to `finer` (the same
/// outputs one level finer, as that solve reports them).
fn ratios(errors: &OutputErrors, finer: [f64; 2]) -> [f64; 2] {
    let mut out = [0.0; 2];
    for (k, (o, _)) in OUTPUTS.iter().enumerate() {
        let e = errors.estimate(*o).expect("estimated");
        out[k] = e.error / (errors.value(*o) - finer[k]).abs();
    }
    out
}

/// Asserts that every ratio of `what` lies in `[1, most]`.
fn assert_brackets(what: &str, r: [f64; 2], most: f64) {
    for (k, (_, name)) in OUTPUTS.iter().enumerate() {
        assert!(
            (1.0..=most).contains(&r[k]),
            "{what} {name}: estimate / distance to the next level = {:.3}",
            r[k]
        );
    }
}

#[test]
fn line_contact_estimates_bracket_the_next_finer_level() {
    // Fig. 7's five line contacts by the rule at the figure's level 8 (each ends on the level
    // whose ladder reads three levels in the asymptotic range: 8 to 10), against the same
    // contact one level finer solved alone. The upper bound 3 is Roache's untrusted safety
    // factor, the most an estimate may exceed the distance it bounds before it misplaces the
    // time the rule spends (measured 1.04-1.53 in friction, 1.69-1.84 in film). At level 7
    // line contact 1's friction levels converge at order 3.2, outside the accepted range: its
    // first-order bound is 10.6 times its distance to level 8, which is why the test is at 8.
    let (cases, physics) = table3_line_cases().unwrap();
    for (k, c) in cases.iter().enumerate() {
        let pr = LineProblem::from_physical(c, physics).unwrap();
        let s = line::solve(&pr, &line::Params::for_problem(&pr, 8), None).unwrap();
        let e = s.errors.as_ref().expect("three levels converged");
        assert_eq!(e.levels.len(), 3, "line contact {}: {e:?}", k + 1);
        let finer_params = line::Params {
            refinement_levels: 0,
            ..line::Params::for_problem(&pr, s.info.level + 1)
        };
        let f = line::solve(&pr, &finer_params, None).unwrap();
        let r = ratios(e, [f.film.h_central, f.friction.sliding]);
        assert_brackets(&format!("line contact {}", k + 1), r, 3.0);
    }
}

#[test]
fn point_contact_estimates_bracket_the_next_finer_level() {
    // Cheap point contacts by the rule at level 7 (without its refinement, so each stays on
    // the level asked; levels 5-7 read), against the same rule at level 8. Only the bracket
    // is asserted: where the levels oscillate or their order falls outside the accepted range
    // the estimate is the untrusted first-order bound, which overstates the friction's
    // distance to level 8 here (measured 8.0 on M 50 L 10, order 0.78; 5.9 on mineral oil A,
    // oscillating; 1.4 on M 200 L 5, and 1.74-1.76 in film on all three).
    let cases = [
        (
            "Barus M 50 L 10",
            dimensionless(50.0, 10.0, 0.1, Rheology::Eyring),
        ),
        (
            "Barus M 200 L 5",
            dimensionless(200.0, 5.0, 0.1, Rheology::Eyring),
        ),
        (
            "mineral oil A 1 GPa 60 C",
            physical("mineral-oil-a", 60.0, 1e9, 12.0, 0.02, 8e6, 1.0),
        ),
    ];
    for (name, case) in cases {
        let p = problem(&case);
        let alone = |level: u32| {
            let mut params = point::Params::for_problem(&p, level);
            params.accuracy.target = None;
            params.accuracy.refinement_levels = 0;
            point::solve(&p, &params, None).unwrap()
        };
        let s = alone(7);
        let f = alone(8);
        let e = s.errors.as_ref().expect("estimated");
        assert_eq!(e.levels.len(), 3, "{name}: {e:?}");
        let r = ratios(e, [f.film.h_central, f.friction.sliding]);
        assert_brackets(name, r, f64::INFINITY);
    }
}

/// The discretisation error a level-7 solve reports (from its own level and the two below,
/// src/solver/richardson.rs) against the same case solved at level 9: for the central film,
/// the minimum film and the sliding friction, the estimate must be at least the distance to
/// level 9, and at most [`MOST_OVERSTATEMENT`] times it (or times [`OVERSTATEMENT_FLOOR`] of the
/// value). Level 9 is itself not converged, so the distance understates the true error by
/// the level-9 error (a quarter to a half of the level-7 one at orders 2 to 1): bracketing it
/// is what an error bar must do at the least. A case on a chain of nested domains
/// (`Params::nested`) is held against its chain at level 8, whose contact mesh (2.6 / 512)
/// is four times finer than a uniform level 9's on its domain. Returns the level-7 solve.
fn assert_estimate_brackets_level_9(case: &Case, what: &str) -> PointSolution {
    let p = problem(case);
    let s = point::solve(&p, &Params::for_problem(&p, 7), None)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    let fine_level = if Params::for_problem(&p, 7).nested {
        8
    } else {
        9
    };
    let fine_params = {
        let mut params = Params::for_problem(&p, fine_level);
        params.accuracy.error_levels = 0;
        params
    };

    let fine = point::solve(&p, &fine_params, None).unwrap_or_else(|e| panic!("{what} L9: {e}"));
    let e = s
        .errors
        .as_ref()
        .expect("a case is solved with its error estimate");
    assert!(
        e.levels.len() >= 2,
        "{what}: at least two levels, {:?}",
        e.levels
    );
    // The level's own outputs are held against level 9's; a tau-extrapolated central film
    // (the rule's on one grid, `OutputErrors::tau_central`), whose error is about level 9's
    // own (median 0.30 % at level 7 against 0.13 %, docs/ACCURACY_NOTES.md,
    // "Tau-extrapolation, measured"), against level 9's tau-extrapolated one (the rule gives
    // it beside a solve without a ladder), a tenth of that.
    let fine_central = match (e.tau_central, &fine.tau) {
        (Some(_), Some(tau)) => tau.film.h_central,
        _ => fine.film.h_central,
    };
    let outputs = [
        ("Hc", Output::HCentral, s.film.h_central, fine_central),
        ("Hmin", Output::HMin, s.film.h_min, fine.film.h_min),
        (
            "mu-bar",
            Output::MuBarSliding,
            s.friction.sliding,
            fine.friction.sliding,
        ),
    ];
    for (name, output, value, level_9) in outputs {
        let estimate = e
            .estimate(output)
            .unwrap_or_else(|| panic!("{what}: no estimate of {name}"));
        // The outputs are converged to the stopping rule's output tolerance (5e-4 relative,
        // `StoppingParams::output_tolerance`), so a difference below it is algebraic, not a grid
        // error: case 23's chain puts its central film 5.3e-4 from its level 8 with an
        // estimate of 2.3e-4 (order 2.5 over levels 5-7).
        let algebraic = Params::default().stopping.output_tolerance * value.abs();
        let distance = (value - level_9).abs();
        assert!(
            estimate.error + algebraic >= distance,
            "{what} {name}: level {} {value} +- {} (order {:?}), level 9 {level_9}",
            s.info.level,
            estimate.error,
            estimate.order
        );
        // Nor overstated by more than 3 times the distance, or 3 times 0.1 % of the value
        // where the distance is smaller (issue 53's bound: an estimate far above the error
        // refines for nothing). Measured (this test, 2-core AMD EPYC): 1.17-1.92 times the
        // distance, and case 23's central film, its distance to its chain's level 8 under
        // 0.1 %, 2.24 times 0.1 % (docs/ACCURACY_NOTES.md, "The estimate, measured").
        let floor = OVERSTATEMENT_FLOOR * level_9.abs();
        eprintln!(
            "{what} {name}: estimate / max(distance, 0.1 %) = {:.2}",
            estimate.error / distance.max(floor)
        );
        // A level-8 solve's top refined across the rolling direction (512 x 1 024) has level
        // 9's mesh across it: its minimum film, made by that mesh, differs from level 9's by
        // the error along it alone, while its estimate holds both (M 11 070: 0.78 % from
        // level 9 under an estimate of 10.6 %, docs/ACCURACY_NOTES.md, "The top refined
        // across on level 8"). Level 9 bounds that estimate from below only. The top's
        // friction, 80 % of whose error is along the rolling direction, keeps the bound
        // (measured 1.92 times its distance).
        let shares_level_9s_mesh_across =
            s.grid.is_refined_y() && s.info.level + 1 == fine_level && output == Output::HMin;
        if shares_level_9s_mesh_across {
            continue;
        }
        assert!(
            estimate.error <= MOST_OVERSTATEMENT * distance.max(floor),
            "{what} {name}: estimate {} for a distance {distance} to level 9 {level_9}",
            estimate.error
        );
    }
    s
}

/// The most an estimate may overstate its distance to level 9 (issue 53).
const MOST_OVERSTATEMENT: f64 = 3.0;

/// The relative distance below which the overstatement is read against this share of the
/// value instead: 0.1 %, a tenth of the friction target (issue 53).
const OVERSTATEMENT_FLOOR: f64 = 1e-3;

#[test]
fn the_error_estimate_brackets_level_9_on_a_light_contact() {
    // Fig. 6 case 23 (5P4E, 40 C, 1 GPa, 12 m/s; M 4.76, L 57) on its wide domain with the
    // far field and two nested rectangles: friction within half a per cent at level 7.
    let c = physical("5p4e", 40.0, 1e9, 12.0, 0.005, 6e6, 1.0);
    let s = assert_estimate_brackets_level_9(&c, "Fig. 6 case 23");
    assert!(s.surroundings.is_some(), "solved on nested domains");
    // Three levels, and an order observed for each output (2.50, 1.50, 1.47).
    let e = s.errors.unwrap();
    assert_eq!(e.levels.len(), 3);
    let trusted = |o| e.estimate(o).unwrap().trusted();
    assert!(trusted(Output::MuBarSliding) && trusted(Output::HCentral));
}

#[test]
fn the_error_estimate_brackets_level_9_on_the_table_4_case() {
    // The Appendix case (M 1 739, L 14.8): the middle of the envelope.
    let c = Table4Case::shipped().unwrap().case;
    let s = assert_estimate_brackets_level_9(&c, "Table 4");
    // Its level 5's central film is a fifth of level 7's (the paper's own level-5 film is six
    // times too thin): outside the asymptotic range, levels 6-7 are read.
    let e = s.errors.unwrap();
    assert_eq!(e.levels.len(), 2);
    assert_eq!(e.stopped, Some(LadderStop::FilmUnresolved { level: 5 }));
    // Its level-7 minimum film misses 10 % (21 %): the rule adds the top refined across the
    // rolling direction, whose outputs are reported and estimated with the 6y under it, so
    // the bracket above is that estimate's (measured 1.58 times the minimum film's distance).
    assert!(s.grid.is_refined_y());
    assert!(e.across.is_some_and(|a| a.below.is_some()), "{e:?}");
}

#[test]
fn the_error_estimate_brackets_level_9_on_a_heavy_contact() {
    // Fig. 4 case 140 (mineral oil A, 60 C, 3 GPa, 2 m/s; M 11 070): its film closes at
    // level 7, so it is solved at level 8; its level 6 closes at the centre, so the estimate
    // reads levels 7-8 alone and is the first-order bound.
    let c = physical("mineral-oil-a", 60.0, 3e9, 2.0, 0.005, 6e6, 1.0);
    let s = assert_estimate_brackets_level_9(&c, "M 11 070");
    assert_eq!(s.info.level, 8);
    let e = s.errors.unwrap();
    assert_eq!(e.stopped, Some(LadderStop::FilmClosed { level: 6 }));
    assert!(!e.estimate(Output::MuBarSliding).unwrap().trusted());
    // Its level-8 minimum film misses 10 % (12.2 %): the rule adds the top refined across the
    // rolling direction, estimated with the 7y under it.
    assert!(s.grid.is_refined_y());
    assert!(e.across.is_some_and(|a| a.below.is_some()), "{e:?}");
}
