//! The order study of `docs/ACCURACY_NOTES.md` ("First-order convergence: the bisection"):
//! one point contact solved cold at a range of levels on one domain with one edge, its
//! central film, minimum film and sliding friction per level, the differences between
//! successive levels and the observed order `p = log2(d_k / d_k+1)`.
//!
//! `cargo run --release --example order_probe -- CASE CONFIG FROM TO`
//!
//! - `CASE`: `case23` (Fig. 6 case 23: 5P4E, 40 C, 1 GPa, 12 m/s, S 0.5 %, tau0 6 MPa;
//!   Roelands, Dowson-Higginson, Eyring) or `d:M:L:SBAR` (Moes groups, circular, Barus,
//!   incompressible, Eyring: `repro solve --m M --l L --s-bar SBAR`).
//! - `CONFIG`: `paper0` (the paper's domain, `P = 0`), `vl0` (`-4.5..1.5 x 3`, `P = 0`),
//!   `rule0` (the rule's case-sized domain, `P = 0`), `rule` (that domain with the far field:
//!   the product's default), or `X0:X1:YH:EDGE` with `EDGE` `0` or `far`.
//! - `FROM TO`: the levels.
//!
//! Every solve uses the product's friction region (the loaded film, over the applied load);
//! `mu_all` is the sliding friction over every pressurised node, over the applied load. The
//! diagnostics per level: `Delta`, where `X = 0` falls between its two nodes (`t`, 0 when it
//! is a node), the film there by linear (the solver's) and by quadratic interpolation, and
//! the largest change over the loaded film of the deformation the boundary nodes' pressure
//! would add (the FFT leaves them out), and the loaded film's sliding friction split into
//! `mu_cont`, the stress less its value at `P = 0` (continuous across the cavitation
//! boundary), and `mu_step`, that value (a step there); the largest pressure and where;
//! `dlneta`, the largest change of `ln(eta)` between neighbouring nodes. `PROBE_OUTTOL` sets the output
//! tolerance, `PROBE_TOL` the residual tolerance (`Params::tolerance`); `PROBE_NEWTONIAN`
//! takes a Newtonian fluid instead of Eyring; `PROBE_MEAN=exp` the exponential fit at the
//! half points (`HalfPointMean::ExponentialFit`) instead of the arithmetic mean.
mod common;

use repro::physics::case::*;
use repro::physics::lubricant::LubricantTable;
use repro::solver::deformation::Kernel;
use repro::solver::grid::{Domain, Grid};
use repro::solver::point::{self, Edge, FrictionRegion};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let case = common::case_of(&a[1]);
    // PROBE_NEWTONIAN=1 takes a Newtonian fluid instead of Eyring (the film's study only).
    let mut case = case;
    if std::env::var_os("PROBE_NEWTONIAN").is_some() {
        case.physics.rheology = repro::physics::rheology::Rheology::Newtonian;
    }
    let problem = Problem::from_case(&case, &LubricantTable::table1()).unwrap();
    let rule = Domain::for_problem(&problem);
    let (domain, edge) = match a[2].as_str() {
        "paper0" => (Domain::default(), Edge::Zero),
        "vl0" => (Domain::wide(), Edge::Zero),
        "rule0" => (rule, Edge::Zero),
        "rule" => (rule, Edge::FarField),
        s => {
            let v: Vec<&str> = s.split(':').collect();
            let f = |i: usize| v[i].parse::<f64>().unwrap();
            let d = Domain {
                x_start: f(0),
                x_end: f(1),
                y_half: f(2),
                y_centre: 0.0,
            };
            (
                d,
                if v[3] == "0" {
                    Edge::Zero
                } else {
                    Edge::FarField
                },
            )
        }
    };
    let (from, to): (u32, u32) = (a[3].parse().unwrap(), a[4].parse().unwrap());
    let g = problem.groups;
    println!(
        "{} {}: M {:.3} L {:.2} lambda {:.3}, domain {:?}, edge {:?}",
        a[1], a[2], g.m, g.l, g.lambda, domain, edge
    );
    let mut rows: Vec<[f64; 6]> = Vec::new();
    for level in from..=to {
        let mut params = {
            let mut params = point::Params::at_level(level);
            params.domain = domain;
            params.edge = edge;
            params.friction.region = FrictionRegion::LoadedFilm;
            params
        };
        if let Ok(t) = std::env::var("PROBE_OUTTOL") {
            params.stopping.output_tolerance = t.parse().unwrap();
        }
        if let Ok(t) = std::env::var("PROBE_TOL") {
            params.stopping.tolerance = t.parse().unwrap();
        }
        if std::env::var("PROBE_MEAN").as_deref() == Ok("exp") {
            params.half_point = point::HalfPointMean::ExponentialFit;
        }
        let t = std::time::Instant::now();
        let s = match point::solve(&problem, &params, None) {
            Ok(s) => s,
            Err(e) => {
                println!("level {level}: ERROR {e}");
                continue;
            }
        };
        let secs = t.elapsed().as_secs_f64();
        let gr = s.grid;
        let ns = problem.eyring_n_s();
        // The sliding stress over the pressurised nodes: all of them, and over the loaded
        // film split into the stress less its value at `P = 0` (continuous across the
        // cavitation boundary) and that value (a step there).
        let (mut all, mut cont, mut step) = (0.0, 0.0, 0.0);
        let limit = 4.0 * s.film.h_central;
        for j in 1..gr.ny {
            for i in 1..gr.nx {
                let k = gr.idx(i, j);
                let (p, h) = (s.p[k], s.h[k]);
                if p > 0.0 {
                    let tau = problem
                        .shear
                        .mean_shear_stress(ns * problem.viscosity.eta_bar(p) / h, p);
                    all += tau;
                    if h <= limit {
                        let tau0 = problem.shear.mean_shear_stress(ns / h, 0.0);
                        cont += tau - tau0;
                        step += tau0;
                    }
                }
            }
        }
        let per_load = gr.hx * gr.hy / (2.0 * std::f64::consts::PI / 3.0);
        let (mu_all, mu_cont, mu_step) = (all * per_load, cont * per_load, step * per_load);
        let (lin, quad, frac) = centre(&gr, &s.h);
        // How well the grid resolves the viscosity's exponential scale: the largest change
        // of ln(eta) between neighbouring nodes along X and along Y.
        let (mut jump, mut jump_at) = (0.0, (0.0, 0.0));
        for j in 0..gr.ny {
            for i in 0..gr.nx {
                let k = gr.idx(i, j);
                let l = |k: usize| problem.viscosity.ln_eta_bar(s.p[k].max(0.0));
                let d = (l(k + 1) - l(k)).abs().max((l(k + gr.px()) - l(k)).abs());
                if d > jump {
                    (jump, jump_at) = (d, (gr.x(i), gr.y(j)));
                }
            }
        }
        // The pressure spike: the largest pressure and where it is.
        let kmax = (0..gr.len()).fold(0, |a, k| if s.p[k] > s.p[a] { k } else { a });
        let spike = (s.p[kmax], gr.x(kmax % gr.px()), gr.y(kmax / gr.px()));
        let edge_w = edge_deformation(&gr, &problem, &s.p, &s.h, s.film.h_central);
        println!(
            "level {level} ({}x{}, hx {:.5}): Hc {:.6} Hmin {:.6} (Moes) mu {:.6} mu_all {:.6} \
             mu_cont {mu_cont:.6} mu_step {mu_step:.6} Pmax {:.5} at ({:.4}, {:.4}) dlneta {jump:.3} at ({:.3}, {:.3}) \
             | Delta {:.6} t {frac:.3} Hc lin {lin:.6} quad {quad:.6} edgeW {edge_w:.2e} \
             | {:?} cycles {} newton {} res {:.1e} | {secs:.1} s",
            gr.nx,
            gr.ny,
            gr.hx,
            s.film.hc_moes,
            s.film.hmin_moes,
            s.friction.sliding,
            mu_all,
            spike.0,
            spike.1,
            spike.2,
            jump_at.0,
            jump_at.1,
            s.delta,
            s.info.method,
            s.info.cycles,
            s.info.newton_steps,
            s.info.residual(),
        );
        rows.push([
            level as f64,
            s.film.hc_moes,
            s.film.hmin_moes,
            s.friction.sliding,
            mu_cont,
            mu_step,
        ]);
    }
    for (q, name) in [(1, "Hc"), (2, "Hmin"), (3, "mu"), (4, "mu_c"), (5, "mu_s")] {
        let mut line = format!("{name:5}");
        for w in rows.windows(3) {
            let (d0, d1) = (w[1][q] - w[0][q], w[2][q] - w[1][q]);
            line += &format!(
                " | {}-{}-{}: d {:.4e} {:.4e} p {:.2}",
                w[0][0],
                w[1][0],
                w[2][0],
                d0,
                d1,
                (d0 / d1).abs().log2()
            );
        }
        println!("{line}");
    }
}

/// The film at `X = Y = 0`: linear between the two nodes beside it (the solver's), and
/// quadratic through those and the next one downstream; `t` where 0 falls between them.
fn centre(g: &Grid, h: &[f64]) -> (f64, f64, f64) {
    let (_, j) = g.nearest(0.0, 0.0);
    let s = -g.x0 / g.hx;
    let i = s.floor() as usize;
    let t = s - i as f64;
    let (a, b, c) = (h[g.idx(i, j)], h[g.idx(i + 1, j)], h[g.idx(i + 2, j)]);
    let lin = (1.0 - t) * a + t * b;
    // Lagrange through t = 0, 1, 2.
    let quad = a * (t - 1.0) * (t - 2.0) / 2.0 - b * t * (t - 2.0) + c * t * (t - 1.0) / 2.0;
    (lin, quad, t)
}

/// The deformation the boundary nodes' pressure adds (as cells of the interior's kind):
/// its largest minus its smallest value over the loaded film `H <= 4 Hc` (a uniform part
/// is taken up by `Delta`). Zero with `P = 0` on the edge; not computed above level 8.
fn edge_deformation(g: &Grid, problem: &Problem, p: &[f64], h: &[f64], hc: f64) -> f64 {
    let mut edge = vec![0.0; g.len()];
    let mut any = false;
    for k in g.boundary() {
        edge[k] = p[k];
        any |= p[k] != 0.0;
    }
    if !any || g.nx > 512 {
        return 0.0;
    }
    let kernel = Kernel::new(g, problem.groups.kappa, problem.ell_k);
    let w = direct_sum_boundary(g, &kernel, &edge);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (k, &wk) in w.iter().enumerate() {
        if h[k] <= 4.0 * hc {
            lo = lo.min(wk);
            hi = hi.max(wk);
        }
    }
    hi - lo
}

/// `sum_b D(i - ib, j - jb) P_b` over the boundary nodes `b` only.
fn direct_sum_boundary(g: &Grid, kernel: &Kernel, p: &[f64]) -> Vec<f64> {
    let sources: Vec<(isize, isize, f64)> = g
        .boundary()
        .filter(|&k| p[k] != 0.0)
        .map(|k| ((k % g.px()) as isize, (k / g.px()) as isize, p[k]))
        .collect();
    let mut w = g.zeros();
    for j in 0..g.py() {
        for i in 0..g.px() {
            w[g.idx(i, j)] = sources
                .iter()
                .map(|&(k, l, pk)| kernel.at(i as isize - k, j as isize - l) * pk)
                .sum();
        }
    }
    w
}
