//! The limiting-shear-stress rheology (issue 19, beyond the paper) against its exact limits:
//! an infinite limit is Eyring to the bit, the friction never exceeds the bound the limit sets
//! for the solved pressure field and reaches it when the contact saturates, and the flat-film
//! oracle with the saturated stress follows the solver.

use crate::support::repro;
use repro::paper::figures::line::table3_line_cases;
use repro::physics::case::{Case, CaseForm, LubricantSpec, PhysicalCase, Physics, Problem};
use repro::physics::flat_film::{ln_couette_centre, mu_bar_flat, Geometry};
use repro::physics::line_contact::{LineEyringFlow, LineProblem};
use repro::physics::lubricant::LubricantTable;
use repro::physics::rheology::{LimitingShearStress, Rheology};
use repro::solver::{line, point};

/// Mineral oil A at 40 C, 1 GPa, 2 m/s, S = 2 %, tau0 = 4 MPa: a moderately loaded contact
/// (M = 150) whose centre is deep in the Eyring regime (tau_c ~ 1e8).
fn case(rheology: Rheology) -> Problem {
    let rx = 1.03875e-2;
    let case = Case {
        spec: CaseForm::Physical(PhysicalCase {
            lubricant: LubricantSpec::Named {
                lubricant: "mineral-oil-a".into(),
                temperature_c: 40.0,
            },
            ph_pa: 1e9,
            um_m_s: 2.0,
            slip: 0.02,
            tau0_pa: 4e6,
            rx_m: rx,
            ry_m: rx,
            e_prime_pa: 226e9,
        }),
        physics: Physics {
            rheology,
            ..Physics::figs_4_to_7()
        },
    };
    Problem::from_case(&case, &LubricantTable::table1()).expect("valid case")
}

fn lss(lambda: f64, tau_l0_pa: f64) -> Rheology {
    Rheology::EyringLss(LimitingShearStress { lambda, tau_l0_pa })
}

/// Level 5 (64 x 64): every limit below is an identity of the discrete solution, so the
/// coarse grid tests it as well as a fine one, in a second.
fn solve(problem: &Problem) -> point::PointSolution {
    point::solve(problem, &point::Params::at_level(5), None).expect("converges")
}

/// `A / W` of the solved field as the friction of Eq. (8) sums it: pressurised interior
/// nodes over their summed pressure (the mesh area cancels).
fn area_over_load(s: &point::PointSolution) -> f64 {
    let g = &s.grid;
    let (mut count, mut load) = (0.0, 0.0);
    for j in 1..g.ny {
        for i in 1..g.nx {
            let p = s.p[g.idx(i, j)];
            if p > 0.0 {
                count += 1.0;
                load += p;
            }
        }
    }
    count / load
}

#[test]
fn an_infinite_limit_solves_as_eyring_to_the_bit() {
    let eyring = solve(&case(Rheology::Eyring));
    let infinite = solve(&case(lss(0.0, 1e300)));
    assert_eq!(
        eyring.friction.sliding.to_bits(),
        infinite.friction.sliding.to_bits()
    );
    assert_eq!(
        eyring.film.h_central.to_bits(),
        infinite.film.h_central.to_bits()
    );
    assert_eq!(eyring.info.cycles, infinite.info.cycles);
}

#[test]
fn friction_stays_below_the_limit_and_follows_the_flat_film() {
    // Lambda-bar = 0.05 * 1 GPa / 4 MPa = 12.5, tau_L0 / tau0 = 0.5: partly saturated
    // (the Eyring stress at the centre is about 19).
    let problem = case(lss(0.05, 2e6));
    let s = solve(&problem);
    let bound = problem.shear.friction_bound(area_over_load(&s)).unwrap();
    let mu = s.friction.sliding;
    let eyring = solve(&case(Rheology::Eyring)).friction.sliding;
    assert!(
        mu < bound && mu < eyring,
        "mu {mu}, bound {bound}, Eyring {eyring}"
    );
    // Measured: mu-bar 7.49 against Eyring's 9.63 and a bound of 15.3 for the solved field.
    // The flat-film oracle with the saturated stress, at the solver's central film: measured
    // 0.25 % from the solver; 3 % is the oracle's documented reach on Figs. 3-6 and fails on
    // plain Eyring (28 % higher).
    let flat = mu_bar_flat(
        Geometry::Elliptical,
        problem.shear,
        &problem.viscosity,
        ln_couette_centre(problem.eyring_n_s(), &problem.viscosity, s.film.h_central),
    );
    assert!(
        (mu / flat - 1.0).abs() < 0.03,
        "solver {mu}, flat film {flat}"
    );
}

#[test]
fn a_saturated_contact_carries_its_limit() {
    // tau_L0 / tau0 = 0.05, Lambda-bar = 0.5: tau_L <= 0.55 against Eyring stresses of 5-19
    // over most of the contact, so tau_m = tau_L (1 - (tau_L / tau_E)^2 / 2 ...): mu-bar
    // is near the Hertzian saturated value Lambda-bar + 1.5 tau_L0 / tau0 = 0.575.
    let problem = case(lss(0.002, 0.2e6));
    let s = solve(&problem);
    let mu = s.friction.sliding;
    let bound = problem.shear.friction_bound(area_over_load(&s)).unwrap();
    let hertzian = problem.shear.friction_bound(1.5).unwrap();
    let flat = mu_bar_flat(
        Geometry::Elliptical,
        problem.shear,
        &problem.viscosity,
        ln_couette_centre(problem.eyring_n_s(), &problem.viscosity, s.film.h_central),
    );
    assert!(mu < bound, "mu {mu}, bound {bound}");
    // Measured 3.8 % below the Hertzian value and 3.0 % below the flat film (which takes
    // the Hertzian pressure): the low-pressure edge of the EHL field, where tau_E < tau_L0,
    // carries less than its limit. 5 % allows for that and fails on a limit without
    // tau_L0 (0.5 against 0.575, 13 % low).
    assert!(
        (mu / hertzian - 1.0).abs() < 0.05,
        "mu {mu}, Hertzian saturated {hertzian}"
    );
    assert!((mu / flat - 1.0).abs() < 0.05, "mu {mu}, flat film {flat}");
}

#[test]
fn the_line_contact_takes_the_same_law() {
    // Table 3's first row as a line contact at level 8.
    let (cases, physics) = table3_line_cases().unwrap();
    let with = |rheology: Rheology| {
        LineProblem::from_physical(
            &cases[0],
            Physics {
                rheology,
                ..physics
            },
        )
        .unwrap()
    };
    let solve =
        |p: &LineProblem| line::solve(p, &line::Params::default(), None).expect("converges");
    // An infinite limit is the perturbation form of Eyring. Not to the bit: the line
    // solver's Eyring conductance takes hypot, the shared law sqrt(a^2 + b^2) (as the point
    // contact), which differ in the last bit; 1e-12 relative is that rounding carried through
    // the converged Newton solve, and far below any modelling change.
    let eyring = solve(&with(Rheology::Eyring).with_eyring_flow(LineEyringFlow::Perturbation));
    let infinite = solve(&with(lss(0.0, 1e300)));
    let (a, b) = (eyring.friction.sliding, infinite.friction.sliding);
    assert!((a / b - 1.0).abs() < 1e-12, "{a} vs {b}");
    // A finite one lowers the friction below the bound of the solved field (A/W = nodes over
    // summed pressure, as the 1-D friction sums them).
    let problem = with(lss(0.02, 1e6));
    let s = solve(&problem);
    let inner = &s.p[1..s.p.len() - 1];
    let count = inner.iter().filter(|p| **p > 0.0).count() as f64;
    let load: f64 = inner.iter().filter(|p| **p > 0.0).sum();
    let bound = problem.shear.friction_bound(count / load).unwrap();
    let mu = s.friction.sliding;
    assert!(
        mu < bound && mu < eyring.friction.sliding,
        "mu {mu}, bound {bound}"
    );
}

#[test]
fn repro_solve_takes_the_limit_from_flags_and_refuses_half_of_it() {
    let base = [
        "solve",
        "--lubricant",
        "mineral-oil-a",
        "--temperature",
        "40",
        "--ph",
        "1e9",
        "--um",
        "2",
        "--slip",
        "0.02",
        "--tau0",
        "4e6",
        "--level",
        "4",
        "-q",
    ];
    let with = |extra: &[&str]| {
        let mut args = base.to_vec();
        args.extend_from_slice(extra);
        repro(&args)
    };
    let (code, out, err) = with(&[
        "--rheology",
        "eyring-lss",
        "--lambda-lss",
        "0.05",
        "--tau-l0",
        "2e6",
    ]);
    assert_eq!(code, 0, "{out}\n{err}");
    // Lambda-bar = 0.05 * 1 GPa / 4 MPa = 12.5, tau_L0 / tau0 = 0.5: the printed limit.
    assert!(
        out.contains("tau_L/tau0 = 0.5000 + 12.5000 P"),
        "the limit line: {out}"
    );
    let (code, _, err) = with(&["--rheology", "eyring-lss", "--lambda-lss", "0.05"]);
    assert_ne!(code, 0);
    assert!(err.contains("--tau-l0"), "{err}");
    let (code, _, err) = with(&["--tau-l0", "2e6"]);
    assert_ne!(code, 0);
    assert!(err.contains("--rheology eyring-lss"), "{err}");
    let (code, _, err) = with(&[
        "--rheology",
        "eyring-lss",
        "--lambda-lss",
        "0.05",
        "--tau-l0",
        "0",
    ]);
    assert_ne!(code, 0);
    assert!(err.contains("tau-l0"), "{err}");
    // Without the limit the summary has no limit line.
    let (code, out, _) = with(&[]);
    assert_eq!(code, 0);
    assert!(!out.contains("tau_L/tau0"), "{out}");
}

#[test]
fn a_study_file_states_the_limit_in_its_physics() {
    let text = r#"
title = "limited"
[physics]
viscosity = "roelands"
density = "dowson-higginson"
rheology = { eyring-lss = { lambda = 0.08, tau_l0_pa = 5e6 } }
[grid]
lubricant = ["mineral-oil-a"]
temperature_c = [40.0]
ph_gpa = [2.0]
um_m_s = [7.0]
slip = [0.005]
tau0_mpa = [4.0]
rx_m = [1.03875e-2]
d = [1.0]
e_prime_gpa = [226.0]
"#;
    let sweep = repro::pipeline::sweep::Sweep::parse("limited.toml", text).expect("valid");
    assert_eq!(sweep.cases[0].physics.rheology, lss(0.08, 5e6));
    // A misspelt parameter is refused, naming it.
    let bad = text.replace("tau_l0_pa", "tau_l0");
    let e = repro::pipeline::sweep::Sweep::parse("limited.toml", &bad).unwrap_err();
    assert!(e.to_string().contains("tau_l0"), "{e}");
}
