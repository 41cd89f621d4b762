//! Solver-level tests of the line contact; the kernel's own oracles (dry Hertz deformation,
//! FFT against the direct sum) are in `kernel.rs`.

use super::*;
use crate::physics::case::Physics;
use crate::physics::line_contact::tests::heavy_case;
use crate::physics::line_contact::{LineDimensionlessCase, LineEyringFlow};
use crate::physics::rheology::Rheology;

/// Mineral oil A at 40 C (Table 1), the last row of Table 3: 3 GPa, 7 m/s, S = 0.1 %, 8 MPa.
fn heavy() -> LineProblem {
    LineProblem::from_physical(&heavy_case(), Physics::figs_4_to_7()).unwrap()
}

fn newtonian(m: f64, l: f64) -> LineProblem {
    let d = LineDimensionlessCase {
        m,
        l,
        s_bar: 0.0,
        slip: 0.0,
        eta0_pa_s: None,
        ph_pa: None,
    };
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    LineProblem::from_dimensionless(&d, physics).unwrap()
}

#[test]
fn heavy_case_converges_with_a_physical_solution() {
    // Mineral oil A, 3 GPa, 40 C, Roelands, Dowson-Higginson, Eyring (Table 3, last row).
    let s = solve(&heavy(), &Params::default(), None).unwrap();
    assert!(s.p.iter().all(|v| v.is_finite() && *v >= 0.0));
    assert!(s.h.iter().all(|v| v.is_finite() && *v > 0.0));
    // Load balance: the solver's tolerance 1e-8, plus round-off.
    let load: f64 = s.p.iter().sum::<f64>() * (s.x[1] - s.x[0]);
    assert!(
        (load / std::f64::consts::FRAC_PI_2 - 1.0).abs() < 1e-7,
        "load {load}"
    );
    assert!(s.info.residual() < 1e-9);
    // Newton converges quadratically from the interpolated coarser solution: a handful of
    // iterations (measured 5); 12 means the Jacobian is wrong.
    assert!(s.info.cycles <= 12, "{} iterations", s.info.cycles);
    // The pressure peaks near the Hertzian maximum (a heavily loaded contact is nearly
    // Hertzian): within 20 % of 1 (the spike of the Roelands case stays below it).
    let pmax = s.p.iter().cloned().fold(0.0, f64::max);
    assert!((pmax - 1.0).abs() < 0.2, "P max {pmax}");
    assert!(s.friction.sliding > 0.0 && s.friction.rolling.is_some());
}

#[test]
fn grid_convergence_is_about_second_order() {
    // Differences of the central film (Moes units) and the sliding mu-bar between successive
    // levels must shrink like second order: a factor 4 per level; more than 3 is asked (first
    // order gives 2). Measured on this case, levels 6..11: film differences 2.29, 0.760,
    // 0.206, 0.0525, 0.0133 (ratios 3.0, 3.7, 3.9, 3.9), mu-bar differences 2.06, 0.279,
    // 0.0667, 0.0177, 0.0042 (ratios 7.4, 4.2, 3.8, 4.2). Level 6 is left out: its film is
    // pre-asymptotic (H_min ~ 0.03 in Moes units). Levels 7..9 keep the test at ~2 s; the
    // dense Newton costs ~1.5 s at level 10 and ~7 s at level 11 (faer LU).
    let pr = heavy();
    let runs: Vec<LineSolution> = (7..=9)
        .map(|l| solve(&pr, &Params::at_level(l), None).unwrap())
        .collect();
    let dh: Vec<f64> = runs
        .windows(2)
        .map(|w| (w[1].film.hc_moes - w[0].film.hc_moes).abs())
        .collect();
    let dmu: Vec<f64> = runs
        .windows(2)
        .map(|w| (w[1].friction.sliding - w[0].friction.sliding).abs())
        .collect();
    assert!(dh[1] < dh[0] / 3.0, "film differences {dh:?}");
    assert!(dmu[1] < dmu[0] / 3.0, "mu-bar differences {dmu:?}");
    // Richardson: the level-9 error is about a third of the last difference. The film is
    // within 3 % (measured 1.8 %), the sliding mu-bar within 0.5 % (measured 0.06 %).
    assert!(dh[1] / 3.0 < 0.03 * runs[2].film.hc_moes, "{dh:?}");
    assert!(dmu[1] / 3.0 < 5e-3 * runs[2].friction.sliding, "{dmu:?}");
}

#[test]
fn newtonian_film_matches_moes_line_formula() {
    // Moes' line-contact formula is a fit of full numerical Newtonian Barus incompressible
    // solutions; its authors quote a few per cent. At level 9 the discretisation error of
    // the central film is below 0.5 % (grid test), so 5 % bounds the fit error with margin;
    // a wrong unit (the factor 8M/pi, u_s vs u_m) would be off by 40 % or more.
    for (m, l) in [(10.0, 5.0), (20.0, 10.0), (100.0, 10.0)] {
        let s = solve(&newtonian(m, l), &Params::at_level(9), None).unwrap();
        let hc = LineFilmFormula::Moes.hc(m, l);
        let dev = s.film.hc_moes / hc - 1.0;
        assert!(dev.abs() < 0.05, "M {m} L {l}: {} vs {hc}", s.film.hc_moes);
        // Minimum film below the central one (the outlet constriction).
        assert!(s.film.hmin_moes < s.film.hc_moes);
    }
}

#[test]
fn exact_and_perturbation_eyring_differ_little() {
    // On the heavy case the Poiseuille stress G = (h/2)(dp/dx)/tau0 is ~0.1 in the contact,
    // so G/sinh G and F(G) differ from 1 by ~1e-3: sliding mu-bar within 0.5 %.
    let pr = heavy();
    let e = solve(&pr, &Params::default(), None).unwrap();
    let p = solve(
        &pr.clone().with_eyring_flow(LineEyringFlow::Perturbation),
        &Params::default(),
        None,
    )
    .unwrap();
    let d = e.friction.sliding / p.friction.sliding - 1.0;
    assert!(
        d.abs() < 5e-3,
        "exact {} perturbation {}",
        e.friction.sliding,
        p.friction.sliding
    );
}

#[test]
fn failure_is_typed_with_the_residual_history() {
    let params = Params {
        max_iterations: 2,
        ..Params::default()
    };
    match solve(&heavy(), &params, None) {
        Err(SolveError::NotConverged {
            cycles,
            residual_history,
            ..
        }) => {
            assert_eq!(cycles, 2);
            assert_eq!(residual_history.len(), 2);
            assert!(residual_history.iter().all(|r| r.is_finite()));
        }
        other => panic!("expected NotConverged, got {:?}", other.map(|s| s.info)),
    }
    let bad = Params::at_level(MAX_LEVEL + 1);
    assert!(matches!(
        solve(&heavy(), &bad, None),
        Err(SolveError::InvalidParams(_))
    ));
}

#[test]
fn observer_hears_every_iteration() {
    let mut seen = Vec::new();
    let mut obs = |p: &Progress| seen.push((p.level, p.residual));
    let s = solve(&heavy(), &Params::at_level(7), Some(&mut obs)).unwrap();
    let finest: Vec<f64> = seen.iter().filter(|(l, _)| *l == 7).map(|x| x.1).collect();
    assert_eq!(finest, s.info.residual_history);
    assert!(seen.iter().any(|(l, _)| *l == 6));
}
