//! The mastercurve: Eq. (13) `mu-bar = asinh(tau_c / c)` with `c = 5`, the least-squares `c`
//! of a set of points, and their deviations from Eq. (13).

use serde::Serialize;

/// The paper's constant in Eq. (13).
pub const PAPER_C: f64 = 5.0;

/// Eq. (13) (and Eq. 14) with constant `c`.
pub fn mastercurve(tau_c: f64, c: f64) -> f64 {
    (tau_c / c).asinh()
}

/// A fit of the mastercurve to points `(tau_c, mu-bar)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Fit {
    /// Points used.
    pub points: usize,
    /// Least-squares `c` of `mu-bar = asinh(tau_c / c)`.
    pub c: f64,
    /// RMS of `mu-bar / asinh(tau_c / 5) - 1`.
    pub rms_rel_dev: f64,
    /// Largest `|mu-bar / asinh(tau_c / 5) - 1|`.
    pub max_rel_dev: f64,
}

fn sum_sq(points: &[(f64, f64)], c: f64) -> f64 {
    points
        .iter()
        .map(|&(t, m)| (m - mastercurve(t, c)).powi(2))
        .sum()
}

/// Fits `c` by golden-section search of the squared residuals over `ln c` in
/// `[ln 0.01, ln 1000]` (the residual is smooth and, for points near any such curve,
/// unimodal in `c`), and measures the deviations from Eq. (13). Points with
/// `tau_c <= 0` or non-finite values are skipped. `None` for no usable point.
pub fn fit(points: &[(f64, f64)]) -> Option<Fit> {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|&(t, m)| t > 0.0 && t.is_finite() && m.is_finite())
        .collect();
    if pts.is_empty() {
        return None;
    }
    let (mut a, mut b) = (0.01f64.ln(), 1000f64.ln());
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let f = |x: f64| sum_sq(&pts, x.exp());
    let (mut x1, mut x2) = (b - g * (b - a), a + g * (b - a));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..200 {
        if f1 < f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
        if b - a < 1e-12 {
            break;
        }
    }
    let c = (0.5 * (a + b)).exp();
    let devs: Vec<f64> = pts
        .iter()
        .map(|&(t, m)| m / mastercurve(t, PAPER_C) - 1.0)
        .collect();
    let rms = (devs.iter().map(|d| d * d).sum::<f64>() / devs.len() as f64).sqrt();
    let max = devs.iter().fold(0.0f64, |acc, d| acc.max(d.abs()));
    Some(Fit {
        points: pts.len(),
        c,
        rms_rel_dev: rms,
        max_rel_dev: max,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_the_constant_of_exact_points() {
        let pts: Vec<(f64, f64)> = (0..30)
            .map(|i| 10f64.powf(i as f64 / 3.0 - 2.0))
            .map(|t| (t, mastercurve(t, 4.2)))
            .collect();
        let f = fit(&pts).unwrap();
        // Golden section to 1e-12 in ln c; exact data.
        assert!((f.c - 4.2).abs() < 1e-6, "{}", f.c);
        let on = fit(&pts
            .iter()
            .map(|&(t, _)| (t, mastercurve(t, 5.0)))
            .collect::<Vec<_>>())
        .unwrap();
        assert!(on.rms_rel_dev < 1e-12 && on.max_rel_dev < 1e-12);
        assert!(f.max_rel_dev > 0.01, "4.2 is visibly off Eq. (13)");
    }

    #[test]
    fn skips_unusable_points() {
        assert!(fit(&[(0.0, 1.0), (f64::NAN, 2.0)]).is_none());
        assert_eq!(fit(&[(1.0, 0.2), (-1.0, 0.1)]).unwrap().points, 1);
    }
}
