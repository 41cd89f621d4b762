//! One rule from a case to its solver parameters (issue 29): a contact solved by `repro
//! solve`, `repro predict --solve`, a one-point study (`repro run FILE`) and the accuracy
//! study's pipeline gives the same bits in every one of them.
//!
//! Level 5 (64 x 64): every path takes the level it is given, so a path with parameters of its
//! own shows at any level (before the rule, `repro predict --solve` on the paper's domain did
//! not even converge on the 5P4E contact at level 5), and at level 5 each solve takes at most
//! a second or two (the 5P4E contact needs the Newton-Krylov finish), so the seven solves
//! stay within seconds. Outputs are compared exactly (`f64::to_bits`): the
//! same parameters on the same problem are the same arithmetic, and the JSON and the cache
//! print floats in shortest round-trip form, so any difference is a different path.

use crate::support::{repro, repro_in, scratch};
use repro::paper::accuracy::cases::{
    accuracy_cases, pipeline_params, AccuracyProblem, LevelOutputs,
};
use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::pipeline::cache::{Cache, Lookup};
use repro::pipeline::job::point_jobs;
use repro::pipeline::outcome::{CaseOutcome, SolvedCase};
use repro::pipeline::sweep::Sweep;
use std::path::Path;

/// The level the paths are compared at: cheap. The 5P4E contacts (on their nested chain)
/// miss the rule's 1 % in friction there and every path refines them to level 6 alike; the
/// accuracy study measures a level as it is, so it is compared with `repro solve
/// --exact-level`, which stays on it.
const LEVEL: u32 = 5;

/// The light Barus case's: it meets the 1 % friction target at level 7 (0.68 %); at levels 5
/// and 6 the rule refines it one level, which the accuracy study's point does not.
const LIGHT_LEVEL: u32 = 7;

/// The 5P4E contact of issue 29 (M about 4.8: a light case, whose domain is not the paper's):
/// Table 1's 5P4E at 40 C, 1 GPa, 12 m/s, S 0.5 %, tau0 6 MPa, on the default ball (Rx
/// 1.03875e-2 m, circular, E' 226 GPa), physics of Figs. 4-7.
const FLAGS_5P4E: [&str; 12] = [
    "--lubricant",
    "5p4e",
    "--temperature",
    "40",
    "--ph",
    "1e9",
    "--um",
    "12",
    "--slip",
    "0.005",
    "--tau0",
    "6e6",
];

/// The same contact as a study file.
const STUDY_5P4E: &str = r#"title = "one rule, 5P4E"
[physics]
viscosity = "roelands"
density = "dowson-higginson"
rheology = "eyring"
[[point]]
lubricant = "5p4e"
temperature_c = 40.0
ph_gpa = 1.0
um_m_s = 12.0
slip = 0.005
tau0_mpa = 6.0
rx_m = 1.03875e-2
d = 1.0
e_prime_gpa = 226.0
"#;

/// The accuracy study's `light-barus` case, a Figs. 1-3 style light case (M 50, L 10, S-bar
/// 0.1, tau0_hat 2 so S = 0.2; Barus, incompressible, Eyring), as flags of `repro solve`.
const FLAGS_LIGHT: [&str; 14] = [
    "--m",
    "50",
    "--l",
    "10",
    "--s-bar",
    "0.1",
    "--slip",
    "0.2",
    "--viscosity",
    "barus",
    "--density",
    "incompressible",
    "--rheology",
    "eyring",
];

/// The same case as a study file (as `cases/fig1-3.toml` writes it).
const STUDY_LIGHT: &str = r#"title = "one rule, light Barus"
[physics]
viscosity = "barus"
density = "incompressible"
rheology = "eyring"
[[point]]
m = 50.0
l = 10.0
s_bar = 0.1
tau0_hat = 2.0
"#;

/// What the paths are compared on: central and minimum film (`H = h/c` and Moes) and sliding
/// `mu-bar`, equal when their bits are (`f64::to_bits`; printed as numbers when not).
#[derive(Debug, Clone, Copy)]
struct Outputs {
    h_central: f64,
    hc_moes: Option<f64>,
    hmin_moes: Option<f64>,
    mu_bar_sliding: f64,
}

impl PartialEq for Outputs {
    fn eq(&self, o: &Self) -> bool {
        let bits = |v: Option<f64>| v.map(f64::to_bits);
        self.h_central.to_bits() == o.h_central.to_bits()
            && bits(self.hc_moes) == bits(o.hc_moes)
            && bits(self.hmin_moes) == bits(o.hmin_moes)
            && self.mu_bar_sliding.to_bits() == o.mu_bar_sliding.to_bits()
    }
}

impl Outputs {
    fn of_json(v: &serde_json::Value, what: &str) -> Self {
        let f = |k: &str| {
            v[k].as_f64()
                .unwrap_or_else(|| panic!("{what}: no {k} in {v}"))
        };
        Outputs {
            h_central: f("h_central"),
            hc_moes: Some(f("hc_moes")),
            hmin_moes: Some(f("hmin_moes")),
            mu_bar_sliding: f("mu_bar_sliding"),
        }
    }

    fn of_record(r: &SolvedCase) -> Self {
        Outputs {
            h_central: r.h_central,
            hc_moes: Some(r.hc_moes),
            hmin_moes: Some(r.hmin_moes),
            mu_bar_sliding: r.mu_bar_sliding,
        }
    }

    /// The fields compared with the accuracy study: the central film and sliding `mu-bar`
    /// (it has the minimum film in `H`, not in Moes units).
    fn of_measured(m: &LevelOutputs) -> Self {
        Outputs {
            h_central: m.h_central,
            hc_moes: None,
            hmin_moes: None,
            mu_bar_sliding: m.mu_bar,
        }
    }

    /// The fields the accuracy study has.
    fn measured_part(&self) -> Self {
        Outputs {
            hc_moes: None,
            hmin_moes: None,
            ..*self
        }
    }
}

/// `repro solve FLAGS --level 5 --json`.
fn solve(flags: &[&str]) -> Outputs {
    solve_at(flags, LEVEL)
}

/// `repro solve FLAGS --level LEVEL --json`.
fn solve_at(flags: &[&str], level: u32) -> Outputs {
    let level = level.to_string();
    let mut args = vec!["solve"];
    args.extend(flags);
    solve_args(args, &level)
}

/// `repro solve [--cold] FLAGS --exact-level --level 5 --json`: the level alone, warm or
/// from the Hertzian pressure.
fn solve_exact(flags: &[&str], cold: bool) -> Outputs {
    let level = LEVEL.to_string();
    let mut args = vec!["solve", "--exact-level"];
    if cold {
        args.push("--cold");
    }
    args.extend(flags);
    solve_args(args, &level)
}

fn solve_args<'a>(mut args: Vec<&'a str>, level: &'a str) -> Outputs {
    args.extend(["--level", level, "--json", "-q"]);
    let (code, out, err) = repro(&args);
    assert_eq!(code, 0, "repro solve: {err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
    Outputs::of_json(&v, "repro solve")
}

/// `repro predict FLAGS --solve --level 5 --json`: its `solve` object.
fn predict(flags: &[&str]) -> Outputs {
    let level = LEVEL.to_string();
    let mut args = vec!["predict"];
    args.extend(flags);
    args.extend(["--solve", "--level", &level, "--json", "-q"]);
    let (code, out, err) = repro(&args);
    assert_eq!(code, 0, "repro predict --solve: {out}{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
    Outputs::of_json(&v["solve"], "repro predict --solve")
}

/// `repro run FILE --level 5` of a one-point study, read back from its cache entry (the
/// CSV rounds to 7 digits; the entry holds the record's full bits).
fn study(name: &str, text: &str) -> Outputs {
    study_at(name, text, LEVEL)
}

/// [`study`] at `level`.
fn study_at(name: &str, text: &str, level: u32) -> Outputs {
    let dir = scratch("one_rule", name);
    let file = dir.join(format!("{name}.toml"));
    std::fs::write(&file, text).expect("write the study");
    let level_flag = level.to_string();
    let (code, out, err) = repro_in(
        Path::new(env!("CARGO_MANIFEST_DIR")),
        &[
            "run",
            file.to_str().expect("utf-8 path"),
            "--level",
            &level_flag,
            "--cache",
            dir.join("cache").to_str().expect("utf-8 path"),
            "--out",
            dir.join("out").to_str().expect("utf-8 path"),
            "-q",
        ],
    );
    assert_eq!(code, 0, "repro run: {out}{err}");
    let cache = Cache::new(dir.join("cache"));
    // The point's own entry (a point that is not its own base has its base's entry beside it).
    let sweep = Sweep::parse("one-rule.toml", text).expect("a valid study");
    let job = point_jobs(&sweep.cases, level)
        .expect("the study's job")
        .remove(0)
        .job;
    let keys = cache.keys().expect("the study's cache");
    let entries = if job.base.is_some() { 2 } else { 1 };
    assert_eq!(keys.len(), entries, "its entry and its base's: {keys:?}");
    let bits = match cache.get::<CaseOutcome>(&job.key) {
        Lookup::Hit(CaseOutcome::Solved(r), _) => Outputs::of_record(&r),
        other => panic!("repro run: {other:?}"),
    };
    let _ = std::fs::remove_dir_all(&dir);
    bits
}

/// The accuracy study's pipeline ([`pipeline_params`]) on `contact` at level 5.
fn accuracy(contact: &AccuracyProblem) -> Outputs {
    accuracy_at(contact, LEVEL)
}

/// [`accuracy`] at `level`.
fn accuracy_at(contact: &AccuracyProblem, level: u32) -> Outputs {
    Outputs::of_measured(
        &contact
            .solve(level)
            .expect("the accuracy pipeline converges"),
    )
}

#[test]
fn every_path_solves_the_5p4e_contact_alike() {
    let by_solve = solve(&FLAGS_5P4E);
    let by_predict = predict(&FLAGS_5P4E);
    let by_study = study("5p4e", STUDY_5P4E);
    let sweep = Sweep::parse("one-rule.toml", STUDY_5P4E).expect("a valid study");
    let problem =
        Problem::from_case(&sweep.cases[0], &LubricantTable::table1()).expect("a valid case");
    assert!(problem.groups.m < 10.0, "M = {}", problem.groups.m);
    let by_accuracy = accuracy(&AccuracyProblem::Point {
        problem: Box::new(problem),
        params: pipeline_params,
    });
    assert_eq!(by_predict, by_solve, "repro predict --solve vs repro solve");
    assert_eq!(by_study, by_solve, "repro run vs repro solve");
    assert_eq!(
        by_accuracy,
        solve_exact(&FLAGS_5P4E, false).measured_part(),
        "accuracy pipeline vs repro solve --exact-level"
    );
}

#[test]
fn every_path_solves_the_light_barus_case_alike() {
    // `repro predict` takes the physical form only: this case goes through the other paths.
    let by_solve = solve_at(&FLAGS_LIGHT, LIGHT_LEVEL);
    let by_study = study_at("light", STUDY_LIGHT, LIGHT_LEVEL);
    let cases = accuracy_cases(false).expect("the accuracy study's cases");
    let light = cases
        .iter()
        .find(|c| c.name == "light-barus")
        .expect("the accuracy study has light-barus");
    let by_accuracy = accuracy_at(&light.contact, LIGHT_LEVEL);
    assert_eq!(by_study, by_solve, "repro run vs repro solve");
    assert_eq!(
        by_accuracy,
        by_solve.measured_part(),
        "accuracy study (light-barus) vs repro solve"
    );
}

/// The 5P4E contact of the first test at S 2 % and tau0 4 MPa: a member of its family, not
/// its base, so every path solves the base (S 0.5 %, tau0 6 MPa) first and the contact from
/// it (issue 30); the accuracy study measures the cold solve, which `repro solve --cold` is.
fn member_flags() -> Vec<&'static str> {
    let mut flags = FLAGS_5P4E.to_vec();
    for (flag, value) in [("--slip", "0.02"), ("--tau0", "4e6")] {
        let at = flags.iter().position(|f| *f == flag).expect("the flag") + 1;
        flags[at] = value;
    }
    flags
}

#[test]
fn every_path_starts_a_family_member_from_its_base_alike() {
    let member = STUDY_5P4E
        .replace("slip = 0.005", "slip = 0.02")
        .replace("tau0_mpa = 6.0", "tau0_mpa = 4.0");
    let flags = member_flags();
    let by_solve = solve(&flags);
    let by_predict = predict(&flags);
    let by_study = study("member", &member);
    assert_eq!(by_predict, by_solve, "repro predict --solve vs repro solve");
    assert_eq!(by_study, by_solve, "repro run vs repro solve");
    let sweep = Sweep::parse("one-rule.toml", &member).expect("a valid study");
    let problem =
        Problem::from_case(&sweep.cases[0], &LubricantTable::table1()).expect("a valid case");
    let by_accuracy = accuracy(&AccuracyProblem::Point {
        problem: Box::new(problem),
        params: pipeline_params,
    });
    let cold = solve_exact(&flags, true);
    assert_eq!(
        by_accuracy,
        cold.measured_part(),
        "accuracy study vs repro solve --cold --exact-level"
    );
    // Warm and cold are two converged solves of one contact at one level: within the stopping
    // rule's bound on the algebraic error of each (5e-4 relative, `OUTPUT_TOLERANCE`), twice.
    let warm = solve_exact(&flags, false);
    let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-3;
    assert!(
        close(warm.h_central, cold.h_central) && close(warm.mu_bar_sliding, cold.mu_bar_sliding),
        "warm {warm:?} vs cold {cold:?}"
    );
}

#[test]
fn the_papers_setup_beside_fig6_differs_from_the_rule_in_edge_domain_and_region_alone() {
    use repro::pipeline::job::{point_jobs_in, Setup};
    use repro::solver::grid::Domain;
    use repro::solver::point::{Edge, FrictionRegion};
    let sweep = repro::paper::cases::shipped_sweep("fig6").unwrap();
    // Case 23 (M 4.76): the rule puts it on a wide domain with the far field.
    let case = sweep.cases[22].clone();
    let rule = &point_jobs(std::slice::from_ref(&case), 7).unwrap()[0];
    let paper = &point_jobs_in(std::slice::from_ref(&case), 7, Setup::Paper).unwrap()[0];
    // The rule's jobs are the ones every other path builds (same key), the paper's setup
    // has a key of its own (its solves never stand in for the rule's in the cache).
    assert_eq!(
        rule.job.key,
        point_jobs_in(std::slice::from_ref(&case), 7, Setup::Rule).unwrap()[0]
            .job
            .key
    );
    assert_ne!(rule.job.key, paper.job.key);
    assert_ne!(rule.params.domain, Domain::default());
    assert_eq!(paper.params.domain, Domain::default());
    assert_eq!(paper.params.edge, Edge::Zero);
    assert_eq!(paper.params.friction.region, FrictionRegion::Domain);
    // Nothing else differs.
    let back = {
        let mut params = paper.params.clone();
        params.domain = rule.params.domain;
        params.edge = Edge::FarField;
        params.friction.region = FrictionRegion::LoadedFilm;
        params
    };
    assert_eq!(back, rule.params);
}
