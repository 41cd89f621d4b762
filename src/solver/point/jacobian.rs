//! The Jacobian of the point contact's Newton rows (see [`super::newton`]) at one state:
//! applied exactly without forming it (the film coupling through the elastic kernel by the
//! same zero-padded FFT as the film itself), assembled with the kernel truncated to a box
//! as the sparse preconditioner, and assembled whole as the dense oracle of the tests.
//!
//! Row `c` (an active node) is `d(r_c / s_c)`, `r = f - L(P)` the Reynolds residual and `s`
//! the row scales, or, at a node that cavitates (the `P` branch of `min(P, r / s)`), the
//! identity; the unknowns are `P` at the active nodes and `Delta`; the last row is the
//! force balance `sum P hx hy / LOAD`. With `L_c = sum_nb xi_nb (P_nb - P_c) - wedge_c`,
//! `xi` the half-point means of `eps = rho H^3 / (eta lambda)` and the wedge the upstream
//! difference of `rho H`:
//!
//! `dL_c = sum_nb xi_nb (dP_nb - dP_c) + sum_nb dxi_nb (P_nb - P_c) - dwedge_c`,
//! `d eps_k = eps_P dP_k + eps_H dH_k`, `d(rho H)_k = rho_P H_k dP_k + rho_k dH_k`,
//! `dH = K * dP + dDelta` (the elastic kernel `K`).
//!
//! The local derivatives `eps_P`, `eps_H`, `rho_P` of the coefficient functions are central
//! differences of those scalar functions; everything else is exact.

use super::level::{LevelFields, Model, LOAD};
use crate::solver::bordered_lu::{BorderedLu, Entry, LuStorage};
use crate::solver::deformation::Kernel;

/// Relative step of the local finite differences.
const FD_REL: f64 = 1e-5;

/// Central difference of the three coefficients in one argument.
fn central(f: impl Fn(f64) -> (f64, f64, f64), x: f64, scale: f64) -> [f64; 3] {
    let d = FD_REL * x.abs().max(scale);
    let (a, b) = (f(x + d), f(x - d));
    let r = 0.5 / d;
    [(a.0 - b.0) * r, (a.1 - b.1) * r, (a.2 - b.2) * r]
}

/// The upstream wedge difference at column `i`: `(offset along X, weight)` of `rho H`
/// (second order from `i = 2`, first order at `i = 1`), as [`LevelFields::wedge`] uses it.
pub(super) fn wedge_weights(i: usize) -> &'static [(isize, f64)] {
    if i >= 2 {
        &[(0, 1.5), (-1, -2.0), (-2, 0.5)]
    } else {
        &[(0, 1.0), (-1, -1.0)]
    }
}

/// The Jacobian at one state of a level (film and coefficients current).
pub(crate) struct Jacobian {
    /// The active nodes, in unknown order.
    pub active: Vec<usize>,
    /// Per unknown: whether its row is the identity (a node that cavitates).
    pub cavitating: Vec<bool>,
    /// Each node's unknown, `usize::MAX` for a node that stays dry.
    pub column: Vec<usize>,
    /// Row scales `s`.
    scale: Vec<f64>,
    /// `(eps_x, eps_y, rho)` derivatives in `P` and in `H` at every node.
    d_dp: Vec<[f64; 3]>,
    d_dh: Vec<[f64; 3]>,
    /// Work space of [`Jacobian::apply`]: `dP`, `dH`, `d eps_x`, `d eps_y`, `d(rho H)`.
    dp: Vec<f64>,
    dh: Vec<f64>,
    dex: Vec<f64>,
    dey: Vec<f64>,
    drh: Vec<f64>,
}

/// One row's sparse local part and the nodes its film dependence acts through.
struct Row {
    /// `dL_c / dP_m` through the stencil and the coefficients' pressure dependence.
    local: Vec<(usize, f64)>,
    /// `(node k, dL_c / dH_k)`: the film enters through these nodes' coefficients.
    film: Vec<(usize, f64)>,
}

impl Jacobian {
    /// Linearises `level` (film and coefficients current) for the `active` nodes, those
    /// marked in `cavitating` with identity rows.
    pub fn new(
        level: &LevelFields,
        model: &Model,
        active: Vec<usize>,
        cavitating: Vec<bool>,
        scale: Vec<f64>,
    ) -> Self {
        let n = level.grid.len();
        let mut column = vec![usize::MAX; n];
        for (r, &k) in active.iter().enumerate() {
            column[k] = r;
        }
        let (mut d_dp, mut d_dh) = (vec![[0.0; 3]; n], vec![[0.0; 3]; n]);
        for k in 0..n {
            let (pk, hk) = (level.p[k], level.h[k]);
            d_dp[k] = central(|v| model.coefficients(v, hk), pk, 1e-3);
            d_dh[k] = central(|v| model.coefficients(pk, v), hk, 1e-6);
        }
        Jacobian {
            active,
            cavitating,
            column,
            scale,
            d_dp,
            d_dh,
            dp: vec![0.0; n],
            dh: vec![0.0; n],
            dex: vec![0.0; n],
            dey: vec![0.0; n],
            drh: vec![0.0; n],
        }
    }

    /// Unknowns: the active nodes and `Delta`.
    pub fn len(&self) -> usize {
        self.active.len() + 1
    }

    /// Weight of each pressure unknown in the force-balance row.
    fn load_weight(level: &LevelFields) -> f64 {
        level.grid.hx * level.grid.hy / LOAD
    }

    /// `out = J v` exactly: the film change by the FFT deformation of `dP`.
    pub fn apply(&mut self, level: &mut LevelFields, v: &[f64], out: &mut [f64]) {
        let g = level.grid;
        let n = self.len();
        self.dp.iter_mut().for_each(|x| *x = 0.0);
        for (r, &k) in self.active.iter().enumerate() {
            self.dp[k] = v[r];
        }
        level.deformation.apply(&self.dp, &mut self.dh);
        let d_delta = v[n - 1];
        for k in 0..g.len() {
            let dh = self.dh[k] + d_delta;
            let (a, b) = (&self.d_dp[k], &self.d_dh[k]);
            let dp = self.dp[k];
            self.dex[k] = a[0] * dp + b[0] * dh;
            self.dey[k] = a[1] * dp + b[1] * dh;
            self.drh[k] = a[2] * level.h[k] * dp + level.rho[k] * dh;
        }
        let (rx2, ry2) = (0.5 / (g.hx * g.hx), 0.5 / (g.hy * g.hy));
        let (p, dp) = (&level.p, &self.dp);
        let px = g.px();
        for (r, &c) in self.active.iter().enumerate() {
            if self.cavitating[r] {
                out[r] = v[r];
                continue;
            }
            let i = c % px;
            let [xw, xe, xs, xn] = level.xi(i, c / px);
            let (w, e, s, nn) = (c - 1, c + 1, c - px, c + px);
            let mut dl = xw * (dp[w] - dp[c])
                + xe * (dp[e] - dp[c])
                + xs * (dp[s] - dp[c])
                + xn * (dp[nn] - dp[c]);
            // The arithmetic mean's terms as they were written before the other means,
            // so its products keep their bits (the revision guard's digests).
            dl += match level.half_derivatives(c) {
                None => {
                    (self.dex[c] + self.dex[w]) * rx2 * (p[w] - p[c])
                        + (self.dex[c] + self.dex[e]) * rx2 * (p[e] - p[c])
                        + (self.dey[c] + self.dey[s]) * ry2 * (p[s] - p[c])
                        + (self.dey[c] + self.dey[nn]) * ry2 * (p[nn] - p[c])
                }
                Some([dw, de, ds, dn]) => {
                    (self.dex[c] * dw[0] + self.dex[w] * dw[1]) * rx2 * (p[w] - p[c])
                        + (self.dex[c] * de[0] + self.dex[e] * de[1]) * rx2 * (p[e] - p[c])
                        + (self.dey[c] * ds[0] + self.dey[s] * ds[1]) * ry2 * (p[s] - p[c])
                        + (self.dey[c] * dn[0] + self.dey[nn] * dn[1]) * ry2 * (p[nn] - p[c])
                }
            };
            for &(off, wgt) in wedge_weights(i) {
                dl -= wgt / g.hx * self.drh[(c as isize + off) as usize];
            }
            out[r] = -dl / self.scale[c];
        }
        out[n - 1] = Self::load_weight(level) * v[..n - 1].iter().sum::<f64>();
    }

    /// Row `c`'s local part and film dependence (unscaled `dL_c`).
    fn row(&self, level: &LevelFields, c: usize) -> Row {
        let g = level.grid;
        let px = g.px();
        let (i, j) = (c % px, c / px);
        let p = &level.p;
        let [xw, xe, xs, xn] = level.xi(i, j);
        let (w, e, s, nn) = (c - 1, c + 1, c - px, c + px);
        let (rx2, ry2) = (0.5 / (g.hx * g.hx), 0.5 / (g.hy * g.hy));
        let mut local = vec![
            (w, xw),
            (e, xe),
            (s, xs),
            (nn, xn),
            (c, -(xw + xe + xs + xn)),
        ];
        // Through the coefficients: (node, dL/d eps_x, dL/d eps_y, dL/d(rho H)); each
        // half point's mean weighs its two nodes (both 1 for the arithmetic mean, whose
        // terms keep the form, and so the bits, they had before the other means).
        let mut through: Vec<(usize, f64, f64, f64)> = match level.half_derivatives(c) {
            None => vec![
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
            ],
            Some([dw, de, ds, dn]) => vec![
                (
                    c,
                    rx2 * ((p[w] - p[c]) * dw[0] + (p[e] - p[c]) * de[0]),
                    ry2 * ((p[s] - p[c]) * ds[0] + (p[nn] - p[c]) * dn[0]),
                    0.0,
                ),
                (w, rx2 * (p[w] - p[c]) * dw[1], 0.0, 0.0),
                (e, rx2 * (p[e] - p[c]) * de[1], 0.0, 0.0),
                (s, 0.0, ry2 * (p[s] - p[c]) * ds[1], 0.0),
                (nn, 0.0, ry2 * (p[nn] - p[c]) * dn[1], 0.0),
            ],
        };
        for &(off, wgt) in wedge_weights(i) {
            let k = (c as isize + off) as usize;
            let d = -wgt / g.hx;
            match through.iter_mut().find(|t| t.0 == k) {
                Some(t) => t.3 += d,
                None => through.push((k, 0.0, 0.0, d)),
            }
        }
        let mut film = Vec::with_capacity(through.len());
        for &(k, a, b, q) in &through {
            let [ex_p, ey_p, rho_p] = self.d_dp[k];
            let [ex_h, ey_h, _] = self.d_dh[k];
            local.push((k, a * ex_p + b * ey_p + q * level.h[k] * rho_p));
            film.push((k, a * ex_h + b * ey_h + q * level.rho[k]));
        }
        Row { local, film }
    }

    /// Entry `(c, m)` of the kernel part of row `c`: `sum_k dL_c/dH_k K(k - m)`.
    fn kernel_part(film: &[(usize, f64)], kernel: &Kernel, px: usize, m: usize) -> f64 {
        let (mi, mj) = ((m % px) as isize, (m / px) as isize);
        film.iter()
            .map(|&(k, gh)| gh * kernel.at((k % px) as isize - mi, (k / px) as isize - mj))
            .sum()
    }

    /// Calls `emit(row, column, value)` for every entry of the Reynolds rows whose column
    /// node lies within `radius` cells of the row's node (`None`: every column), or, for
    /// the rows at `(i, j)` where `local_only(i, j)` (and a radius is given), at the row's
    /// local stencil; returns the `Delta` column.
    fn assemble(
        &self,
        level: &LevelFields,
        radius: Option<usize>,
        local_only: impl Fn(usize, usize) -> bool,
        mut emit: impl FnMut(usize, usize, f64),
    ) -> Vec<f64> {
        let g = level.grid;
        let px = g.px();
        let kernel = level.deformation.kernel();
        let mut delta = Vec::with_capacity(self.active.len());
        let mut local_at = vec![0.0; g.len()];
        for (r, &c) in self.active.iter().enumerate() {
            if self.cavitating[r] {
                emit(r, r, 1.0);
                delta.push(0.0);
                continue;
            }
            let row = self.row(level, c);
            let inv = -1.0 / self.scale[c];
            for &(m, v) in &row.local {
                local_at[m] += v;
            }
            let (i, j) = (c % px, c / px);
            let mut put = |m: usize| {
                if self.column[m] != usize::MAX {
                    let v = local_at[m] + Self::kernel_part(&row.film, kernel, px, m);
                    emit(r, self.column[m], v * inv);
                }
            };
            if radius.is_some() && local_only(i, j) {
                let mut nodes: Vec<usize> = row.local.iter().map(|l| l.0).collect();
                nodes.sort_unstable();
                nodes.dedup();
                nodes.into_iter().for_each(&mut put);
            } else {
                let (lo_i, hi_i, lo_j, hi_j) = match radius {
                    Some(b) => (
                        i.saturating_sub(b),
                        (i + b).min(g.nx),
                        j.saturating_sub(b),
                        (j + b).min(g.ny),
                    ),
                    None => (0, g.nx, 0, g.ny),
                };
                for mj in lo_j..=hi_j {
                    for mi in lo_i..=hi_i {
                        put(mj * px + mi);
                    }
                }
            }
            for &(m, _) in &row.local {
                local_at[m] = 0.0;
            }
            delta.push(row.film.iter().map(|f| f.1).sum::<f64>() * inv);
        }
        delta
    }

    /// The preconditioner: this Jacobian with the elastic kernel truncated, bordered by the
    /// exact `Delta` column and force-balance row, factorised.
    ///
    /// A row where the film coupling dominates (the high-pressure zone, where `eps` is
    /// tiny and the wedge's own elastic term outweighs the Poiseuille stencil) keeps the
    /// kernel within the `(2 radius + 1)^2` box around its node; a row where the Poiseuille
    /// stencil dominates (the inlet and the sides) keeps only its local stencil entries,
    /// kernel parts included. The 5P4E hard case at level 7 needs the same GMRES
    /// iterations per Newton step either way (1-14), but the factor is a quarter the
    /// size and five times faster to compute (0.4 s against 2.0 s) with the box on the
    /// contact alone.
    /// `local_rows: false` keeps the box on every row. `storage` is an earlier
    /// factorisation's, reused.
    pub fn preconditioner(
        &self,
        level: &LevelFields,
        radius: usize,
        local_rows: bool,
        storage: LuStorage,
    ) -> Option<BorderedLu> {
        let g = level.grid;
        let d0 = level.deformation.kernel().at(0, 0);
        let local_only = |i: usize, j: usize| {
            let poiseuille: f64 = level.xi(i, j).iter().sum();
            local_rows && poiseuille > 1.5 * level.rho[g.idx(i, j)] * d0 / g.hx
        };
        let mut entries: Vec<Entry> = Vec::with_capacity(self.active.len() * 9);
        let delta = self.assemble(level, Some(radius.max(2)), local_only, |r, c, v| {
            entries.push(Entry::new(r, c, v));
        });
        let w = vec![Self::load_weight(level); self.active.len()];
        BorderedLu::factorize(&entries, &self.active, &delta, &w, 0.0, storage)
    }

    /// The whole Jacobian, dense row-major `len() x len()`: the oracle of the tests.
    #[cfg(test)]
    pub fn dense(&self, level: &LevelFields) -> Vec<f64> {
        let n = self.len();
        let mut jac = vec![0.0; n * n];
        let delta = self.assemble(level, None, |_, _| false, |r, c, v| jac[r * n + c] = v);
        for (r, d) in delta.into_iter().enumerate() {
            jac[r * n + n - 1] = d;
        }
        let wgt = Self::load_weight(level);
        for c in 0..n - 1 {
            jac[(n - 1) * n + c] = wgt;
        }
        jac
    }
}
