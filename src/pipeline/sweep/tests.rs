//! Sweep files: order, forms, study lubricants, errors.

use super::*;
use crate::physics::case::{CaseForm, LubricantSpec};

#[test]
fn grid_order_is_deterministic_last_key_fastest() {
    let s = Sweep::parse(
        "t.toml",
        "title = 't'\n[grid]\nm = [100.0, 200.0]\nl = [5.0, 10.0]\ns_bar = [0.1]\ntau0_hat = [2.0]\n",
    )
    .unwrap();
    let ml: Vec<(f64, f64)> = s
        .cases
        .iter()
        .map(|c| match &c.spec {
            CaseForm::Dimensionless(d) => (d.m, d.l),
            _ => unreachable!(),
        })
        .collect();
    assert_eq!(
        ml,
        vec![(100.0, 5.0), (100.0, 10.0), (200.0, 5.0), (200.0, 10.0)]
    );
    if let CaseForm::Dimensionless(d) = &s.cases[0].spec {
        assert!((d.slip - 0.2).abs() < 1e-15, "S = tau0_hat S-bar");
    }
}

/// A study of the ISO VG 68 gear oil (`physics::case::tests::gear_oil`) at 80 C, with
/// `extra` lines in its lubricant table and `point` keys in its one point.
fn gear_study(extra: &str, point: &str) -> String {
    format!(
        "title = 'g'\n[lubricants.gear-oil]\niso_vg = 68\nviscosity_index = 97\n\
         rho15_kg_m3 = 880\nbase_oil = 'mineral'\n{extra}\n[[point]]\n\
         lubricant = 'gear-oil'\nph_gpa = 1.0\num_m_s = 5.0\nslip = 0.01\ntau0_mpa = 5.0\n\
         rx_m = 1.03875e-2\ne_prime_gpa = 226.0\n{point}\n"
    )
}

#[test]
fn a_study_lubricant_becomes_a_datasheet_case() {
    use crate::physics::case::tests::gear_oil;
    let s = Sweep::parse("g.toml", &gear_study("", "temperature_c = 80.0")).unwrap();
    let CaseForm::Physical(p) = &s.cases[0].spec else {
        panic!("physical")
    };
    assert_eq!(p.lubricant, gear_oil(None));
    // The user's alpha is carried into the case (and so into its key).
    let s = Sweep::parse(
        "g.toml",
        &gear_study("alpha_per_gpa = 25", "temperature_c = 80.0"),
    )
    .unwrap();
    let CaseForm::Physical(p) = &s.cases[0].spec else {
        panic!("physical")
    };
    assert_eq!(p.lubricant, gear_oil(Some(25.0)));
    // In a grid, with Table 1 beside it: Table 1's names keep meaning Table 1.
    let text = gear_study("", "temperature_c = 80.0").replace(
        "[[point]]",
        "[grid]\nlubricant = ['gear-oil', 'mineral-oil-a']\ntemperature_c = [60.0]\n\
         ph_gpa = [1.0]\num_m_s = [5.0]\nslip = [0.01]\ntau0_mpa = [5.0]\nrx_m = [0.01]\n\
         e_prime_gpa = [226.0]\n[[point]]",
    );
    let s = Sweep::parse("g.toml", &text).unwrap();
    let lubs: Vec<_> = s
        .cases
        .iter()
        .map(|c| match &c.spec {
            CaseForm::Physical(p) => p.lubricant.clone(),
            CaseForm::Dimensionless(_) => unreachable!(),
        })
        .collect();
    assert!(
        matches!(&lubs[0], LubricantSpec::Datasheet { temperature_c, .. } if *temperature_c == 60.0)
    );
    assert!(
        matches!(&lubs[1], LubricantSpec::Named { lubricant, .. } if lubricant == "mineral-oil-a")
    );
    assert_eq!(lubs[2], gear_oil(None));
}

#[test]
fn study_lubricant_errors_name_the_file_and_field() {
    let err = |extra: &str, point: &str| {
        Sweep::parse("g.toml", &gear_study(extra, point))
            .unwrap_err()
            .to_string()
    };
    for (extra, point, needle) in [
        ("", "temperature_c = 200.0", "g.toml: temperature_c: "),
        ("", "", "g.toml: temperature_c: missing"),
        (
            "vi = 3",
            "temperature_c = 80.0",
            "g.toml: lubricants.gear-oil: unknown field `vi`",
        ),
        (
            "nu40_mm2_s = 68.0",
            "temperature_c = 80.0",
            "g.toml: lubricants.gear-oil.iso_vg: ",
        ),
        (
            "alpha_per_gpa = 'x'",
            "temperature_c = 80.0",
            "g.toml: lubricants.gear-oil.alpha_per_gpa: ",
        ),
        (
            "alpha_per_gpa = -2.0",
            "temperature_c = 80.0",
            "g.toml: lubricants.gear-oil.alpha_per_gpa: ",
        ),
        (
            "expansion15_per_k = 0.0",
            "temperature_c = 80.0",
            "g.toml: lubricants.gear-oil.expansion15_per_k: ",
        ),
    ] {
        let e = err(extra, point);
        assert!(e.starts_with(needle), "{extra} / {point}: {e}");
    }
    let e = Sweep::parse(
        "g.toml",
        &gear_study("", "temperature_c = 80.0").replace(
            "iso_vg = 68\nviscosity_index = 97",
            "nu40_mm2_s = 68.0\nnu100_mm2_s = 70.0",
        ),
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.starts_with("g.toml: lubricants.gear-oil.nu100_mm2_s: "),
        "{e}"
    );
    let e = Sweep::parse(
        "g.toml",
        &gear_study("", "temperature_c = 80.0").replace("gear-oil", "mineral-oil-a"),
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.starts_with("g.toml: lubricants.mineral-oil-a: ") && e.contains("Table 1"),
        "{e}"
    );
}

#[test]
fn errors_name_the_file_and_field() {
    let e = Sweep::parse("my.toml", "title = 'x'\n[grid]\nph_gpa = [1.0]\n")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("my.toml: lubricant"), "{e}");
    let e = Sweep::parse(
        "my.toml",
        "title = 'x'\n[grid]\nph_gpa = [1.0]\nbogus = [1]\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.starts_with("my.toml") && e.contains("bogus"), "{e}");
    let e = Sweep::parse(
        "my.toml",
        "title = 'x'\n[[point]]\nm = 10.0\nl = 2.0\ns_bar = 0.1\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("slip"), "{e}");
    let e = Sweep::parse("my.toml", "title = 'x'\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("no [grid]"), "{e}");
}
