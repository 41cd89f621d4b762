//! Restarted flexible GMRES with right preconditioning (Saad, "Iterative Methods for Sparse
//! Linear Systems", 2nd ed., Alg. 9.6): the linear solver of the point contact's
//! Newton-Krylov finish, whose Jacobian is applied, never formed.
//!
//! Right preconditioning minimises the true residual `|b - A x|` over the Krylov space of
//! `A M^-1`, so the stopping test is on the residual the Newton iteration sees. The flexible
//! form keeps every preconditioned vector `z_k = M^-1 v_k` and builds the solution from them,
//! so the residual it reports is that of its solution even where `M^-1` is not exactly
//! linear: the preconditioner's single-precision factor rounds each solve (plain GMRES,
//! which applies `M^-1` once more to a combination of the `v_k`, left an error of 4e-7 behind
//! a reported 4e-13 residual); and that last application is saved.

/// How long a GMRES solve may run: the GMRES solves of the Newton-Krylov finish
/// ([`crate::solver::point::NewtonParams::krylov`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KrylovParams {
    /// Krylov vectors kept before a restart.
    pub restart: usize,
    /// Most iterations (matrix-vector products) in all. Default 200 per Newton step.
    pub max_iterations: usize,
}

/// What [`solve`] reached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Convergence {
    /// Matrix-vector products with `A`.
    pub iterations: usize,
    /// The relative residual `|b - A x| / |b|` at the end (from the Arnoldi recurrence,
    /// exact in exact arithmetic).
    pub relative_residual: f64,
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// Solves `A x = b` from `x = 0` to the relative residual `|b - A x| / |b|` `tolerance`: `apply(v,
/// out)` sets `out = A v`, `precondition(v, out)` sets `out = M^-1 v`. `x` receives the solution.
pub(crate) fn solve(
    b: &[f64],
    x: &mut [f64],
    params: &KrylovParams,
    tolerance: f64,
    mut apply: impl FnMut(&[f64], &mut [f64]),
    mut precondition: impl FnMut(&[f64], &mut [f64]),
) -> Convergence {
    let n = b.len();
    let m = params.restart.max(1);
    x.iter_mut().for_each(|v| *v = 0.0);
    let b_norm = norm(b);
    if b_norm == 0.0 || !b_norm.is_finite() {
        return Convergence {
            iterations: 0,
            relative_residual: if b_norm == 0.0 { 0.0 } else { f64::NAN },
        };
    }
    // Krylov basis (grown as the iteration needs it: a solve that converges in a few
    // iterations touches a few vectors, not `m + 1`), Hessenberg matrix (column-major,
    // (m + 1) x m), Givens rotations.
    let mut basis = vec![vec![0.0; n]];
    // The preconditioned vectors `z_k = M^-1 v_k`.
    let mut preconditioned: Vec<Vec<f64>> = Vec::new();
    let mut hess = vec![0.0; (m + 1) * m];
    let (mut cs, mut sn) = (vec![0.0; m], vec![0.0; m]);
    let mut g = vec![0.0; m + 1];
    let mut w = vec![0.0; n];
    let mut iterations = 0;
    let mut relative;
    let mut r = b.to_vec();
    loop {
        // r = b - A x (the true residual at every restart).
        if iterations > 0 {
            apply(x, &mut w);
            for (ri, (bi, wi)) in r.iter_mut().zip(b.iter().zip(&w)) {
                *ri = bi - wi;
            }
        }
        let beta = norm(&r);
        relative = beta / b_norm;
        if relative <= tolerance || iterations >= params.max_iterations {
            break;
        }
        for (v, ri) in basis[0].iter_mut().zip(&r) {
            *v = ri / beta;
        }
        g.iter_mut().for_each(|v| *v = 0.0);
        g[0] = beta;
        let mut k = 0;
        while k < m && iterations < params.max_iterations {
            if preconditioned.len() == k {
                preconditioned.push(vec![0.0; n]);
            }
            precondition(&basis[k], &mut preconditioned[k]);
            apply(&preconditioned[k], &mut w);
            iterations += 1;
            // Modified Gram-Schmidt.
            for i in 0..=k {
                let hik = dot(&w, &basis[i]);
                hess[k * (m + 1) + i] = hik;
                for (wj, vj) in w.iter_mut().zip(&basis[i]) {
                    *wj -= hik * vj;
                }
            }
            let h_next = norm(&w);
            hess[k * (m + 1) + k + 1] = h_next;
            if basis.len() == k + 1 {
                basis.push(vec![0.0; n]);
            }
            if h_next > 0.0 {
                for (v, wj) in basis[k + 1].iter_mut().zip(&w) {
                    *v = wj / h_next;
                }
            }
            // Apply the earlier rotations to the new column, then make its own.
            let col = &mut hess[k * (m + 1)..(k + 1) * (m + 1)];
            for i in 0..k {
                let t = cs[i] * col[i] + sn[i] * col[i + 1];
                col[i + 1] = -sn[i] * col[i] + cs[i] * col[i + 1];
                col[i] = t;
            }
            let rho = col[k].hypot(col[k + 1]);
            (cs[k], sn[k]) = if rho > 0.0 {
                (col[k] / rho, col[k + 1] / rho)
            } else {
                (1.0, 0.0)
            };
            col[k] = rho;
            col[k + 1] = 0.0;
            g[k + 1] = -sn[k] * g[k];
            g[k] *= cs[k];
            k += 1;
            relative = g[k].abs() / b_norm;
            if relative <= tolerance || h_next == 0.0 {
                break;
            }
        }
        // y = H^-1 g (upper triangular k x k); x += Z y.
        let mut y = vec![0.0; k];
        for i in (0..k).rev() {
            let mut s = g[i];
            for (j, yj) in y.iter().enumerate().skip(i + 1) {
                s -= hess[j * (m + 1) + i] * yj;
            }
            y[i] = s / hess[i * (m + 1) + i];
        }
        for (yi, zi) in y.iter().zip(&preconditioned) {
            for (xj, zj) in x.iter_mut().zip(zi) {
                *xj += yi * zj;
            }
        }
        if relative <= tolerance || iterations >= params.max_iterations || k == 0 {
            break;
        }
    }
    Convergence {
        iterations,
        relative_residual: relative,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A non-symmetric, diagonally dominant-ish convection-diffusion matrix on a line of
    /// `n` nodes, dense row-major.
    fn matrix(n: usize) -> Vec<f64> {
        let mut a = vec![0.0; n * n];
        for i in 0..n {
            a[i * n + i] = 2.5;
            if i > 0 {
                a[i * n + i - 1] = -1.6;
            }
            if i + 1 < n {
                a[i * n + i + 1] = -0.7;
            }
            // A long-range coupling, like the elastic kernel's.
            a[i * n + (i * 7) % n] += 0.05;
        }
        a
    }

    fn multiply(a: &[f64], v: &[f64], out: &mut [f64]) {
        let n = v.len();
        for (i, o) in out.iter_mut().enumerate() {
            *o = dot(&a[i * n..(i + 1) * n], v);
        }
    }

    #[test]
    fn matches_a_dense_solve_with_and_without_restarts() {
        let n = 60;
        let a = matrix(n);
        let exact: Vec<f64> = (0..n).map(|i| ((i * 13) % 7) as f64 - 3.0).collect();
        let mut b = vec![0.0; n];
        multiply(&a, &exact, &mut b);
        for restart in [n, 10] {
            let mut x = vec![0.0; n];
            let out = solve(
                &b,
                &mut x,
                &KrylovParams {
                    restart,
                    max_iterations: 1000,
                },
                1e-12,
                |v, o| multiply(&a, v, o),
                |v, o| o.copy_from_slice(v),
            );
            let err = x
                .iter()
                .zip(&exact)
                .fold(0.0f64, |m, (u, v)| m.max((u - v).abs()));
            // The matrix is well conditioned (dominant diagonal): a 1e-12 residual leaves an
            // error of a few 1e-12; 1e-9 catches any wrong update.
            assert!(out.relative_residual <= 1e-12, "restart {restart}: {out:?}");
            assert!(err < 1e-9, "restart {restart}: error {err:.3e}, {out:?}");
            if restart == n {
                assert!(out.iterations <= n, "{out:?}");
            }
        }
    }

    #[test]
    fn an_exact_preconditioner_converges_in_one_iteration() {
        let n = 30;
        let a = matrix(n);
        let b: Vec<f64> = (0..n).map(|i| (i as f64).sin()).collect();
        // M^-1 = A^-1 by a dense LU: A M^-1 = I, so one Krylov vector spans the solution.
        let inverse = |v: &[f64], o: &mut [f64]| {
            o.copy_from_slice(v);
            assert!(crate::solver::dense::solve(&a, o, n));
        };
        let mut x = vec![0.0; n];
        let out = solve(
            &b,
            &mut x,
            &KrylovParams {
                restart: 20,
                max_iterations: 50,
            },
            1e-10,
            |v, o| multiply(&a, v, o),
            inverse,
        );
        assert_eq!(out.iterations, 1, "{out:?}");
        let mut ax = vec![0.0; n];
        multiply(&a, &x, &mut ax);
        let res = ax
            .iter()
            .zip(&b)
            .fold(0.0f64, |m, (u, v)| m.max((u - v).abs()));
        assert!(res < 1e-12, "residual {res:.3e}");
    }
}
