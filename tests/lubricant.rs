//! A lubricant as its datasheet gives it (issue 32): `repro predict` and `repro solve` with
//! datasheet flags, the same oil through a study file, and errors that name the flag or field.

use crate::support::{repro, repro_json, with_flags};
use repro::physics::case::{CaseForm, Problem};
use repro::physics::lubricant::LubricantTable;
use repro::pipeline::sweep::Sweep;
use std::path::Path;

/// docs/gear-oil-study.toml: an ISO VG 68, VI 97 mineral gear oil, 880 kg/m^3 at 15 C.
const OIL: [&str; 8] = [
    "--iso-vg",
    "68",
    "--vi",
    "97",
    "--rho15",
    "880",
    "--base-oil",
    "mineral",
];

/// The study's contact at 1.5 GPa, 2 m/s, S 2 %, tau0 5 MPa, 80 C (its case 14).
const CONTACT: [&str; 16] = [
    "--temperature",
    "80",
    "--ph",
    "1.5e9",
    "--rx",
    "5e-3",
    "--e-prime",
    "231e9",
    "--um",
    "2",
    "--slip",
    "0.02",
    "--tau0",
    "5e6",
    "--json",
    "-q",
];

fn predict(extra: &[&str]) -> serde_json::Value {
    let args: Vec<&str> = ["predict"]
        .iter()
        .chain(&OIL)
        .chain(&CONTACT)
        .chain(extra)
        .copied()
        .collect();
    repro_json(&args)
}

fn num(v: &serde_json::Value, path: &[&str]) -> f64 {
    path.iter()
        .fold(v, |v, k| &v[*k])
        .as_f64()
        .unwrap_or_else(|| panic!("missing {path:?}"))
}

fn pair(v: &serde_json::Value, key: &str) -> (f64, f64) {
    let b = v[key].as_array().unwrap_or_else(|| panic!("missing {key}"));
    (b[0].as_f64().unwrap(), b[1].as_f64().unwrap())
}

#[test]
fn predict_iso_vg_68_at_80_c_gives_eta0_by_d341_and_alpha_and_mu_with_bands() {
    let v = predict(&[]);
    let lub = &v["lubricant"];
    // By hand (a calculator, 6 digits). D2270: VI 97 at U = 68 mm^2/s means U = 0.03 L +
    // 0.97 H; its Table 1 rows 8.6 (L 113.9, H 66.48: 67.9026) and 8.7 (116.2, 67.64:
    // 69.0968) give nu100 = 8.6 + 0.1 x 0.0974 / 1.1942 = 8.6082 mm^2/s. D341 (Z = nu + 0.7
    // above 2 mm^2/s): log log Z40 = log log 68.7 = 0.264099, log log Z100 = log log 9.3082 =
    // -0.013736; log T = 2.495752 (40 C), 2.571883 (100 C), 2.547959 (80 C); B = 0.277835 /
    // 0.076131 = 3.64944; at 80 C log log Z = 0.264099 - 3.64944 x 0.052207 = 0.073572, Z =
    // 15.297, nu = 14.597 mm^2/s. D1250 54D: a15 = 0.6278 / 880 = 7.13409e-4 1/K, a dT =
    // 0.0463716, rho = 880 exp(-0.0463716 x 1.0370973) = 880 x 0.953046 = 838.68 kg/m^3.
    // eta0 = 14.597e-6 x 838.68 = 1.22422e-2 Pa s. The issue asks for 2 %; the hand values'
    // 5 digits agree with repro's to 1e-4.
    let eta0 = num(lub, &["eta0_pa_s"]);
    assert!((eta0 / 1.22422e-2 - 1.0).abs() < 0.02, "eta0 {eta0}");
    assert!((eta0 / 1.22422e-2 - 1.0).abs() < 1e-4, "eta0 {eta0}");
    assert!((num(lub, &["nu_mm2_s"]) / 14.597 - 1.0).abs() < 1e-4);
    assert!((num(lub, &["rho_kg_m3"]) / 838.68 - 1.0).abs() < 1e-5);
    assert!((num(lub, &["nu100_mm2_s"]) / 8.6082 - 1.0).abs() < 1e-4);
    // alpha: AGMA 925 for a mineral oil at 12.242 mPa s: 0.010471 x 12.242^0.1348 = 0.010471 x
    // 1.40166 = 14.677 1/GPa (hand, 5 digits); band [1.0, 1.65] x alpha; said correlated.
    let alpha = num(lub, &["alpha_per_pa"]);
    assert!((alpha / 14.677e-9 - 1.0).abs() < 1e-4, "alpha {alpha}");
    assert_eq!(lub["alpha_correlated"], true);
    assert!(lub["alpha_source"].as_str().unwrap().contains("AGMA 925"));
    let (lo, hi) = pair(lub, "alpha_band_per_pa");
    assert!((lo / alpha - 1.0).abs() < 1e-12 && (hi / alpha - 1.65).abs() < 1e-12);
    // mu (Eq. 14) with the band the alpha band gives: alpha is the band's low end, and a
    // larger alpha means a larger tau_c, so mu is the band's low end too.
    let mu = num(&v, &["mu"]);
    let (mu_lo, mu_hi) = pair(&v, "mu_band");
    assert!(mu_lo <= mu && mu < mu_hi, "{mu_lo} {mu} {mu_hi}");
    let (h_lo, h_hi) = pair(&v, "hc_m_band");
    assert!(h_lo <= num(&v, &["hc_m"]) && num(&v, &["hc_m"]) < h_hi);
    // The refined formula's band holds its own 5.1 % and the alpha band's range.
    let r = num(&v, &["mu_bar_refined"]);
    let (r_lo, r_hi) = pair(&v, "mu_bar_refined_band");
    assert!(
        r_lo < r * (1.0 - 0.04) && r_hi > r * 1.5,
        "{r_lo} {r} {r_hi}"
    );
    assert!(v["mu_bar_refined_source"]
        .as_str()
        .unwrap()
        .contains("alpha band"));
    // The text says it too.
    let args: Vec<&str> = ["predict"]
        .iter()
        .chain(&OIL)
        .chain(&CONTACT[..14])
        .copied()
        .collect();
    let (code, text, err) = repro(&args);
    assert_eq!(code, 0, "{err}");
    for needle in [
        "eta0 = nu rho = 1.2242e-2 Pa s",
        "ASTM D341",
        "CORRELATED (no --alpha given): band 14.68 .. 24.22 1/GPa; AGMA 925-A03",
        "over the alpha band",
    ] {
        assert!(text.contains(needle), "{needle}: {text}");
    }
    // A given alpha replaces the correlation: no alpha band, the refined formula's own band.
    let v = predict(&["--alpha", "2.2e-8"]);
    assert_eq!(v["lubricant"]["alpha_correlated"], false);
    assert!((num(&v["lubricant"], &["alpha_per_pa"]) / 2.2e-8 - 1.0).abs() < 1e-15);
    assert_eq!(num(&v["lubricant"], &["eta0_pa_s"]), eta0);
    assert!(v["mu_band"].is_null() && v["lubricant"]["alpha_band_per_pa"].is_null());
}

#[test]
fn the_same_oil_through_a_study_gives_the_same_eta0_alpha_and_groups_bit_for_bit() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/gear-oil-study.toml");
    let sweep = Sweep::read(&file).expect("docs/gear-oil-study.toml");
    assert_eq!(sweep.cases.len(), 16);
    // The grid's last key is fastest: case 14 is 80 C, 1.5 GPa, 2 m/s, S 2 %, the contact
    // of `CONTACT`.
    let case = &sweep.cases[13];
    let CaseForm::Physical(p) = &case.spec else {
        panic!("physical")
    };
    assert_eq!(
        (p.lubricant.temperature_c(), p.ph_pa, p.um_m_s, p.slip),
        (Some(80.0), 1.5e9, 2.0, 0.02)
    );
    let lubs = LubricantTable::table1();
    let state = p.lubricant.resolve(&lubs).unwrap();
    let problem = Problem::from_case(case, &lubs).unwrap();
    // JSON floats round-trip exactly (serde_json's float_roundtrip), so == is bit for bit.
    let v = predict(&[]);
    assert_eq!(num(&v["lubricant"], &["eta0_pa_s"]), state.eta0_pa_s);
    assert_eq!(num(&v["lubricant"], &["alpha_per_pa"]), state.alpha_per_pa);
    for (key, group) in [
        ("m", problem.groups.m),
        ("l", problem.groups.l),
        ("s_bar", problem.groups.s_bar),
    ] {
        assert_eq!(num(&v, &[key]), group, "{key}");
    }
}

#[test]
fn the_gear_oil_study_runs_at_level_5() {
    // 16 cases and 8 bases at level 5: about 2 s.
    let dir = std::env::temp_dir().join(format!("repro-gear-oil-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let (out, cache) = (dir.join("out"), dir.join("cache"));
    let (code, stdout, err) = repro(&[
        "run",
        "docs/gear-oil-study.toml",
        "--level",
        "5",
        "--out",
        out.to_str().unwrap(),
        "--cache",
        cache.to_str().unwrap(),
        "-q",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(stdout.contains("16 cases, 16 solved"), "{stdout}");
    let csv = std::fs::read_to_string(out.join("gear-oil-study.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(rows.len(), 17, "header and 16 cases: {csv}");
    assert!(
        rows[1].starts_with("1,ISO VG 68 VI 97 mineral,6.000000e1,"),
        "{}",
        rows[1]
    );
    assert!(out.join("gear-oil-study.svg").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_datasheet_flags_get_one_line_naming_the_flag() {
    // Each replaces or adds flags of a valid predict (and solve) command line.
    let cases: &[(&[&str], &str)] = &[
        (&["--nu40", "68"], "--iso-vg"),
        (&["--iso-vg", "70"], "--iso-vg"),
        (&["--vi", "900"], "--vi"),
        (&["--nu100", "9"], "--vi"),
        (&["--temperature", "200"], "--temperature"),
        (&["--temperature", "-40"], "--temperature"),
        (&["--rho15", "1300"], "--rho15"),
        (&["--rho15", "-880"], "--rho15"),
        (&["--expansion15", "0"], "--expansion15"),
        (&["--alpha", "-0.00000002"], "--alpha"),
        (&["--lubricant", "mineral-oil-a"], "--lubricant"),
        (&["--eta0", "0.01"], "--eta0"),
    ];
    for command in ["predict", "solve"] {
        for (extra, flag) in cases {
            let base: Vec<&str> = [command]
                .iter()
                .chain(&OIL)
                .chain(&CONTACT)
                .copied()
                .collect();
            let (code, _, err) = repro(&with_flags(base, extra));
            assert_eq!(code, 2, "{command} {extra:?}: {err}");
            assert!(
                err.starts_with(&format!("error: {flag}")),
                "{command} {extra:?}: {err}"
            );
            assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
        }
    }
    // Missing pieces of a datasheet: nu100 and VI (both absent), rho15, base oil, temperature.
    let without = |drop: &[&str]| -> Vec<&str> {
        let mut args = vec!["predict"];
        let all: Vec<&str> = OIL.iter().chain(&CONTACT).copied().collect();
        let mut i = 0;
        while i < all.len() {
            if drop.contains(&all[i]) {
                i += 2;
            } else {
                args.push(all[i]);
                i += 1;
            }
        }
        args
    };
    for (drop, flag) in [
        (&["--vi"][..], "--nu100"),
        (&["--iso-vg"][..], "--nu40"),
        (&["--rho15"][..], "--rho15"),
        (&["--base-oil"][..], "--base-oil"),
        (&["--temperature"][..], "--temperature"),
    ] {
        let (code, _, err) = repro(&without(drop));
        assert_eq!(code, 2, "{drop:?}: {err}");
        assert!(
            err.starts_with(&format!("error: {flag}")),
            "{drop:?}: {err}"
        );
        assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    }
    // An unknown base oil is clap's (exit 2, naming the flag and the choices).
    let mut args = without(&["--base-oil"]);
    args.extend_from_slice(&["--base-oil", "ester"]);
    let (code, _, err) = repro(&args);
    assert_eq!(code, 2);
    assert!(err.contains("--base-oil") && err.contains("pao"), "{err}");
}

#[test]
fn dimensionless_roelands_takes_eta0_and_ph() {
    // --ph and --eta0 belong to the dimensionless form when --m/--l/--s-bar are given (they
    // were taken for the physical form's, and the mix refused).
    let groups = [
        "solve",
        "--m",
        "0.2",
        "--l",
        "47",
        "--s-bar",
        "0.1",
        "--viscosity",
        "roelands",
        "--eta0",
        "0.05",
    ];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        groups.iter().chain(extra).copied().collect()
    };
    let (code, out, err) = repro(&with(&["--ph", "5e8", "--level", "4", "--json", "-q"]));
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["viscosity"], "roelands");
    assert!((num(&v, &["m"]) - 0.2).abs() < 1e-12);
    // Without --ph Roelands still asks for it, by name; a physical-only flag is still a mix.
    let (code, _, err) = repro(&with(&[]));
    assert_eq!(code, 2);
    assert!(err.starts_with("error: --ph"), "{err}");
    let (code, _, err) = repro(&with(&["--ph", "5e8", "--iso-vg", "68"]));
    assert_eq!(code, 2);
    assert!(err.contains("cannot be mixed"), "{err}");
}

#[test]
fn bad_study_lubricants_name_the_file_and_field() {
    let dir = std::env::temp_dir().join(format!("repro-bad-lube-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let study = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/gear-oil-study.toml"),
    )
    .unwrap();
    for (name, from, to, needle) in [
        (
            "hot.toml",
            "temperature_c = [60.0, 80.0]",
            "temperature_c = [60.0, 180.0]",
            "hot.toml: temperature_c: ",
        ),
        (
            "thin.toml",
            "viscosity_index = 97 ",
            "nu100_mm2_s = 80.0 ",
            "thin.toml: lubricants.iso-vg-68.nu100_mm2_s: ",
        ),
        (
            "grade.toml",
            "iso_vg = 68 ",
            "iso_vg = 69 ",
            "grade.toml: lubricants.iso-vg-68.iso_vg: ",
        ),
    ] {
        assert!(study.contains(from), "{from}");
        let path = dir.join(name);
        std::fs::write(&path, study.replace(from, to)).unwrap();
        let (code, _, err) = repro(&[
            "run",
            path.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
        ]);
        assert_eq!(code, 2, "{name}: {err}");
        assert!(err.contains(needle), "{name}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
