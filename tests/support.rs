//! What the integration tests share: running the `repro` binary.

use repro::paper::table4::Table4Case;
use repro::physics::case::{Case, CaseForm, LubricantSpec, PhysicalCase, Physics, Problem};
use std::path::{Path, PathBuf};
use std::process::Command;

/// An empty scratch folder for test `name` of module `module`, under the system's temporary
/// folder and named with the process, so that parallel tests and runs do not share one.
pub fn scratch(module: &str, name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("repro-{module}-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// Runs `repro args` in `dir`: exit code (-1 if killed), stdout, stderr.
pub fn repro_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_repro"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("run repro");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs `repro args` in the crate's root (where `cases/` and `snapshots/` are).
pub fn repro(args: &[&str]) -> (i32, String, String) {
    repro_in(Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

/// Runs `repro args` (a `--json` command) in the crate's root, asserts it succeeded and returns
/// the one JSON object it printed.
pub fn repro_json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = repro(args);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).expect("one JSON object")
}

/// The Appendix (Table 4) case as the physical-form flags of `repro solve` and `repro
/// predict` (what a user types for `cases/table4.toml`; `appendix_problem` reads the file).
pub const WORKED_FLAGS: [&str; 12] = [
    "--lubricant",
    "mineral-oil-a",
    "--temperature",
    "40",
    "--ph",
    "3e9",
    "--um",
    "12",
    "--slip",
    "0.005",
    "--tau0",
    "4e6",
];

/// The Appendix case of `cases/table4.toml` as a dimensionless problem.
pub fn appendix_problem() -> Problem {
    Table4Case::shipped()
        .and_then(|t| t.problem())
        .expect("cases/table4.toml")
}

/// `args` with each flag-value pair of `extra` replacing the flag's value where `args` has
/// the flag, appended where it does not (clap would keep the last value, but a test that
/// states the final command line reads better).
pub fn with_flags<'a>(mut args: Vec<&'a str>, extra: &[&'a str]) -> Vec<&'a str> {
    for pair in extra.chunks(2) {
        match args.iter().position(|a| *a == pair[0]) {
            Some(i) => args[i + 1] = pair[1],
            None => args.extend_from_slice(pair),
        }
    }
    args
}

/// `first`, then `rest`: a command line.
pub fn args<'a>(first: &[&'a str], rest: &[&'a str]) -> Vec<&'a str> {
    first.iter().chain(rest).copied().collect()
}

/// Every key `repro solve --json` documents, point and line contact alike.
pub const SOLVE_KEYS: [&str; 21] = [
    "level",
    "m",
    "l",
    "s_bar",
    "alpha_bar",
    "lambda",
    "kappa",
    "h_central",
    "h_min",
    "hc_moes",
    "hmin_moes",
    "mu_bar_sliding",
    "mu_bar_rolling",
    "mu_bar_total",
    "tau_c",
    "method",
    "cycles",
    "newton_steps",
    "krylov_iterations",
    "residual",
    "seconds",
];

/// A physical circular contact with the physics of Figs. 4-6 (Rx 10.39 mm, E' 226 GPa): a
/// Table 1 lubricant at `t` C, `p_H` in GPa, `u_m` in m/s, the slide-to-roll ratio and `tau0`
/// in MPa.
pub fn physical(lubricant: &str, t: f64, ph_gpa: f64, um: f64, slip: f64, tau0_mpa: f64) -> Case {
    Case {
        spec: CaseForm::Physical(PhysicalCase {
            lubricant: LubricantSpec::Named {
                lubricant: lubricant.into(),
                temperature_c: t,
            },
            ph_pa: ph_gpa * 1e9,
            um_m_s: um,
            slip,
            tau0_pa: tau0_mpa * 1e6,
            rx_m: 1.03875e-2,
            ry_m: 1.03875e-2,
            e_prime_pa: 226e9,
        }),
        physics: Physics::figs_4_to_7(),
    }
}
