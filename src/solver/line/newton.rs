//! Damped semi-smooth Newton iteration for the discrete line contact on one grid (the
//! approach of Houpert and Hamrock 1986 and Conry, Wang and Cusano 1987: the full Jacobian,
//! elastic coupling included).
//!
//! Unknowns: `P_1 .. P_{n-1}` and `Delta`. Equations: at each interior node the complementarity
//! form of Reynolds with cavitation, `min(P_i, -L_i(P) / c_i) = 0` (`L_i` the discrete
//! Reynolds operator of [`LineLevelFields::operator`], `c_i = |dL_i/dP_i|`): either `P_i = 0` and the
//! fluid would cavitate (`L_i <= 0`), or `P_i > 0` and Reynolds holds. This is the
//! `P = max(P, 0)` rule of the paper, written so that Newton sees it. Plus the force balance
//! `sum P_j dX = pi/2`.
//!
//! The Jacobian is assembled exactly except for the local derivatives of the coefficient
//! `eps(P, H, dP/dX)`, which are central differences of that scalar function.

use super::level::{LineLevelFields, LineModel, LOAD};
use crate::solver::{dense, line_search};

/// Relative step of the local finite differences of `eps` (central differences: truncation
/// ~ 1e-12 relative, round-off ~ 1e-10 relative; the Newton step tolerates far more).
const FD_REL: f64 = 1e-5;

/// `eps = rho H^3 / (eta_eff lambda)` at one node, as [`LineLevelFields::update_coefficients`] forms it.
fn eps_at(m: &LineModel, p: f64, h: f64, slope: f64) -> f64 {
    let rho = if m.density.is_incompressible() {
        1.0
    } else {
        m.density.rho_bar(p)
    };
    let g = if m.uses_gradient() {
        m.g_scale * h * slope
    } else {
        0.0
    };
    rho * m.inv_lambda * m.flow.conductance(m.rheology, h, m.eta(p), m.n_s, g, p)
}

fn central(f: impl Fn(f64) -> f64, x: f64, scale: f64) -> f64 {
    let d = FD_REL * x.abs().max(scale);
    (f(x + d) - f(x - d)) / (2.0 * d)
}

/// The state after an evaluation: the complementarity residual `phi` (Reynolds rows, then
/// the load row) and its norm.
struct Eval {
    phi: Vec<f64>,
    norm: f64,
}

/// Film, coefficients and `phi` for the level's current pressure and `delta`.
fn evaluate(level: &mut LineLevelFields, model: &LineModel, delta: f64, scale: &[f64]) -> Eval {
    level.update_film(delta);
    level.update_coefficients(model);
    let n = level.n;
    let mut phi = vec![0.0; n];
    for i in 1..n {
        let minus_l = -level.operator(&level.p, i) / scale[i];
        phi[i - 1] = level.p[i].min(minus_l);
    }
    phi[n - 1] = level.load() - LOAD;
    let norm = phi.iter().map(|v| v * v).sum::<f64>().sqrt();
    Eval { phi, norm }
}

/// `|dL_i/dP_i|` from the Poiseuille stencil and the wedge term's own kernel coefficient: the
/// scale that makes `-L_i / c_i` a pressure.
fn row_scales(level: &LineLevelFields) -> Vec<f64> {
    let k = level.deformation.kernel();
    let n = level.n;
    let mut c = vec![1.0; n + 1];
    for i in 1..n {
        let [xw, xe] = level.xi(i);
        let wedge = if i >= 2 {
            (1.5 * level.rho[i] * k.at(0) - 2.0 * level.rho[i - 1] * k.at(1)
                + 0.5 * level.rho[i - 2] * k.at(2))
                / level.dx
        } else {
            (level.rho[i] * k.at(0) - level.rho[i - 1] * k.at(1)) / level.dx
        };
        c[i] = (xw + xe + wedge).abs().max(1e-12);
    }
    c
}

/// The Jacobian of `phi` (row-major, `n x n`; column `n - 1` is `Delta`).
fn jacobian(level: &LineLevelFields, model: &LineModel, scale: &[f64]) -> Vec<f64> {
    let n = level.n;
    let dx = level.dx;
    let kern = level.deformation.kernel();
    let p = &level.p;
    let h = &level.h;
    // Local derivatives of eps and rho at every node.
    let mut de_dp = vec![0.0; n + 1];
    let mut de_dh = vec![0.0; n + 1];
    let mut de_ds = vec![0.0; n + 1];
    let mut drho = vec![0.0; n + 1];
    let gradient = model.uses_gradient();
    for k in 0..=n {
        let s = level.slope(p, k);
        let (pk, hk) = (p[k], h[k]);
        de_dp[k] = central(|v| eps_at(model, v, hk, s), pk, 1e-3);
        de_dh[k] = central(|v| eps_at(model, pk, v, s), hk, 1e-6);
        if gradient {
            de_ds[k] = central(|v| eps_at(model, pk, hk, v), s, 1e-3);
        }
        if !model.density.is_incompressible() {
            drho[k] = central(|v| model.density.rho_bar(v), pk, 1e-3);
        }
    }
    // d(slope_k)/dP_j for j = k -+ 1.
    let dslope = |k: usize, j: usize| -> f64 {
        if k == 0 {
            if j == 1 {
                1.0 / dx
            } else {
                0.0
            }
        } else if k == n {
            if j + 1 == n {
                -1.0 / dx
            } else {
                0.0
            }
        } else if j == k + 1 {
            0.5 / dx
        } else if j + 1 == k {
            -0.5 / dx
        } else {
            0.0
        }
    };
    let mut jac = vec![0.0; n * n];
    let r2 = 0.5 / (dx * dx);
    for i in 1..n {
        let row = &mut jac[(i - 1) * n..i * n];
        if p[i] <= -level.operator(p, i) / scale[i] {
            // Cavitated (or about to be): the row is P_i = 0.
            row[i - 1] = 1.0;
            continue;
        }
        let [a, b] = level.xi(i);
        // dL_i/dP_j, then scaled by -1/c_i at the end.
        let add = |j: usize, v: f64, row: &mut [f64]| {
            if j >= 1 && j < n {
                row[j - 1] += v;
            }
        };
        add(i - 1, a, row);
        add(i, -(a + b), row);
        add(i + 1, b, row);
        // Through eps_k, k = i-1, i, i+1.
        let g = [
            (i - 1, (p[i - 1] - p[i]) * r2),
            (i, (p[i - 1] + p[i + 1] - 2.0 * p[i]) * r2),
            (i + 1, (p[i + 1] - p[i]) * r2),
        ];
        // Weights w_k of the dense kernel part: sum_k w_k K(k - j), and the Delta column.
        let mut dense_w: Vec<(usize, f64)> = Vec::with_capacity(6);
        let mut dh0 = 0.0;
        for &(k, gk) in &g {
            add(k, gk * de_dp[k], row);
            if gradient {
                for j in [k.wrapping_sub(1), k + 1] {
                    if j <= n {
                        add(j, gk * de_ds[k] * dslope(k, j), row);
                    }
                }
            }
            dense_w.push((k, gk * de_dh[k]));
            dh0 += gk * de_dh[k];
        }
        // Wedge: -(sum_k c_k rho_k H_k) / dx.
        let wedge: &[(usize, f64)] = if i >= 2 {
            &[(i, 1.5), (i - 1, -2.0), (i - 2, 0.5)]
        } else {
            &[(i, 1.0), (i - 1, -1.0)]
        };
        for &(k, ck) in wedge {
            let c = ck / dx;
            add(k, -c * drho[k] * h[k], row);
            dense_w.push((k, -c * level.rho[k]));
            dh0 -= c * level.rho[k];
        }
        for (j, v) in row.iter_mut().enumerate().take(n - 1) {
            let j = j + 1;
            let mut s = 0.0;
            for &(k, w) in &dense_w {
                s += w * kern.at(k as isize - j as isize);
            }
            *v += s;
        }
        row[n - 1] = dh0;
        let inv = -1.0 / scale[i];
        row.iter_mut().for_each(|v| *v *= inv);
    }
    // Load row: d(sum P dX)/dP_j = dX.
    let last = &mut jac[(n - 1) * n..];
    last[..n - 1].iter_mut().for_each(|v| *v = dx);
    jac
}

/// Outcome of [`iterate`].
pub(crate) struct NewtonRun {
    /// Whether the tolerances were met.
    pub converged: bool,
    /// Iterations run.
    pub iterations: usize,
}

/// Newton iterations on `level` from its current pressure and `delta` until the mean absolute
/// Reynolds residual is below `tol` and the relative load error below `load_tol`, or
/// `max_iter` steps. After each step `report(residual, load_error, delta)` is called; its return
/// value `false` stops the iteration.
pub(crate) fn iterate(
    level: &mut LineLevelFields,
    model: &LineModel,
    delta: &mut f64,
    max_iter: usize,
    tol: f64,
    load_tol: f64,
    report: &mut dyn FnMut(&LineLevelFields, f64, f64, f64) -> bool,
) -> NewtonRun {
    let n = level.n;
    level.update_film(*delta);
    level.update_coefficients(model);
    let mut scale = row_scales(level);
    let mut ev = evaluate(level, model, *delta, &scale);
    for it in 1..=max_iter {
        let jac = jacobian(level, model, &scale);
        let mut step: Vec<f64> = ev.phi.iter().map(|v| -v).collect();
        if !dense::solve(&jac, &mut step, n) {
            return NewtonRun {
                converged: false,
                iterations: it,
            };
        }
        // Backtracking on |phi|: halve the step until it decreases (or the smallest damping).
        let p_old = level.p.clone();
        let delta_old = *delta;
        line_search::backtrack(ev.norm, |omega| {
            for i in 1..n {
                level.p[i] = (p_old[i] + omega * step[i - 1]).max(0.0);
            }
            *delta = delta_old + omega * step[n - 1];
            evaluate(level, model, *delta, &scale).norm
        });
        scale = row_scales(level);
        ev = evaluate(level, model, *delta, &scale);
        let residual = level.residual_norm();
        let load_error = ((level.load() - LOAD) / LOAD).abs();
        if !report(level, residual, load_error, *delta) {
            return NewtonRun {
                converged: false,
                iterations: it,
            };
        }
        if residual < tol && load_error < load_tol {
            return NewtonRun {
                converged: true,
                iterations: it,
            };
        }
    }
    NewtonRun {
        converged: false,
        iterations: max_iter,
    }
}
