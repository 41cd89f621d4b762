//! The flat-film friction estimate: the Eyring mean shear stress of a parallel film under the
//! dry Hertzian pressure, averaged over the load. An oracle for the solvers' friction that
//! shares nothing with them but the viscosity law, and the base of the refined friction
//! formula (`paper::mastercurve::refined`).
//!
//! With the film `H` taken equal everywhere to its central value, the Couette argument of
//! Eq. (4) at pressure `P` is `x(P) = x_c eta_bar(P) / eta_bar(1)`, `x_c = N S eta_bar(1) / H`
//! its value at the centre, and the reduced friction of Eq. (8) over the Hertzian pressure is
//!
//! - elliptical contact (in `X = x/a`, `Y = y/b` the contact is the unit circle, the load
//!   `2 pi / 3`): `mu-bar_flat = 3 int_0^1 tau_m(x(P)) P dP`, `P = sqrt(1 - r^2)`;
//! - line contact (load `pi / 2` per unit length): `mu-bar_flat = (4 / pi) int_0^1
//!   tau_m(x(P)) P / sqrt(1 - P^2) dP`, integrated as `(4/pi) int_0^{pi/2} tau_m(x(cos t)) cos t dt`.
//!
//! For a circular contact `x_c = (tau_c / 2)(Hc / H)` with `Hc` of Eq. (10) and `H` in the
//! same (Moes) units: the form in SPEC.md. At large `x` with Barus, `tau_m = ln(2 x)` gives
//! `mu-bar_flat = 1.5 ln(2 x_c) - 0.5 alpha-bar`: at a given `tau_c` friction also falls with
//! the pressure-viscosity coefficient, which is why one curve in `tau_c` cannot hold exactly.

use super::rheology::ShearLaw;
use super::viscosity::Viscosity;
use std::f64::consts::{FRAC_PI_2, PI};

/// Intervals of the composite Simpson rule. The integrand is smooth; its sharpest feature is
/// the knee where `x(P) = 1`, about `1 / alpha_e` wide in `P` (`alpha_e` up to 64 in the
/// paper's cases), so 1024 intervals put some 16 points across it (a unit test shows the rule
/// with half the intervals agrees to 1e-7).
const INTERVALS: usize = 1024;

/// Above this `ln x` the Eyring stress `asinh(x)` is `ln(2x)` to double precision
/// (`asinh x - ln 2x ~ 1/(4x^2)`), and `x` itself may overflow.
const LN_X_ASYMPTOTIC: f64 = 20.0;

/// The contact's shape, which sets the Hertzian pressure's area weight.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Geometry {
    /// Elliptical (or circular) contact: weight `3 P dP` on `[0, 1]`.
    Elliptical,
    /// Line contact: weight `(4 / pi) P / sqrt(1 - P^2) dP`.
    Line,
}

/// The mean shear stress `tau_m / tau0` of Eq. (4) at pressure `P` for a Couette argument
/// given by its logarithm (`ln x`), without overflow however large `x` is; with a limiting
/// shear stress, the Eyring stress saturated at `tau_L(P)`.
fn mean_stress(rheology: ShearLaw, ln_x: f64, p: f64) -> f64 {
    let eyring = || {
        if ln_x > LN_X_ASYMPTOTIC {
            ln_x + std::f64::consts::LN_2
        } else {
            ln_x.exp().asinh()
        }
    };
    match rheology {
        ShearLaw::Newtonian => ln_x.exp(),
        ShearLaw::Eyring => eyring(),
        ShearLaw::EyringLss { .. } => rheology.saturate(eyring(), p),
    }
}

/// Composite Simpson rule of `f` over `[a, b]` with [`INTERVALS`] intervals.
fn simpson(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let h = (b - a) / INTERVALS as f64;
    let inner: f64 = (1..INTERVALS)
        .map(|i| {
            let w = if i % 2 == 1 { 4.0 } else { 2.0 };
            w * f(a + h * i as f64)
        })
        .sum();
    (f(a) + f(b) + inner) * h / 3.0
}

/// `mu-bar_flat` of a contact (module doc) with the lubricant's `viscosity` and `rheology`
/// and the centre's Couette argument `x_c = N S eta_bar(1) / H`, given by its logarithm
/// `ln_x_centre` (so that `eta_bar(1)` of 1e30 does not overflow).
pub fn mu_bar_flat(
    geometry: Geometry,
    rheology: ShearLaw,
    viscosity: &Viscosity,
    ln_x_centre: f64,
) -> f64 {
    let ln_eta_ph = viscosity.ln_eta_bar(1.0);
    let stress = |p: f64| {
        mean_stress(
            rheology,
            ln_x_centre + viscosity.ln_eta_bar(p) - ln_eta_ph,
            p,
        )
    };
    match geometry {
        Geometry::Elliptical => 3.0 * simpson(0.0, 1.0, |p| stress(p) * p),
        Geometry::Line => {
            4.0 / PI
                * simpson(0.0, FRAC_PI_2, |t| {
                    let c = t.cos();
                    stress(c) * c
                })
        }
    }
}

/// `ln x_c = ln(N S) + ln eta_bar(p_H) - ln H`: the logarithm of the centre's Couette argument
/// of Eq. (4) for `n_s = N S` and the central film `h_central` (`H`, the solver's units).
pub fn ln_couette_centre(n_s: f64, viscosity: &Viscosity, h_central: f64) -> f64 {
    n_s.ln() + viscosity.ln_eta_bar(1.0) - h_central.ln()
}

/// The effective pressure-viscosity exponent `alpha_e = p_H d(ln eta)/dp` at `p_H`: `alpha-bar`
/// for Barus, less for Roelands, whose viscosity bends over at high pressure. A central
/// difference of `ln eta_bar` in `P` (step 1e-4: the truncation error, `~ 1e-8` relative, is far
/// below any use of it).
pub fn alpha_e(viscosity: &Viscosity) -> f64 {
    let dp = 1e-4;
    (viscosity.ln_eta_bar(1.0 + dp) - viscosity.ln_eta_bar(1.0 - dp)) / (2.0 * dp)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_viscosity_gives_the_load_weights() {
        // eta independent of p (Barus with alpha-bar = 0): the stress is asinh(x_c) everywhere
        // and the weights integrate to int dA / int P dA: 3/2 for the ellipse, 4/pi for the
        // line. Simpson is exact on the polynomial weight; the cosine weight to ~1e-13.
        let v = Viscosity::barus(0.0);
        let x: f64 = 7.0;
        let e = mu_bar_flat(Geometry::Elliptical, ShearLaw::Eyring, &v, x.ln());
        assert!((e / (1.5 * x.asinh()) - 1.0).abs() < 1e-12, "{e}");
        let l = mu_bar_flat(Geometry::Line, ShearLaw::Eyring, &v, x.ln());
        assert!((l / (4.0 / PI * x.asinh()) - 1.0).abs() < 1e-10, "{l}");
    }

    #[test]
    fn barus_asymptote_is_one_and_a_half_l_minus_half_alpha() {
        // ln x_c = 60 > alpha-bar: x(P) >= e^30 over the whole contact, so tau_m = ln 2x to
        // 1e-26 and the integrand is a quadratic in P, which Simpson's rule integrates exactly:
        // only round-off remains.
        let alpha = 30.0;
        let v = Viscosity::barus(alpha);
        let ln_xc = 60.0;
        let m = mu_bar_flat(Geometry::Elliptical, ShearLaw::Eyring, &v, ln_xc);
        let asymptote = 1.5 * (ln_xc + std::f64::consts::LN_2) - 0.5 * alpha;
        assert!((m / asymptote - 1.0).abs() < 1e-12, "{m} vs {asymptote}");
        // Newtonian: 3 int x_c e^{alpha (P - 1)} P dP, in closed form.
        let xc: f64 = 0.01;
        let n = mu_bar_flat(Geometry::Elliptical, ShearLaw::Newtonian, &v, xc.ln());
        let a: f64 = alpha;
        let exact = 3.0 * xc * (1.0 / a - (1.0 - (-a).exp()) / (a * a));
        assert!((n / exact - 1.0).abs() < 1e-8, "{n} vs {exact}");
    }

    #[test]
    fn quadrature_is_converged_on_the_sharpest_profile() {
        // Roelands of 5P4E at 40 C and 3 GPa (the steepest viscosity of the paper's cases,
        // alpha_e = 64) with the knee x(P) = 1 inside the contact: the rule with half the
        // intervals agrees to 1e-7, so the full rule is converged well below that (Simpson's
        // error falls 16-fold per halving).
        let v = Viscosity::roelands(0.266, 35e-9, 3e9);
        let ln_xc = 10.0;
        let full = mu_bar_flat(Geometry::Elliptical, ShearLaw::Eyring, &v, ln_xc);
        let ln_eta = v.ln_eta_bar(1.0);
        let h = 1.0 / (INTERVALS / 2) as f64;
        let half: f64 = (0..=INTERVALS / 2)
            .map(|i| {
                let p = h * i as f64;
                let w = if i == 0 || i == INTERVALS / 2 {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * mean_stress(ShearLaw::Eyring, ln_xc + v.ln_eta_bar(p) - ln_eta, p) * p
            })
            .sum::<f64>()
            * 3.0
            * h
            / 3.0;
        assert!((full / half - 1.0).abs() < 1e-7, "{full} vs {half}");
        assert!(alpha_e(&v) > 60.0 && alpha_e(&v) < 70.0, "{}", alpha_e(&v));
    }

    #[test]
    fn a_saturated_hertzian_contact_carries_the_limit() {
        // The exact limit: with the whole Hertzian contact saturated, mu-bar =
        // Lambda-bar + (tau_L0/tau0) A/W, A/W = 3/2 for the ellipse and 4/pi for the line.
        // ln x_c = 600 with constant viscosity: tau_E = 600.7 everywhere against tau_L <= 2.3,
        // so tau_m = tau_L (1 - r^-1/2 ...) with r >= 6.8e4: 7.4e-6 relative at most. The
        // remaining integrand is a polynomial in P for the ellipse (Simpson exact) and
        // (a + b cos t) cos t for the line (Simpson's error ~ 1e-13).
        let law = ShearLaw::EyringLss {
            tau_l0_bar: 0.3,
            lambda_bar: 2.0,
        };
        let v = Viscosity::barus(0.0);
        for (geometry, a_w) in [(Geometry::Elliptical, 1.5), (Geometry::Line, 4.0 / PI)] {
            let m = mu_bar_flat(geometry, law, &v, 600.0);
            let exact = law.friction_bound(a_w).unwrap();
            assert!(
                m < exact && m / exact > 1.0 - 7.5e-6,
                "{geometry:?}: {m} vs {exact}"
            );
        }
        // Unsaturated (x_c = 1e-3, tau_E <= 1e-3 << tau_L0): the limit changes nothing
        // measurable ((tau_E/tau_L)^2 / 2 <= 5.6e-6 relative).
        let plain = mu_bar_flat(Geometry::Elliptical, ShearLaw::Eyring, &v, (1e-3f64).ln());
        let limited = mu_bar_flat(Geometry::Elliptical, law, &v, (1e-3f64).ln());
        assert!((limited / plain - 1.0).abs() < 6e-6 && limited < plain);
    }

    #[test]
    fn alpha_e_of_barus_is_alpha_bar() {
        // ln eta is linear in P: the central difference is exact up to round-off.
        assert!((alpha_e(&Viscosity::barus(21.6)) - 21.6).abs() < 1e-8);
    }

    #[test]
    fn huge_arguments_do_not_overflow() {
        let v = Viscosity::barus(70.0);
        let m = mu_bar_flat(Geometry::Line, ShearLaw::Eyring, &v, 800.0);
        assert!(m.is_finite() && m > 500.0, "{m}");
    }
}
