//! The damping of a Newton step, shared by the line- and point-contact Newton iterations.

/// Smallest damping factor tried.
pub(crate) const MIN_DAMPING: f64 = 1.0 / 256.0;

/// Backtracking on the residual norm: `apply(omega)` applies the step scaled by `omega` and
/// returns the new norm; `omega` is halved from 1 until that norm falls below
/// `(1 - 1e-4 omega) norm0` (Armijo's sufficient decrease) or `omega` reaches 1/256, where
/// the last trial stays applied. Returns the `omega` taken.
pub(crate) fn backtrack(norm0: f64, mut apply: impl FnMut(f64) -> f64) -> f64 {
    let mut omega = 1.0;
    loop {
        let norm = apply(omega);
        if (norm.is_finite() && norm < (1.0 - 1e-4 * omega) * norm0) || omega <= MIN_DAMPING {
            return omega;
        }
        omega *= 0.5;
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn halves_until_the_norm_decreases() {
        // A norm that only decreases for steps of at most 1/8.
        let omega = super::backtrack(1.0, |w| if w <= 0.125 { 0.5 } else { 2.0 });
        assert_eq!(omega, 0.125);
        // Never decreasing: stops at the smallest damping.
        assert_eq!(super::backtrack(1.0, |_| f64::NAN), 1.0 / 256.0);
    }
}
