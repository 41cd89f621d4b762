//! A sparse matrix bordered by one dense column and one dense row,
//! `[[A, u], [w^T, d]]`, solved through a sparse LU of `A` alone (faer's supernodal LU with
//! partial pivoting, in a COLAMD fill-reducing column order, single precision) and the
//! scalar Schur complement `d - w^T A^-1 u`.
//!
//! This is the preconditioner of the point contact's Newton-Krylov finish: `A` the Reynolds
//! rows with the elastic kernel truncated to a box, `u` the `Delta` column, `w` the force
//! balance. Keeping the two dense vectors out of the sparse factorisation keeps them from
//! filling it.
//!
//! The column order is kept from one factorisation to the next while the columns are mostly
//! the same ones: each column carries a label (its grid node), and a new system whose labels
//! the last COLAMD order ranked, but for a few, is factorised in that order (the few last):
//! COLAMD is a fifth to a quarter of a factorisation, and a Newton step moves only the
//! cavitation boundary's nodes. faer's own driver recomputes it every time; this one calls
//! faer's public symbolic and numeric steps itself to pass the order in.
//!
//! The factor is single precision: the box already makes the preconditioner an approximation
//! of the Jacobian that GMRES corrects, a rounding of 1e-7 relative changes nothing it sees,
//! and single precision halves the memory the factorisation and its solves stream through.
//! GMRES is the flexible form, which does not need the rounded solves to be exactly linear
//! ([`super::gmres`]). The measurements behind both choices: docs/ACCURACY_NOTES.md, "The
//! Newton-Krylov preconditioner's factor".
//! Its factorisation and solves run with flush-to-zero: the factor's fill decays through
//! `f32`'s subnormal range, which costs an Intel core a microcode assist per operand
//! ([`super::subnormal`]).

use super::subnormal::{self, FlushToZero};
use faer::dyn_stack::{MemStack, StackReq};
use faer::perm::{Perm, PermRef};
use faer::sparse::linalg::lu::supernodal::{
    factorize_supernodal_numeric_lu, factorize_supernodal_numeric_lu_scratch,
    factorize_supernodal_symbolic_lu, factorize_supernodal_symbolic_lu_scratch,
    solve_in_place_scratch, SupernodalLu, SymbolicSupernodalLu,
};
use faer::sparse::linalg::{colamd, qr};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, MatMut};
use std::mem::MaybeUninit;

/// An entry `(row, column, value)` of the sparse block.
pub(crate) type Entry = Triplet<usize, usize, f64>;

/// The floating-point type of the factor.
type Factor = f32;

/// Largest share of a system's columns the kept order may lack a rank for: above it,
/// COLAMD orders the system afresh. 2 %: the Newton steps of the M = 19 205 case change a
/// few hundred of 200 000 active nodes at level 8.
const NEW_COLUMNS_SHARE: f64 = 0.02;

/// The storage of a factorisation, handed from one factorisation to the next (the Newton
/// steps of a level): the numeric factor and work buffers (faer allocates its own afresh for
/// every factorisation and every solve; at level 7 the kernel's page faults on that fresh
/// memory were a fifth of a Newton-Krylov solve) and the column order by label.
#[derive(Default, Clone)]
pub(crate) struct LuStorage {
    /// The last numeric factor, refilled by the next factorisation whatever its order
    /// (faer's supernodal factor; its simplicial one, which faer's own driver chooses for
    /// small systems, kept a longer system's column pointers and failed an assertion on a
    /// shorter one).
    numeric: SupernodalLu<usize, Factor>,
    /// The last COLAMD order's position of each label, `u32::MAX` for none.
    ranks: Vec<u32>,
    /// Row permutation of the last factor (forward, inverse).
    row_perm: (Vec<usize>, Vec<usize>),
    factor_work: Vec<MaybeUninit<u8>>,
    solve_work: Vec<MaybeUninit<u8>>,
    rhs: Vec<Factor>,
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

/// The column order of a system whose column `c` carries `labels[c]`: the kept ranks', the
/// unranked columns last, or `None` when too many are unranked.
fn kept_order(ranks: &[u32], labels: &[usize]) -> Option<Vec<usize>> {
    let rank = |c: usize| ranks.get(labels[c]).copied().unwrap_or(u32::MAX);
    let unranked = (0..labels.len()).filter(|&c| rank(c) == u32::MAX).count();
    if ranks.is_empty() || unranked as f64 > NEW_COLUMNS_SHARE * labels.len() as f64 {
        return None;
    }
    let mut order: Vec<usize> = (0..labels.len()).collect();
    order.sort_by_key(|&c| (rank(c), labels[c]));
    Some(order)
}

/// COLAMD's column order of `a`.
fn colamd_order(a: &SparseColMat<usize, Factor>) -> Option<Vec<usize>> {
    let n = a.ncols();
    let (mut fwd, mut inv) = (vec![0usize; n], vec![0usize; n]);
    let mut buffer = Vec::new();
    let req = colamd::order_scratch::<usize>(n, n, a.compute_nnz());
    colamd::order(
        &mut fwd,
        &mut inv,
        a.symbolic(),
        Default::default(),
        work_space(&mut buffer, req),
    )
    .ok()?;
    Some(fwd)
}

/// The supernodal symbolic factorisation of `a` (`at` its transpose) in column order
/// `perm`, as faer's own driver computes it: the column elimination tree, its postorder,
/// the column counts of the Cholesky factor of `A^T A`.
fn symbolic(
    a: &SparseColMat<usize, Factor>,
    at: &SparseColMat<usize, Factor>,
    perm: PermRef<'_, usize>,
) -> Option<SymbolicSupernodalLu<usize>> {
    let n = a.ncols();
    let mut buffer = Vec::new();
    let mut etree = vec![0usize; n];
    let etree = qr::col_etree(
        a.symbolic(),
        Some(perm),
        &mut etree,
        work_space(&mut buffer, qr::col_etree_scratch::<usize>(n, n)),
    );
    let mut post = vec![0usize; n];
    qr::postorder(
        &mut post,
        etree,
        work_space(&mut buffer, qr::postorder_scratch::<usize>(n)),
    );
    let (mut counts, mut min_col) = (vec![0usize; n], vec![0usize; n]);
    qr::column_counts_ata(
        &mut counts,
        &mut min_col,
        at.symbolic(),
        Some(perm),
        etree,
        &post,
        work_space(&mut buffer, qr::column_counts_aat_scratch::<usize>(n, n)),
    );
    factorize_supernodal_symbolic_lu(
        a.symbolic(),
        Some(perm),
        &min_col,
        etree,
        &counts,
        work_space(
            &mut buffer,
            factorize_supernodal_symbolic_lu_scratch::<usize>(n, n),
        ),
        Default::default(),
    )
    .ok()
}

/// The factorised bordered matrix.
#[derive(Clone)]
pub(crate) struct BorderedLu {
    numeric: SupernodalLu<usize, Factor>,
    /// Column and row orders, checked once here: each solve of GMRES's hundreds would
    /// otherwise check both again (1.1 % of a level-7 Newton-Krylov family's time).
    col_perm: Perm<usize>,
    row_perm: Perm<usize>,
    /// Whether COLAMD ordered the system afresh (else the kept order served): for the tests.
    #[cfg(test)]
    reordered: bool,
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
    /// positions are summed) and `labels[c]` column `c`'s label, in `storage` (an earlier
    /// factorisation's, or a new one). `None` when `A` or the Schur complement is singular
    /// or not finite.
    pub fn factorize(
        entries: &[Entry],
        labels: &[usize],
        u: &[f64],
        w: &[f64],
        d: f64,
        mut storage: LuStorage,
    ) -> Option<Self> {
        let n = labels.len();
        debug_assert!(u.len() == n && w.len() == n);
        if entries.iter().any(|e| !e.val.is_finite()) {
            return None;
        }
        // The entries narrowed and factorised with flush-to-zero ([`subnormal`]).
        let ftz = FlushToZero::new();
        let narrow: Vec<Triplet<usize, usize, Factor>> = entries
            .iter()
            .map(|e| Triplet::new(e.row, e.col, e.val as Factor))
            .collect();
        let a = SparseColMat::<usize, Factor>::try_new_from_triplets(n, n, &narrow).ok()?;
        let at = a.as_ref().transpose().to_col_major().ok()?;
        let kept = kept_order(&storage.ranks, labels);
        #[cfg(test)]
        let reordered = kept.is_none();
        let fwd = match kept {
            Some(order) => order,
            None => {
                let order = colamd_order(&a)?;
                let size = labels.iter().max().map_or(0, |m| m + 1);
                storage.ranks.clear();
                storage.ranks.resize(size, u32::MAX);
                for (position, &c) in order.iter().enumerate() {
                    storage.ranks[labels[c]] = position as u32;
                }
                order
            }
        };
        let mut inv = vec![0usize; n];
        for (position, &c) in fwd.iter().enumerate() {
            inv[c] = position;
        }
        let perm = PermRef::new_checked(&fwd, &inv, n);
        let symbolic = symbolic(&a, &at, perm)?;
        super::fix_factorisation_parallelism();
        let par = faer::get_global_parallelism();
        let mut numeric = std::mem::replace(&mut storage.numeric, SupernodalLu::new());
        let (row_fwd, row_inv) = &mut storage.row_perm;
        row_fwd.resize(n, 0);
        row_inv.resize(n, 0);
        let req =
            factorize_supernodal_numeric_lu_scratch::<usize, Factor>(&symbolic, Default::default());
        factorize_supernodal_numeric_lu(
            row_fwd,
            row_inv,
            &mut numeric,
            a.as_ref(),
            at.as_ref(),
            perm,
            &symbolic,
            par,
            work_space(&mut storage.factor_work, req),
            Default::default(),
        )
        .ok()?;
        drop(ftz);
        subnormal::record_factor(&numeric);
        let (row_fwd, row_inv) = std::mem::take(&mut storage.row_perm);
        let mut out = BorderedLu {
            numeric,
            col_perm: Perm::new_checked(fwd.into_boxed_slice(), inv.into_boxed_slice(), n),
            row_perm: Perm::new_checked(row_fwd.into_boxed_slice(), row_inv.into_boxed_slice(), n),
            #[cfg(test)]
            reordered,
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
        storage.numeric = self.numeric;
        let (row_fwd, row_inv) = self.row_perm.into_arrays();
        storage.row_perm = (row_fwd.into_vec(), row_inv.into_vec());
        storage
    }

    /// `x = A^-1 b`.
    fn solve_block(&mut self, b: &[f64], x: &mut [f64]) {
        let n = b.len();
        let par = faer::get_global_parallelism();
        let req = solve_in_place_scratch::<usize, Factor>(n, 1, par);
        let storage = &mut self.storage;
        // Narrowed, solved and widened with flush-to-zero ([`subnormal`]).
        let _ftz = FlushToZero::new();
        let rhs = &mut storage.rhs;
        rhs.clear();
        rhs.extend(b.iter().map(|&v| v as Factor));
        self.numeric.solve_in_place_with_conj(
            self.row_perm.as_ref(),
            self.col_perm.as_ref(),
            Conj::No,
            MatMut::from_column_major_slice_mut(rhs, n, 1),
            par,
            work_space(&mut storage.solve_work, req),
        );
        x.iter_mut()
            .zip(rhs.iter())
            .for_each(|(x, &r)| *x = r as f64);
    }

    /// Solves the bordered system for `rhs` (length `n + 1`, the last entry the border
    /// row's) into `out`.
    pub fn solve(&mut self, rhs: &[f64], out: &mut [f64]) {
        let n = self.w.len();
        subnormal::record_vector(rhs);
        self.solve_block(&rhs[..n], &mut out[..n]);
        // A y = b; then xd = (bd - w^T y) / schur, x = y - A^-1 u xd.
        let wy: f64 = self.w.iter().zip(&out[..n]).map(|(a, b)| a * b).sum();
        let xd = (rhs[n] - wy) / self.schur;
        for i in 0..n {
            out[i] -= self.a_inv_u[i] * xd;
        }
        out[n] = xd;
        subnormal::record_vector(out);
    }
}

#[cfg(test)]
mod tests;
