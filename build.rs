//! Records the git revision of the build as `REPRO_GIT_REVISION` (provenance of every cache
//! entry and output): `git rev-parse HEAD`, with `-dirty` when a tracked file the binary is
//! built from ([`SOURCES`]) differs from that commit; `unknown` outside a git checkout. A
//! `REPRO_GIT_REVISION` in the environment wins (builds from a source archive). Outputs
//! (`figures/`, `snapshots/`) and notes do not make a build dirty: regenerating the figures
//! before committing them must not mark the next build's provenance.

use std::process::Command;

/// What the binary is built from: a change here (committed or not) changes what it computes.
const SOURCES: [&str; 6] = [
    "build.rs",
    "Cargo.toml",
    "Cargo.lock",
    "src",
    "cases",
    "templates",
];

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

fn main() {
    println!("cargo:rerun-if-env-changed=REPRO_GIT_REVISION");
    // The revision moves with HEAD, the branch's ref and the index; the dirty flag with any
    // tracked source file.
    for path in SOURCES {
        println!("cargo:rerun-if-changed={path}");
    }
    // (A path that does not exist would rerun this script on every build: only existing
    // files are named.)
    let mut watched = Vec::new();
    if let Some(dir) = git(&["rev-parse", "--git-dir"]) {
        watched.push(format!("{dir}/HEAD"));
        watched.push(format!("{dir}/index"));
    }
    if let Some(common) = git(&["rev-parse", "--git-common-dir"]) {
        if let Some(head_ref) = git(&["symbolic-ref", "-q", "HEAD"]) {
            watched.push(format!("{common}/{head_ref}"));
        }
        watched.push(format!("{common}/packed-refs"));
    }
    for path in watched.iter().filter(|p| std::path::Path::new(p).exists()) {
        println!("cargo:rerun-if-changed={path}");
    }
    let revision = std::env::var("REPRO_GIT_REVISION")
        .ok()
        .filter(|r| !r.is_empty())
        .or_else(|| {
            let head = git(&["rev-parse", "HEAD"])?;
            // Without refreshing the index: a status that rewrites it would make the index newer
            // than this script's run, and the next cargo command would run it (and compile the
            // crate) again.
            let mut status = vec![
                "--no-optional-locks",
                "status",
                "--porcelain",
                "--untracked-files=no",
                "--",
            ];
            status.extend(SOURCES);
            let dirty = git(&status).is_some_and(|s| !s.is_empty());
            Some(if dirty { format!("{head}-dirty") } else { head })
        })
        .unwrap_or_else(|| "unknown".into());
    println!("cargo:rustc-env=REPRO_GIT_REVISION={revision}");
}
