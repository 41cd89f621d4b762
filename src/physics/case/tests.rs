use super::*;

/// The Appendix (Table 4) case, read from `cases/table4.toml`, its one definition.
pub(crate) fn worked_case() -> Case {
    #[derive(Deserialize)]
    struct File {
        case: Case,
    }
    let file: File = toml::from_str(include_str!("../../../cases/table4.toml"))
        .expect("cases/table4.toml holds the Appendix case");
    file.case
}

/// The worked case's operating conditions.
pub(crate) fn worked_physical() -> PhysicalCase {
    match worked_case().spec {
        CaseForm::Physical(p) => p,
        CaseForm::Dimensionless(_) => {
            panic!("cases/table4.toml: the Appendix case is physical")
        }
    }
}

#[test]
fn moes_groups_of_the_worked_case() {
    // Appendix: M = 1738, L = 14.79. We get M = 1738.8: the paper's last digit is
    // truncated (or its constants rounded), so M is held to within one unit of it.
    let p = Problem::from_case(&worked_case(), &LubricantTable::table1()).unwrap();
    assert!((p.groups.m - 1738.0).abs() < 1.0, "M = {}", p.groups.m);
    assert!((p.groups.l - 14.79).abs() < 0.005, "L = {}", p.groups.l);
    assert!((p.groups.alpha_bar - 64.8).abs() < 1e-9);
    // Circular contact: Venner's lambda = (128 pi^3 / (3 M^4))^(1/3).
    let lam = (128.0 * std::f64::consts::PI.powi(3) / (3.0 * p.groups.m.powi(4))).cbrt();
    assert!((p.groups.lambda / lam - 1.0).abs() < 1e-12);
    // Moes film scale (1.5 M)^(2/3) for a circle.
    assert!((p.groups.moes_film_scale / (1.5 * p.groups.m).powf(2.0 / 3.0) - 1.0).abs() < 1e-12);
}

#[test]
fn a_pressure_given_in_gpa_instead_of_pa_is_refused_by_name() {
    let mut case = worked_case();
    if let CaseForm::Physical(p) = &mut case.spec {
        p.ph_pa = 3.0;
    }
    let e = Problem::from_case(&case, &LubricantTable::table1()).unwrap_err();
    let text = e.to_string();
    assert!(text.contains("ph") && text.contains("3e9"), "{text}");
    // The ends of the range are accepted.
    for ph in [1e6, 2e10] {
        assert_eq!(hertzian_pressure("ph", ph).unwrap(), ph);
    }
}

#[test]
fn dimensionless_form_reproduces_the_physical_groups() {
    let lubs = LubricantTable::table1();
    let phys = Problem::from_case(&worked_case(), &lubs).unwrap();
    let g = phys.groups;
    let dimless = Case {
        spec: CaseForm::Dimensionless(DimensionlessCase {
            m: g.m,
            l: g.l,
            s_bar: g.s_bar,
            d: 1.0,
            slip: 0.005,
            eta0_pa_s: Some(8.24e-3),
            ph_pa: Some(3e9),
        }),
        physics: Physics::figs_4_to_7(),
    };
    let p = Problem::from_case(&dimless, &lubs).unwrap();
    for (a, b, what) in [
        (p.groups.lambda, g.lambda, "lambda"),
        (p.groups.alpha_bar, g.alpha_bar, "alpha_bar"),
        (p.groups.n, g.n, "N"),
        (p.groups.moes_film_scale, g.moes_film_scale, "moes scale"),
        (
            p.viscosity.eta_bar(1.0),
            phys.viscosity.eta_bar(1.0),
            "eta(p_H)",
        ),
        (p.tau_c(), phys.tau_c(), "tau_c"),
    ] {
        assert!((a / b - 1.0).abs() < 1e-10, "{what}: {a} vs {b}");
    }
}

#[test]
fn eyring_group_is_the_couette_stress_at_the_centre() {
    // N eta_bar S / H = eta du / (h tau0) with du = S u_m: check the units by hand.
    let p = Problem::from_case(&worked_case(), &LubricantTable::table1()).unwrap();
    let h = 1e-7; // m
    let eta = 8.24e-3 * p.viscosity.eta_bar(1.0);
    let direct = eta * 0.005 * 12.0 / (h * 4e6);
    let via_n = p.groups.n * p.viscosity.eta_bar(1.0) * 0.005 / (h / p.hertz.c);
    assert!((direct / via_n - 1.0).abs() < 1e-12);
}

#[test]
fn centre_stress_of_the_eq10_film_is_half_tau_c() {
    // SPEC.md: with the Hertzian pressure and the Eq. (10) film, the Couette argument at
    // the centre, N eta_bar(p_H) S / H, is tau_c / 2: an identity of N and the Moes units.
    let p = Problem::from_case(&worked_case(), &LubricantTable::table1()).unwrap();
    let h = super::super::film::hc_eq10(p.groups.m, p.groups.l) / p.groups.moes_film_scale;
    let centre = p.eyring_n_s() * p.viscosity.eta_bar(1.0) / h;
    assert!((centre / (p.tau_c() / 2.0) - 1.0).abs() < 1e-12);
}

#[test]
fn table1_and_given_cases_serialise_as_before_the_datasheet_variant() {
    // The case is serialised into every cache key: these strings are the JSON of the
    // Named and Given forms before `LubricantSpec::Datasheet` existed (main at e616684),
    // so Table 1's cases keep their keys and no figure moves.
    let named = serde_json::to_string(&worked_case()).unwrap();
    assert_eq!(named,
        "{\"spec\":{\"physical\":{\"lubricant\":\"mineral-oil-a\",\"temperature_c\":40.0,\"ph_pa\":3000000000.0,\"um_m_s\":12.0,\"slip\":0.005,\"tau0_pa\":4000000.0,\"rx_m\":0.0103875,\"ry_m\":0.0103875,\"e_prime_pa\":226000000000.0}},\"physics\":{\"viscosity\":\"roelands\",\"density\":\"dowson-higginson\",\"rheology\":\"eyring\"}}"
    );
    let mut given = worked_case();
    if let CaseForm::Physical(p) = &mut given.spec {
        p.lubricant = LubricantSpec::Given {
            alpha_per_pa: 21.6e-9,
            eta0_pa_s: 8.24e-3,
        };
    }
    let given_json = serde_json::to_string(&given).unwrap();
    assert_eq!(given_json,
        "{\"spec\":{\"physical\":{\"alpha_per_pa\":2.16e-8,\"eta0_pa_s\":0.00824,\"ph_pa\":3000000000.0,\"um_m_s\":12.0,\"slip\":0.005,\"tau0_pa\":4000000.0,\"rx_m\":0.0103875,\"ry_m\":0.0103875,\"e_prime_pa\":226000000000.0}},\"physics\":{\"viscosity\":\"roelands\",\"density\":\"dowson-higginson\",\"rheology\":\"eyring\"}}"
    );
    // And they read back as the same variants.
    assert_eq!(serde_json::from_str::<Case>(&named).unwrap(), worked_case());
    assert_eq!(serde_json::from_str::<Case>(&given_json).unwrap(), given);
}

/// ISO VG 68, VI 97, 880 kg/m^3 mineral gear oil at 80 C (docs/gear-oil-study.toml).
pub(crate) fn gear_oil(alpha_per_gpa: Option<f64>) -> LubricantSpec {
    LubricantSpec::Datasheet {
        datasheet: Datasheet {
            nu40_mm2_s: None,
            iso_vg: Some(68),
            nu100_mm2_s: None,
            viscosity_index: Some(97.0),
            rho15_kg_m3: 880.0,
            expansion15_per_k: None,
            base_oil: super::super::pressure_viscosity::BaseOil::Mineral,
        },
        temperature_c: 80.0,
        alpha_per_gpa,
    }
}

#[test]
fn a_datasheet_case_reads_back_as_a_datasheet_and_resolves_to_nu_rho() {
    let mut case = worked_case();
    if let CaseForm::Physical(p) = &mut case.spec {
        p.lubricant = gear_oil(None);
    }
    // JSON (the cache key) and TOML (a case file) both round-trip to the variant.
    let json = serde_json::to_string(&case).unwrap();
    assert!(
        json.contains("\"iso_vg\":68") && !json.contains("alpha_per_gpa"),
        "{json}"
    );
    assert_eq!(serde_json::from_str::<Case>(&json).unwrap(), case);
    let toml_text = "[spec.physical]\niso_vg = 68\nviscosity_index = 97\nrho15_kg_m3 = 880\n\
                     base_oil = 'mineral'\ntemperature_c = 80.0\nph_pa = 3.0e9\num_m_s = 12.0\n\
                     slip = 0.005\ntau0_pa = 4.0e6\nrx_m = 1.03875e-2\nry_m = 1.03875e-2\n\
                     e_prime_pa = 226.0e9\n[physics]\nviscosity = 'roelands'\n\
                     density = 'dowson-higginson'\nrheology = 'eyring'\n";
    assert_eq!(toml::from_str::<Case>(toml_text).unwrap(), case);
    // eta0 = nu rho at 80 C and AGMA 925's alpha; datasheet_state says it was correlated.
    let lubs = LubricantTable::table1();
    let spec = gear_oil(None);
    let s = spec.resolve(&lubs).unwrap();
    let d = spec.datasheet_state().unwrap().unwrap();
    assert_eq!(s, d.state);
    assert_eq!(s.eta0_pa_s, d.nu_mm2_s * 1e-6 * d.rho_kg_m3);
    let est = d.correlated.expect("no alpha given: correlated");
    assert_eq!(s.alpha_per_pa, est.alpha_per_pa);
    assert!(est.low_per_pa <= s.alpha_per_pa && s.alpha_per_pa < est.high_per_pa);
    // A given alpha replaces the correlation and is reported as given.
    let given = gear_oil(Some(25.0));
    let d = given.datasheet_state().unwrap().unwrap();
    assert!(d.correlated.is_none());
    assert!((d.state.alpha_per_pa / 25e-9 - 1.0).abs() < 1e-15);
    assert_eq!(d.state.eta0_pa_s, s.eta0_pa_s);
    // The Table 1 and given forms have no datasheet state.
    assert!(worked_physical().lubricant.datasheet_state().is_none());
}

#[test]
fn datasheet_errors_name_their_key() {
    let lubs = LubricantTable::table1();
    let err = |spec: LubricantSpec| match spec.resolve(&lubs).unwrap_err() {
        CaseError::Datasheet(e) => e.field(),
        other => panic!("{other}"),
    };
    let with = |f: &dyn Fn(&mut Datasheet, &mut f64, &mut Option<f64>)| {
        let mut spec = gear_oil(None);
        if let LubricantSpec::Datasheet {
            datasheet,
            temperature_c,
            alpha_per_gpa,
        } = &mut spec
        {
            f(datasheet, temperature_c, alpha_per_gpa);
        }
        spec
    };
    assert_eq!(err(with(&|_, t, _| *t = 200.0)), "temperature_c");
    assert_eq!(err(with(&|_, t, _| *t = -40.0)), "temperature_c");
    assert_eq!(err(with(&|d, _, _| d.iso_vg = Some(70))), "iso_vg");
    assert_eq!(err(with(&|d, _, _| d.nu40_mm2_s = Some(68.0))), "iso_vg");
    assert_eq!(err(with(&|d, _, _| d.rho15_kg_m3 = 1300.0)), "rho15_kg_m3");
    assert_eq!(
        err(with(&|d, _, _| d.viscosity_index = Some(900.0))),
        "viscosity_index"
    );
    assert_eq!(err(with(&|_, _, a| *a = Some(-1.0))), "alpha_per_gpa");
    assert_eq!(
        err(with(&|d, _, _| {
            d.viscosity_index = None;
            d.nu100_mm2_s = Some(70.0);
        })),
        "nu100_mm2_s"
    );
    assert_eq!(
        err(with(&|d, _, _| d.expansion15_per_k = Some(0.0))),
        "expansion15_per_k"
    );
}

#[test]
fn bad_fields_are_named() {
    let lubs = LubricantTable::table1();
    let mut c = worked_case();
    if let CaseForm::Physical(p) = &mut c.spec {
        p.slip = 2.5;
    }
    assert!(Problem::from_case(&c, &lubs)
        .unwrap_err()
        .to_string()
        .starts_with("slip:"));
    let mut c = worked_case();
    if let CaseForm::Physical(p) = &mut c.spec {
        p.ph_pa = -1.0;
    }
    assert!(Problem::from_case(&c, &lubs)
        .unwrap_err()
        .to_string()
        .starts_with("ph:"));
    let mut c = worked_case();
    if let CaseForm::Physical(p) = &mut c.spec {
        p.ry_m = p.rx_m / 2.0;
    }
    assert!(Problem::from_case(&c, &lubs)
        .unwrap_err()
        .to_string()
        .starts_with("ry:"));
}
