//! `repro predict` (Eq. 14 for a user's contact) and `repro fig8` (measured data on the
//! mastercurve): outputs, warnings, and errors that name the flag, file, row and column.

use crate::support::{appendix_problem, args, repro, repro_in, scratch, with_flags, WORKED_FLAGS};

/// `repro predict` at the Appendix (Table 4) case.
fn worked() -> Vec<&'static str> {
    args(&["predict"], &WORKED_FLAGS)
}

fn with<'a>(base: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
    args(base, extra)
}

#[test]
fn predict_gives_eq14_at_the_worked_case() {
    let (code, out, err) = repro(&with(&worked(), &["--json"]));
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
    let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("missing {k}"));
    // tau_c is the case's own (Problem::tau_c, Eq. 12): same code path, round-off only.
    let tau_c = appendix_problem().tau_c();
    assert!((f("tau_c") / tau_c - 1.0).abs() < 1e-12);
    // Eq. (14) and Eq. (8), by hand.
    assert!((f("mu_bar") - (tau_c / 5.0).asinh()).abs() < 1e-12);
    assert!((f("mu") - f("mu_bar") * 4e6 / 3e9).abs() < 1e-15);
    // Appendix: M = 1738, L = 14.79 (the paper's M is truncated: 1738.8).
    assert!((f("m") - 1738.0).abs() < 1.0 && (f("l") - 14.79).abs() < 0.005);
    // Against the paper's level-7 sliding mu-bar (Table 4, 41.13): the points of our Figs.
    // 4-7 scatter about Eq. (13) by 7-14 % RMS (tau_c >= 100); 5 % is inside that scatter and
    // still catches a unit error of tau_c by a factor 10 (mu-bar ~ ln(2 tau_c / 5) moves by 2.3,
    // 5.6 %).
    assert!(
        (f("mu_bar") / 41.13 - 1.0).abs() < 0.05,
        "mu-bar {}",
        f("mu_bar")
    );
    assert_eq!(v["warnings"].as_array().map(|w| w.len()), Some(0));
    assert!(v["solve"].is_null() && v["difference"].is_null());
    assert!(f("compute_seconds") > 0.0);
}

#[test]
fn predict_refined_is_within_one_per_cent_of_the_level7_solve() {
    // Issue 16: on the Table 4 case the refined formula gives the level-7 friction within
    // 1 % (the formula's residuals: 95 % of the cross-validated cases within 4.5 %; the fit's
    // own residual at this case is a few hundredths of a per cent). About 2 s of solve.
    let (code, out, err) = repro(&with(
        &worked(),
        &["--solve", "--level", "7", "--json", "-q"],
    ));
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let solved = v["solve"]["mu_bar_sliding"].as_f64().unwrap();
    let refined = v["mu_bar_refined"].as_f64().unwrap();
    assert!(
        (refined / solved - 1.0).abs() < 0.01,
        "{refined} vs {solved}"
    );
    let rel = v["difference"]["relative_refined"].as_f64().unwrap();
    assert!((rel - (refined / solved - 1.0)).abs() < 1e-12);
    let band = v["mu_bar_refined_band"].as_array().unwrap();
    let (lo, hi) = (band[0].as_f64().unwrap(), band[1].as_f64().unwrap());
    assert!(lo < solved && solved < hi, "{lo} .. {hi}");
    // Which is the paper's is said.
    assert!(v["mu_bar_source"].as_str().unwrap().contains("Eq. (14)"));
    assert!(v["mu_bar_refined_source"]
        .as_str()
        .unwrap()
        .contains("beyond the paper"));
    let (code, text, _) = repro(&worked());
    assert_eq!(code, 0);
    assert!(
        text.contains("the paper's Eq. 14") && text.contains("mu_bar_refined"),
        "{text}"
    );
}

#[test]
fn predict_load_form_is_the_ph_form() {
    // The Hertz load of p_H = 3 GPa on the circular Table 2 contact: f = 2 pi a^2 p_H / 3 with
    // a = pi Rx p_H / E'.
    let a = std::f64::consts::PI * 1.03875e-2 * 3e9 / 226e9;
    let load = format!("{:e}", 2.0 * std::f64::consts::PI * a * a * 3e9 / 3.0);
    let mut args = worked();
    args[5] = "--load";
    args[6] = &load;
    let (code, out, err) = repro(&with(&args, &["--json"]));
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // Hertz inverse (1e-12) amplified by the Roelands exponent: 1e-9.
    assert!((v["ph_pa"].as_f64().unwrap() / 3e9 - 1.0).abs() < 1e-9);
}

#[test]
fn predict_warns_where_the_paper_says_the_mastercurve_fails() {
    // Large slip: above the 2 % of the paper's isothermal runs.
    let mut args = worked();
    args[10] = "0.1";
    let (code, out, err) = repro(&args);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("mu-bar = asinh(tau_c/5)"), "{out}");
    assert!(
        err.contains("warning") && err.contains("isothermal"),
        "{err}"
    );
    // Low tau_c: light load, hot oil, tiny slip (tau_c ~ 1).
    let (code, _, err) = repro(&[
        "predict",
        "--lubricant",
        "mineral-oil-a",
        "--temperature",
        "100",
        "--ph",
        "1e9",
        "--um",
        "2",
        "--slip",
        "1e-4",
        "--tau0",
        "8e6",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("warning") && err.contains("rolling friction"),
        "{err}"
    );
}

#[test]
fn predict_with_solve_prints_both_and_the_difference() {
    // Table 3 case 1 on a circular contact from level 4: a fraction of a second.
    let (code, out, err) = repro(&[
        "predict", "--alpha", "18.6e-9", "--eta0", "4.19e-3", "--ph", "1e9", "--um", "12",
        "--slip", "0.02", "--tau0", "8e6", "--solve", "--level", "4", "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let solved = v["solve"]["mu_bar_sliding"].as_f64().expect("solve part");
    // Asked for level 4, solved on 5: level 4's friction estimate misses the rule's 1 % target.
    assert_eq!(v["solve"]["level"], 5);
    let d = v["difference"]["mu_bar"].as_f64().unwrap();
    assert!((d - (v["mu_bar"].as_f64().unwrap() - solved)).abs() < 1e-12);
    // The solve's mu in physical terms: mu-bar tau0 / p_H.
    assert!((v["solve"]["mu_sliding"].as_f64().unwrap() - solved * 8e6 / 1e9).abs() < 1e-15);
}

#[test]
fn predict_bad_flags_are_named() {
    let cases: &[(&[&str], &str)] = &[
        (&["--slip", "3"], "--slip"),
        (&["--tau0", "-1"], "--tau0"),
        (&["--lubricant", "castor-oil"], "--lubricant"),
        (&["--temperature", "20"], "--temperature"),
        (&["--ry", "1e-3"], "--ry"),
        (&["--level", "20"], "--level"),
        (&["--load", "100"], "--load"),
        (&["--e-prime", "0"], "--e-prime"),
    ];
    for (extra, flag) in cases {
        // The flags replace the worked case's.
        let (code, _, err) = repro(&with_flags(worked(), extra));
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert!(err.contains(flag), "{extra:?}: {err}");
    }
    let (code, _, err) = repro(&[
        "predict",
        "--lubricant",
        "mineral-oil-a",
        "--temperature",
        "40",
        "--um",
        "1",
        "--slip",
        "0.01",
        "--tau0",
        "4e6",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--ph"), "{err}");
}

/// A fresh folder for one test (its own name, the process id).

#[test]
fn fig8_without_data_says_so() {
    let dir = scratch("predict", "fig8-empty");
    let (code, out, err) = repro_in(&dir, &["fig8", "--out", "out"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("fig8.csv") && out.contains("fig8.svg"),
        "{out}"
    );
    assert!(err.contains("No measured dataset"), "{err}");
    // The CSV is its header alone (no comment line a CSV reader would take for data); the
    // sidecar says why.
    let csv = std::fs::read_to_string(dir.join("out/fig8.csv")).unwrap();
    assert!(csv.starts_with("dataset,row,"), "{csv}");
    assert_eq!(csv.lines().count(), 1, "header only: {csv}");
    assert!(
        fig8_note(&dir).starts_with("No measured dataset is included"),
        "{}",
        fig8_note(&dir)
    );
    let svg = std::fs::read_to_string(dir.join("out/fig8.svg")).unwrap();
    assert!(svg.contains("No measured dataset included"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The note of `out/fig8.provenance.json` in `dir`: what `fig8.csv` holds, in words.
fn fig8_note(dir: &std::path::Path) -> String {
    let text = std::fs::read_to_string(dir.join("out/fig8.provenance.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["target"], "fig8", "{text}");
    v["note"].as_str().unwrap_or_default().to_string()
}

const HEADER: &str = "series,source,contact,rx_m,ry_m,e_prime_pa,ph_pa,temperature_c,um_m_s,slip,mu,tau0_pa,lubricant,viscosity_law,film_formula";

#[test]
fn fig8_transforms_every_dataset_and_names_bad_rows() {
    let dir = scratch("predict", "fig8-data");
    std::fs::create_dir_all(dir.join("cases/fig8")).unwrap();
    // Synthetic rows (this test's own numbers, not measurements).
    std::fs::write(
        dir.join("cases/fig8/a.csv"),
        format!("{HEADER}\nT,\"test input, not measured\",elliptical,1.03875e-2,,226e9,3e9,40,12,0.005,0.05,4e6,mineral-oil-a,roelands,eq10\nT,\"test input, not measured\",elliptical,1.03875e-2,,226e9,1e9,60,12,0.02,0.06,8e6,mineral-oil-a,roelands,eq10\n"),
    )
    .unwrap();
    let (code, _, err) = repro_in(&dir, &["fig8", "--out", "out"]);
    assert_eq!(code, 0, "{err}");
    let csv = std::fs::read_to_string(dir.join("out/fig8.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 3, "header and two rows: {csv}");
    assert!(lines[0].starts_with("dataset,row,"), "{csv}");
    let note = fig8_note(&dir);
    assert!(
        note.starts_with("2 measured points from 1 file(s)"),
        "{note}"
    );
    // mu-bar = mu p_H / tau0 = 0.05 * 3e9 / 4e6 = 37.5, written with 7 digits.
    assert!(lines[1].contains(",3.750000e1,"), "{}", lines[1]);
    assert!(
        lines[1].ends_with("\"test input, not measured\""),
        "{}",
        lines[1]
    );
    // A bad row stops the target and names file, row and column.
    std::fs::write(
        dir.join("cases/fig8/b.csv"),
        format!("{HEADER}\nT,src,elliptical,1.03875e-2,,226e9,3e9,40,12,5,0.05,4e6,mineral-oil-a,roelands,eq10\n"),
    )
    .unwrap();
    let (code, _, err) = repro_in(&dir, &["fig8", "--out", "out"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("b.csv: row 1 (line 2): slip:"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn predict_estimates_the_shear_heating_and_warns_above_five_per_cent() {
    // The Appendix case: the flat-film thermal estimate lowers friction by a few per cent
    // (4.4 % measured), under the 5 % of the warning; Eq. (14) with the correction is said.
    let (code, out, err) = repro(&with(&worked(), &["--json"]));
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let c = v["thermal"]["correction"].as_f64().unwrap();
    assert!((-0.05..-0.01).contains(&c), "correction {c}");
    let mu = v["mu_bar"].as_f64().unwrap();
    let thermal = v["mu_bar_thermal"].as_f64().unwrap();
    assert!((thermal / (mu * (1.0 + c)) - 1.0).abs() < 1e-12);
    // At 2 % slip the shear heat quadruples: 14.6 % measured, above 5 %, warned by name.
    let mut args = worked();
    let slip = args.iter().position(|a| *a == "--slip").unwrap() + 1;
    args[slip] = "0.02";
    let (code, out, err) = repro(&with(&args, &["--json"]));
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let c = v["thermal"]["correction"].as_f64().unwrap();
    assert!((-0.3..-0.08).contains(&c), "correction {c}");
    let warnings = v["warnings"].to_string();
    assert!(warnings.contains("shear heating"), "{warnings}");
    // The through-hardened steel heats more (a lower conductivity): a larger correction.
    let (_, out, _) = repro(&with(&args, &["--json", "--k-solid", "21"]));
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["thermal"]["correction"].as_f64().unwrap() < c);
    // A lubricant given by alpha and eta0 alone has no temperature coefficient: no estimate,
    // and the paper's largest slip is the warning instead.
    let (code, out, err) = repro(&[
        "predict", "--alpha", "21.6e-9", "--eta0", "8.24e-3", "--ph", "3e9", "--um", "12",
        "--slip", "0.05", "--tau0", "4e6", "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["thermal"].is_null());
    assert!(v["warnings"].to_string().contains("isothermal"));
}
