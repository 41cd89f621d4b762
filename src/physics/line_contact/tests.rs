use super::*;

/// Mineral oil A at 40 C (Table 1), the fifth case of Table 3 (3 GPa, 7 m/s, S = 0.1 %,
/// 8 MPa) as a line contact: the heavy case of the line-contact tests.
pub(crate) fn heavy_case() -> LinePhysicalCase {
    LinePhysicalCase {
        alpha_per_pa: 21.6e-9,
        eta0_pa_s: 8.24e-3,
        ph_pa: 3e9,
        um_m_s: 7.0,
        slip: 0.001,
        tau0_pa: 8e6,
        rx_m: 1.03875e-2,
        e_prime_pa: 226e9,
    }
}

#[test]
fn hertz_scales_are_consistent() {
    let h = LineHertz::from_ph(3e9, 1.03875e-2, 226e9);
    // w' = pi a p_H / 2 returns p_H through p_H = sqrt(w' E' / (2 pi Rx)) (round-off).
    let back = LineHertz::from_load(h.load_per_length, 1.03875e-2, 226e9);
    assert!((back.ph / 3e9 - 1.0).abs() < 1e-14);
    assert!((back.a / h.a - 1.0).abs() < 1e-14);
    // a = 4 Rx p_H / E' (hand value 0.551549 mm, 6 digits).
    assert!((h.a - 5.51549e-4).abs() < 1e-9, "a = {}", h.a);
}

#[test]
fn groups_obey_the_moes_identities() {
    let p = LineProblem::from_physical(&heavy_case(), Physics::figs_4_to_7()).unwrap();
    let g = p.groups;
    // Identities of the line-contact scaling (exact up to round-off).
    assert!((g.alpha_bar / (g.l * (g.m / (2.0 * PI)).sqrt()) - 1.0).abs() < 1e-12);
    assert!((g.lambda / (3.0 * PI * PI / (8.0 * g.m * g.m)) - 1.0).abs() < 1e-12);
    assert!((g.moes_film_scale / (8.0 * g.m / PI) - 1.0).abs() < 1e-12);
    assert!((g.poiseuille_stress_scale / (6.0 * g.n / g.lambda) - 1.0).abs() < 1e-12);
    // Hand values: U = eta0 u_s / (E' Rx) = 4.9140e-11, W' = 2 pi (p_H/E')^2 = 1.1072e-3,
    // M = W' U^{-1/2} = 157.9, L = alpha E' U^{1/4} = 12.93 (4 digits).
    assert!((g.m - 157.9).abs() < 0.1, "M = {}", g.m);
    assert!((g.l - 12.93).abs() < 0.01, "L = {}", g.l);
    // S-bar = S sqrt(u_s eta0 E' / Rx) / tau0 = 1.98033e-4 (hand, 6 digits).
    assert!((g.s_bar - 1.98033e-4).abs() < 1e-9, "S-bar = {}", g.s_bar);
}

#[test]
fn dimensionless_form_reproduces_the_physical_groups() {
    let phys = LineProblem::from_physical(&heavy_case(), Physics::figs_4_to_7()).unwrap();
    let g = phys.groups;
    let d = LineDimensionlessCase {
        m: g.m,
        l: g.l,
        s_bar: g.s_bar,
        slip: g.slip,
        eta0_pa_s: Some(8.24e-3),
        ph_pa: Some(3e9),
    };
    let p = LineProblem::from_dimensionless(&d, Physics::figs_4_to_7()).unwrap();
    for (a, b, what) in [
        (p.groups.lambda, g.lambda, "lambda"),
        (p.groups.alpha_bar, g.alpha_bar, "alpha_bar"),
        (p.groups.n, g.n, "N"),
        (p.groups.moes_film_scale, g.moes_film_scale, "moes scale"),
        (
            p.groups.poiseuille_stress_scale,
            g.poiseuille_stress_scale,
            "G scale",
        ),
        (p.viscosity.eta_bar(1.0), phys.viscosity.eta_bar(1.0), "eta"),
        (p.tau_c(), phys.tau_c(), "tau_c"),
    ] {
        // Round-off through different routes (powers and square roots): 1e-10.
        assert!((a / b - 1.0).abs() < 1e-10, "{what}: {a} vs {b}");
    }
}

#[test]
fn moes_formula_meets_its_asymptotes() {
    let f = LineFilmFormula::Moes;
    // Elastic-piezoviscous corner (large M, large L): H_EP dominates; the combination
    // adds the other asymptotes with exponents 7/2 and s, a few per cent at M = 1e4.
    let (m, l) = (1e4_f64, 20.0_f64);
    let h_ep = 1.311 * m.powf(-0.125) * l.powf(0.75);
    assert!((f.hc(m, l) / h_ep - 1.0).abs() < 0.05);
    // Rigid-isoviscous corner (small M, L -> 0): 3/M.
    let (m, l) = (0.01, 1e-3);
    assert!((f.hc(m, l) / (3.0 / m) - 1.0).abs() < 1e-3);
    // The Dowson formulas are Moes-similar: spot values by hand (4 digits).
    assert!((LineFilmFormula::DowsonToyoda.hc(100.0, 10.0) - 4.3452).abs() < 5e-4);
    assert!((LineFilmFormula::DowsonHigginson.hc(100.0, 10.0) - 3.1083).abs() < 5e-4);
}

#[test]
fn eyring_flow_functions() {
    // F(G) = 3 (G cosh G - sinh G)/G^3 at G = 1: 3 (cosh 1 - sinh 1) = 3/e = 1.10364.
    assert!((eyring_f(1.0) - 3.0 / std::f64::consts::E).abs() < 1e-14);
    // Continuity at the series switches: truncation (< 1e-12 at G = 0.1) plus the
    // cancellation of the closed forms there (~ 1e-13).
    for s in [0.1, 1e-3] {
        let (a, b) = (eyring_f(s * (1.0 - 1e-13)), eyring_f(s * (1.0 + 1e-13)));
        assert!((a - b).abs() < 1e-12);
        let (a, b) = (
            g_over_sinh(s * (1.0 - 1e-13)),
            g_over_sinh(s * (1.0 + 1e-13)),
        );
        assert!((a - b).abs() < 1e-12);
        let (a, b) = (
            f_g_over_sinh(s * (1.0 - 1e-13)),
            f_g_over_sinh(s * (1.0 + 1e-13)),
        );
        assert!((a - b).abs() < 1e-12);
    }
    for g in [0.3, 2.0, 20.0] {
        assert!((f_g_over_sinh(g) / (eyring_f(g) * g_over_sinh(g)) - 1.0).abs() < 1e-12);
    }
    // The exact flow tends to the perturbation form as G -> 0, for any Couette stress.
    let (e, p) = (LineEyringFlow::Exact, LineEyringFlow::Perturbation);
    let r = ShearLaw::Eyring;
    for (h, eta, ns) in [(0.02, 1e20, 1e-3), (0.5, 3.0, 0.01)] {
        let ce = e.conductance(r, h, eta, ns, 1e-6, 1.0);
        let cp = p.conductance(r, h, eta, ns, 1e-6, 1.0);
        assert!((ce / cp - 1.0).abs() < 1e-10);
    }
    // Huge G and viscosity stay finite; the flux conductance * G saturates (-> 3 h^2 N S).
    let c = e.conductance(r, 0.01, 1e25, 1e-3, 1e4, 1.0);
    assert!(c.is_finite() && c > 0.0);
    // Mean stress: sinh(tau_m) = x G / sinh G.
    let tau = e.mean_shear_stress(r, 50.0, 2.0, 1.0);
    assert!((tau.sinh() - 50.0 * 2.0 / 2f64.sinh()).abs() < 1e-10);
    assert_eq!(
        e.mean_shear_stress(ShearLaw::Newtonian, 3.0, 5.0, 1.0),
        3.0,
        "Newtonian: superposition"
    );
}

#[test]
fn bad_fields_are_named() {
    let phys = Physics::figs_4_to_7();
    let mut c = heavy_case();
    c.slip = -0.1;
    let e = LineProblem::from_physical(&c, phys).unwrap_err();
    assert!(e.to_string().starts_with("slip:"), "{e}");
    let mut c = heavy_case();
    c.tau0_pa = 0.0;
    let e = LineProblem::from_physical(&c, phys).unwrap_err();
    assert!(e.to_string().starts_with("tau0:"), "{e}");
    let mut c = heavy_case();
    c.rx_m = f64::NAN;
    let e = LineProblem::from_physical(&c, phys).unwrap_err();
    assert!(e.to_string().starts_with("rx:"), "{e}");
    let d = LineDimensionlessCase {
        m: 100.0,
        l: 10.0,
        s_bar: 0.1,
        slip: 0.001,
        eta0_pa_s: None,
        ph_pa: None,
    };
    let e = LineProblem::from_dimensionless(&d, phys).unwrap_err();
    assert!(e.to_string().starts_with("ph:"), "{e}");
    // Barus incompressible needs neither.
    assert!(LineProblem::from_dimensionless(&d, Physics::default()).is_ok());
}
