//! What the paper's pictures share: its symbols in the plot kit's text markup, and the model
//! curve every figure draws, Eq. (13), dashed.

use crate::plot::{significant, Curve};

/// Reduced friction coefficient, mu-bar (dimensionless), with an overbar.
pub const MU_BAR: &str = "μ\u{304}";
/// Characteristic shear stress, tau_c-bar (dimensionless), Eq. (12).
pub const TAU_C: &str = "τ\u{304}_{c}";
/// The severity group of Fig. 1, S-bar^(1/4) M L^3 (dimensionless).
pub const SEVERITY: &str = "S\u{304}^{1/4} M L^{3}";

/// Mastercurve Eq. (13) with constant `c`: mu-bar = asinh(tau_c / c), sampled at `n` points
/// (at least 2) spaced uniformly in log tau_c over [`x_min`, `x_max`], dashed.
///
/// The label reads "Eq. (13): ..." for c = 5 and "fit: ..." otherwise. Bounds that are not
/// finite with 0 < `x_min` < `x_max`, or a `c` that is not finite and positive, give a curve
/// without points: nothing is drawn for it.
pub fn eq13_curve(x_min: f64, x_max: f64, c: f64, n: usize) -> Curve {
    let is_eq13 = (c - 5.0).abs() < 1e-12;
    let label = if is_eq13 {
        format!("Eq. (13): {MU_BAR} = asinh({TAU_C}/5)")
    } else {
        format!("fit: {MU_BAR} = asinh({TAU_C}/{})", significant(c, 3))
    };
    let valid = x_min.is_finite()
        && x_max.is_finite()
        && x_min > 0.0
        && x_max > x_min
        && c.is_finite()
        && c > 0.0;
    let points = if valid {
        let n = n.max(2);
        let (l0, l1) = (x_min.log10(), x_max.log10());
        (0..n)
            .map(|i| {
                let t = i as f64 / (n - 1) as f64;
                let x = if i == 0 {
                    x_min
                } else if i == n - 1 {
                    x_max
                } else {
                    10f64.powf(l0 + t * (l1 - l0))
                };
                (x, (x / c).asinh())
            })
            .collect()
    } else {
        Vec::new()
    };
    Curve {
        label,
        points,
        dashed: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mastercurve_samples_eq13_log_uniformly() {
        let c = eq13_curve(0.01, 1e4, 5.0, 7);
        assert!(c.dashed);
        assert!(c.label.starts_with("Eq. (13)"));
        assert_eq!(c.points.len(), 7);
        assert_eq!(c.points[0].0, 0.01);
        assert_eq!(c.points[6].0, 1e4);
        for (i, &(x, y)) in c.points.iter().enumerate() {
            // log-uniform: one decade per step here; 1e-12 relative covers powf rounding.
            let expect = 10f64.powi(i as i32 - 2);
            assert!((x / expect - 1.0).abs() < 1e-12, "x[{i}] = {x}");
            assert!((y - (x / 5.0).asinh()).abs() < 1e-15);
        }
        let fit = eq13_curve(0.1, 10.0, 4.9312, 10);
        assert!(fit.label.contains("/4.93)"), "{}", fit.label);
        assert!(eq13_curve(0.0, 10.0, 5.0, 10).points.is_empty());
        assert!(eq13_curve(1.0, 10.0, -5.0, 10).points.is_empty());
        assert_eq!(eq13_curve(1.0, 10.0, 5.0, 0).points.len(), 2);
    }
}
