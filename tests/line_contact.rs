//! The line-contact solver through the library API and the CLI: the Table 3 line cases of
//! Fig. 7, the point-contact trend in Rx/Ry, and `repro solve --line`.

use crate::support::{repro, SOLVE_KEYS};
use repro::paper::figures::line::table3_line_cases;
use repro::physics::case::{Case, CaseForm, LubricantSpec, PhysicalCase, Physics, Problem};
use repro::physics::line_contact::LineProblem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::line;
use repro::solver::point;

#[test]
fn table3_line_cases_converge_near_eq13() {
    // All five Table 3 cases as line contacts at the working level (8): sound solutions, and
    // sliding mu-bar near Eq. (13) at the tau_c of the Moes line film. Measured deviations
    // -6.0, -4.6, -3.7, -1.1, -1.2 %; the paper's Fig. 7 shows its line points on the curve to
    // within the scatter of Figs. 4-6 (a few per cent). 7 % leaves room for the level-8
    // discretisation error (~0.2 %) and fails on a wrong tau_c unit (an order of magnitude).
    let (cases, physics) = table3_line_cases().unwrap();
    for (k, c) in cases.iter().enumerate() {
        let pr = LineProblem::from_physical(c, physics).unwrap();
        let s = line::solve(&pr, &line::Params::default(), None)
            .unwrap_or_else(|e| panic!("case {}: {e}", k + 1));
        assert!(s.p.iter().all(|v| *v >= 0.0) && s.h.iter().all(|v| *v > 0.0));
        let eq13 = (pr.tau_c() / 5.0).asinh();
        let dev = s.friction.sliding / eq13 - 1.0;
        assert!(
            dev.abs() < 0.07,
            "case {}: mu {} vs Eq. 13 {eq13}",
            k + 1,
            s.friction.sliding
        );
    }
}

fn point_case(d: f64) -> Case {
    // Table 3, third row: mineral oil A, 2 GPa, 40 C, 7 m/s, S = 0.1 %, tau0 = 8 MPa.
    let rx = 1.03875e-2;
    Case {
        spec: CaseForm::Physical(PhysicalCase {
            lubricant: LubricantSpec::Named {
                lubricant: "mineral-oil-a".into(),
                temperature_c: 40.0,
            },
            ph_pa: 2e9,
            um_m_s: 7.0,
            slip: 0.001,
            tau0_pa: 8e6,
            rx_m: rx,
            ry_m: rx / d,
            e_prime_pa: 226e9,
        }),
        physics: Physics::figs_4_to_7(),
    }
}

#[test]
fn elliptical_friction_trend_in_rx_over_ry_and_the_line_value() {
    // Sliding mu-bar of elliptical contacts with Rx/Ry = 1, 1/2, 1/5, 1/10 at one Table 3
    // case (level 5, ~1 s each) changes monotonically with Rx/Ry. It does NOT move toward the
    // line-contact value: measured 22.18, 22.08, 22.02, 21.99 against the line 22.92. At a
    // fixed p_H the Hertzian pressure of every ellipse is P = sqrt(1 - X^2 - Y^2), so mu-bar
    // is a 2-D average over the ellipse whatever D is, while the line contact averages over
    // the 1-D semi-ellipse, which weights high pressures more (int P^2 / int P: 0.85 vs
    // 0.75); only the film shape changes with D. docs/LINE_NOTES.md gives the numbers. The test
    // asserts the monotone trend and that all values stay within 5 % of the line value
    // (measured 3.3-4.0 % below it).
    let lubs = LubricantTable::table1();
    let params = {
        let mut params = point::Params::at_level(5);
        params.friction.rolling = false;
        params
    };
    let mu: Vec<f64> = [1.0, 0.5, 0.2, 0.1]
        .iter()
        .map(|&d| {
            let pr = Problem::from_case(&point_case(d), &lubs).unwrap();
            point::solve(&pr, &params, None).unwrap().friction.sliding
        })
        .collect();
    let (cases, physics) = table3_line_cases().unwrap();
    let pr = LineProblem::from_physical(&cases[2], physics).unwrap();
    let line_mu = line::solve(&pr, &line::Params::default(), None)
        .unwrap()
        .friction
        .sliding;
    let decreasing = mu.windows(2).all(|w| w[1] < w[0]);
    let increasing = mu.windows(2).all(|w| w[1] > w[0]);
    assert!(decreasing || increasing, "not monotone: {mu:?}");
    for m in &mu {
        assert!((m / line_mu - 1.0).abs() < 0.05, "{mu:?} vs line {line_mu}");
    }
}

const HEAVY: [&str; 13] = [
    "solve",
    "--line",
    "--lubricant",
    "mineral-oil-a",
    "--temperature",
    "40",
    "--ph",
    "3e9",
    "--um",
    "7",
    "--slip",
    "0.001",
    "--tau0=8e6",
];

#[test]
fn cli_solve_line_json_has_the_point_contact_keys() {
    let mut args = HEAVY.to_vec();
    args.extend(["--json", "-q", "--level", "7"]);
    let (code, out, err) = repro(&args);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
    // The point contact's keys, `newton_steps` (0: Newton throughout) among them.
    for key in SOLVE_KEYS {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["contact"], "line");
    // Asked for level 7, the rule refines to level 9: levels 5 (film closed) and 6 (film at
    // 18 % of level 7's, 14 % of level 8's) are outside the asymptotic range, and level 9's
    // estimate is the first to read three levels (7-9) inside it.
    assert_eq!(v["level"], 9);
    assert_eq!(v["discretisation_error"]["levels"][0]["level"], 7);
    // Line-contact M of the heavy case: W' U^{-1/2} = 157.9 (hand value, 4 digits).
    assert!((v["m"].as_f64().unwrap() - 157.9).abs() < 0.1);
    let mu = v["mu_bar_sliding"].as_f64().unwrap();
    assert!(mu > 30.0 && mu < 50.0, "mu {mu}");
}

#[test]
fn cli_solve_line_dimensionless_and_rejected_flags() {
    let (code, out, err) = repro(&[
        "solve", "--line", "--m", "20", "--l", "10", "--s-bar", "0.1", "--json", "-q",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["level"], 8);
    for (flag, value) in [("--ry", "0.1"), ("--d", "0.5"), ("--domain", "wide")] {
        let mut args = HEAVY.to_vec();
        args.extend([flag, value]);
        let (code, _, err) = repro(&args);
        assert_ne!(code, 0);
        assert!(err.contains(flag), "{flag}: {err}");
    }
}
