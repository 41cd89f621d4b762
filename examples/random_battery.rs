//! The seeded random battery of physical point contacts (docs/DOMAIN_NOTES.md): cases drawn
//! over the ranges an engineer meets, each solved at a level by the one rule
//! (`point::Params::for_problem`, with its automatic refinement of a closed film), one
//! markdown row per case.
//!
//! `cargo run --release --example random_battery -- [COUNT] [SEED] [LEVEL] [THREADS] [light]`
//! (default 40 cases, seed 29, level 7, 2 threads). The draws: `p_H` 0.3-4 GPa, `u_m`
//! 0.3-30 m/s, `eta0` 2 mPa s-1 Pa s, slip 3e-4-3e-2 and `tau0` 2-20 MPa log-uniform
//! (`light`: the light, viscous corner, `p_H` 0.3-0.6 GPa, `u_m` 3-30 m/s, `eta0` 0.1-1 Pa s);
//! `alpha` 8-40 /GPa and `D = Rx/Ry` 0.1-1 uniform; `Rx` 10.4 mm, `E'` 226 GPa; Roelands,
//! Dowson-Higginson, Eyring (the physics of Figs. 4-7).
use repro::physics::case::{
    Case, CaseForm as CaseSpec, LubricantSpec, PhysicalCase, Physics, Problem,
};
use repro::physics::lubricant::LubricantTable;
use repro::solver::point;
use std::sync::Mutex;

/// SplitMix64: a fixed, documented generator, so a seed names the same battery everywhere.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.next()).exp()
    }
}

fn draw(rng: &mut SplitMix, light: bool) -> PhysicalCase {
    let rx_m = 1.03875e-2;
    let (ph, um, eta0) = if light {
        ((0.3e9, 0.6e9), (3.0, 30.0), (0.1, 1.0))
    } else {
        ((0.3e9, 4e9), (0.3, 30.0), (2e-3, 1.0))
    };
    let ph_pa = rng.log_uniform(ph.0, ph.1);
    let um_m_s = rng.log_uniform(um.0, um.1);
    let alpha_per_pa = rng.uniform(8e-9, 40e-9);
    let eta0_pa_s = rng.log_uniform(eta0.0, eta0.1);
    let d = rng.uniform(0.1, 1.0);
    let slip = rng.log_uniform(3e-4, 3e-2);
    let tau0_pa = rng.log_uniform(2e6, 2e7);
    PhysicalCase {
        lubricant: LubricantSpec::Given {
            alpha_per_pa,
            eta0_pa_s,
        },
        ph_pa,
        um_m_s,
        slip,
        tau0_pa,
        rx_m,
        ry_m: rx_m / d,
        e_prime_pa: 226e9,
    }
}

fn row(i: usize, c: &PhysicalCase, level: u32) -> String {
    let case = Case {
        spec: CaseSpec::Physical(c.clone()),
        physics: Physics::figs_4_to_7(),
    };
    let problem = match Problem::from_case(&case, &LubricantTable::table1()) {
        Ok(p) => p,
        Err(e) => return format!("| {i} | invalid case: {e} |"),
    };
    let g = problem.groups;
    let LubricantSpec::Given {
        alpha_per_pa,
        eta0_pa_s,
    } = c.lubricant
    else {
        unreachable!("the battery draws given lubricants")
    };
    let head = format!(
        "| {i} | {:.3} | {:.2} | {:.4} | {:.1} | {:.3e} | {:.3} | {:.1} | {:.4} | {:.1} | {:.2} | {:.3} |",
        c.ph_pa / 1e9,
        c.um_m_s,
        eta0_pa_s,
        alpha_per_pa * 1e9,
        g.m,
        g.l,
        g.lambda,
        c.slip,
        c.tau0_pa / 1e6,
        g.d,
        problem.tau_c().log10(),
    );
    let params = point::Params::for_problem(&problem, level);
    let t = std::time::Instant::now();
    match point::solve(&problem, &params, None) {
        Ok(s) => format!(
            "{head} {} | {:?} | {:.4} | {:.4} | {:.4} | {:.2e} | {:.1} |",
            s.info.level,
            s.info.method,
            s.film.hc_moes,
            s.film.hmin_moes,
            s.friction.sliding,
            s.info.residual(),
            t.elapsed().as_secs_f64()
        ),
        Err(e) => {
            let first = e.to_string();
            let first = first.split(" (history").next().unwrap_or("");
            format!(
                "{head} failed | {first}; `repro solve --alpha {alpha_per_pa:e} --eta0 {eta0_pa_s:e} --ph {:e} --um {:e} --slip {:e} --tau0 {:e} --ry {:e}` | | | | | {:.1} |",
                c.ph_pa,
                c.um_m_s,
                c.slip,
                c.tau0_pa,
                c.ry_m,
                t.elapsed().as_secs_f64()
            )
        }
    }
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let arg = |i: usize, default: u64| a.get(i).map_or(default, |v| v.parse().unwrap());
    let (count, seed, level, threads) = (
        arg(1, 40) as usize,
        arg(2, 29),
        arg(3, 7) as u32,
        arg(4, 2) as usize,
    );
    let light = a.get(5).is_some_and(|v| v == "light");
    let mut rng = SplitMix(seed);
    let cases: Vec<PhysicalCase> = (0..count).map(|_| draw(&mut rng, light)).collect();
    println!(
        "| # | p_H GPa | u_m m/s | eta0 Pa s | alpha /GPa | M | L | lambda | S | tau0 MPa | Rx/Ry | log10 tau_c | level | method | Hc Moes | Hmin Moes | mu-bar sliding | residual | s |"
    );
    println!("|{}", "---|".repeat(19));
    let next = Mutex::new(0usize);
    let rows = Mutex::new(vec![String::new(); count]);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let i = {
                    let mut n = next.lock().unwrap();
                    *n += 1;
                    *n - 1
                };
                if i >= count {
                    break;
                }
                let r = row(i, &cases[i], level);
                eprintln!("{r}");
                rows.lock().unwrap()[i] = r;
            });
        }
    });
    for r in rows.into_inner().unwrap() {
        println!("{r}");
    }
}
