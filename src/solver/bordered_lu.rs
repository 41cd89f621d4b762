//! A sparse matrix bordered by one dense column and one dense row,
//! `[[A, u], [w^T, d]]`, solved through a sparse LU of `A` alone (faer's, with its COLAMD
//! fill-reducing column ordering) and the scalar Schur complement `d - w^T A^-1 u`.
//!
//! This is the preconditioner of the point contact's Newton-Krylov finish: `A` the Reynolds
//! rows with the elastic kernel truncated to a box, `u` the `Delta` column, `w` the force
//! balance. Keeping the two dense vectors out of the sparse factorisation keeps them from
//! filling it.

use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Lu, SymbolicLu};
use faer::sparse::{SparseColMat, Triplet};
use faer::Mat;

/// An entry `(row, column, value)` of the sparse block.
pub(crate) type Entry = Triplet<usize, usize, f64>;

/// The factorised bordered matrix.
pub(crate) struct BorderedLu {
    lu: Lu<usize, f64>,
    /// `A^-1 u`.
    a_inv_u: Vec<f64>,
    /// The border row `w`.
    w: Vec<f64>,
    /// The Schur complement `d - w^T A^-1 u`.
    schur: f64,
}

impl BorderedLu {
    /// Factorises `[[A, u], [w^T, d]]` with `A` the `n x n` matrix of `entries` (repeated
    /// positions are summed). `None` when `A` or the Schur complement is singular or not
    /// finite.
    pub fn factorize(n: usize, entries: &[Entry], u: &[f64], w: &[f64], d: f64) -> Option<Self> {
        debug_assert!(u.len() == n && w.len() == n);
        if entries.iter().any(|e| !e.val.is_finite()) {
            return None;
        }
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, entries).ok()?;
        super::fix_factorisation_parallelism();
        let symbolic = SymbolicLu::try_new(a.symbolic()).ok()?;
        let lu = Lu::try_new_with_symbolic(symbolic, a.as_ref()).ok()?;
        let mut out = BorderedLu {
            lu,
            a_inv_u: Vec::new(),
            w: w.to_vec(),
            schur: 0.0,
        };
        out.a_inv_u = out.solve_block(u);
        if out.a_inv_u.iter().any(|x| !x.is_finite()) {
            return None;
        }
        let wz: f64 = out.w.iter().zip(&out.a_inv_u).map(|(a, b)| a * b).sum();
        out.schur = d - wz;
        (out.schur.is_finite() && out.schur != 0.0).then_some(out)
    }

    /// `A^-1 b`.
    fn solve_block(&self, b: &[f64]) -> Vec<f64> {
        let x = self.lu.solve(Mat::from_fn(b.len(), 1, |i, _| b[i]));
        (0..b.len()).map(|i| x[(i, 0)]).collect()
    }

    /// Solves the bordered system for `rhs` (length `n + 1`, the last entry the border
    /// row's) into `out`.
    pub fn solve(&self, rhs: &[f64], out: &mut [f64]) {
        let n = self.w.len();
        let y = self.solve_block(&rhs[..n]);
        // A y = b; then xd = (bd - w^T y) / schur, x = y - A^-1 u xd.
        let wy: f64 = self.w.iter().zip(&y).map(|(a, b)| a * b).sum();
        let xd = (rhs[n] - wy) / self.schur;
        for i in 0..n {
            out[i] = y[i] - self.a_inv_u[i] * xd;
        }
        out[n] = xd;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_bordered_system_like_its_dense_form() {
        // A 1-D convection-diffusion block, a column and a row like Delta's and the load's.
        let n = 40;
        let mut entries = Vec::new();
        for i in 0..n {
            entries.push(Triplet::new(i, i, 2.4));
            if i > 0 {
                entries.push(Triplet::new(i, i - 1, -1.5));
            }
            if i + 1 < n {
                entries.push(Triplet::new(i, i + 1, -0.8));
                // A repeated position: summed.
                entries.push(Triplet::new(i, i + 1, 0.1));
            }
        }
        let u: Vec<f64> = (0..n).map(|i| 0.3 + 0.01 * i as f64).collect();
        let w = vec![0.05; n];
        let d = 0.0;
        let lu = BorderedLu::factorize(n, &entries, &u, &w, d).expect("regular");
        // The dense form of the same matrix, solved by the dense LU.
        let m = n + 1;
        let mut dense = vec![0.0; m * m];
        for e in &entries {
            dense[e.row * m + e.col] += e.val;
        }
        for i in 0..n {
            dense[i * m + n] = u[i];
            dense[n * m + i] = w[i];
        }
        dense[n * m + n] = d;
        let rhs: Vec<f64> = (0..m).map(|i| (0.37 * i as f64).cos()).collect();
        let mut expect = rhs.clone();
        assert!(crate::solver::dense::solve(&dense, &mut expect, m));
        let mut got = vec![0.0; m];
        lu.solve(&rhs, &mut got);
        let err = got
            .iter()
            .zip(&expect)
            .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
        // Both are backward-stable LU solves of a matrix with condition number ~1e2: they
        // agree to ~1e-14; 1e-11 catches a wrong Schur complement or border.
        assert!(err < 1e-11, "max difference {err:.3e}");
    }

    #[test]
    fn a_singular_block_is_refused() {
        let entries = vec![Triplet::new(0, 0, 1.0), Triplet::new(1, 0, 1.0)];
        assert!(BorderedLu::factorize(2, &entries, &[1.0, 1.0], &[1.0, 1.0], 0.0).is_none());
    }
}
