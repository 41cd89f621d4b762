use super::*;

fn vg46_vi100() -> Datasheet {
    Datasheet {
        nu40_mm2_s: None,
        iso_vg: Some(46),
        nu100_mm2_s: None,
        viscosity_index: Some(100.0),
        rho15_kg_m3: 870.0,
        expansion15_per_k: None,
        base_oil: BaseOil::Mineral,
    }
}

#[test]
fn iso_vg_grades() {
    let g = IsoVg::new(46).unwrap();
    assert_eq!(g.grade(), 46);
    let (lo, hi) = g.nu40_limits_mm2_s();
    // ISO 3448: VG 46 spans 41.4 to 50.6 mm^2/s; VG 2 has midpoint 2.2 and 1.98 to 2.42.
    assert!((lo - 41.4).abs() < 1e-9 && (hi - 50.6).abs() < 1e-9);
    let (lo, hi) = IsoVg::new(2).unwrap().nu40_limits_mm2_s();
    assert!((lo - 1.98).abs() < 1e-9 && (hi - 2.42).abs() < 1e-9);
    assert!(ISO_3448_GRADES.windows(2).all(|w| w[1].1 > w[0].1));
}

#[test]
fn vg46_vi100_mineral_oil() {
    let lub = vg46_vi100().resolve().unwrap();
    // A VI-100 oil has U = H, so Y solves H(Y) = 46: between the D2270 rows 6.7
    // (H = 45.33) and 6.8 (H = 46.44), Y = 6.7 + 0.1 x 0.67 / 1.11 = 6.7604.
    assert!(
        (lub.nu100_mm2_s() - 6.7604).abs() < 1e-4,
        "{}",
        lub.nu100_mm2_s()
    );
    // The line passes through its data (D341 Eq. 3 inverts Eq. 2 to round-off here).
    assert!((lub.nu_mm2_s(40.0).unwrap() / 46.0 - 1.0).abs() < 1e-9);
    assert!((lub.nu_mm2_s(100.0).unwrap() / lub.nu100_mm2_s() - 1.0).abs() < 1e-9);
    assert!((lub.viscosity_index().unwrap() - 100.0).abs() < 1e-12);
    // D1250 54D at 870 kg/m^3: a15 = 0.6278 / 870 = 7.2161e-4 1/K; at 40 C,
    // 870 exp(-0.018040 x 1.014432) = 854.223 kg/m^3 (hand calculation, 6 digits).
    let d = lub.density();
    assert!((d.expansion15_per_k() - 7.2161e-4).abs() < 1e-8);
    assert!((lub.rho_kg_m3(40.0).unwrap() - 854.223).abs() < 1e-3);
    assert!((lub.rho_kg_m3(15.0).unwrap() - 870.0).abs() < 1e-12);
    // eta = nu rho: 46 mm^2/s x 854.223 kg/m^3 = 39.294 mPa s; 3e-8 Pa s is the
    // 5e-4 kg/m^3 rounding of the hand value times 46e-6 m^2/s.
    let eta = lub.eta_pa_s(40.0).unwrap();
    assert!((eta - 46e-6 * 854.223).abs() < 3e-8, "{eta}");
    // alpha from AGMA 925 at that eta; state() carries its central value.
    let a = lub.alpha(40.0).unwrap();
    let s = lub.state(40.0).unwrap();
    assert!((s.alpha_per_pa - a.alpha_per_pa).abs() < 1e-24);
    assert!((s.eta0_pa_s - eta).abs() < 1e-15);
    assert!(a.low_per_pa < a.high_per_pa);
}

#[test]
fn measured_viscosities_and_a_given_expansion() {
    // The D2270 Procedure B example as a datasheet: VI 156 comes back.
    let sheet = Datasheet {
        nu40_mm2_s: Some(22.83),
        iso_vg: None,
        nu100_mm2_s: Some(5.05),
        viscosity_index: None,
        rho15_kg_m3: 830.0,
        expansion15_per_k: Some(7.0e-4),
        base_oil: BaseOil::Polyalphaolefin,
    };
    let lub = sheet.resolve().unwrap();
    assert!((lub.viscosity_index().unwrap().round() - 156.0).abs() < 1e-12);
    assert!((lub.density().expansion15_per_k() - 7.0e-4).abs() < 1e-18);
    // A 100 C viscosity below 2 mm^2/s has no VI but a D341 line.
    let thin = Datasheet {
        nu40_mm2_s: Some(5.0),
        nu100_mm2_s: Some(1.8),
        ..sheet
    };
    let lub = thin.resolve().unwrap();
    assert!(lub.viscosity_index().is_none());
    assert!(lub.nu_mm2_s(70.0).unwrap() < 5.0);
}

#[test]
fn reads_from_toml() {
    let text = "iso_vg = 46\nviscosity_index = 100\nrho15_kg_m3 = 870\nbase_oil = 'mineral'\n";
    let sheet: Datasheet = toml::from_str(text).unwrap();
    assert_eq!(sheet, vg46_vi100());
    let e = toml::from_str::<Datasheet>("iso_vg = 46\nvi = 100\n").unwrap_err();
    assert!(e.to_string().contains("unknown field"), "{e}");
}

#[test]
fn every_error_is_reachable() {
    let base = vg46_vi100();
    let err = |s: Datasheet| s.resolve().unwrap_err();
    let e = err(Datasheet {
        iso_vg: None,
        ..base.clone()
    });
    assert!(
        matches!(
            e,
            DatasheetError::Missing {
                field: "nu40_mm2_s",
                ..
            }
        ),
        "{e}"
    );
    let e = err(Datasheet {
        viscosity_index: None,
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::Missing {
            field: "nu100_mm2_s",
            ..
        }
    ));
    let e = err(Datasheet {
        nu40_mm2_s: Some(46.0),
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::Conflicting {
            other: "iso_vg",
            ..
        }
    ));
    let e = err(Datasheet {
        nu100_mm2_s: Some(6.8),
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::Conflicting {
            other: "viscosity_index",
            ..
        }
    ));
    let e = err(Datasheet {
        iso_vg: Some(50),
        ..base.clone()
    });
    assert!(matches!(e, DatasheetError::UnknownIsoVg { grade: 50, .. }));
    assert!(e.to_string().contains("46"), "{e}");
    let e = err(Datasheet {
        rho15_kg_m3: -870.0,
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::NotPositive {
            field: "rho15_kg_m3",
            ..
        }
    ));
    let e = err(Datasheet {
        expansion15_per_k: Some(0.0),
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::NotPositive {
            field: "expansion15_per_k",
            ..
        }
    ));
    // 5P4E's density (about 1200 kg/m^3) is beyond Table 54D.
    let e = err(Datasheet {
        rho15_kg_m3: 1200.0,
        ..base.clone()
    });
    assert!(matches!(e, DatasheetError::Rho15OutsideTable54D { .. }));
    // Inconsistent viscosities: nu100 >= nu40 (D2270's check, names both fields).
    let e = err(Datasheet {
        iso_vg: None,
        nu40_mm2_s: Some(5.0),
        viscosity_index: None,
        nu100_mm2_s: Some(5.0),
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::ViscosityIndex(ViscosityIndexError::Nu100NotBelowNu40 { .. })
    ));
    assert!(e.to_string().contains("nu100_mm2_s"), "{e}");
    // A VI no VG 10 oil can have.
    let e = err(Datasheet {
        iso_vg: Some(10),
        viscosity_index: Some(-200.0),
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::ViscosityIndex(ViscosityIndexError::ViscosityIndexOutOfRange { .. })
    ));
    // A measured viscosity below the D341 floor.
    let e = err(Datasheet {
        iso_vg: None,
        nu40_mm2_s: Some(1.0),
        viscosity_index: None,
        nu100_mm2_s: Some(0.1),
        ..base.clone()
    });
    assert!(matches!(
        e,
        DatasheetError::Walther(WaltherError::ViscosityBelowRange { .. })
    ));
    // Temperatures outside the laws' range, viscosity first, density on its own.
    let lub = base.resolve().unwrap();
    assert!(matches!(
        lub.eta_pa_s(200.0),
        Err(DatasheetError::Walther(
            WaltherError::TemperatureOutOfRange { .. }
        ))
    ));
    assert!(matches!(
        lub.rho_kg_m3(-40.0),
        Err(DatasheetError::TemperatureOutOfRange { .. })
    ));
    // eta is positive by construction, so the correlation's error only arrives by
    // conversion; its message is the correlation's own.
    let inner = PressureViscosityError::NotPositive {
        field: "eta_pa_s",
        value: 0.0,
    };
    let e = DatasheetError::from(inner.clone());
    assert_eq!(e.to_string(), inner.to_string());
}
