//! The level study's unit tests, and the runs and studies the picture's tests build on.

use super::*;

/// A level that converged to `h` and `mu` in `0.1 level` seconds.
pub(crate) fn run(level: u32, h: f64, mu: f64) -> LevelRun {
    LevelRun {
        level,
        outcome: Ok(LevelOutputs {
            h_central: h,
            h_central_grid: h,
            h_min: 0.5 * h,
            mu_bar: mu,
            cycles: 10,
            level,
            across: false,
        }),
        seconds: 0.1 * f64::from(level),
    }
}

/// A point-contact study of `levels` that stands for Fig. 3.
pub(crate) fn study(levels: Vec<LevelRun>) -> AccuracyResult {
    AccuracyResult {
        name: "t",
        description: "",
        kind: "point",
        targets: vec!["fig3"],
        level_offset: 0,
        reference: reference(&levels),
        twin: None,
        domain: None,
        points: levels.iter().map(|_| String::new()).collect(),
        levels,
    }
}

#[test]
fn richardson_removes_an_exact_second_order_error() {
    // X_n = 2 + 3 h^2 with h = 2^-n: the extrapolation is exact (to rounding) and the
    // observed order is 2.
    let x = |n: u32| 2.0 + 3.0 * 4f64.powi(-(n as i32));
    let levels: Vec<_> = (4..=7).map(|n| run(n, x(n), x(n))).collect();
    let r = reference(&levels).unwrap();
    assert_eq!(r.kind, "observed-order");
    assert!((r.mu_bar - 2.0).abs() < 1e-14, "{}", r.mu_bar);
    // The minimum film (half the central one here) from the same levels, the same way.
    let h_min = r.h_min.unwrap();
    assert!((h_min - 1.0).abs() < 1e-14, "{h_min}");
    assert!((r.order_used_h_min.unwrap() - 2.0).abs() < 1e-9);
    let (oh, om) = r.order.unwrap();
    assert!((oh - 2.0).abs() < 1e-9 && (om - 2.0).abs() < 1e-9);
    // Two levels only: the second order assumed, exact here too.
    let r = reference(&levels[2..]).unwrap();
    assert_eq!((r.kind, r.order_used), ("richardson", Some((2.0, 2.0))));
    assert!((r.h_central - 2.0).abs() < 1e-14, "{}", r.h_central);
}

#[test]
fn the_reference_reads_the_grids_films_and_the_reported_one_is_measured_against_it() {
    // X_n = 2 + 3 h^2 (exact at order 2). Level 7's film reported tau-extrapolated, 1e-6
    // from the limit: the reference is still the grids' (2), the reported film's error
    // is its 5e-7 and the grid's own its 3 h^2 / 2 = 9.2e-5.
    let x = |n: u32| 2.0 + 3.0 * 4f64.powi(-(n as i32));
    let mut levels: Vec<_> = (5..=7).map(|n| run(n, x(n), x(n))).collect();
    let plain = reference(&levels).unwrap();
    if let Ok(m) = &mut levels[2].outcome {
        m.h_central = 2.0 + 1e-6;
    }
    let s = study(levels);
    assert_eq!(s.reference.unwrap().h_central, plain.h_central);
    assert!(s.extrapolates_film());
    let top = &s.levels[2];
    assert!((s.errors(top).unwrap().0 - 5e-7).abs() < 1e-12);
    let grid = s.grid_film_error(top).unwrap();
    assert!((grid - 1.5 * 4f64.powi(-7)).abs() < 1e-12, "{grid}");
}

#[test]
fn the_observed_order_extrapolates_a_first_order_error_exactly() {
    // X_n = 2 + 3 h with h = 2^-n (the light contacts' friction converges near first
    // order): the observed order 1 is used, and the extrapolation is exact, where the
    // second order assumed would leave two thirds of the finest level's error.
    let x = |n: u32| 2.0 + 3.0 * 2f64.powi(-(n as i32));
    let levels: Vec<_> = (5..=8).map(|n| run(n, x(n), x(n))).collect();
    let r = reference(&levels).unwrap();
    let (ph, pm) = r.order_used.unwrap();
    assert!((ph - 1.0).abs() < 1e-9 && (pm - 1.0).abs() < 1e-9);
    assert!((r.mu_bar - 2.0).abs() < 1e-13, "{}", r.mu_bar);
}

#[test]
fn an_oscillating_order_is_bounded_at_first_order_and_a_high_one_held_to_second() {
    // Film oscillates (+0.1, -0.05): p = 1, X_R = X_f + (X_f - X_{f-1}). Friction
    // converges at order 4 (above the scheme's): held to p = 2, X_R = X_f + d_f / 3.
    let levels = vec![run(6, 1.0, 10.0), run(7, 1.1, 11.0), run(8, 1.05, 11.0625)];
    let r = reference(&levels).unwrap();
    assert_eq!(r.order_used, Some((1.0, 2.0)));
    assert!((r.h_central - 1.0).abs() < 1e-12, "{}", r.h_central);
    assert!(
        (r.mu_bar - 11.083333333333334).abs() < 1e-12,
        "{}",
        r.mu_bar
    );
}

#[test]
fn a_gap_below_the_finest_level_falls_back_to_the_finest() {
    let mut levels = vec![run(5, 1.0, 40.0), run(6, 1.1, 41.0), run(7, 1.2, 41.5)];
    levels[1].outcome = Err(SolveError::InvalidParams("x".into()));
    let r = reference(&levels).unwrap();
    assert_eq!(r.kind, "finest");
    assert_eq!(r.mu_bar, 41.5);
    assert!(reference(&[]).is_none());
}

#[test]
fn the_cheapest_level_must_hold_for_every_finer_level() {
    // mu: 40.5 (in by chance), 38 (out), 40.1, 40.02, 40.0 -> reference 39.993...
    let levels = vec![
        run(4, 1.0, 40.5),
        run(5, 1.0, 38.0),
        run(6, 1.0, 40.1),
        run(7, 1.0, 40.02),
        run(8, 1.0, 40.0),
    ];
    let s = study(levels);
    assert_eq!(s.cheapest_within(0.01).map(|r| r.level), Some(6));
    assert_eq!(s.cheapest_within(1e-9).map(|r| r.level), None);
    let recs = recommend(&[s], 0.01);
    assert_eq!(recs.len(), 1);
    assert_eq!((recs[0].target, recs[0].level), ("fig3", Some(6)));
}

#[test]
fn a_case_with_one_converged_level_qualifies_no_level() {
    // The heavy-m19205 study: levels 4-7 close the film, level 8 alone converges; its
    // reference is itself, so the error of 0 it prints is no evidence, and the target
    // it stands for gets no level rather than level 8 at "0 %".
    let mut levels = vec![run(6, 1.0, 25.0), run(7, 1.0, 25.0), run(8, 1.4e-3, 25.1)];
    for l in &mut levels[..2] {
        l.outcome = Err(SolveError::InvalidParams("closed".into()));
    }
    let s = study(levels);
    assert_eq!(s.reference.map(|r| r.kind), Some("finest"));
    assert!(s.cheapest_within(0.01).is_none());
    let recs = recommend(&[s], 0.01);
    assert_eq!((recs[0].case, recs[0].level), ("t", None));
}

#[test]
fn the_most_demanding_case_decides_a_target() {
    let easy = study(vec![
        run(4, 1.0, 40.0),
        run(5, 1.0, 40.0),
        run(6, 1.0, 40.0),
    ]);
    // Second order: reference 40.133, level 5 1.3 % off, level 6 0.33 %.
    let hard = study(vec![
        run(4, 1.0, 38.0),
        run(5, 1.0, 39.6),
        run(6, 1.0, 40.0),
    ]);
    let recs = recommend(&[easy, hard], 0.01);
    assert_eq!(recs[0].level, Some(6));
}

#[test]
fn the_csv_has_a_row_for_failed_levels_too() {
    let mut levels = vec![run(4, 1.0, 40.0), run(5, 1.0, 41.0), run(6, 1.0, 41.2)];
    levels[0].outcome = Err(SolveError::InvalidParams("x".into()));
    let s = study(levels);
    let csv = super::files::to_csv(std::slice::from_ref(&s));
    assert_eq!(csv.lines().count(), 4);
    assert!(csv.lines().nth(1).unwrap().contains("failed"));
}
