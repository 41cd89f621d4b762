//! Relaxation of the line-contact Reynolds equation (Venner and Lubrecht 2000), switching per
//! point on the local coefficient `xi = eps/h^2`:
//!
//! - Gauss-Seidel where `xi` is large (the inlet and outside the contact), where the
//!   Poiseuille term dominates and the operator is elliptic;
//! - Jacobi distributive where `xi` is small (the high-pressure zone), where the equation
//!   degenerates to the integral wedge term: a change `delta` at a node is applied with
//!   `-delta/2` at its two neighbours, which turns the smooth logarithmic kernel into a local,
//!   diagonally dominant operator.
//!
//! In one dimension the whole grid is one "line": the changes of all interior nodes are solved
//! together, with the Poiseuille stencil and the elastic coupling of the wedge term (the kernel
//! coefficients, distributed for Jacobi points) in a band of 3 lower and 2 upper diagonals,
//! exactly as the point contact relaxes each of its lines.

use super::level::Level;
use crate::solver::banded::BandMatrix;

/// `xi = eps/h^2` above which a point is relaxed by Gauss-Seidel. The wedge term's own
/// diagonal is `(1 + ln 2 + ...)/pi ~ 0.5` per unit of `rho`, so below about 0.3 the
/// Poiseuille term no longer dominates (Venner and Lubrecht use the same switch).
const XI_SWITCH: f64 = 0.3;
/// Under-relaxation of the Gauss-Seidel changes.
const OMEGA_GS: f64 = 0.6;
/// Under-relaxation of the Jacobi distributive changes.
const OMEGA_JD: f64 = 0.3;
const LOWER: usize = 3;
const UPPER: usize = 2;

/// Work space for the relaxation.
#[derive(Debug)]
pub(crate) struct Scratch {
    matrix: BandMatrix,
    rhs: Vec<f64>,
    gauss_seidel: Vec<bool>,
    pnew: Vec<f64>,
}

impl Scratch {
    pub fn new() -> Self {
        Scratch {
            matrix: BandMatrix::new(1, LOWER, UPPER),
            rhs: Vec::new(),
            gauss_seidel: Vec::new(),
            pnew: Vec::new(),
        }
    }
}

/// Kernel coefficients `dk[m] = K(m)` for Gauss-Seidel and the distributed
/// `K(m) - (K(m+1) + K(|m-1|))/2` for Jacobi distributive.
fn wedge_kernels(level: &Level) -> ([f64; 6], [f64; 6]) {
    let k = level.deformation.kernel();
    let mut gs = [0.0; 6];
    let mut jd = [0.0; 6];
    for m in 0..6isize {
        gs[m as usize] = k.at(m);
        jd[m as usize] = k.at(m) - 0.5 * (k.at(m + 1) + k.at((m - 1).abs()));
    }
    (gs, jd)
}

/// One relaxation sweep of `level` (film and coefficients are recomputed first, from the
/// current pressure and `h0`, by the caller's `prepare`).
pub(crate) fn relax(level: &mut Level, s: &mut Scratch) {
    let n = level.n;
    let (dk_gs, dk_jd) = wedge_kernels(level);
    let rdx = 1.0 / level.dx;
    let unknowns = n - 1;
    s.matrix.reset(unknowns);
    s.rhs.clear();
    s.rhs.resize(unknowns, 0.0);
    s.gauss_seidel.clear();
    s.gauss_seidel.resize(unknowns, false);
    s.pnew.clear();
    s.pnew.extend_from_slice(&level.p);
    let p = &level.p;
    for i in 1..n {
        let r = i - 1;
        let [xw, xe] = level.xi(i);
        let sum = xw + xe;
        let gs = xw.max(xe) > XI_SWITCH;
        s.gauss_seidel[r] = gs;
        let dk = if gs { &dk_gs } else { &dk_jd };
        let rho = |k: usize| level.rho[k];
        let d = |m: isize| dk[m.unsigned_abs()];
        // Derivative of the wedge term with respect to the change at offset m.
        let dwedge = |m: isize| -> f64 {
            if i >= 2 {
                rdx * (1.5 * rho(i) * d(m) - 2.0 * rho(i - 1) * d(m + 1)
                    + 0.5 * rho(i - 2) * d(m + 2))
            } else {
                rdx * (rho(i) * d(m) - rho(i - 1) * d(m + 1))
            }
        };
        s.rhs[r] = level.f[i] - level.operator(p, i);
        let diag = if gs { -sum } else { -1.5 * sum };
        s.matrix.set(r, r, diag - dwedge(0));
        // Off-diagonal coupling only inside the pressurised region: at the cavitation
        // boundary the projection P = max(P, 0) decouples the nodes.
        let inside = |k: isize| k >= 0 && (k as usize) <= n;
        let coupled = [-2isize, -1, 1, 2]
            .iter()
            .all(|&m| inside(i as isize + m) && p[(i as isize + m) as usize] > 0.0);
        if coupled {
            // A Jacobi distributive change at i-1 moves P_{i-1} by 1 and P_i, P_{i-2} by -1/2.
            let (m1, m2, p1, p2) = if gs {
                (xw, 0.0, xe, 0.0)
            } else {
                (
                    1.5 * xw + 0.5 * xe,
                    -0.5 * xw,
                    1.5 * xe + 0.5 * xw,
                    -0.5 * xe,
                )
            };
            for (m, poiseuille) in [(-3isize, 0.0), (-2, m2), (-1, m1), (1, p1), (2, p2)] {
                let k = i as isize + m;
                if k >= 1 && (k as usize) < n {
                    s.matrix.set(r, (k - 1) as usize, poiseuille - dwedge(m));
                }
            }
        }
    }
    if !s.matrix.solve(&mut s.rhs) {
        return;
    }
    let pnew = &mut s.pnew;
    for i in 1..n {
        let r = i - 1;
        if s.gauss_seidel[r] {
            pnew[i] = (pnew[i] + OMEGA_GS * s.rhs[r]).max(0.0);
        } else {
            let old = pnew[i];
            pnew[i] = (old + OMEGA_JD * s.rhs[r]).max(0.0);
            let delta = pnew[i] - old;
            if pnew[i] > 0.0 && pnew[i - 1] > 0.0 && pnew[i + 1] > 0.0 {
                if i > 1 {
                    pnew[i - 1] = (pnew[i - 1] - 0.5 * delta).max(0.0);
                }
                if i < n - 1 {
                    pnew[i + 1] = (pnew[i + 1] - 0.5 * delta).max(0.0);
                }
            }
        }
    }
    std::mem::swap(&mut level.p, &mut s.pnew);
}
