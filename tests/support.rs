//! What the integration tests share: running the `repro` binary.

use std::path::Path;
use std::process::Command;

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
