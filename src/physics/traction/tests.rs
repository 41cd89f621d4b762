use super::*;
use crate::physics::case::tests::{worked_case, worked_physical};
use crate::physics::line_contact::tests::heavy_case;
use crate::physics::viscosity::Viscosity;

/// The Appendix case (`cases/table4.toml`) as an operating point, Eq. (10) film.
fn worked_point() -> OperatingPoint {
    let c = worked_physical();
    OperatingPoint {
        contact: Contact::Elliptical {
            rx_m: c.rx_m,
            ry_m: c.ry_m,
        },
        e_prime_pa: c.e_prime_pa,
        load: Load::MaxPressure(c.ph_pa),
        lubricant: c.lubricant,
        speed: Speed::Mean(c.um_m_s),
        sliding: Sliding::Slip(c.slip),
        tau0_pa: c.tau0_pa,
        viscosity: ViscosityAtPh::Law(ViscosityLaw::Roelands),
        film: FilmFormula::Eq10,
    }
}

#[test]
fn elliptical_tau_c_is_the_problem_tau_c() {
    let lubs = LubricantTable::table1();
    let c = characteristic(&worked_point(), &lubs).unwrap();
    let case = worked_case();
    let p = Problem::from_case(&case, &lubs).unwrap();
    // Same groups through the same code: equal to round-off.
    assert!(
        (c.tau_c / p.tau_c() - 1.0).abs() < 1e-14,
        "{} vs {}",
        c.tau_c,
        p.tau_c()
    );
    assert!((c.m - p.groups.m).abs() < 1e-9);
}

#[test]
fn tau_c_is_twice_the_newtonian_centre_stress_of_the_formula_film() {
    // Eq. (12) in physical units: tau_c = 2 eta(p_H) gamma_dot / tau0 with
    // gamma_dot = S u_m / h_c. An independent evaluation from SI quantities: only the
    // Roelands law and the film in metres are shared; 1e-12 is round-off.
    let lubs = LubricantTable::table1();
    let c = characteristic(&worked_point(), &lubs).unwrap();
    let eta = 8.24e-3 * Viscosity::roelands(8.24e-3, 21.6e-9, 3e9).eta_bar(1.0);
    let direct = 2.0 * eta * (0.005 * 12.0 / c.hc_m) / 4e6;
    assert!(
        (c.tau_c / direct - 1.0).abs() < 1e-12,
        "{} vs {direct}",
        c.tau_c
    );
    // The film in metres from its definition, Hc (h/Rx) (eta0 u_s / (E' Rx))^{-1/2}.
    let u: f64 = 8.24e-3 * 24.0 / (226e9 * 1.03875e-2);
    assert!((c.hc_m / (c.hc_moes * 1.03875e-2 * u.sqrt()) - 1.0).abs() < 1e-12);
}

#[test]
fn shear_rate_and_load_forms_give_the_slip_form() {
    let lubs = LubricantTable::table1();
    let base = characteristic(&worked_point(), &lubs).unwrap();
    let mut p = worked_point();
    p.sliding = Sliding::ShearRate {
        per_s: 0.005 * 12.0 / base.hc_m,
        film_m: None,
    };
    p.load = Load::Force(Hertz::from_ph(3e9, 1.03875e-2, 1.03875e-2, 226e9).load);
    p.speed = Speed::Sum(24.0);
    let c = characteristic(&p, &lubs).unwrap();
    // Load -> p_H through the cube root of Hertz (1e-12, hertz.rs), amplified by the
    // Roelands exponent (ln eta_bar ~ 25): 1e-9.
    assert!((c.tau_c / base.tau_c - 1.0).abs() < 1e-9);
    assert!((c.slip / 0.005 - 1.0).abs() < 1e-9);
    // A measured eta(p_H) equal to the law's gives the same tau_c.
    let mut q = worked_point();
    q.viscosity = ViscosityAtPh::Given(8.24e-3 * base.eta_bar_ph);
    let c = characteristic(&q, &lubs).unwrap();
    assert!((c.tau_c / base.tau_c - 1.0).abs() < 1e-14);
}

#[test]
fn line_contact_uses_the_line_groups_and_its_formula() {
    let lubs = LubricantTable::table1();
    let p = OperatingPoint {
        contact: Contact::Line { rx_m: 1.03875e-2 },
        film: FilmFormula::Line(LineFilmFormula::DowsonHigginson),
        sliding: Sliding::Slip(0.001),
        speed: Speed::Mean(7.0),
        tau0_pa: 8e6,
        ..worked_point()
    };
    let c = characteristic(&p, &lubs).unwrap();
    let lp = LineProblem::from_physical(&heavy_case(), Physics::figs_4_to_7()).unwrap();
    let expect = lp.tau_c_with(LineFilmFormula::DowsonHigginson);
    assert!(
        (c.tau_c / expect - 1.0).abs() < 1e-13,
        "{} vs {expect}",
        c.tau_c
    );
    // Load per length returns the same p_H.
    let w = LineHertz::from_ph(3e9, 1.03875e-2, 226e9).load_per_length;
    let c2 = characteristic(
        &OperatingPoint {
            load: Load::PerLength(w),
            ..p
        },
        &lubs,
    )
    .unwrap();
    assert!((c2.ph_pa / 3e9 - 1.0).abs() < 1e-13);
}

#[test]
fn reduced_friction_is_eq_8() {
    let lubs = LubricantTable::table1();
    let r = reduce(&worked_point(), 0.05, &lubs).unwrap();
    // 0.05 * 3 GPa / 4 MPa = 37.5.
    assert!((r.mu_bar - 37.5).abs() < 1e-12);
    assert!((r.characteristic.friction(37.5, 4e6) - 0.05).abs() < 1e-15);
}

#[test]
fn bad_fields_are_named() {
    let lubs = LubricantTable::table1();
    let err = |p: OperatingPoint| characteristic(&p, &lubs).unwrap_err().to_string();
    let mut p = worked_point();
    p.film = FilmFormula::Line(LineFilmFormula::Moes);
    assert!(err(p).starts_with("film:"));
    let mut p = worked_point();
    p.sliding = Sliding::ShearRate {
        per_s: 1e12,
        film_m: None,
    };
    assert!(err(p).starts_with("shear-rate:"));
    let mut p = worked_point();
    p.load = Load::PerLength(1e6);
    assert!(err(p).starts_with("load:"));
    let mut p = worked_point();
    p.tau0_pa = -1.0;
    assert!(err(p).starts_with("tau0:"));
    let mut p = worked_point();
    p.viscosity = ViscosityAtPh::Given(0.0);
    assert!(err(p).starts_with("eta-ph:"));
    assert!(reduce(&worked_point(), f64::NAN, &lubs)
        .unwrap_err()
        .to_string()
        .starts_with("mu:"));
}
