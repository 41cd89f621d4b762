//! Criterion benchmarks: the speed cases (Table 4 at levels 6-8, the Newtonian M = 20, L = 10
//! contact at 7 and 8), the 5P4E hard case at level 7 (Newton-Krylov), one point-contact
//! solve per level for the cases of the accuracy study (`repro accuracy`), the cost of each
//! optional physical effect on the Table 4 case, and one whole small target.
//!
//! `cargo bench` runs everything (levels 5-7; level 8 is measured by `repro accuracy` only,
//! a sample of ten level-8 solves would take minutes). Under `cargo test --all-targets` the
//! harness runs each benchmark once as a smoke test; there only the level-5 solves, the
//! effects at level 4 and a level-4 target run, so that the test run stays within seconds (the full set would take a
//! minute of single solves).

use criterion::{BenchmarkId, Criterion};
use repro::paper::accuracy::cases::{accuracy_cases, AccuracyProblem};
use repro::paper::build;
use repro::paper::figures::FIG7;
use repro::physics::case::{Case, CaseForm, LubricantSpec, PhysicalCase, Physics, Problem};
use repro::physics::density::DensityLaw;
use repro::physics::lubricant::LubricantTable;
use repro::physics::rheology::Rheology;
use repro::physics::viscosity::ViscosityLaw;
use repro::pipeline::context::Context;
use repro::solver::point::{solve, Params};
use std::time::Duration;

/// True under `cargo bench` (the harness is given `--bench`); false in test mode.
fn full() -> bool {
    std::env::args().any(|a| a == "--bench")
}

fn levels(c: &mut Criterion) {
    let cases = accuracy_cases(false).expect("the shipped cases resolve");
    let levels: &[u32] = if full() { &[5, 6, 7] } else { &[5] };
    let mut group = c.benchmark_group("solve");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(20));
    for case in &cases {
        for &level in levels {
            // The study's cases that fail at a level (a film that collapses on a coarse grid)
            // are not timed there: a failure is not a cost.
            if case.contact.solve(level).is_err() {
                continue;
            }
            group.bench_with_input(BenchmarkId::new(case.name, level), &level, |b, &l| {
                b.iter(|| case.contact.solve(l))
            });
        }
    }
    group.finish();
}

/// The Table 4 case with one effect swapped for its cheaper alternative.
fn effects(c: &mut Criterion) {
    let cases = accuracy_cases(false).expect("the shipped cases resolve");
    let Some(AccuracyProblem::Point { problem, .. }) = cases
        .iter()
        .find(|c| c.name == "table4")
        .map(|c| &c.contact)
    else {
        panic!("the study has the Table 4 case");
    };
    let base: &Problem = problem;
    let level = if full() { 6 } else { 4 };
    let with = |physics: Physics| -> Problem {
        let mut p = base.clone();
        let g = p.groups;
        p.viscosity = match physics.viscosity {
            ViscosityLaw::Barus => repro::physics::viscosity::Viscosity::barus(g.alpha_bar),
            ViscosityLaw::Roelands => base.viscosity,
        };
        p.density = match physics.density {
            DensityLaw::Incompressible => repro::physics::density::Density::Incompressible,
            DensityLaw::DowsonHigginson => base.density,
        };
        p.rheology = physics.rheology;
        p
    };
    let full_physics = Physics::figs_4_to_7();
    let variants = [
        ("roelands-dh-eyring", with(full_physics), true),
        (
            "barus",
            with(Physics {
                viscosity: ViscosityLaw::Barus,
                ..full_physics
            }),
            true,
        ),
        (
            "incompressible",
            with(Physics {
                density: DensityLaw::Incompressible,
                ..full_physics
            }),
            true,
        ),
        (
            "newtonian",
            with(Physics {
                rheology: Rheology::Newtonian,
                ..full_physics
            }),
            true,
        ),
        ("no-rolling", with(full_physics), false),
    ];
    let mut group = c.benchmark_group(format!("effects-level{level}"));
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(15));
    for (name, problem, rolling) in &variants {
        let params = {
            let mut params = Params::for_problem(problem, level);
            params.friction.rolling = *rolling;
            params.accuracy.require_positive_film = false;
            params
        };
        if solve(problem, &params, None).is_err() {
            eprintln!("effects: {name} does not converge at level {level}; not timed");
            continue;
        }
        group.bench_function(*name, |b| b.iter(|| solve(problem, &params, None)));
    }
    group.finish();
}

/// A whole target, cold (no cache): Fig. 7's ten elliptical cases and five line contacts, in parallel as `repro fig7`
/// runs them, files written to a temporary folder.
fn target(c: &mut Criterion) {
    let level = if full() { 5 } else { 4 };
    let out = std::env::temp_dir().join(format!("repro-bench-{}", std::process::id()));
    let progress = |_: &str, _: repro::pipeline::executor::RunProgress| {};
    let warn = |_: String| {};
    let ctx = Context {
        out: out.clone(),
        cache: None,
        level: Some(level),
        progress: &progress,
        warn: &warn,
        stride: 1,
        offline: false,
        stop: None,
    };
    let mut group = c.benchmark_group("target");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(30));
    group.bench_function(format!("fig7-level{level}-cold"), |b| {
        b.iter(|| build(&FIG7, &ctx).expect("fig7 builds"))
    });
    group.finish();
    let _ = std::fs::remove_dir_all(out);
}

/// The hardest case of the paper's range: 5P4E at 40 C, 3 GPa, 7 m/s, S = 0.5 %,
/// tau0 = 6 MPa (M = 192, L = 49.9, alpha-bar = 105), whose cycles diverge at level 7 and
/// which the grid-sequenced Newton-Krylov finish converges (level 5 in test mode).
fn hard_case(c: &mut Criterion) {
    let rx = 1.03875e-2;
    let case = Case {
        spec: CaseForm::Physical(PhysicalCase {
            lubricant: LubricantSpec::Named {
                lubricant: "5p4e".into(),
                temperature_c: 40.0,
            },
            ph_pa: 3e9,
            um_m_s: 7.0,
            slip: 0.005,
            tau0_pa: 6e6,
            rx_m: rx,
            ry_m: rx,
            e_prime_pa: 226e9,
        }),
        physics: Physics::figs_4_to_7(),
    };
    let problem = Problem::from_case(&case, &LubricantTable::table1()).expect("valid case");
    let level = if full() { 7 } else { 5 };
    let params = Params::for_problem(&problem, level);
    let mut group = c.benchmark_group("hard-case");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(60));
    group.bench_function(format!("5p4e-40c-3gpa-level{level}"), |b| {
        b.iter(|| solve(&problem, &params, None).expect("the hard case converges"))
    });
    group.finish();
}

/// The speed targets of the solver: the Table 4 case at levels 6, 7 and 8 (Table 4's own
/// parameters: the figures' defaults) and the Newtonian M = 20, L = 10 rolling contact
/// (Barus, incompressible: the case of the Venner-Lubrecht FMG code) at levels 7 and 8.
fn speed(c: &mut Criterion) {
    let table4 = repro::paper::table4::Table4Case::shipped()
        .expect("cases/table4.toml")
        .problem()
        .expect("the Table 4 case resolves");
    let newtonian = Problem::from_case(
        &Case {
            spec: CaseForm::Dimensionless(repro::physics::case::DimensionlessCase {
                m: 20.0,
                l: 10.0,
                s_bar: 0.0,
                d: 1.0,
                slip: 0.0,
                eta0_pa_s: None,
                ph_pa: None,
            }),
            physics: Physics {
                viscosity: ViscosityLaw::Barus,
                density: DensityLaw::Incompressible,
                rheology: Rheology::Newtonian,
            },
        },
        &LubricantTable::table1(),
    )
    .expect("valid case");
    let runs: Vec<(&str, &Problem, u32)> = if full() {
        vec![
            ("table4", &table4, 6),
            ("table4", &table4, 7),
            ("table4", &table4, 8),
            ("newtonian-m20-l10", &newtonian, 7),
            ("newtonian-m20-l10", &newtonian, 8),
        ]
    } else {
        vec![("table4", &table4, 5), ("newtonian-m20-l10", &newtonian, 5)]
    };
    let mut group = c.benchmark_group("speed");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(20));
    // The solve alone (the unit the README's times are given in), without the coarser levels
    // of its error estimate; the product's solve with them as `table4-estimated`.
    for (name, problem, level) in runs {
        let params = {
            let mut params = Params::for_problem(problem, level);
            params.accuracy.error_levels = 0;
            params
        };
        group.bench_with_input(BenchmarkId::new(name, level), &level, |b, _| {
            b.iter(|| solve(problem, &params, None).expect("the speed cases converge"))
        });
    }
    let level = if full() { 7 } else { 5 };
    let params = Params::for_problem(&table4, level);
    group.bench_with_input(
        BenchmarkId::new("table4-estimated", level),
        &level,
        |b, _| b.iter(|| solve(&table4, &params, None).expect("the speed cases converge")),
    );
    group.finish();
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    speed(&mut c);
    hard_case(&mut c);
    levels(&mut c);
    effects(&mut c);
    target(&mut c);
    c.final_summary();
}
