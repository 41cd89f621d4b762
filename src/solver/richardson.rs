//! The discretisation error of an output from its values on consecutive grid levels: the
//! observed order of convergence fitted by least squares, Richardson extrapolation at that
//! order, and Roache's safety factor on the correction (the grid convergence index, Roache,
//! "Verification and Validation in Computational Science and Engineering", 1998).
//!
//! With `X_n` the value on level `n` (mesh `2^-n`) and `d_n = X_n - X_(n-1)`, an error
//! `C h^p` makes `log2 |d_n|` fall by `p` per level: the order is the slope of a
//! least-squares line through `log2 |d_n|` over the levels (with three levels, two
//! differences, it is `log2 |d_(f-1) / d_f|`). It is accepted in [`ORDER_RANGE`] with every
//! difference of one sign; then `X_R = X_f + d_f / (2^p - 1)` and the error of `X_f` is
//! [`SAFETY_OBSERVED`] `|d_f| / (2^p - 1)`. Otherwise (oscillating, stagnating or
//! superconvergent levels, or only two) no order is trusted: the extrapolation takes `p = 1`,
//! whose correction `d_f` bounds the error of any order at least 1, and the error is
//! [`SAFETY_UNTRUSTED`] times `|d_f|` (Roache's two-grid factor), or, where the levels
//! oscillate or the finest difference vanished, times the larger of `|d_f|` and
//! `|d_(f-1)| / 2` (what first order predicts from the level below).
//!
//! The discretisation is second order where the grid resolves the pressure peak's flank and
//! falls to first order where it does not (docs/ACCURACY_NOTES.md, "the bisection"); the
//! orders observed at the working levels drift between 1 and 1.4 on the light contacts
//! (Fig. 6 case 23's central film: 1.33 over levels 5-7, 0.98 over 6-8), which is why the
//! correction carries a safety factor: without it, level 7's estimate of that film (0.29)
//! falls short of its distance to level 9 (0.31).

use serde::{Deserialize, Serialize};

/// The observed orders an extrapolation accepts: a uniform-grid discretisation of this
/// problem converges at first to second order (docs/ACCURACY_NOTES.md), and an order outside
/// [0.8, 3] says the levels are not in the asymptotic range (or that two of them agree by
/// chance) rather than what the next level will do.
pub const ORDER_RANGE: (f64, f64) = (0.8, 3.0);

/// Coarser levels a case is solved on for its discretisation error, below the finest: two,
/// the fewest that show an order of convergence.
pub const ERROR_LEVELS: u32 = 2;

/// Roache's safety factor where the order is observed over three or more levels.
pub const SAFETY_OBSERVED: f64 = 1.25;

/// Roache's safety factor where no observed order is trusted (two levels, or an order
/// outside [`ORDER_RANGE`], or oscillating levels): on the first-order bound.
pub const SAFETY_UNTRUSTED: f64 = 3.0;

/// An output's discretisation error on its finest level.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ErrorEstimate {
    /// The value extrapolated to a vanishing mesh (Richardson at [`ErrorEstimate::order_used`]).
    pub extrapolated: f64,
    /// The estimated absolute error of the finest value: the safety factor times its distance
    /// to the extrapolated value.
    pub error: f64,
    /// The order fitted over the levels (`None` where a difference is zero or not finite).
    pub order: Option<f64>,
    /// The order the extrapolation used: the fitted one where accepted, else 1.
    pub order_used: f64,
    /// Whether the differences between levels alternate in sign somewhere.
    pub oscillating: bool,
    /// Levels the estimate read.
    pub levels: usize,
}

impl ErrorEstimate {
    /// Whether the fitted order was accepted (else the estimate is the first-order bound).
    pub fn trusted(&self) -> bool {
        self.order
            .is_some_and(|p| !self.oscillating && p == self.order_used)
    }

    /// The error relative to the finest value `value`.
    pub fn relative(&self, value: f64) -> f64 {
        (self.error / value).abs()
    }
}

/// The least-squares order of `values` on consecutive levels, coarse to fine: minus the slope
/// of `log2 |d_n|` against `n`. `None` with fewer than two differences or a zero or
/// non-finite one.
pub fn fitted_order(values: &[f64]) -> Option<f64> {
    let logs: Vec<f64> = values
        .windows(2)
        .map(|w| (w[1] - w[0]).abs().log2())
        .collect();
    if logs.len() < 2 || logs.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let n = logs.len() as f64;
    let mean_i = (n - 1.0) / 2.0;
    let mean_l = logs.iter().sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (i, l) in logs.iter().enumerate() {
        let di = i as f64 - mean_i;
        sxy += di * (l - mean_l);
        sxx += di * di;
    }
    Some(-sxy / sxx)
}

/// The estimate of the finest of `values`, on consecutive levels coarse to fine; `None` with
/// fewer than two values or a non-finite one.
pub fn estimate(values: &[f64]) -> Option<ErrorEstimate> {
    if values.len() < 2 || values.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let diffs: Vec<f64> = values.windows(2).map(|w| w[1] - w[0]).collect();
    let oscillating = diffs.windows(2).any(|w| w[0] * w[1] < 0.0);
    let order = fitted_order(values);
    let accepted = order.filter(|p| !oscillating && (ORDER_RANGE.0..=ORDER_RANGE.1).contains(p));
    let (order_used, safety) = match accepted {
        Some(p) => (p, SAFETY_OBSERVED),
        None => (1.0, SAFETY_UNTRUSTED),
    };
    let last = diffs[diffs.len() - 1];
    let correction = last / (2f64.powf(order_used) - 1.0);
    // An oscillation's amplitude, or a finest difference that vanished by chance, is
    // bounded by what first order predicts from the difference below.
    let n = diffs.len();
    let size = if accepted.is_none() && n >= 2 && (oscillating || last == 0.0) {
        correction.abs().max(0.5 * diffs[n - 2].abs())
    } else {
        correction.abs()
    };
    Some(ErrorEstimate {
        extrapolated: values[values.len() - 1] + correction,
        error: safety * size,
        order,
        order_used,
        oscillating,
        levels: values.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn levels(exact: f64, c: f64, p: f64, n: std::ops::RangeInclusive<i32>) -> Vec<f64> {
        n.map(|l| exact + c * 2f64.powf(-p * l as f64)).collect()
    }

    #[test]
    fn an_exact_power_law_is_extrapolated_to_its_limit_at_its_order() {
        for p in [1.0, 1.3, 2.0] {
            let v = levels(11.4, -40.0, p, 5..=8);
            let e = estimate(&v).unwrap();
            assert!((e.order.unwrap() - p).abs() < 1e-9, "order {p}");
            assert!((e.extrapolated - 11.4).abs() < 1e-9, "order {p}");
            assert!(e.trusted());
            // The error is the safety factor times the true error of the finest level.
            let truth = (v[3] - 11.4).abs();
            assert!((e.error - SAFETY_OBSERVED * truth).abs() < 1e-9 * truth.max(1.0));
        }
    }

    #[test]
    fn three_levels_give_the_classical_observed_order() {
        let v: [f64; 3] = [9.5235, 10.6410, 11.0858];
        let p: f64 = ((v[1] - v[0]) / (v[2] - v[1])).log2();
        assert!((fitted_order(&v).unwrap() - p).abs() < 1e-12);
    }

    #[test]
    fn oscillating_or_out_of_range_levels_take_the_bounded_first_order() {
        // Oscillating: the larger of the finest difference and half the one below, times the
        // untrusted factor.
        let e = estimate(&[1.0, 1.2, 1.1]).unwrap();
        assert!(e.oscillating && !e.trusted());
        assert_eq!(e.order_used, 1.0);
        assert!((e.error - SAFETY_UNTRUSTED * 0.1).abs() < 1e-12);
        let e = estimate(&[1.0, 1.4, 1.3]).unwrap();
        assert!((e.error - SAFETY_UNTRUSTED * 0.2).abs() < 1e-12);
        // Superconvergent by chance (order 5): not trusted either, bounded by the finest
        // difference alone (the coarsest level is the one out of range).
        let e = estimate(&[1.0, 1.32, 1.33]).unwrap();
        assert!(!e.oscillating && !e.trusted());
        assert!((e.error - SAFETY_UNTRUSTED * 0.01).abs() < 1e-12);
        // Two levels: no order at all.
        let e = estimate(&[2.0, 2.1]).unwrap();
        assert_eq!(e.order, None);
        assert!((e.extrapolated - 2.2).abs() < 1e-12);
    }

    #[test]
    fn a_level_that_equals_the_next_has_no_order() {
        // Bounded by the level below, not zero.
        let e = estimate(&[1.0, 1.1, 1.1]).unwrap();
        assert_eq!(e.order, None);
        assert!((e.error - SAFETY_UNTRUSTED * 0.05).abs() < 1e-12);
        assert!(estimate(&[1.0]).is_none());
        assert!(estimate(&[1.0, f64::NAN, 1.0]).is_none());
    }
}
