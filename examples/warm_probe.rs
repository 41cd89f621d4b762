//! Continuation probe (issue 30): one family of Figs. 4-6 (a lubricant at a temperature,
//! p_H and u_m; its nine slip x Eyring-stress members), each member solved cold and warm from
//! the family's base (S 0.5 %, tau0 6 MPa), with the times and the warm-cold differences.
//!
//! `cargo run --release --example warm_probe -- LUBRICANT T PH_GPA UM LEVEL [TIGHT]`, or
//! `-- moes M L LEVEL [TIGHT]` for a Figs. 1-3 family (S-bar 0.01-1 at tau0_hat 2 from its
//! base at S-bar 0.1; Barus, incompressible, Eyring);
//! `TIGHT` 1 solves the cold members with the output rule off (to a mean residual of 1e-6,
//! or by Newton-Krylov), the reference a warm solve is judged against.
use repro::physics::case::{
    Case, CaseForm, DimensionlessCase, LubricantSpec, PhysicalCase, Physics, Problem,
};
use repro::physics::lubricant::LubricantTable;
use repro::pipeline::base::base_of;
use repro::solver::point::{self, Params, Start};
use std::time::Instant;

fn case(lubricant: &str, t: f64, ph: f64, um: f64, slip: f64, tau0: f64) -> Case {
    Case {
        spec: CaseForm::Physical(PhysicalCase {
            lubricant: LubricantSpec::Named {
                lubricant: lubricant.into(),
                temperature_c: t,
            },
            ph_pa: ph * 1e9,
            um_m_s: um,
            slip,
            tau0_pa: tau0,
            rx_m: 1.03875e-2,
            ry_m: 1.03875e-2,
            e_prime_pa: 226e9,
        }),
        physics: Physics::figs_4_to_7(),
    }
}

fn moes(m: f64, l: f64, s_bar: f64) -> Case {
    Case {
        spec: CaseForm::Dimensionless(DimensionlessCase {
            m,
            l,
            s_bar,
            d: 1.0,
            slip: 2.0 * s_bar,
            eta0_pa_s: None,
            ph_pa: None,
        }),
        physics: Physics::default(),
    }
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let f = |i: usize| a[i].parse::<f64>().unwrap();
    let members: Vec<Case>;
    let (level, tight) = if a[1] == "moes" {
        members = [0.01, 0.03, 0.1, 0.3, 1.0]
            .iter()
            .map(|&sb| moes(f(2), f(3), sb))
            .collect();
        (f(4) as u32, a.get(5).is_some_and(|v| v == "1"))
    } else {
        let (lub, t, ph, um) = (&a[1], f(2), f(3), f(4));
        members = [0.001, 0.005, 0.02]
            .iter()
            .flat_map(|&slip| [4e6, 6e6, 8e6].map(|tau0| case(lub, t, ph, um, slip, tau0)))
            .collect();
        (f(5) as u32, a.get(6).is_some_and(|v| v == "1"))
    };
    let table = LubricantTable::table1();
    let problem_of = |c: &Case| Problem::from_case(c, &table).unwrap();
    let base = base_of(&members[0]).unwrap();
    let bp = problem_of(&base);
    let clock = Instant::now();
    let bs = point::solve(&bp, &Params::for_problem(&bp, level), None).unwrap();
    let base_s = clock.elapsed().as_secs_f64();
    let start = Start::of(&bs);
    println!(
        "base M {:.1} L {:.2}: {:?} level {} cycles {} newton {} residual {:.2e}, {base_s:.2} s",
        bp.groups.m,
        bp.groups.l,
        bs.info.method,
        bs.info.level,
        bs.info.cycles,
        bs.info.newton_steps,
        bs.info.residual()
    );
    let (mut cold_total, mut warm_total) = (base_s, base_s);
    for c in &members {
        {
            let p = problem_of(c);
            let (slip, tau0) = (p.groups.slip, p.groups.s_bar);
            let mut params = Params::for_problem(&p, level);
            if tight {
                params.stopping.output_tolerance = 0.0;
            }
            let clock = Instant::now();
            let cold = point::solve(&p, &params, None);
            let cold_s = clock.elapsed().as_secs_f64();
            let params = Params::for_problem(&p, level);
            let clock = Instant::now();
            let warm = point::solve_from(&p, &params, &start, None);
            let warm_s = clock.elapsed().as_secs_f64();
            cold_total += cold_s;
            warm_total += warm_s;
            match (cold, warm) {
                (Ok(c), Ok(w)) => {
                    let d = |a: f64, b: f64| (a - b).abs() / b.abs();
                    println!(
                        "S {slip} S-bar {:.3}: cold {:?} {}c+{}n {cold_s:.2} s | warm {:?} {:?} {}c+{}n {warm_s:.2} s | dHc {:.1e} dHmin {:.1e} dmu {:.1e} dmu_r {:.1e}",
                        tau0,
                        c.info.method,
                        c.info.cycles,
                        c.info.newton_steps,
                        w.info.start,
                        w.info.method,
                        w.info.cycles,
                        w.info.newton_steps,
                        d(w.film.h_central, c.film.h_central),
                        d(w.film.h_min, c.film.h_min),
                        d(w.friction.sliding, c.friction.sliding),
                        d(
                            w.friction.rolling.unwrap_or(0.0),
                            c.friction.rolling.unwrap_or(1.0)
                        ),
                    )
                }
                (c, w) => println!(
                    "S {slip} tau0 {tau0}: cold {:?} warm {:?}",
                    c.map(|s| s.film.h_central),
                    w.map(|s| s.film.h_central)
                ),
            }
        }
    }
    println!(
        "family: cold {cold_total:.2} s (base counted once), warm {warm_total:.2} s (base + 9 warm), ratio {:.2}",
        cold_total / warm_total
    );
}
