//! Dense LU factorisation with partial pivoting: the Newton steps of the line contact, whose
//! Jacobian is full because every pressure moves every film value through the elastic kernel.

/// Solves `A x = b` in place (`a` row-major `n x n`, destroyed; `b` becomes `x`). Returns
/// false when a pivot vanishes or is not finite.
pub(crate) fn solve(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    debug_assert_eq!(a.len(), n * n);
    for k in 0..n {
        let (mut piv, mut big) = (k, a[k * n + k].abs());
        for i in k + 1..n {
            let v = a[i * n + k].abs();
            if v > big {
                piv = i;
                big = v;
            }
        }
        if !(big > 0.0 && big.is_finite()) {
            return false;
        }
        if piv != k {
            for j in 0..n {
                a.swap(k * n + j, piv * n + j);
            }
            b.swap(k, piv);
        }
        let (top, rest) = a.split_at_mut((k + 1) * n);
        let row_k = &top[k * n + k..k * n + n];
        let inv = 1.0 / row_k[0];
        let bk = b[k];
        for (r, row) in rest.chunks_exact_mut(n).enumerate() {
            let l = row[k] * inv;
            if l == 0.0 {
                continue;
            }
            for (x, y) in row[k..].iter_mut().zip(row_k) {
                *x -= l * y;
            }
            b[k + 1 + r] -= l * bk;
        }
    }
    for k in (0..n).rev() {
        let row = &a[k * n..k * n + n];
        let s: f64 = row[k + 1..]
            .iter()
            .zip(&b[k + 1..])
            .map(|(x, y)| x * y)
            .sum();
        b[k] = (b[k] - s) / row[k];
    }
    b.iter().all(|v| v.is_finite())
}

#[cfg(test)]
mod tests {
    #[test]
    fn solves_a_pivoting_system() {
        // A zero leading pivot forces a row interchange; the answer (1, 2, 3) is exact in
        // binary floating point up to a few ulps.
        let mut a = vec![0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 4.0, -1.0, 2.0];
        let x = [1.0, 2.0, 3.0];
        let mut b: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[i * 3 + j] * x[j]).sum())
            .collect();
        assert!(super::solve(&mut a, &mut b, 3));
        for (u, v) in b.iter().zip(x) {
            assert!((u - v).abs() < 1e-14, "{u} vs {v}");
        }
        let mut singular = vec![1.0, 2.0, 2.0, 4.0];
        assert!(!super::solve(&mut singular, &mut [1.0, 1.0], 2));
    }
}
