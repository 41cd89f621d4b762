use super::*;

#[test]
fn the_eyring_stress_is_asinh_to_round_off() {
    // Against the standard asinh from 1e-300 to 1e14 and across both switches: within
    // 4e-16 relative (the fast forms' bound, 3e-16, plus asinh's own rounding).
    let mut x = 1e-300;
    while x < 1e14 {
        for y in [x, 0.5, 0.5 - 1e-12, 1e8, 1e8 * (1.0 - 1e-15)] {
            let e = (eyring_stress(y) / y.asinh() - 1.0).abs();
            assert!(e < 4e-16, "x {y}: {e:e}");
        }
        x *= 1.37;
    }
    assert_eq!(eyring_stress(0.0), 0.0);
    assert_eq!(
        eyring_stress(f64::MIN_POSITIVE / 4.0),
        f64::MIN_POSITIVE / 4.0
    );
    assert_eq!(eyring_stress(-2.0), (-2.0f64).asinh());
}

const EYRING: ShearLaw = ShearLaw::Eyring;

#[test]
fn eyring_tends_to_newtonian_at_low_stress() {
    let e = EYRING;
    for x in [0.0, 1e-8, 1e-5] {
        assert!((e.mean_shear_stress(x, 1.0) - x).abs() <= 1e-15);
        assert!((e.flow_factor_x(x, 1.0) - 1.0).abs() < 1e-9);
        assert!((e.flow_factor_y(x, 1.0) - 1.0).abs() < 1e-9);
    }
    // Continuity across the series switch (error of the series ~ x^4/... < 1e-17).
    let below = e.flow_factor_y(0.99999e-4, 1.0);
    let above = e.flow_factor_y(1.00001e-4, 1.0);
    assert!((below - above).abs() < 1e-12);
}

#[test]
fn eyring_factors_are_cosh_and_sinh_over_tau() {
    let e = EYRING;
    for tau in [0.5_f64, 3.0, 40.0] {
        let x = tau.sinh();
        assert!((e.mean_shear_stress(x, 1.0) - tau).abs() < 1e-12 * tau.max(1.0));
        assert!((e.flow_factor_x(x, 1.0) / tau.cosh() - 1.0).abs() < 1e-12);
        assert!((e.flow_factor_y(x, 1.0) / (tau.sinh() / tau) - 1.0).abs() < 1e-12);
    }
    // Huge arguments stay finite.
    assert!(e.flow_factor_x(1e200, 1.0).is_finite());
}

#[test]
fn conductances_are_h_cubed_over_the_effective_viscosities() {
    let lss = ShearLaw::EyringLss {
        tau_l0_bar: 0.7,
        lambda_bar: 12.0,
    };
    for law in [EYRING, lss] {
        for (h, eta, ns, p) in [
            (0.02, 1e20, 1e-5, 0.9),
            (0.5, 3.0, 0.01, 0.2),
            (1.0, 1.0, 0.0, 0.0),
        ] {
            let x = ns * eta / h;
            let cx = h * h * h / eta * law.flow_factor_x(x, p);
            let cy = h * h * h / eta * law.flow_factor_y(x, p);
            // Two roundings of the same product: 1e-12 is a thousand ulps.
            assert!((law.conductance_x(h, eta, ns, p) / cx - 1.0).abs() < 1e-12);
            assert!((law.conductance_y(h, eta, ns, p) / cy - 1.0).abs() < 1e-12);
        }
        assert_eq!(law.conductance_x(-1e-3, 1.0, 0.1, 0.5), 0.0);
    }
    // Where eta overflows to infinity the Eyring conductance stays finite.
    assert!(EYRING
        .conductance_x(0.02, f64::INFINITY, 1e-5, 1.0)
        .is_finite());
}

#[test]
fn newtonian_is_linear() {
    let n = ShearLaw::Newtonian;
    assert_eq!(n.mean_shear_stress(3.0, 1.0), 3.0);
    assert_eq!(n.flow_factor_x(3.0, 1.0), 1.0);
    assert_eq!(n.flow_factor_y(3.0, 1.0), 1.0);
}

/// The limiting-stress law's `g(tau) = sinh(tau (1 - (tau/tau_L)^2)^(-1/2))` (module doc),
/// written independently of the code under test.
fn g(tau: f64, tau_l: f64) -> f64 {
    (tau / (1.0 - (tau / tau_l).powi(2)).sqrt()).sinh()
}

#[test]
fn limiting_stress_law_is_the_perturbation_of_its_flow_law() {
    // tau_L = 0.5 + 4 P: at P = 0.75 the limit is 3.5.
    let law = ShearLaw::EyringLss {
        tau_l0_bar: 0.5,
        lambda_bar: 4.0,
    };
    let (p, tau_l) = (0.75, 3.5);
    for x in [0.01, 0.5, 3.0, 30.0, 1e4] {
        let tau = law.mean_shear_stress(x, p);
        assert!(tau > 0.0 && tau < tau_l, "x = {x}: {tau}");
        // tau_m = g^-1(x): g(tau_m) returns x up to the conditioning of g near tau_L
        // (relative 1e-9 is far above round-off, far below any modelling effect).
        assert!((g(tau, tau_l) / x - 1.0).abs() < 1e-9, "x = {x}");
        // eta/eta_x = g'(tau_m): central difference of g, step 1e-6 tau (truncation
        // ~ (1e-6)^2 relative times g'''/g', round-off ~ 1e-16 / 1e-6: both below 1e-6).
        let d = 1e-6 * tau;
        let fd = (g(tau + d, tau_l) - g(tau - d, tau_l)) / (2.0 * d);
        assert!((law.flow_factor_x(x, p) / fd - 1.0).abs() < 1e-6, "x = {x}");
        // eta/eta_y = g(tau_m)/tau_m = x/tau_m, exactly as defined.
        assert!(
            (law.flow_factor_y(x, p) / (x / tau) - 1.0).abs() < 1e-12,
            "x = {x}"
        );
    }
}

#[test]
fn an_infinite_limit_is_eyring_to_the_bit() {
    // (tau_E / tau_L)^2 underflows against 1: every factor is exactly 1.
    let law = ShearLaw::EyringLss {
        tau_l0_bar: 1e200,
        lambda_bar: 0.0,
    };
    for (x, p) in [(0.0, 0.0), (1e-5, 0.3), (2.0, 1.0), (1e12, 1.0)] {
        assert_eq!(
            law.mean_shear_stress(x, p).to_bits(),
            EYRING.mean_shear_stress(x, p).to_bits()
        );
        assert_eq!(
            law.flow_factor_x(x, p).to_bits(),
            EYRING.flow_factor_x(x, p).to_bits()
        );
        assert_eq!(
            law.flow_factor_y(x, p).to_bits(),
            EYRING.flow_factor_y(x, p).to_bits()
        );
        assert_eq!(
            law.conductance_x(0.1, 1e8, 1e-6, p).to_bits(),
            EYRING.conductance_x(0.1, 1e8, 1e-6, p).to_bits()
        );
        assert_eq!(
            law.conductance_y(0.1, 1e8, 1e-6, p).to_bits(),
            EYRING.conductance_y(0.1, 1e8, 1e-6, p).to_bits()
        );
    }
}

#[test]
fn a_saturated_fluid_carries_the_limiting_stress() {
    // tau_m = tau_L (1 + (tau_L/tau_E)^2)^(-1/2) -> tau_L: at tau_E = 700 (x = e^700 / 2)
    // and tau_L = 1.5 the defect is (1.5/700)^2 / 2 = 2.3e-6 relative.
    let law = ShearLaw::EyringLss {
        tau_l0_bar: 0.5,
        lambda_bar: 1.0,
    };
    let x = (700.0_f64).exp() / 2.0;
    let tau = law.mean_shear_stress(x, 1.0);
    assert!((tau / 1.5 - 1.0).abs() < 2.4e-6 && tau < 1.5, "{tau}");
    // Negative pressure (cavitated zone) keeps tau_L0.
    assert!((law.mean_shear_stress(x, -0.2) / 0.5 - 1.0).abs() < 1e-6);
}

#[test]
fn the_limit_is_read_in_physical_units() {
    let lss = LimitingShearStress {
        lambda: 0.08,
        tau_l0_pa: 5e6,
    };
    // Lambda-bar = 0.08 * 2 GPa / 4 MPa = 40, tau_L0 / tau0 = 1.25.
    match lss.shear_law(4e6, 2e9) {
        ShearLaw::EyringLss {
            tau_l0_bar,
            lambda_bar,
        } => {
            assert!((tau_l0_bar - 1.25).abs() < 1e-15);
            assert!((lambda_bar - 40.0).abs() < 1e-12);
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(lss.checked().unwrap(), lss);
    let bad = LimitingShearStress {
        tau_l0_pa: 0.0,
        ..lss
    };
    assert_eq!(bad.checked().unwrap_err().0, "tau-l0");
    let bad = LimitingShearStress {
        lambda: -0.1,
        ..lss
    };
    assert_eq!(bad.checked().unwrap_err().0, "lambda-lss");
}

#[test]
fn plain_rheologies_keep_their_case_file_names() {
    // The cache keys of every existing case serialise the rheology: these must not move.
    assert_eq!(
        serde_json::to_string(&Rheology::Eyring).unwrap(),
        "\"eyring\""
    );
    assert_eq!(
        serde_json::to_string(&Rheology::Newtonian).unwrap(),
        "\"newtonian\""
    );
    let lss = Rheology::EyringLss(LimitingShearStress {
        lambda: 0.08,
        tau_l0_pa: 5e6,
    });
    let text = serde_json::to_string(&lss).unwrap();
    assert_eq!(
        text,
        r#"{"eyring-lss":{"lambda":0.08,"tau_l0_pa":5000000.0}}"#
    );
    assert_eq!(serde_json::from_str::<Rheology>(&text).unwrap(), lss);
}
