//! Damped semi-smooth Newton iteration for the point contact on one grid: the finish of a
//! solve whose multigrid cycles stall (the most heavily loaded, most piezoviscous cases).
//!
//! Unknowns: `P` at the interior nodes and `Delta`. Equations: at each interior node the
//! complementarity form of Reynolds with cavitation, `min(P, r / c) = 0` with `r = f - L(P)`
//! the residual of [`Level::residual`] and `c` the magnitude of its own diagonal (so `r / c`
//! is a pressure): either `P = 0` and the fluid would cavitate, or `P > 0` and Reynolds
//! holds. Plus the force balance. The unknowns of a step are the pressurised nodes and the
//! dry ones whose residual asks for pressure (`r / c < 0`), each with its Reynolds row
//! (a pressurised node that should cavitate is lowered by the step and projected on
//! `P >= 0`, not zeroed at once); the other nodes stay at `P = 0`. The system is full,
//! because every pressure moves every film value through the elastic kernel, and factorised
//! by [`dense::solve`]; its size, the number of pressurised nodes, keeps the iteration to the
//! coarser levels ([`Limits::unknowns`]).
//!
//! The Jacobian is exact except for the local derivatives of the coefficients
//! `eps_x(P, H)`, `eps_y(P, H)` and `rho(P)`, which are central differences of those scalar
//! functions.

use super::level::{Level, Model, LOAD};
use crate::solver::{dense, line_search};

/// Relative step of the local finite differences.
const FD_REL: f64 = 1e-5;
/// Central difference of the three coefficients in one argument.
fn central(f: impl Fn(f64) -> (f64, f64, f64), x: f64, scale: f64) -> [f64; 3] {
    let d = FD_REL * x.abs().max(scale);
    let (a, b) = (f(x + d), f(x - d));
    let r = 0.5 / d;
    [(a.0 - b.0) * r, (a.1 - b.1) * r, (a.2 - b.2) * r]
}

/// `|dL/dP|` at every interior node: the Poiseuille stencil and the wedge term's own kernel
/// coefficient. Dividing the residual by it makes a pressure.
fn row_scales(level: &Level) -> Vec<f64> {
    let g = level.grid;
    let d0 = level.deformation.kernel().at(0, 0);
    let mut c = vec![1.0; g.len()];
    for j in 1..g.ny {
        for i in 1..g.nx {
            let k = g.idx(i, j);
            let wedge = if i >= 2 { 1.5 } else { 1.0 } * level.rho[k] * d0 / g.hx;
            c[k] = (level.xi(i, j).iter().sum::<f64>() + wedge).max(1e-12);
        }
    }
    c
}

/// The complementarity residual: `min(P, r / c)` per interior node and the relative load
/// error, and the Euclidean norm of all of them.
struct Eval {
    phi: Vec<f64>,
    load: f64,
    norm: f64,
}

fn evaluate(level: &mut Level, model: &Model, h0: f64, scale: &[f64]) -> Eval {
    level.update_film(h0);
    level.update_coefficients(model);
    let g = level.grid;
    let mut phi = vec![0.0; g.len()];
    let mut sum = 0.0;
    for j in 1..g.ny {
        for i in 1..g.nx {
            let k = g.idx(i, j);
            phi[k] = level.p[k].min(level.residual(i, j) / scale[k]);
            sum += phi[k] * phi[k];
        }
    }
    let load = level.load_defect() / LOAD;
    Eval {
        phi,
        load,
        norm: (sum + load * load).sqrt(),
    }
}

/// Outcome of [`iterate`].
pub(crate) struct Outcome {
    /// Whether the tolerances were met.
    pub converged: bool,
    /// Steps taken.
    pub iterations: usize,
}

/// What [`iterate`] reports after each step.
pub(crate) struct Step {
    /// Mean absolute Reynolds residual.
    pub residual: f64,
    /// `(X, Y)` of the largest residual.
    pub worst_at: (f64, f64),
    /// Relative force-balance error.
    pub load_error: f64,
}

/// When [`iterate`] stops.
pub(crate) struct Limits {
    /// Most steps.
    pub steps: usize,
    /// Largest system (pressurised nodes + 1); a larger one ends the iteration unconverged.
    pub unknowns: usize,
    /// Mean absolute Reynolds residual to reach.
    pub tolerance: f64,
    /// Relative force-balance error to reach.
    pub load_tolerance: f64,
}

/// Newton steps on `level` (its own equations: the finest level) from its current pressure
/// and `h0` until both tolerances are met, within `limits`. `report` hears of every step.
pub(crate) fn iterate(
    level: &mut Level,
    model: &Model,
    h0: &mut f64,
    limits: &Limits,
    report: &mut dyn FnMut(&Level, &Step),
) -> Outcome {
    let g = level.grid;
    let mut scale = row_scales(level);
    let mut ev = evaluate(level, model, *h0, &scale);
    for it in 1..=limits.steps {
        let stop = Outcome {
            converged: false,
            iterations: it - 1,
        };
        // Reynolds rows: the pressurised nodes and the dry ones whose residual asks for
        // pressure; the others stay dry.
        let active: Vec<usize> = (1..g.ny)
            .flat_map(|j| (1..g.nx).map(move |i| g.idx(i, j)))
            .filter(|&k| level.p[k] > 0.0 || ev.phi[k] < 0.0)
            .collect();
        let n = active.len() + 1;
        if n > limits.unknowns {
            return stop;
        }
        let mut column = vec![usize::MAX; g.len()];
        for (r, &k) in active.iter().enumerate() {
            column[k] = r;
        }
        let jac = jacobian(level, model, &scale, &active, &column);
        let mut step: Vec<f64> = active.iter().map(|&k| -ev.phi[k]).collect();
        step.push(-ev.load);
        if !dense::solve(&jac, &mut step, n) {
            return stop;
        }
        // Backtracking on |phi|: halve the step until it decreases (or the smallest damping).
        let p_old = level.p.clone();
        let h0_old = *h0;
        line_search::backtrack(ev.norm, |omega| {
            for j in 1..g.ny {
                for i in 1..g.nx {
                    let k = g.idx(i, j);
                    if let Some(&dp) = step.get(column[k]) {
                        level.p[k] = (p_old[k] + omega * dp).max(0.0);
                    }
                }
            }
            *h0 = h0_old + omega * step[n - 1];
            evaluate(level, model, *h0, &scale).norm
        });
        scale = row_scales(level);
        ev = evaluate(level, model, *h0, &scale);
        let (residual, worst_at) = level.residual_norm();
        let load_error = ev.load.abs();
        report(
            level,
            &Step {
                residual,
                worst_at,
                load_error,
            },
        );
        if !residual.is_finite() {
            return Outcome {
                converged: false,
                iterations: it,
            };
        }
        if residual < limits.tolerance && load_error < limits.load_tolerance {
            return Outcome {
                converged: true,
                iterations: it,
            };
        }
    }
    Outcome {
        converged: false,
        iterations: limits.steps,
    }
}

/// The Jacobian of the active rows (row-major `n x n`, the last row and column the load and
/// `Delta`); `column[k]` is node `k`'s unknown, `usize::MAX` for a node that stays dry.
fn jacobian(
    level: &Level,
    model: &Model,
    scale: &[f64],
    active: &[usize],
    column: &[usize],
) -> Vec<f64> {
    let g = level.grid;
    let n = active.len() + 1;
    let kern = level.deformation.kernel();
    let (p, h) = (&level.p, &level.h);
    // Local derivatives of (eps_x, eps_y, rho) in P and in H at every node.
    let mut d_dp = vec![[0.0; 3]; g.len()];
    let mut d_dh = vec![[0.0; 3]; g.len()];
    for k in 0..g.len() {
        let (pk, hk) = (p[k], h[k]);
        d_dp[k] = central(|v| model.coefficients(v, hk), pk, 1e-3);
        d_dh[k] = central(|v| model.coefficients(pk, v), hk, 1e-6);
    }
    let (rx2, ry2) = (0.5 / (g.hx * g.hx), 0.5 / (g.hy * g.hy));
    let mut jac = vec![0.0; n * n];
    // Scratch: d L / d P_m over the whole grid for one row (sparse local part + dense part).
    let mut full = vec![0.0; g.len()];
    let (px, nodes) = (g.px() as isize, g.len());
    for (r, &c) in active.iter().enumerate() {
        let (i, j) = (c % g.px(), c / g.px());
        full.iter_mut().for_each(|v| *v = 0.0);
        let [xw, xe, xs, xn] = level.xi(i, j);
        let (w, e, s, nn) = (c - 1, c + 1, c - g.px(), c + g.px());
        full[w] += xw;
        full[e] += xe;
        full[s] += xs;
        full[nn] += xn;
        full[c] -= xw + xe + xs + xn;
        // Through the coefficients: (node, dL/d eps_x, dL/d eps_y, dL/d(rho H)).
        let mut through: Vec<(usize, f64, f64, f64)> = vec![
            (
                c,
                rx2 * (p[w] + p[e] - 2.0 * p[c]),
                ry2 * (p[s] + p[nn] - 2.0 * p[c]),
                0.0,
            ),
            (w, rx2 * (p[w] - p[c]), 0.0, 0.0),
            (e, rx2 * (p[e] - p[c]), 0.0, 0.0),
            (s, 0.0, ry2 * (p[s] - p[c]), 0.0),
            (nn, 0.0, ry2 * (p[nn] - p[c]), 0.0),
        ];
        let wedge: &[(usize, f64)] = if i >= 2 {
            &[(c, 1.5), (w, -2.0), (c - 2, 0.5)]
        } else {
            &[(c, 1.0), (w, -1.0)]
        };
        for &(k, ck) in wedge {
            let d = -ck / g.hx;
            match through.iter_mut().find(|t| t.0 == k) {
                Some(t) => t.3 += d,
                None => through.push((k, 0.0, 0.0, d)),
            }
        }
        // Local P parts, and the weights of the kernel part sum_k gH_k D(k - m).
        let mut dense_w: Vec<(isize, isize, f64)> = Vec::with_capacity(through.len());
        let mut d_delta = 0.0;
        for &(k, a, b, q) in &through {
            let [ex_p, ey_p, rho_p] = d_dp[k];
            let [ex_h, ey_h, _] = d_dh[k];
            full[k] += a * ex_p + b * ey_p + q * h[k] * rho_p;
            let gh = a * ex_h + b * ey_h + q * level.rho[k];
            dense_w.push(((k % g.px()) as isize, (k / g.px()) as isize, gh));
            d_delta += gh;
        }
        let inv = -1.0 / scale[c];
        let row = &mut jac[r * n..(r + 1) * n];
        for m in 0..nodes {
            let (mi, mj) = ((m as isize) % px, (m as isize) / px);
            let on_grid = mi > 0 && mj > 0 && (mi as usize) < g.nx && (mj as usize) < g.ny;
            if !on_grid || column[m] == usize::MAX {
                continue;
            }
            let mut v = full[m];
            for &(ki, kj, gh) in &dense_w {
                v += gh * kern.at(ki - mi, kj - mj);
            }
            row[column[m]] = v * inv;
        }
        row[n - 1] = d_delta * inv;
    }
    // Load row: d(sum P hx hy / LOAD)/dP_m.
    let wgt = g.hx * g.hy / LOAD;
    for r in 0..n - 1 {
        jac[(n - 1) * n + r] = wgt;
    }
    jac
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::{Case, DimensionlessCase, Physics, Problem, Spec};
    use crate::physics::hertz::Hertz;
    use crate::physics::lubricant::LubricantTable;
    use crate::solver::grid::{Domain, Grid};

    /// A moderately loaded Eyring contact on a level-4 grid, at the Hertzian pressure and a
    /// `Delta` that keeps the film positive.
    fn setup() -> (Level, Model, f64) {
        let case = Case {
            spec: Spec::Dimensionless(DimensionlessCase {
                m: 100.0,
                l: 10.0,
                s_bar: 0.5,
                d: 1.0,
                slip: 0.01,
                eta0_pa_s: None,
                ph_pa: None,
            }),
            physics: Physics::default(),
        };
        let problem = Problem::from_case(&case, &LubricantTable::table1()).unwrap();
        let model = Model::new(&problem);
        let grid = Grid::level(&Domain::default(), 4);
        let mut level = Level::new(grid, &model);
        level.p = grid.sample(Hertz::pressure);
        let h0 = 0.3;
        level.update_film(h0);
        assert!(
            level.h.iter().all(|&h| h > 0.0),
            "the test needs a positive film"
        );
        (level, model, h0)
    }

    /// `r / c` at the given nodes and the relative load error, for pressure `p` and `h0`.
    fn reynolds(
        level: &mut Level,
        model: &Model,
        p: &[f64],
        h0: f64,
        scale: &[f64],
        at: &[usize],
    ) -> Vec<f64> {
        level.p.copy_from_slice(p);
        let ev = evaluate(level, model, h0, scale);
        let g = level.grid;
        let mut out: Vec<f64> = at
            .iter()
            .map(|&k| level.residual(k % g.px(), k / g.px()) / scale[k])
            .collect();
        out.push(ev.load);
        out
    }

    #[test]
    fn jacobian_matches_central_differences_of_the_residual() {
        let (mut level, model, h0) = setup();
        let g = level.grid;
        level.update_coefficients(&model);
        let scale = row_scales(&level);
        let active: Vec<usize> = (1..g.ny)
            .flat_map(|j| (1..g.nx).map(move |i| g.idx(i, j)))
            .filter(|&k| level.p[k] > 0.0)
            .collect();
        assert!(active.len() > 100, "{} pressurised nodes", active.len());
        let mut column = vec![usize::MAX; g.len()];
        for (r, &k) in active.iter().enumerate() {
            column[k] = r;
        }
        let jac = jacobian(&level, &model, &scale, &active, &column);
        let n = active.len() + 1;
        // A direction with every node moving differently, and Delta moving too.
        let v: Vec<f64> = (0..n)
            .map(|r| ((r * 7919) % 101) as f64 / 101.0 - 0.3)
            .collect();
        let jv: Vec<f64> = (0..n)
            .map(|r| (0..n).map(|c| jac[r * n + c] * v[c]).sum())
            .collect();
        let p0 = level.p.clone();
        let eps = 1e-6;
        let moved = |sign: f64| {
            let mut p = p0.clone();
            for (r, &k) in active.iter().enumerate() {
                p[k] += sign * eps * v[r];
            }
            (p, h0 + sign * eps * v[n - 1])
        };
        let (pp, hp) = moved(1.0);
        let (pm, hm) = moved(-1.0);
        let plus = reynolds(&mut level, &model, &pp, hp, &scale, &active);
        let minus = reynolds(&mut level, &model, &pm, hm, &scale, &active);
        let fd: Vec<f64> = plus
            .iter()
            .zip(&minus)
            .map(|(a, b)| (a - b) / (2.0 * eps))
            .collect();
        let big = fd.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let worst = jv
            .iter()
            .zip(&fd)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        // Central differences with step 1e-6 are exact to ~1e-10 relative (truncation
        // O(eps^2), round-off 1e-16 / eps), the Jacobian's local coefficient derivatives to
        // ~1e-9 (FD_REL = 1e-5): 1e-6 leaves room for both and catches any wrong term.
        assert!(
            worst < 1e-6 * big,
            "max |J v - FD| = {worst:.3e}, max |FD| = {big:.3e}"
        );
    }
}
