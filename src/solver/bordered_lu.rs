//! A sparse matrix bordered by one dense column and one dense row,
//! `[[A, u], [w^T, d]]`, solved through a sparse LU of `A` alone (faer's, with its COLAMD
//! fill-reducing column ordering) and the scalar Schur complement `d - w^T A^-1 u`.
//!
//! This is the preconditioner of the point contact's Newton-Krylov finish: `A` the Reynolds
//! rows with the elastic kernel truncated to a box, `u` the `Delta` column, `w` the force
//! balance. Keeping the two dense vectors out of the sparse factorisation keeps them from
//! filling it.

use faer::dyn_stack::{MemStack, StackReq};
use faer::sparse::linalg::lu::{factorize_symbolic_lu, LuRef, NumericLu, SymbolicLu};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, Mat};
use std::mem::MaybeUninit;

/// An entry `(row, column, value)` of the sparse block.
pub(crate) type Entry = Triplet<usize, usize, f64>;

/// The storage of a factorisation, handed from one factorisation to the next (the Newton
/// steps of a level). faer's own `Lu` allocates its work buffers afresh for every
/// factorisation and every solve (each GMRES iteration) and grows a new factor by
/// reallocation; at level 7 the kernel's page faults on that fresh memory were a fifth of
/// a Newton-Krylov solve (the 5P4E case: 200 000 faults). The arithmetic, and so every bit
/// of the result, is the same.
pub(crate) struct LuStorage {
    /// The last numeric factor and the order of its system. faer refills a numeric factor
    /// for a system at least as large without a trace of the old one, but for a smaller
    /// one its simplicial form keeps the old, longer column pointers (and fails an
    /// assertion when solving): a smaller system gets a new factor.
    numeric: Option<(usize, NumericLu<usize, f64>)>,
    factor_work: Vec<MaybeUninit<u8>>,
    solve_work: Vec<MaybeUninit<u8>>,
    rhs: Mat<f64>,
}

impl Default for LuStorage {
    fn default() -> Self {
        LuStorage {
            numeric: None,
            factor_work: Vec::new(),
            solve_work: Vec::new(),
            rhs: Mat::new(),
        }
    }
}

/// A work buffer of at least `req`, reusing `buffer`'s allocation where it is big enough.
fn work_space(buffer: &mut Vec<MaybeUninit<u8>>, req: StackReq) -> &mut MemStack {
    // The buffer's start need not be aligned as `req` asks: room for the padding too.
    let bytes = req.size_bytes() + req.align_bytes();
    if buffer.len() < bytes {
        buffer.resize(bytes, MaybeUninit::uninit());
    }
    MemStack::new(buffer.as_mut_slice())
}

/// The factorised bordered matrix.
pub(crate) struct BorderedLu {
    symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, f64>,
    storage: LuStorage,
    /// `A^-1 u`.
    a_inv_u: Vec<f64>,
    /// The border row `w`.
    w: Vec<f64>,
    /// The Schur complement `d - w^T A^-1 u`.
    schur: f64,
}

impl BorderedLu {
    /// Factorises `[[A, u], [w^T, d]]` with `A` the `n x n` matrix of `entries` (repeated
    /// positions are summed), in `storage` (an earlier factorisation's, or a new one).
    /// `None` when `A` or the Schur complement is singular or not finite.
    pub fn factorize(
        n: usize,
        entries: &[Entry],
        u: &[f64],
        w: &[f64],
        d: f64,
        mut storage: LuStorage,
    ) -> Option<Self> {
        debug_assert!(u.len() == n && w.len() == n);
        if entries.iter().any(|e| !e.val.is_finite()) {
            return None;
        }
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, entries).ok()?;
        super::fix_factorisation_parallelism();
        let par = faer::get_global_parallelism();
        let symbolic = factorize_symbolic_lu(a.symbolic(), Default::default()).ok()?;
        let req = symbolic.factorize_numeric_lu_scratch::<f64>(par, Default::default());
        let stack = work_space(&mut storage.factor_work, req);
        let mut numeric = match storage.numeric.take() {
            Some((order, numeric)) if order <= n => numeric,
            _ => NumericLu::new(),
        };
        symbolic
            .factorize_numeric_lu(&mut numeric, a.as_ref(), par, stack, Default::default())
            .ok()?;
        let mut out = BorderedLu {
            symbolic,
            numeric,
            storage,
            a_inv_u: Vec::new(),
            w: w.to_vec(),
            schur: 0.0,
        };
        let mut a_inv_u = vec![0.0; n];
        out.solve_block(u, &mut a_inv_u);
        out.a_inv_u = a_inv_u;
        if out.a_inv_u.iter().any(|x| !x.is_finite()) {
            return None;
        }
        let wz: f64 = out.w.iter().zip(&out.a_inv_u).map(|(a, b)| a * b).sum();
        out.schur = d - wz;
        (out.schur.is_finite() && out.schur != 0.0).then_some(out)
    }

    /// The storage, for the next factorisation.
    pub fn into_storage(self) -> LuStorage {
        let mut storage = self.storage;
        storage.numeric = Some((self.w.len(), self.numeric));
        storage
    }

    /// `x = A^-1 b`.
    fn solve_block(&mut self, b: &[f64], x: &mut [f64]) {
        let n = b.len();
        let par = faer::get_global_parallelism();
        let storage = &mut self.storage;
        if storage.rhs.nrows() != n {
            storage.rhs = Mat::zeros(n, 1);
        }
        storage
            .rhs
            .col_mut(0)
            .iter_mut()
            .zip(b)
            .for_each(|(r, v)| *r = *v);
        let req = self.symbolic.solve_in_place_scratch::<f64>(1, par);
        let stack = work_space(&mut storage.solve_work, req);
        LuRef::new_unchecked(&self.symbolic, &self.numeric).solve_in_place_with_conj(
            Conj::No,
            storage.rhs.as_mut(),
            par,
            stack,
        );
        x.iter_mut()
            .zip(storage.rhs.col(0).iter())
            .for_each(|(x, r)| *x = *r);
    }

    /// Solves the bordered system for `rhs` (length `n + 1`, the last entry the border
    /// row's) into `out`.
    pub fn solve(&mut self, rhs: &[f64], out: &mut [f64]) {
        let n = self.w.len();
        self.solve_block(&rhs[..n], &mut out[..n]);
        // A y = b; then xd = (bd - w^T y) / schur, x = y - A^-1 u xd.
        let wy: f64 = self.w.iter().zip(&out[..n]).map(|(a, b)| a * b).sum();
        let xd = (rhs[n] - wy) / self.schur;
        for i in 0..n {
            out[i] -= self.a_inv_u[i] * xd;
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
        let mut lu =
            BorderedLu::factorize(n, &entries, &u, &w, d, LuStorage::default()).expect("regular");
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

    /// A 2-D convection-diffusion block on an `m x m` grid with the 5 x 5 box of entries
    /// the Newton preconditioner has (big enough for faer's supernodal factorisation), or a
    /// 1-D one of order `m` (its simplicial one), with a Delta-like column and load row.
    fn system(m: usize, two_d: bool) -> (usize, Vec<Entry>, Vec<f64>, Vec<f64>) {
        let mut entries = Vec::new();
        let n = if two_d { m * m } else { m };
        for r in 0..n {
            entries.push(Triplet::new(r, r, 30.0 + (r % 7) as f64));
            if two_d {
                let (i, j) = ((r % m) as isize, (r / m) as isize);
                for dj in -2isize..=2 {
                    for di in -2isize..=2 {
                        let (a, b) = (i + di, j + dj);
                        if (di, dj) != (0, 0)
                            && (0..m as isize).contains(&a)
                            && (0..m as isize).contains(&b)
                        {
                            let c = (b * m as isize + a) as usize;
                            entries.push(Triplet::new(
                                r,
                                c,
                                -0.5 / (1.0 + (di * di + dj * dj) as f64) - 0.1 * di as f64,
                            ));
                        }
                    }
                }
            } else {
                if r > 0 {
                    entries.push(Triplet::new(r, r - 1, -1.5));
                }
                if r + 1 < n {
                    entries.push(Triplet::new(r, r + 1, -0.8));
                }
            }
        }
        let u = (0..n).map(|i| 0.3 + 0.01 * (i % 11) as f64).collect();
        let w = vec![1.0 / n as f64; n];
        (n, entries, u, w)
    }

    #[test]
    fn storage_handed_on_gives_the_bits_of_a_fresh_factorisation() {
        // Orders that shrink and grow, in both of faer's factorisations, as a Newton
        // iteration's active sets do: each solve must be the fresh factorisation's, bit for bit.
        let mut storage = LuStorage::default();
        for (m, two_d) in [
            (40, false),
            (30, false),
            (50, false),
            (50, false),
            (24, true),
            (20, true),
            (26, true),
            (35, false),
        ] {
            let (n, entries, u, w) = system(m, two_d);
            let rhs: Vec<f64> = (0..=n).map(|i| (0.37 * i as f64).cos()).collect();
            let mut fresh = BorderedLu::factorize(n, &entries, &u, &w, 0.0, LuStorage::default())
                .expect("regular");
            let mut reused =
                BorderedLu::factorize(n, &entries, &u, &w, 0.0, storage).expect("regular");
            let (mut a, mut b) = (vec![0.0; n + 1], vec![0.0; n + 1]);
            fresh.solve(&rhs, &mut a);
            reused.solve(&rhs, &mut b);
            assert_eq!(a, b, "order {n}");
            storage = reused.into_storage();
        }
    }

    #[test]
    fn a_singular_block_is_refused() {
        let entries = vec![Triplet::new(0, 0, 1.0), Triplet::new(1, 0, 1.0)];
        assert!(BorderedLu::factorize(
            2,
            &entries,
            &[1.0, 1.0],
            &[1.0, 1.0],
            0.0,
            LuStorage::default()
        )
        .is_none());
    }
}
