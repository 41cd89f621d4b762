//! The form of the friction curve with a limiting shear stress (beyond the paper).
//!
//! With a limit the reduced friction can no longer follow one curve in `tau_c`: it cannot
//! exceed the saturated value `mu_S = Lambda-bar + 1.5 tau_L0 / tau0` (the Hertzian circle's
//! friction with the limiting stress everywhere, `rheology::ShearLaw::friction_bound`). The
//! second parameter is therefore `mu_S`, and the candidate form joins the Eyring curve `mu_E`
//! to it with the same smooth minimum the rheology uses for the stress,
//!
//! `mu-bar = mu_E (1 + (mu_E / mu_S)^n)^(-1/n)`,
//!
//! with `mu_E` either Eq. (13), `asinh(tau_c / 5)` (a curve in `tau_c` and `mu_S` alone), or
//! the case's own Eyring friction (which separates the scatter of Eq. (13) from that of the
//! saturation). The exponent `n` is fitted by least squares in `mu-bar` units.

/// The candidate form with exponent `n`: `mu_E (1 + (mu_E / mu_S)^n)^(-1/n)`.
pub fn saturated(mu_e: f64, mu_s: f64, n: f64) -> f64 {
    mu_e * (1.0 + (mu_e / mu_s).powf(n)).powf(-1.0 / n)
}

/// One case: its Eyring friction, saturated value and the limited solver's friction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FormPoint {
    /// Eyring friction (Eq. 13 at the case's `tau_c`, or the case's own Eyring solve).
    pub mu_e: f64,
    /// Saturated friction `mu_S`.
    pub mu_s: f64,
    /// The solver's friction with the limit.
    pub mu_bar: f64,
}

/// The fitted form and its scatter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FormFit {
    /// Fitted exponent `n`.
    pub n: f64,
    /// Cases.
    pub points: usize,
    /// RMS deviation, `mu-bar` units.
    pub rms_abs_dev: f64,
    /// Largest absolute deviation, `mu-bar` units.
    pub max_abs_dev: f64,
    /// RMS relative deviation.
    pub rms_rel_dev: f64,
}

/// Range of the exponent searched: below 0.5 the join is softer than any saturation the
/// rheology produces, above 20 it is a sharp `min`.
const N_RANGE: (f64, f64) = (0.5, 20.0);

/// The scatter of `points` about the form with exponent `n`.
fn scatter(points: &[FormPoint], n: f64) -> FormFit {
    let (mut sq, mut max, mut rel) = (0.0_f64, 0.0_f64, 0.0_f64);
    for p in points {
        let d = p.mu_bar - saturated(p.mu_e, p.mu_s, n);
        sq += d * d;
        max = max.max(d.abs());
        rel += (d / p.mu_bar).powi(2);
    }
    let k = points.len() as f64;
    FormFit {
        n,
        points: points.len(),
        rms_abs_dev: (sq / k).sqrt(),
        max_abs_dev: max,
        rms_rel_dev: (rel / k).sqrt(),
    }
}

/// The least-squares exponent over [`N_RANGE`], searched by golden section on `ln n` (the
/// RMS is smooth and, over the cases of the target, unimodal in `n`; a coarse scan first
/// brackets the minimum so that a second local minimum could not capture the search).
/// `None` for fewer than two points.
pub fn fit(points: &[FormPoint]) -> Option<FormFit> {
    if points.len() < 2 {
        return None;
    }
    let rms = |ln_n: f64| scatter(points, ln_n.exp()).rms_abs_dev;
    let (lo, hi) = (N_RANGE.0.ln(), N_RANGE.1.ln());
    let steps = 40;
    let at = |i: usize| lo + (hi - lo) * i as f64 / steps as f64;
    let best = (0..=steps)
        .min_by(|&a, &b| rms(at(a)).total_cmp(&rms(at(b))))
        .unwrap_or(0);
    let (mut a, mut b) = (at(best.saturating_sub(1)), at((best + 1).min(steps)));
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..60 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if rms(c) < rms(d) {
            b = d;
        } else {
            a = c;
        }
    }
    Some(scatter(points, ((a + b) / 2.0).exp()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_form_tends_to_its_two_limits() {
        // mu_E << mu_S: Eyring (defect (mu_E/mu_S)^n / n relative = 5e-9 at n = 2);
        // mu_E >> mu_S: the saturated value (defect (mu_S/mu_E)^n / n = 5e-9).
        assert!((saturated(1e-3, 10.0, 2.0) / 1e-3 - 1.0).abs() < 1e-8);
        assert!((saturated(1e5, 10.0, 2.0) / 10.0 - 1.0).abs() < 1e-8);
        // Equal: 2^(-1/n) of either.
        assert!((saturated(4.0, 4.0, 3.0) - 4.0 * 2f64.powf(-1.0 / 3.0)).abs() < 1e-14);
    }

    #[test]
    fn fit_recovers_the_exponent_of_exact_data() {
        // Points made with n = 3.7 exactly: the search returns it to its tolerance (golden
        // section 60 steps on a bracket of one scan step: far below 1e-6) with zero scatter.
        let points: Vec<FormPoint> = [
            (2.0, 5.0),
            (5.0, 5.0),
            (9.0, 5.0),
            (20.0, 10.0),
            (8.0, 40.0),
        ]
        .iter()
        .map(|&(mu_e, mu_s)| FormPoint {
            mu_e,
            mu_s,
            mu_bar: saturated(mu_e, mu_s, 3.7),
        })
        .collect();
        let f = fit(&points).unwrap();
        assert!((f.n - 3.7).abs() < 1e-6, "{f:?}");
        assert!(f.rms_abs_dev < 1e-9 && f.max_abs_dev < 1e-9, "{f:?}");
        assert_eq!(f.points, 5);
        assert!(fit(&points[..1]).is_none());
    }
}
