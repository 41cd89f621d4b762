//! Hertzian dry contact of two elastic bodies: elliptic integrals, the ellipticity
//! `kappa = a/b`, the contact scales `a`, `b`, `c`, `p_H` and the shape factor of Eq. (6).
//!
//! Conventions of the paper's Nomenclature: `x` is the rolling direction, `a` the semi-axis
//! along `x`, `b` along `y`, `D = Rx/Ry <= 1` so that `kappa = a/b <= 1`.

use std::f64::consts::PI;

/// The dimensionless load of the force balance, Eq. (7): the Hertzian pressure
/// `sqrt(1 - X^2 - Y^2)` integrated over the unit circle, `int P dX dY = 2 pi / 3`.
pub const DIMENSIONLESS_LOAD: f64 = 2.0 * PI / 3.0;

/// Complete elliptic integrals `(K, E)` of the Nomenclature, with parameter `1 - kappa^2`:
/// `K = int_0^{pi/2} (1 - (1-kappa^2) sin^2 psi)^{-1/2} dpsi`, `E` likewise with the power 1/2.
///
/// Computed by the arithmetic-geometric mean, which converges quadratically to machine
/// precision for `0 < kappa <= 1`.
pub fn elliptic_integrals(kappa: f64) -> (f64, f64) {
    let mut a = 1.0_f64;
    let mut b = kappa;
    // E = K (1 - sum 2^(n-1) c_n^2), c_0^2 = 1 - kappa^2.
    let mut sum = 0.5 * (1.0 - kappa * kappa);
    let mut pow2 = 0.5;
    for _ in 0..64 {
        if (a - b).abs() <= 1e-16 * a {
            break;
        }
        let c = 0.5 * (a - b);
        let an = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = an;
        pow2 *= 2.0;
        sum += pow2 * c * c;
    }
    let k = PI / (2.0 * a);
    (k, k * (1.0 - sum))
}

/// The Hertz relation between the ellipticity ratio and the contact ellipse,
/// `D = Rx/Ry = kappa^2 (K - E) / (E - kappa^2 K)`.
pub fn ellipticity_ratio(kappa: f64) -> f64 {
    let m = 1.0 - kappa * kappa;
    if m < 1e-7 {
        // Series about the circle, D = 1 - 3m/4 + O(m^2), where the quotient cancels.
        return 1.0 - 0.75 * m;
    }
    let (k, e) = elliptic_integrals(kappa);
    kappa * kappa * (k - e) / (e - kappa * kappa * k)
}

/// Solves the exact Hertz relation for `kappa` given `D = Rx/Ry` in `(0, 1]`
/// (bisection on the monotone `ellipticity_ratio`, to 1e-14).
pub fn kappa_from_ratio(d: f64) -> f64 {
    if d >= 1.0 {
        return 1.0;
    }
    let (mut lo, mut hi) = (1e-6_f64, 1.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if ellipticity_ratio(mid) < d {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-15 {
            break;
        }
    }
    0.5 * (lo + hi)
}

/// Shape factor of Eq. (6), `S(kappa) = (E - kappa^2 K) / ((1 - kappa^2) K)`, so that the
/// gap is `S X^2 + (1 - S) Y^2` in `X = x/a`, `Y = y/b`; `S(1) = 1/2`.
pub fn shape_factor(kappa: f64) -> f64 {
    let m = 1.0 - kappa * kappa;
    if m < 1e-7 {
        // Series about the circle: S = 1/2 - m/16 + O(m^2).
        return 0.5 - m / 16.0;
    }
    let (k, e) = elliptic_integrals(kappa);
    (e - kappa * kappa * k) / (m * k)
}

/// The Hertzian scales of an elliptical contact (Nomenclature), SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    /// Reduced radius of curvature in the rolling direction, m.
    pub rx: f64,
    /// Reduced radius of curvature across the rolling direction, m.
    pub ry: f64,
    /// Reduced modulus of elasticity `E'`, Pa.
    pub e_prime: f64,
    /// `kappa = a/b`.
    pub kappa: f64,
    /// Elliptic integral of the first kind at `kappa`.
    pub ell_k: f64,
    /// Elliptic integral of the second kind at `kappa`.
    pub ell_e: f64,
    /// Semi-axis along `x`, m.
    pub a: f64,
    /// Semi-axis along `y`, m.
    pub b: f64,
    /// Hertzian approach `c = (a^2 / 2R)(K/E)`, m.
    pub c: f64,
    /// Maximum Hertzian pressure, Pa.
    pub ph: f64,
    /// Normal load `f`, N.
    pub load: f64,
}

impl Hertz {
    /// Reduced radius `R`, `1/R = 1/Rx + 1/Ry`.
    pub fn reduced_radius(rx: f64, ry: f64) -> f64 {
        1.0 / (1.0 / rx + 1.0 / ry)
    }

    /// Contact scales from the maximum Hertzian pressure: eliminating `f` from the
    /// Nomenclature gives `a = 4 R E p_H / E'`, `b = a/kappa`, `c = 2 p_H a K / E'`.
    pub fn from_ph(ph: f64, rx: f64, ry: f64, e_prime: f64) -> Self {
        let kappa = kappa_from_ratio(rx / ry);
        let (ell_k, ell_e) = elliptic_integrals(kappa);
        let r = Self::reduced_radius(rx, ry);
        let a = 4.0 * r * ell_e * ph / e_prime;
        let b = a / kappa;
        let c = 2.0 * ph * a * ell_k / e_prime;
        let load = 2.0 * PI * a * b * ph / 3.0;
        Hertz {
            rx,
            ry,
            e_prime,
            kappa,
            ell_k,
            ell_e,
            a,
            b,
            c,
            ph,
            load,
        }
    }

    /// Contact scales from the load: `a = (3 f R / E')^{1/3} (2 kappa E / pi)^{1/3}` and
    /// `p_H = 3 f / (2 pi a b)`.
    pub fn from_load(load: f64, rx: f64, ry: f64, e_prime: f64) -> Self {
        let kappa = kappa_from_ratio(rx / ry);
        let (_, ell_e) = elliptic_integrals(kappa);
        let r = Self::reduced_radius(rx, ry);
        let a = (3.0 * load * r / e_prime * 2.0 * kappa * ell_e / PI).cbrt();
        let b = a / kappa;
        Self::from_ph(3.0 * load / (2.0 * PI * a * b), rx, ry, e_prime)
    }

    /// Shape factor `S(kappa)` of Eq. (6).
    pub fn shape_factor(&self) -> f64 {
        shape_factor(self.kappa)
    }

    /// Dimensionless Hertzian pressure `P = sqrt(1 - X^2 - Y^2)` inside the ellipse.
    pub fn pressure(x: f64, y: f64) -> f64 {
        let r2 = x * x + y * y;
        if r2 < 1.0 {
            (1.0 - r2).sqrt()
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elliptic_integrals_match_tabulated_values() {
        // K and E at parameter m = 1/2 (kappa = sqrt(1/2)), Abramowitz & Stegun Table 17.1,
        // printed to 1e-9.
        let (k, e) = elliptic_integrals(0.5_f64.sqrt());
        assert!((k - 1.854_074_677).abs() < 1e-9, "K = {k}");
        assert!((e - 1.350_643_881).abs() < 1e-9, "E = {e}");
        let (k1, e1) = elliptic_integrals(1.0);
        assert!((k1 - PI / 2.0).abs() < 1e-15 && (e1 - PI / 2.0).abs() < 1e-15);
    }

    #[test]
    fn kappa_of_the_spec_ellipticity_ratios() {
        // SPEC.md section 2 gives kappa to 4 digits for D = 1/2 and 1/5.
        assert!((kappa_from_ratio(0.5) - 0.6306).abs() < 5e-5);
        assert!((kappa_from_ratio(0.2) - 0.3460).abs() < 5e-5);
        assert!((kappa_from_ratio(1.0) - 1.0).abs() < 1e-15);
        // The inverse is exact to the bisection tolerance.
        for d in [0.05, 0.1, 0.3, 0.9, 0.999] {
            assert!(
                (ellipticity_ratio(kappa_from_ratio(d)) - d).abs() < 1e-10,
                "D = {d}"
            );
        }
    }

    #[test]
    fn shape_factor_is_one_half_for_a_circle_and_continuous() {
        assert!((shape_factor(1.0) - 0.5).abs() < 1e-15);
        // Continuity across the series switch at 1 - kappa^2 = 1e-7 (error of order m^2).
        let near = shape_factor((1.0 - 2e-7_f64).sqrt());
        assert!((near - 0.5).abs() < 1e-6);
        // S falls from 1/2 towards 0 as the ellipse narrows (K grows like ln(4/kappa)).
        assert!(shape_factor(0.346) < shape_factor(0.6306));
        assert!(shape_factor(0.6306) < 0.5);
    }

    #[test]
    fn load_returns_the_hertzian_pressure() {
        // SPEC.md: check that 3 f / (2 pi a b) returns p_H.
        for d in [1.0, 0.5, 0.2] {
            let rx = 1.03875e-2;
            let h = Hertz::from_ph(3e9, rx, rx / d, 226e9);
            let ph = 3.0 * h.load / (2.0 * PI * h.a * h.b);
            assert!((ph / 3e9 - 1.0).abs() < 1e-13, "D = {d}");
            let back = Hertz::from_load(h.load, rx, rx / d, 226e9);
            assert!((back.a / h.a - 1.0).abs() < 1e-12);
            assert!((back.c / h.c - 1.0).abs() < 1e-12);
            // c from the Nomenclature's own formula.
            let r = Hertz::reduced_radius(rx, rx / d);
            let c = h.a * h.a / (2.0 * r) * h.ell_k / h.ell_e;
            assert!((c / h.c - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn circular_worked_case_scales() {
        // Appendix case: p_H = 3 GPa, Rx = 1.03875e-2 m, E' = 226 GPa gives a = pi Rx p_H / E'.
        let h = Hertz::from_ph(3e9, 1.03875e-2, 1.03875e-2, 226e9);
        let a = PI * 1.03875e-2 * 3e9 / 226e9;
        assert!((h.a / a - 1.0).abs() < 1e-14);
        assert!((h.kappa - 1.0).abs() < 1e-15);
    }
}
