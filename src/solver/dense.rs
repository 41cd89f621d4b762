//! Dense LU factorisation with partial pivoting (faer's blocked, parallel one): the Newton
//! steps of the line contact and of the point contact's pressurised nodes, whose Jacobians
//! are full because every pressure moves every film value through the elastic kernel.

use faer::linalg::solvers::Solve;
use faer::Mat;

/// Solves `A x = b` in place (`a` row-major `n x n`; `b` becomes `x`). Returns false when
/// the solution is not finite (a singular or non-finite matrix).
pub(crate) fn solve(a: &[f64], b: &mut [f64], n: usize) -> bool {
    debug_assert_eq!(a.len(), n * n);
    debug_assert_eq!(b.len(), n);
    if a.iter().any(|v| !v.is_finite()) {
        return false;
    }
    super::fix_factorisation_parallelism();
    let lu = Mat::from_fn(n, n, |i, j| a[i * n + j]).partial_piv_lu();
    let x = lu.solve(Mat::from_fn(n, 1, |i, _| b[i]));
    for (i, v) in b.iter_mut().enumerate() {
        *v = x[(i, 0)];
    }
    b.iter().all(|v| v.is_finite())
}

#[cfg(test)]
mod tests {
    #[test]
    fn solves_a_pivoting_system() {
        // A zero leading pivot forces a row interchange; the answer (1, 2, 3) is exact in
        // binary floating point up to a few ulps.
        let a = vec![0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 4.0, -1.0, 2.0];
        let x = [1.0, 2.0, 3.0];
        let mut b: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[i * 3 + j] * x[j]).sum())
            .collect();
        assert!(super::solve(&a, &mut b, 3));
        for (u, v) in b.iter().zip(x) {
            assert!((u - v).abs() < 1e-14, "{u} vs {v}");
        }
        let singular = vec![1.0, 2.0, 2.0, 4.0];
        assert!(!super::solve(&singular, &mut [1.0, 1.0], 2));
    }
}
