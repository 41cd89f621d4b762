//! The revision guard: a cached result is answered only under the revision that computed it,
//! so a change that moves a result must raise the revision its cache key holds. This test
//! notices when one does not.
//!
//! A few probe solves at low levels take, between them, every path a result can come from:
//! the multigrid cycles, the Newton-Krylov finish, a warm member from its base, the nested
//! chain, the refinement to the accuracy target, the error estimate, the paper's setup with
//! `P = 0` on the edge, the inlet patch, a line contact, the thermal post-process and the
//! limiting shear stress (each probe asserts the path it is there for, so a probe that stops
//! taking it is noticed). They run as the pipeline runs a target's jobs (the base first, then
//! the member from its solution), and what is digested is what a cache entry stores, the
//! outcome's JSON (floats in shortest round-trip form) without its wall times
//! (`merge::result_of`): the bits a cache would answer with.
//! The digests are committed in `snapshots/revisions.toml` beside the revisions they belong
//! to: the point contact's results (`SOLVER_REVISION`), the thermal post-process's (with the
//! point revision, whose solution it reads: `THERMAL_REVISION`) and the line contact's.
//!
//! The tolerance is zero, for the solver is deterministic: each case is solved on one thread
//! (the executor runs cases side by side, never one case across threads), faer's
//! factorisations are fixed to one thread (`solver::fix_factorisation_parallelism`), and no
//! sum's order depends on the thread count, so a run gives the same bits whatever the number
//! of threads (the test runs beside the others on cargo's threads). What can differ between
//! processors is the SIMD path the libraries dispatch to at run time (rustfft, faer), so a
//! record names the arithmetic it was made on (the architecture and its AVX2, FMA and
//! AVX-512 features), and a processor without a record of its own is told to make one.
//!
//! Refresh, after raising a revision or on a new kind of processor:
//! `REPRO_RECORD_REVISIONS=1 cargo test --release --test integration revision`. It records
//! only digests that are missing and never overwrites one of the present revisions: a result
//! that moves under the same revision fails, recording or not.

use crate::support::physical;
use repro::paper::cases::shipped_sweep;
use repro::paper::figures::line::table3_jobs;
use repro::paper::target::LINE_LEVEL;
use repro::physics::case::{Case, Physics, Problem};
use repro::physics::lubricant::LubricantTable;
use repro::physics::rheology::{LimitingShearStress, Rheology};
use repro::physics::thermal::THERMAL_REVISION;
use repro::pipeline::cache::sha256_hex;
use repro::pipeline::executor::{run_jobs, CachePolicy};
use repro::pipeline::job::{point_job, Job, Setup, Solve};
use repro::pipeline::keys::LINE_SOLVER_REVISION;
use repro::pipeline::merge::result_of;
use repro::pipeline::outcome::CaseOutcome;
use repro::solver::output::{LadderStop, StartKind};
use repro::solver::point::composite::Patch;
use repro::solver::point::{Edge, SOLVER_REVISION};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::PathBuf;

/// The command that records missing digests.
const RECORD: &str = "REPRO_RECORD_REVISIONS=1 cargo test --release --test integration revision";

/// The point probes' level: every path below is taken at it (the patch's at one above, the
/// lowest whose composite has a level below for its estimate), in tenths of a second a solve.
const LEVEL: u32 = 4;

/// A probe: what it is there for, and its job.
struct Probe {
    name: &'static str,
    job: Job,
    /// Whether the outcome took the path the probe is there for.
    took_its_path: fn(&CaseOutcome) -> bool,
}

/// The pipeline's job of `case` in `setup` at `level`, on a composite grid where `patch`.
fn point(case: &Case, setup: Setup, level: u32, patch: Option<Patch>) -> Job {
    let lubricants = LubricantTable::table1();
    let problem = Problem::from_case(case, &lubricants).expect("a valid probe case");
    let mut params = setup.params(&problem, level);
    params.patch = patch.map(|p| p.set(params.level));
    point_job(case, &problem, params, String::new(), &lubricants).expect("a probe job")
}

/// The solver parameters of a point job.
fn params(job: &Job) -> &repro::solver::point::Params {
    match &job.solve {
        Solve::Point { params, .. } => params,
        Solve::Line { .. } => panic!("a point job"),
    }
}

fn solved(o: &CaseOutcome) -> bool {
    o.solved().is_some()
}

/// The point probes: every path of the point solver and of the pipeline around it.
fn point_probes() -> Vec<Probe> {
    // Mineral oil A at 40 C, 1 GPa, 2 m/s, S 2 %, tau0 4 MPa (M 247, L 9.4): a member of the
    // family whose base has S 0.5 % and 6 MPa.
    let member = physical("mineral-oil-a", 40.0, 1.0, 2.0, 0.02, 4.0);
    let limited = Case {
        physics: Physics {
            rheology: Rheology::EyringLss(LimitingShearStress {
                lambda: 0.08,
                tau_l0_pa: 4e6,
            }),
            ..member.physics
        },
        ..member.clone()
    };
    // Fig. 6 case 23 (5P4E, 40 C, 1 GPa, 12 m/s, S 0.5 %, 6 MPa: M 18, L 24): a light
    // contact on the case-sized domain with nested rectangles.
    let light = shipped_sweep("fig6").expect("cases/fig6.toml").cases[22].clone();
    let probes = vec![
        Probe {
            // Level 4's estimate misses the friction target, so the rule refines to 5.
            name: "member: cycles, warm from its base, refined to the target, estimated, thermal",
            job: point(&member, Setup::Rule, LEVEL, None),
            took_its_path: |o| {
                o.solved().is_some_and(|s| {
                    s.start == StartKind::Warm
                        && s.newton_steps == 0
                        && s.level > LEVEL
                        && s.errors.is_some()
                        && !s.thermal.is_empty()
                })
            },
        },
        Probe {
            name: "limited: the limiting shear stress, warm from its Eyring twin",
            job: point(&limited, Setup::Rule, LEVEL, None),
            took_its_path: |o| o.solved().is_some_and(|s| s.start == StartKind::Warm),
        },
        Probe {
            // Traction fluid at 40 C, 3 GPa, 12 m/s, S 2 % (M 687, L 27): level 6's cycles
            // stall and the Newton-Krylov finish converges it.
            name: "heavy: the Newton-Krylov finish",
            job: point(
                &physical("traction-fluid", 40.0, 3.0, 12.0, 0.02, 4.0),
                Setup::Rule,
                5,
                None,
            ),
            took_its_path: |o| o.solved().is_some_and(|s| s.newton_steps > 0),
        },
        Probe {
            name: "chain: the nested domains",
            job: point(&light, Setup::Rule, LEVEL, None),
            took_its_path: solved,
        },
        Probe {
            name: "paper: the paper's setup, P = 0 on its domain's edge",
            job: point(&light, Setup::Paper, LEVEL, None),
            took_its_path: solved,
        },
        Probe {
            name: "patch: the composite grid's inlet patch",
            job: point(&member, Setup::Rule, LEVEL + 1, Some(Patch::Inlet)),
            took_its_path: solved,
        },
        Probe {
            // Fig. 4 case 214 (mineral oil A, 100 C, 2 GPa, 12 m/s, S 2 %; M 1 484) at level
            // 7: its level 5 is outside the asymptotic range (found by its base, so not solved
            // again), and levels 6-7 meet the target.
            name: "estimate: a coarse level left out, the target met on two levels",
            job: point(
                &physical("mineral-oil-a", 100.0, 2.0, 12.0, 0.02, 4.0),
                Setup::Rule,
                7,
                None,
            ),
            took_its_path: |o| {
                o.solved().is_some_and(|s| {
                    s.level == 7
                        && s.errors.as_ref().is_some_and(|e| {
                            e.stopped == Some(LadderStop::OutsideAtBase { level: 5 })
                        })
                })
            },
        },
    ];
    // The paths the parameters choose.
    assert!(params(&probes[3].job).nested, "the chain probe is nested");
    assert_eq!(params(&probes[4].job).edge, Edge::Zero, "the paper's edge");
    assert!(params(&probes[5].job).patch.is_some(), "the patch probe");
    probes
}

/// The line probes: the five line contacts of Fig. 7 (Table 3) at its level (at level 6 the
/// film of line contact 1 closes; the 1-D solves cost milliseconds at any level).
fn line_probes() -> Vec<Probe> {
    table3_jobs(LINE_LEVEL)
        .expect("cases/fig7.toml")
        .into_iter()
        .map(|(j, _)| Probe {
            name: "line: a Table 3 line contact",
            job: j.job,
            took_its_path: solved,
        })
        .collect()
}

/// Each probe's outcome, solved as a target solves its jobs (no cache).
fn solve(probes: &[Probe]) -> Vec<CaseOutcome> {
    let jobs: Vec<Job> = probes.iter().map(|p| p.job.clone()).collect();
    run_jobs("revision", &jobs, CachePolicy::Ignore, &|_| {}, &|_| {})
        .expect("the probes run")
        .into_iter()
        .map(|d| d.outcome)
        .collect()
}

/// A part of the results and the revisions that answer for it.
struct Part {
    name: &'static str,
    revisions: String,
    /// Each probe's digest, by its short name.
    digests: BTreeMap<String, String>,
    /// Where to raise a revision when the digests move.
    raise: &'static str,
}

/// The SHA-256 of the result `value` holds (its JSON without the wall times).
fn digest<T: Serialize>(value: &T) -> String {
    let json = serde_json::to_string(value).expect("serialisable");
    let result = result_of(&json).expect("JSON");
    sha256_hex(result.to_string().as_bytes())
}

/// The point outcome without its thermal post-process.
fn isothermal(o: &CaseOutcome) -> CaseOutcome {
    match o {
        CaseOutcome::Solved(s) => {
            let mut isothermal = s.clone();
            isothermal.thermal = Vec::new();
            isothermal.thermal_failure = None;
            CaseOutcome::Solved(isothermal)
        }
        failed => failed.clone(),
    }
}

/// The short name of probe `i` (the words before its colon, numbered for the line probes).
fn short(p: &Probe, i: usize) -> String {
    let word = p.name.split(':').next().unwrap_or(p.name);
    if word == "line" {
        format!("line-{}", i + 1)
    } else {
        word.to_string()
    }
}

/// The parts' digests, from the probes solved now.
fn parts_now() -> Vec<Part> {
    let (points, lines) = (point_probes(), line_probes());
    let (po, lo) = (solve(&points), solve(&lines));
    for (p, o) in points.iter().chain(&lines).zip(po.iter().chain(&lo)) {
        assert!(
            (p.took_its_path)(o),
            "probe '{}' no longer takes its path: {o:?}",
            p.name
        );
    }
    let mut point = BTreeMap::new();
    let mut thermal = BTreeMap::new();
    for (i, (p, o)) in points.iter().zip(&po).enumerate() {
        point.insert(short(p, i), digest(&isothermal(o)));
        if let Some(s) = o.solved().filter(|s| !s.thermal.is_empty()) {
            thermal.insert(short(p, i), digest(&(&s.thermal, &s.thermal_failure)));
        }
    }
    let line = lines
        .iter()
        .zip(&lo)
        .enumerate()
        .map(|(i, (p, o))| (short(p, i), digest(o)))
        .collect();
    vec![
        Part {
            name: "point",
            revisions: SOLVER_REVISION.to_string(),
            digests: point,
            raise: "SOLVER_REVISION in src/solver/point/mod.rs",
        },
        Part {
            name: "thermal",
            revisions: format!("{SOLVER_REVISION} {THERMAL_REVISION}"),
            digests: thermal,
            raise: "THERMAL_REVISION in src/physics/thermal/mod.rs (or, where the point part \
                    moved too, SOLVER_REVISION alone)",
        },
        Part {
            name: "line",
            revisions: LINE_SOLVER_REVISION.to_string(),
            digests: line,
            raise: "SOLVER_REVISION in src/solver/line/mod.rs",
        },
    ]
}

/// The processor's arithmetic as the libraries' run-time dispatch sees it.
fn arithmetic() -> String {
    #[cfg(target_arch = "x86_64")]
    {
        let features = [
            ("avx2", is_x86_feature_detected!("avx2")),
            ("fma", is_x86_feature_detected!("fma")),
            ("avx512f", is_x86_feature_detected!("avx512f")),
        ];
        std::iter::once("x86_64")
            .chain(features.iter().filter(|f| f.1).map(|f| f.0))
            .collect::<Vec<_>>()
            .join(" ")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        std::env::consts::ARCH.to_string()
    }
}

/// One part's digests at its revisions on one arithmetic, as committed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Record {
    part: String,
    revisions: String,
    arithmetic: String,
    probes: BTreeMap<String, String>,
}

#[derive(Debug, Default, Serialize, Deserialize)]
struct Records {
    #[serde(default)]
    record: Vec<Record>,
}

fn records_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("snapshots/revisions.toml")
}

const HEADER: &str = "\
# The revision guard's digests (tests/revision.rs): the SHA-256 of each probe's cached outcome,
# per part of the results, at the revisions that answer for it, on the arithmetic it was made
# on. Written by `REPRO_RECORD_REVISIONS=1 cargo test --release --test integration revision`,
# which adds what is missing and never overwrites a digest of the present revisions.
";

#[test]
fn a_result_never_moves_under_the_same_revision() {
    let path = records_path();
    let mut records: Records = match std::fs::read_to_string(&path) {
        Ok(text) => toml::from_str(&text)
            .unwrap_or_else(|e| panic!("{}: not a revisions file: {e}", path.display())),
        Err(_) => Records::default(),
    };
    let record = std::env::var_os("REPRO_RECORD_REVISIONS").is_some();
    let arithmetic = arithmetic();
    let mut failures = Vec::new();
    let mut recorded = Vec::new();
    let parts = parts_now();
    let point_moved = |records: &Records| {
        records.record.iter().any(|r| {
            r.part == "point"
                && r.revisions == parts[0].revisions
                && r.arithmetic == arithmetic
                && r.probes != parts[0].digests
        })
    };
    let point_moved = point_moved(&records);
    for part in &parts {
        let same = |r: &&Record| {
            r.part == part.name && r.revisions == part.revisions && r.arithmetic == arithmetic
        };
        match records.record.iter().find(same) {
            Some(r) if r.probes == part.digests => {}
            Some(r) => {
                let moved: Vec<&str> = part
                    .digests
                    .iter()
                    .filter(|(k, v)| r.probes.get(*k) != Some(v))
                    .map(|(k, _)| k.as_str())
                    .collect();
                let raise = if part.name == "thermal" && point_moved {
                    "SOLVER_REVISION in src/solver/point/mod.rs (the point part moved: the \
                     thermal digests follow it)"
                } else {
                    part.raise
                };
                failures.push(format!(
                    "the {} results moved under the same revisions '{}' (probes: {}): raise \
                     {raise}, then record the new digests with `{RECORD}`",
                    part.name,
                    part.revisions,
                    moved.join(", ")
                ));
            }
            None if record => {
                // The part's records of older revisions on this arithmetic are history (git).
                records.record.retain(|r| {
                    !(r.part == part.name
                        && r.arithmetic == arithmetic
                        && r.revisions != part.revisions)
                });
                records.record.push(Record {
                    part: part.name.into(),
                    revisions: part.revisions.clone(),
                    arithmetic: arithmetic.clone(),
                    probes: part.digests.clone(),
                });
                recorded.push(format!("{} at '{}'", part.name, part.revisions));
            }
            None => failures.push(format!(
                "no digests of the {} results at revisions '{}' on '{arithmetic}' in {}: a \
                 revision was raised, or this is a new kind of processor; record them with \
                 `{RECORD}`",
                part.name,
                part.revisions,
                path.display()
            )),
        }
    }
    if !recorded.is_empty() {
        records
            .record
            .sort_by(|a, b| (&a.part, &a.arithmetic).cmp(&(&b.part, &b.arithmetic)));
        let text = toml::to_string(&records).expect("records serialise");
        std::fs::write(&path, format!("{HEADER}\n{text}")).expect("write the revisions file");
        eprintln!("recorded {} in {}", recorded.join(", "), path.display());
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
