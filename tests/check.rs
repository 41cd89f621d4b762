//! Snapshot checks: every target agrees with the committed baselines, a 1 % change or a changed
//! Eyring stress is caught, and neither the thread count nor a rerun changes a result.

use crate::support::{repro, scratch};
use repro::paper::figures::{rows, Plot};
use repro::pipeline::executor::{run_cases, CachePolicy, PointRun};
use repro::pipeline::snapshot::compare;
use repro::pipeline::sweep::Sweep;
use std::path::PathBuf;

/// The CI promise: `make test` recomputes every target at the snapshot profile and finds it
/// equal to the committed baselines.
#[test]
fn every_target_agrees_with_its_snapshot() {
    let (code, out, err) = repro(&["check", "-q"]);
    assert_eq!(code, 0, "repro check failed:\n{out}\n{err}");
    assert!(out.contains("agree with snapshots"), "{out}");
}

/// Editing one baseline value by 1 % makes the check fail with a message naming it.
#[test]
fn a_one_percent_edit_of_a_baseline_fails_naming_the_value() {
    let dir = scratch("check", "edited");
    let base = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("snapshots/table4.csv"),
    )
    .expect("snapshots/table4.csv is committed");
    // Column 6 of table4.csv is mu_bar_sliding; scale the first row's value by 1.01.
    let mut lines: Vec<String> = base.lines().map(String::from).collect();
    let mut cells: Vec<String> = lines[1].split(',').map(String::from).collect();
    let header: Vec<&str> = lines[0].split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "mu_bar_sliding")
        .expect("column");
    let old: f64 = cells[col].parse().expect("a number");
    cells[col] = format!("{:e}", old * 1.01);
    lines[1] = cells.join(",");
    std::fs::write(dir.join("table4.csv"), lines.join("\n") + "\n").expect("write");
    let (code, out, err) = repro(&[
        "check",
        "table4",
        "-q",
        "--snapshots",
        dir.to_str().unwrap(),
    ]);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(code, 1, "{out}\n{err}");
    assert!(
        err.contains("table4: case 1, column mu_bar_sliding: baseline"),
        "message names target, case and column: {err}"
    );
    assert!(
        err.contains(&cells[col]),
        "and the edited baseline value: {err}"
    );
}

fn small_sweep(tau0_mpa: f64) -> Sweep {
    let text = format!(
        r#"
title = "snapshot test"
level = 5
[physics]
viscosity = "roelands"
density = "dowson-higginson"
[grid]
lubricant = ["mineral-oil-a"]
temperature_c = [60.0, 100.0]
ph_gpa = [0.5, 1.0]
um_m_s = [12.0]
slip = [0.01]
tau0_mpa = [{tau0_mpa}]
rx_m = [1.03875e-2]
d = [1.0]
e_prime_gpa = [226.0]
"#
    );
    Sweep::parse("test.toml", &text).expect("a valid sweep")
}

fn csv_of(sweep: &Sweep, threads: usize) -> String {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool");
    let runs: Vec<PointRun> = pool.install(|| {
        run_cases(
            "test",
            &sweep.cases,
            5,
            CachePolicy::Ignore,
            &|_| {},
            &|_| {},
        )
        .expect("runs")
    });
    rows::csv(&runs, Plot::SLIDING)
}

/// Each case is solved serially on one thread: one thread, two threads and a rerun give the
/// same results, so the check never fails for scheduling.
#[test]
fn thread_count_and_reruns_do_not_change_results() {
    let sweep = small_sweep(4.0);
    let one = csv_of(&sweep, 1);
    let two = csv_of(&sweep, 2);
    let again = csv_of(&sweep, 2);
    // Identical to the last digit, not merely within the check's tolerance.
    assert_eq!(one, two, "one thread against two");
    assert_eq!(two, again, "a rerun");
    assert!(one.lines().skip(1).all(|l| l.ends_with("solved")), "{one}");
}

/// A changed Eyring stress (4 -> 4.2 MPa, 5 %) changes tau_c and mu-bar of every case by far
/// more than the tolerance.
#[test]
fn a_changed_eyring_stress_fails_the_comparison() {
    let base = csv_of(&small_sweep(4.0), 2);
    let changed = csv_of(&small_sweep(4.2), 2);
    let diffs = compare("t", &base, &changed);
    for column in ["tau0_mpa", "tau_c", "mu_bar_sliding"] {
        assert!(
            diffs.iter().any(|d| d.column == column),
            "{column} not flagged: {diffs:?}"
        );
    }
}
