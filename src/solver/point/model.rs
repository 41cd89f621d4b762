//! The case's physics at a node, as the discrete equations use it: the viscosity, density
//! and shear laws of the dimensionless problem and its groups.

use crate::physics::case::Problem;
use crate::physics::density::Density;
use crate::physics::rheology::ShearLaw;
use crate::physics::viscosity::Viscosity;

/// The parts of the dimensionless problem the discrete equations use.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Model {
    pub viscosity: Viscosity,
    pub density: Density,
    pub rheology: ShearLaw,
    /// `N S` of Eq. (4).
    pub n_s: f64,
    /// `1 / lambda`.
    pub inv_lambda: f64,
    /// `kappa^2`, the weight of the `Y` derivative in Eq. (1).
    pub kappa2: f64,
    /// Shape factor `S(kappa)` of Eq. (6).
    pub shape: f64,
    pub kappa: f64,
    pub ell_k: f64,
    /// How the conductances meet at the half points of Eq. (1)'s Poiseuille terms.
    pub half_point: HalfPointMean,
}

/// The conductance of Eq. (1)'s Poiseuille term at the half point between two nodes whose
/// conductances are `a` and `b`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HalfPointMean {
    /// `(a + b) / 2`: second order where the conductance varies smoothly on the mesh.
    #[default]
    Arithmetic,
    /// The mean that is exact for a constant flux through a conductance whose logarithm is
    /// linear between the nodes (`eps = a e^(s x / h)`, `s = ln(b / a)`):
    /// `h / int dx / eps = a b s / (b - a) = sqrt(a b) x / sinh(x)`, `x = s / 2`. Between the
    /// arithmetic mean (`s` small) and `s min(a, b)` (`s` large), where the arithmetic mean
    /// is `max(a, b) / 2`: across the pressure peak's flank the viscosity changes by up to
    /// `e^45` between two nodes (docs/ACCURACY_NOTES.md, "the bisection").
    ExponentialFit,
}

impl HalfPointMean {
    /// Twice the mean of `a` and `b` (the sum for [`HalfPointMean::Arithmetic`]) and its
    /// derivatives in `a` and in `b`. A non-positive conductance (a closed film's) takes the
    /// arithmetic mean.
    #[inline]
    pub fn twice(self, a: f64, b: f64) -> (f64, f64, f64) {
        if self == HalfPointMean::Arithmetic || a <= 0.0 || b <= 0.0 {
            return (a + b, 1.0, 1.0);
        }
        let s = (b / a).ln();
        if s.abs() > 1e-3 {
            // m = a b s / (b - a); dm/da = (b (s - 1) + m) / (b - a),
            // dm/db = (a (s + 1) - m) / (b - a).
            let d = b - a;
            let m = a * b * s / d;
            (
                2.0 * m,
                2.0 * (b * (s - 1.0) + m) / d,
                2.0 * (a * (s + 1.0) - m) / d,
            )
        } else {
            // sqrt(a b) phi(x), phi(x) = x / sinh(x) = 1 - x^2 / 6 + 7 x^4 / 360,
            // phi'(x) = -x / 3 + 7 x^3 / 90; dm/da = (m - G phi') / (2 a), dm/db =
            // (m + G phi') / (2 b).
            let x = 0.5 * s;
            let x2 = x * x;
            let g = (a * b).sqrt();
            let m = g * (1.0 - x2 / 6.0 + 7.0 * x2 * x2 / 360.0);
            let dphi = g * x * (-1.0 / 3.0 + 7.0 * x2 / 90.0);
            (2.0 * m, (m - dphi) / a, (m + dphi) / b)
        }
    }
}

impl Model {
    pub fn new(problem: &Problem) -> Self {
        let g = &problem.groups;
        Model {
            viscosity: problem.viscosity,
            density: problem.density,
            rheology: problem.shear,
            n_s: problem.eyring_n_s(),
            inv_lambda: 1.0 / g.lambda,
            kappa2: g.kappa * g.kappa,
            shape: problem.shape,
            kappa: g.kappa,
            ell_k: problem.ell_k,
            half_point: HalfPointMean::Arithmetic,
        }
    }

    /// This model with the half-point mean `mean`.
    pub fn with_half_point(self, mean: HalfPointMean) -> Self {
        Model {
            half_point: mean,
            ..self
        }
    }

    /// `eta_bar(P)`. Where `P <= 0` (most of the domain: outside the contact and in the
    /// cavitated outlet) every law gives exactly `exp(0) = 1`, returned without evaluating it
    /// (the same bits, a third of the coefficient update saved).
    #[inline]
    pub fn eta(&self, p: f64) -> f64 {
        if p <= 0.0 {
            return 1.0;
        }
        self.viscosity.eta_bar_capped(p)
    }

    /// The mean shear stress `tau_m / tau0` at a node of pressure `p > 0` and film `h`: the
    /// case's shear law (Eq. 4 for Eyring) at the Couette argument `N S eta_bar(P) / H`. The
    /// one formula of the friction (Eq. 8) and of the stress field
    /// ([`super::friction::mean_shear_stress`]).
    #[inline]
    pub fn mean_shear_stress(&self, p: f64, h: f64) -> f64 {
        self.rheology
            .mean_shear_stress(self.n_s * self.eta(p) / h, p)
    }

    /// The coefficients of Eq. (1) at one node of pressure `p` and film `h`:
    /// `(rho H^3 / (eta_x lambda), kappa^2 rho H^3 / (eta_y lambda), rho)`.
    #[inline]
    pub fn coefficients(&self, p: f64, h: f64) -> (f64, f64, f64) {
        // rho_bar(P <= 0) = 1 exactly: not evaluated there, like the viscosity.
        let rho = if self.density.is_incompressible() || p <= 0.0 {
            1.0
        } else {
            self.density.rho_bar(p)
        };
        let eta = self.eta(p);
        let scale = rho * self.inv_lambda;
        (
            scale * self.rheology.conductance_x(h, eta, self.n_s, p),
            scale * self.kappa2 * self.rheology.conductance_y(h, eta, self.n_s, p),
            rho,
        )
    }

    /// Gap geometry `S X^2 + (1 - S) Y^2` of Eq. (6).
    pub fn geometry(&self, x: f64, y: f64) -> f64 {
        self.shape * x * x + (1.0 - self.shape) * y * y
    }
}

#[cfg(test)]
mod tests {
    use super::HalfPointMean::{self, *};

    #[test]
    fn the_exponential_mean_is_exact_for_an_exponential_conductance_and_its_derivatives_are() {
        // h / int_0^h dx / (a e^(s x / h)), by the midpoint rule on 20 000 intervals.
        let exact = |a: f64, b: f64| {
            let (s, n) = ((b / a).ln(), 20_000);
            let sum: f64 = (0..n)
                .map(|k| 1.0 / (a * (s * (k as f64 + 0.5) / n as f64).exp()))
                .sum();
            n as f64 / sum
        };
        for (a, b) in [
            (1.0, 2.0),
            (3.0, 1e-6),
            (1e-20, 1e-19 * 1.3),
            (2.0, 2.0 * (1.0 + 1e-4)),
        ] {
            let (twice, da, db) = ExponentialFit.twice(a, b);
            // The midpoint rule's error is (s / n)^2 / 24 relative: below 1e-7 here.
            assert!((0.5 * twice / exact(a, b) - 1.0).abs() < 1e-7, "{a} {b}");
            // Derivatives against central differences of the mean itself (relative step
            // 1e-6: truncation ~1e-12, rounding ~1e-10 relative).
            let fd = |f: &dyn Fn(f64) -> f64, x: f64| {
                let d = 1e-6 * x;
                (f(x + d) - f(x - d)) / (2.0 * d)
            };
            let fa = fd(&|x| ExponentialFit.twice(x, b).0, a);
            let fb = fd(&|x| ExponentialFit.twice(a, x).0, b);
            let scale = twice / a.min(b);
            assert!((da - fa).abs() < 1e-6 * scale, "{a} {b}: {da} {fa}");
            assert!((db - fb).abs() < 1e-6 * scale, "{a} {b}: {db} {fb}");
        }
        // Symmetric, and continuous across the series' switch at |s| = 1e-3.
        assert_eq!(
            ExponentialFit.twice(1.0, 5.0).0,
            ExponentialFit.twice(5.0, 1.0).0
        );
        let (below, above) = (
            ExponentialFit.twice(1.0, 1.000_999_5).0,
            ExponentialFit.twice(1.0, 1.001_000_5).0,
        );
        assert!((above - below).abs() < 2.1e-6, "{below} {above}");
        // Across e^45 the arithmetic mean is e^45 / 2; this one 45 times the smaller.
        let big = 45f64.exp();
        assert!((ExponentialFit.twice(1.0, big).0 / 90.0 - 1.0).abs() < 1e-12);
        assert_eq!(HalfPointMean::Arithmetic.twice(1.0, 3.0), (4.0, 1.0, 1.0));
    }
}
