//! Cost of the thermal post-process: one physical case of Figs. 4-6 solved once (at the level
//! given, no target, no error ladder), then its thermal correction for both solids of
//! [`TARGET_INPUTS`] (what every figure row computes) timed, the best of `REPS` (default 7).
//! Prints the time and the outputs, whose bits show whether a change kept them.
//!
//! `cargo run --release --example thermal_probe -- LUBRICANT T PH_GPA UM SLIP LEVEL`
//! (tau0 8 MPa), e.g. `-- mineral-oil-a 40 3 2 0.02 8`.
use repro::physics::case::{Case, CaseForm, LubricantSpec, PhysicalCase, Physics, Problem};
use repro::physics::lubricant::LubricantTable;
use repro::physics::thermal::{ThermalContact, TARGET_INPUTS};
use repro::solver::point::{self, Params};
use repro::solver::thermal::point_thermal;
use std::time::Instant;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    if a.len() != 7 {
        eprintln!("usage: thermal_probe LUBRICANT T PH_GPA UM SLIP LEVEL");
        std::process::exit(2);
    }
    let f = |i: usize| a[i].parse::<f64>().expect("a number");
    let level: u32 = a[6].parse().expect("a level");
    let reps: usize = std::env::var("REPS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(7);
    let physical = PhysicalCase {
        lubricant: LubricantSpec::Named {
            lubricant: a[1].clone(),
            temperature_c: f(2),
        },
        ph_pa: f(3) * 1e9,
        um_m_s: f(4),
        slip: f(5),
        tau0_pa: 8e6,
        rx_m: 1.03875e-2,
        ry_m: 1.03875e-2,
        e_prime_pa: 226e9,
    };
    let case = Case {
        spec: CaseForm::Physical(physical.clone()),
        physics: Physics::figs_4_to_7(),
    };
    let lubricants = LubricantTable::table1();
    let problem = Problem::from_case(&case, &lubricants).expect("the case");
    let mut params = Params::for_problem(&problem, level);
    params.accuracy.target = None;
    params.accuracy.error_levels = 0;
    let s = point::solve(&problem, &params, None).expect("the solve");
    let contact = ThermalContact::of_point(&physical, &problem, &lubricants).expect("a contact");
    let mut best = f64::INFINITY;
    let mut out = Vec::new();
    for _ in 0..reps {
        let t = Instant::now();
        out = TARGET_INPUTS
            .iter()
            .map(|i| point_thermal(&s, &problem, &contact, i).expect("the thermal pass"))
            .collect();
        best = best.min(t.elapsed().as_secs_f64());
    }
    println!(
        "level {}: thermal post-process (both solids) best of {reps}: {best:.4} s",
        s.info.level
    );
    for t in &out {
        println!(
            "  k {} W/mK: mu-bar {:e}, mid-plane {:e}, flash {:e} K",
            t.k_solid_w_mk, t.mu_bar_sliding, t.mu_bar_sliding_midplane, t.dt_flash_max_k
        );
    }
}
