//! The domain study's probe (docs/DOMAIN_NOTES.md): one point-contact solve on a given
//! domain, with or without the far-field edge, and its sliding friction integrated over
//! several regions.
//!
//! `cargo run --release --example domain_probe -- d M L SBAR D LEVEL X0 X1 YH FAR` (Moes
//! groups, Barus, incompressible) or `-- p LUBRICANT T PH UM SLIP TAU0 LEVEL X0 X1 YH FAR`
//! (physical, the physics of Figs. 4-6); `FAR` is 1 for the far field, 2 for it with a fitted amplitude, 0 for `P = 0`;
//! `X0` `auto` (with any `X1 YH`) takes `Domain::for_far_field`, `auto2` that domain with
//! its inlet and sides doubled at the same mesh size (run it one level finer).
use repro::physics::case::*;
use repro::physics::lubricant::LubricantTable;
use repro::solver::grid::Domain;
use repro::solver::point;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let f = |i: usize| a[i].parse::<f64>().unwrap();
    let (case, k) = if a[1] == "d" {
        (
            Case {
                spec: CaseForm::Dimensionless(DimensionlessCase {
                    m: f(2),
                    l: f(3),
                    s_bar: f(4),
                    d: f(5),
                    slip: 0.01,
                    eta0_pa_s: None,
                    ph_pa: None,
                }),
                physics: Physics::default(),
            },
            6,
        )
    } else {
        (
            Case {
                spec: CaseForm::Physical(PhysicalCase {
                    lubricant: if a[2] == "given" {
                        // `given T` takes alpha (1/Pa) and eta0 (Pa s) from PROBE_ALPHA, PROBE_ETA0.
                        let env = |k: &str| std::env::var(k).unwrap().parse::<f64>().unwrap();
                        LubricantSpec::Given {
                            alpha_per_pa: env("PROBE_ALPHA"),
                            eta0_pa_s: env("PROBE_ETA0"),
                        }
                    } else {
                        LubricantSpec::Named {
                            lubricant: a[2].clone(),
                            temperature_c: f(3),
                        }
                    },
                    ph_pa: f(4),
                    um_m_s: f(5),
                    slip: f(6),
                    tau0_pa: f(7),
                    rx_m: 1.03875e-2,
                    ry_m: 1.03875e-2,
                    e_prime_pa: 226e9,
                }),
                physics: Physics::figs_4_to_7(),
            },
            8,
        )
    };
    let problem = Problem::from_case(&case, &LubricantTable::table1()).unwrap();
    // PROBE_RATIO overrides the rule's largest H0 / (m r^2) at the edge.
    let ratio = std::env::var("PROBE_RATIO")
        .ok()
        .map_or(repro::solver::grid::FAR_FIELD_GAP_RATIO, |v| {
            v.parse().unwrap()
        });
    // PROBE_SHARE bounds the far field's estimated share of the load outside.
    let share = std::env::var("PROBE_SHARE")
        .ok()
        .map_or(repro::solver::grid::FAR_FIELD_LOAD_SHARE, |v| {
            v.parse().unwrap()
        });
    let domain = if a[k + 1] == "auto" {
        Domain::for_far_field_with(&problem, ratio, share)
    } else if a[k + 1] == "auto2" {
        // The rule's domain with its inlet and side extents doubled at the same mesh size
        // (run it one level finer).
        Domain::for_far_field_with(&problem, ratio, share).doubled()
    } else {
        Domain {
            x_start: f(k + 1),
            x_end: f(k + 2),
            y_half: f(k + 3),
            y_centre: 0.0,
        }
    };
    let params = point::Params {
        domain,
        edge: match a[k + 4].as_str() {
            "0" => point::Edge::Zero,
            "1" => point::Edge::FarField,
            _ => point::Edge::FittedFarField,
        },
        ..point::Params::at_level(f(k) as u32)
    };
    let t = std::time::Instant::now();
    let verbose = std::env::var_os("PROBE_VERBOSE").is_some();
    let mut show = |p: &repro::solver::output::Progress| {
        if verbose {
            eprintln!(
                "  level {} {:?} {} res {:.2e} load {:.1e} dP {:.1e} Hc {:.5} worst at ({:.3}, {:.3})",
                p.level, p.step, p.count, p.residual, p.load_error, p.pressure_change, p.h_central, p.worst_at.0, p.worst_at.1
            )
        }
    };
    let r = point::solve(&problem, &params, Some(&mut show));
    let g = problem.groups;
    match r {
        Ok(s) => {
            let gr = s.grid;
            let ns = problem.eyring_n_s();
            let hc = s.film.h_central;
            let mut out = String::new();
            for (name, inside) in [
                (
                    "r1",
                    Box::new(|x: f64, y: f64, _h: f64| x * x + y * y <= 1.0)
                        as Box<dyn Fn(f64, f64, f64) -> bool>,
                ),
                (
                    "r1.5",
                    Box::new(|x: f64, y: f64, _h: f64| x * x + y * y <= 2.25),
                ),
                (
                    "r2",
                    Box::new(|x: f64, y: f64, _h: f64| x * x + y * y <= 4.0),
                ),
                ("h2", Box::new(move |_x, _y, h: f64| h <= 2.0 * hc)),
                ("h4", Box::new(move |_x, _y, h: f64| h <= 4.0 * hc)),
                ("h10", Box::new(move |_x, _y, h: f64| h <= 10.0 * hc)),
                ("all", Box::new(|_x, _y, _h| true)),
            ] {
                let mut sl = 0.0;
                for j in 1..gr.ny {
                    for i in 1..gr.nx {
                        let k = gr.idx(i, j);
                        let p = s.p[k];
                        if p <= 0.0 || !inside(gr.x(i), gr.y(j), s.h[k]) {
                            continue;
                        }
                        sl += problem
                            .shear
                            .mean_shear_stress(ns * problem.viscosity.eta_bar(p) / s.h[k], p);
                    }
                }
                out += &format!(
                    " {name} {:.4}",
                    sl * gr.hx * gr.hy / (2.0 * std::f64::consts::PI / 3.0)
                );
            }
            let pc = gr.at_centre(&s.p);
            let pmax = s.p.iter().cloned().fold(0.0, f64::max);
            let mut lin = 0.0;
            for j in 0..=gr.ny {
                for i in 0..=gr.nx {
                    let (x, y) = (gr.x(i), gr.y(j));
                    if x * x + y * y <= 1.0 {
                        lin += s.p[gr.idx(i, j)];
                    }
                }
            }
            println!("   delta {:.4} (estimate {:.4}) sliding by region:{out} | Pc {pc:.5} Pmax {pmax:.5} load_in_r1 {:.4} method {:?} res {:.2e} newton {} loaderr {:.1e}", s.delta, repro::physics::film::hc_nijenbanning(g.m, g.l, g.d) / g.moes_film_scale - 1.0, lin*gr.hx*gr.hy, s.info.method, s.info.residual(), s.info.newton_steps, s.info.load_error);
            println!("M {:.3} L {:.2} lam {:.3} dom {:?} far {:?} Hc {:.5} hcm {:.5} hmin {:.5} mu_s {:.5} mu_r {:?} cyc {} t {:.2}", g.m, g.l, g.lambda, (params.domain.x_start, params.domain.x_end, params.domain.y_half), params.edge, s.film.h_central, s.film.hc_moes, s.film.hmin_moes, s.friction.sliding, s.friction.rolling, s.info.cycles, t.elapsed().as_secs_f64())
        }
        Err(e) => println!(
            "M {:.3} L {:.2} dom {:?} far {:?} ERROR {}",
            g.m,
            g.l,
            (
                params.domain.x_start,
                params.domain.x_end,
                params.domain.y_half
            ),
            params.edge,
            e
        ),
    }
}
