//! Line relaxation of the Reynolds equation along `X` (Venner and Lubrecht 2000, ch. 12),
//! switching per point on the local coefficient:
//!
//! - Gauss-Seidel where `xi = eps/h^2` is large (the inlet and outside the contact), where the
//!   Poiseuille term dominates and the operator is elliptic;
//! - Jacobi distributive where `xi` is small (the high-pressure zone), where the equation
//!   degenerates to the integral wedge term: a change `c` at a node is applied with
//!   `-c/4` at its four neighbours, which turns the smooth-kernel integral operator into
//!   a local, diagonally dominant one.
//!
//! Each line's changes are solved together, with the elastic coupling along the line
//! (the kernel coefficients, distributed for Jacobi points) in a band of 3 lower and 2 upper
//! diagonals.

use super::level::{LevelFields, Model};
use crate::solver::banded::BandMatrix;

/// `xi = eps/h^2` above which a point is relaxed by Gauss-Seidel.
const XI_SWITCH: f64 = 0.3;
/// Under-relaxation of the Gauss-Seidel changes.
const OMEGA_GS: f64 = 0.4;
/// Under-relaxation of the Jacobi distributive changes.
const OMEGA_JD: f64 = 0.2;
const LOWER: usize = 3;
const UPPER: usize = 2;

/// Work space for the line solves.
#[derive(Debug)]
pub(crate) struct LineScratch {
    matrix: BandMatrix,
    rhs: Vec<f64>,
    gauss_seidel: Vec<bool>,
    pnew: Vec<f64>,
}

impl LineScratch {
    pub fn new() -> Self {
        LineScratch {
            matrix: BandMatrix::new(1, LOWER, UPPER),
            rhs: Vec::new(),
            gauss_seidel: Vec::new(),
            pnew: Vec::new(),
        }
    }
}

/// Kernel coefficients along the line, `dk[m] = D(m, 0)` for Gauss-Seidel and the
/// distributed `D(m,0) - (D(m+1,0) + D(|m-1|,0) + 2 D(m,1))/4` for Jacobi distributive.
fn line_kernel(level: &LevelFields) -> ([f64; 6], [f64; 6]) {
    let k = level.deformation.kernel();
    let mut gs = [0.0; 6];
    let mut jd = [0.0; 6];
    for m in 0..6isize {
        gs[m as usize] = k.at(m, 0);
        jd[m as usize] =
            k.at(m, 0) - 0.25 * (k.at(m + 1, 0) + k.at((m - 1).abs(), 0) + 2.0 * k.at(m, 1));
    }
    (gs, jd)
}

/// One relaxation sweep over all lines of `level` (film and coefficients are brought up to
/// date first, from the current pressure and `delta`: [`LevelFields::refresh`]).
pub(crate) fn relax(level: &mut LevelFields, model: &Model, delta: f64, scratch: &mut LineScratch) {
    level.refresh(delta, model);
    let (dk_gs, dk_jd) = line_kernel(level);
    scratch.pnew.clear();
    scratch.pnew.extend_from_slice(&level.p);
    let mut pnew = std::mem::take(&mut scratch.pnew);
    for j in 1..level.grid.ny {
        relax_line(level, j, &mut pnew, &dk_gs, &dk_jd, scratch);
    }
    std::mem::swap(&mut level.p, &mut pnew);
    scratch.pnew = pnew;
}

fn relax_line(
    level: &LevelFields,
    j: usize,
    pnew: &mut [f64],
    dk_gs: &[f64; 6],
    dk_jd: &[f64; 6],
    s: &mut LineScratch,
) {
    let g = level.grid;
    let n = g.nx - 1;
    let rhx = 1.0 / g.hx;
    s.matrix.reset(n);
    s.rhs.clear();
    s.rhs.resize(n, 0.0);
    s.gauss_seidel.clear();
    s.gauss_seidel.resize(n, false);
    let row = g.idx(0, j);
    for i in 1..g.nx {
        let r = i - 1;
        let c = row + i;
        let xi = level.xi(i, j);
        let [xw, xe, _, _] = xi;
        let sum: f64 = xi.iter().sum();
        // Gauss-Seidel only where the Poiseuille coupling across lines is strong: with Eyring
        // shear thinning the conductance along X stays large in the contact while the one
        // across lines is small, and there the elastic coupling between lines, which the line
        // solve does not see, needs the distributive scheme (the book's switch on any of the
        // four coefficients does not converge for M = 1000, L = 15, S-bar = 1).
        let gs = xi[2].max(xi[3]) > XI_SWITCH;
        s.gauss_seidel[r] = gs;
        let dk = if gs { dk_gs } else { dk_jd };
        // Jacobian of the wedge term with respect to the pressure at offset m along the line.
        let rho = |k: usize| level.rho[row + k];
        let d = |m: isize| dk[m.unsigned_abs()];
        let dwedge = |m: isize| -> f64 {
            if i >= 2 {
                rhx * (1.5 * rho(i) * d(m) - 2.0 * rho(i - 1) * d(m + 1)
                    + 0.5 * rho(i - 2) * d(m + 2))
            } else {
                rhx * (rho(i) * d(m) - rho(i - 1) * d(m + 1))
            }
        };
        // Gauss-Seidel uses the newest neighbours; Jacobi distributive the old ones.
        let lp = if gs {
            level.operator(pnew, i, j)
        } else {
            level.operator(&level.p, i, j)
        };
        s.rhs[r] = level.f[c] - lp;
        let diag = if gs { -sum } else { -1.25 * sum };
        s.matrix.set(r, r, diag - dwedge(0));
        let inside = |k: isize| k >= 0 && (k as usize) <= g.nx;
        let coupled = [-2isize, -1, 1, 2].iter().all(|&m| {
            inside(i as isize + m) && pnew[(row as isize + i as isize + m) as usize] > 0.0
        });
        if coupled {
            let q = 0.25 * sum;
            let (m1, m2, p1, p2) = if gs {
                (xw, 0.0, xe, 0.0)
            } else {
                (xw + q, -0.25 * xw, xe + q, -0.25 * xe)
            };
            for (m, poiseuille) in [(-3isize, 0.0), (-2, m2), (-1, m1), (1, p1), (2, p2)] {
                let k = i as isize + m;
                if k >= 1 && (k as usize) < g.nx {
                    s.matrix.set(r, (k - 1) as usize, poiseuille - dwedge(m));
                }
            }
        }
    }
    if !s.matrix.solve(&mut s.rhs) {
        return;
    }
    for i in 1..g.nx {
        let r = i - 1;
        let c = row + i;
        if s.gauss_seidel[r] {
            pnew[c] = (pnew[c] + OMEGA_GS * s.rhs[r]).max(0.0);
        } else {
            let old = pnew[c];
            pnew[c] = (old + OMEGA_JD * s.rhs[r]).max(0.0);
            let change = pnew[c] - old;
            let neighbours = [c - 1, c + 1, c - g.px(), c + g.px()];
            if pnew[c] > 0.0 && neighbours.iter().all(|&k| pnew[k] > 0.0) {
                let interior = [i > 1, i < g.nx - 1, j > 1, j < g.ny - 1];
                for (k, ok) in neighbours.iter().zip(interior) {
                    if ok {
                        pnew[*k] = (pnew[*k] - 0.25 * change).max(0.0);
                    }
                }
            }
        }
    }
}
