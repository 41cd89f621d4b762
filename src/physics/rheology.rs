//! Lubricant rheology: Newtonian, Eyring, or Eyring with a limiting shear stress, through the
//! perturbation approach of Eqs. (2)-(4) (Ehret, Dowson and Taylor 1998).
//!
//! Every quantity is written in terms of the local Couette stress argument
//! `x = N eta_bar S / H` (the Newtonian mean shear stress over `tau0`), so that
//! `tau_m = asinh(x)` (Eq. 4), `cosh(tau_m) = sqrt(1 + x^2)` and `sinh(tau_m) = x`.
//! Written this way nothing overflows even where `eta_bar` is 1e25.
//!
//! The perturbation approach for any flow law `eta gamma_dot = g(tau)` (stresses over
//! `tau0` below): `tau_m = g^-1(x)`, `eta / eta_x = g'(tau_m)`, `eta / eta_y = g(tau_m) /
//! tau_m`. Eyring is `g = sinh`. The limiting-shear-stress law ([`ShearLaw::EyringLss`],
//! beyond the paper) saturates the Eyring stress `tau_E = asinh(x)` smoothly at
//! `tau_L = tau_L0 + Lambda p`:
//!
//! `tau_m = tau_E (1 + (tau_E / tau_L)^2)^(-1/2)`, so that
//! `g(tau) = sinh(tau (1 - (tau / tau_L)^2)^(-1/2))` for `tau < tau_L`,
//! `g'(tau_m) = cosh(tau_E) (1 + r)^(3/2)`, `g(tau_m) / tau_m = (x / tau_E) (1 + r)^(1/2)`,
//! `r = (tau_E / tau_L)^2`.
//!
//! Why this form and `n = 2`: it is the Eyring law itself wherever `tau_E << tau_L` (so the
//! inlet and low-pressure zones are untouched), it is analytic in `x` and `P` (no kink for
//! the Newton-Krylov finish to stumble on, unlike `min(tau_E, tau_L)`), and the Poiseuille
//! conductances grow only like `(tau_E / tau_L)^3` in the saturated zone, a factor of tens at
//! the paper's stresses. A larger exponent sharpens the knee at the price of a steeper
//! conductance (`(tau_E/tau_L)^(n+1)`); `n = 1` (the harmonic mean) halves the stress already
//! at `tau_E = tau_L`. At `tau_E = tau_L` this form gives `tau_L / sqrt 2`.

use super::evaluations::{record, Effect};
use serde::{Deserialize, Serialize};

/// Which rheology a case asks for (the case file's and the command line's statement; the
/// solvers consume its dimensionless [`ShearLaw`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Rheology {
    /// Linear viscous: the mean shear stress is `x` and the effective viscosities are `eta`.
    Newtonian,
    /// Eyring: `gamma_dot = (tau0 / eta) sinh(tau / tau0)`.
    #[default]
    Eyring,
    /// Eyring saturating at a limiting shear stress `tau_L = tau_L0 + Lambda p` (module doc).
    EyringLss(LimitingShearStress),
}

/// The limiting shear stress `tau_L = tau_L0 + Lambda p` (Bair and Winer's pressure-linear
/// form), physical units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LimitingShearStress {
    /// Slope `Lambda = d tau_L / dp` (dimensionless), `>= 0`.
    pub lambda: f64,
    /// Limiting shear stress at ambient pressure `tau_L0`, Pa, `> 0` (so that the inlet,
    /// where `p -> 0`, keeps a finite limit).
    pub tau_l0_pa: f64,
}

impl LimitingShearStress {
    /// `Lambda` and `tau_L0` checked: `Lambda >= 0`, `tau_L0 > 0`, both finite; the message
    /// names the field.
    pub fn checked(self) -> Result<Self, (&'static str, String)> {
        if !(self.lambda >= 0.0 && self.lambda.is_finite()) {
            return Err((
                "lambda-lss",
                format!("must be >= 0 and finite, got {}", self.lambda),
            ));
        }
        if !(self.tau_l0_pa > 0.0 && self.tau_l0_pa.is_finite()) {
            return Err((
                "tau-l0",
                format!(
                    "must be positive and finite (Pa), got {}; a zero limit at ambient pressure \
                     leaves the inlet with no shear strength",
                    self.tau_l0_pa
                ),
            ));
        }
        Ok(self)
    }

    /// The dimensionless law for Eyring stress `tau0` and maximum Hertzian pressure `p_H`
    /// (same units, any): `tau_L / tau0 = tau_L0 / tau0 + (Lambda p_H / tau0) P`.
    pub fn shear_law(self, tau0: f64, ph: f64) -> ShearLaw {
        ShearLaw::EyringLss {
            tau_l0_bar: self.tau_l0_pa / tau0,
            lambda_bar: self.lambda * ph / tau0,
        }
    }
}

/// The dimensionless rheology the solvers evaluate, stresses over `tau0`, pressure `P =
/// p / p_H`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShearLaw {
    /// Linear viscous.
    Newtonian,
    /// Eyring, Eqs. (2)-(4).
    Eyring,
    /// Eyring saturating at `tau_L / tau0 = tau_l0_bar + lambda_bar P` (module doc).
    EyringLss {
        /// `tau_L0 / tau0`.
        tau_l0_bar: f64,
        /// `Lambda-bar = Lambda p_H / tau0`.
        lambda_bar: f64,
    },
}

/// The exponent `n` of the smooth saturation `tau_E (1 + (tau_E/tau_L)^n)^(-1/n)`; the
/// closed forms below are written for `n = 2` (module doc says why).
pub const SATURATION_EXPONENT: f64 = 2.0;

impl ShearLaw {
    /// The law of a Newtonian or Eyring rheology (which carry no parameters).
    pub fn of_plain(rheology: Rheology) -> Option<Self> {
        match rheology {
            Rheology::Newtonian => Some(ShearLaw::Newtonian),
            Rheology::Eyring => Some(ShearLaw::Eyring),
            Rheology::EyringLss(_) => None,
        }
    }

    /// Whether the law is Eyring's (with or without a limit): the Poiseuille-dependent exact
    /// line-contact flow exists for plain Eyring only.
    pub fn is_plain_eyring(self) -> bool {
        matches!(self, ShearLaw::Eyring)
    }

    /// The bound on the reduced friction of Eq. (8) that the limit sets for any pressure
    /// field, `mu-bar <= Lambda-bar + (tau_L0 / tau0) A / W` (`tau_m < tau_L0 + Lambda p`
    /// integrated over the pressurised area `A`, load `W = int P dA`), for the ratio
    /// `A / W` (dimensionless: 3/2 for the Hertzian ellipse, `4 / pi` for the Hertzian line);
    /// reached when the whole contact is saturated. `None` without a limit.
    pub fn friction_bound(self, area_over_load: f64) -> Option<f64> {
        match self {
            ShearLaw::EyringLss {
                tau_l0_bar,
                lambda_bar,
            } => Some(lambda_bar + tau_l0_bar * area_over_load),
            _ => None,
        }
    }

    /// `tau_L / tau0` at pressure `P` (the cavitated and dry zones, `P <= 0`, at `tau_L0`).
    #[inline]
    fn limit(tau_l0_bar: f64, lambda_bar: f64, p: f64) -> f64 {
        tau_l0_bar + lambda_bar * p.max(0.0)
    }

    /// `1 + r`, `r = (tau_E / tau_L)^2`: the saturation's one ingredient.
    #[inline]
    fn one_plus_r(tau_e: f64, tau_l: f64) -> f64 {
        let q = tau_e / tau_l;
        1.0 + q * q
    }

    /// The saturated mean stress `tau_E (1 + r)^(-1/2)` for an Eyring stress `tau_E` at
    /// pressure `P`; `tau_E` itself for the laws without a limit.
    #[inline]
    pub fn saturate(self, tau_e: f64, p: f64) -> f64 {
        match self {
            ShearLaw::EyringLss {
                tau_l0_bar,
                lambda_bar,
            } => {
                record(Effect::LimitingShearStress);
                tau_e / Self::one_plus_r(tau_e, Self::limit(tau_l0_bar, lambda_bar, p)).sqrt()
            }
            _ => tau_e,
        }
    }

    /// Dimensionless mean shear stress `tau_m / tau0` for the Couette argument `x` at
    /// pressure `P`: Eq. (4) for Eyring, `x` itself for a Newtonian fluid, the saturated
    /// Eyring stress for the limiting-stress law.
    #[inline]
    pub fn mean_shear_stress(self, x: f64, p: f64) -> f64 {
        match self {
            ShearLaw::Newtonian => x,
            ShearLaw::Eyring => {
                record(Effect::Eyring);
                eyring_stress(x)
            }
            ShearLaw::EyringLss { .. } => {
                record(Effect::Eyring);
                self.saturate(eyring_stress(x), p)
            }
        }
    }

    /// The factors `(f_x, f_y)` by which the limit multiplies Eyring's `eta / eta_x` and
    /// `eta / eta_y` at Couette argument `x` and pressure `P`: `((1 + r)^(3/2), (1 + r)^(1/2))`.
    #[inline]
    fn saturation_factors(tau_l0_bar: f64, lambda_bar: f64, x: f64, p: f64) -> (f64, f64) {
        record(Effect::LimitingShearStress);
        let s = Self::one_plus_r(eyring_stress(x), Self::limit(tau_l0_bar, lambda_bar, p));
        let root = s.sqrt();
        (s * root, root)
    }

    /// `eta / eta_x`: Eq. (2), `g'(tau_m)`: `cosh(tau_m) = sqrt(1 + x^2)` for Eyring, times
    /// `(1 + r)^(3/2)` with the limit.
    #[inline]
    pub fn flow_factor_x(self, x: f64, p: f64) -> f64 {
        match self {
            ShearLaw::Newtonian => 1.0,
            ShearLaw::Eyring => {
                record(Effect::Eyring);
                x.hypot(1.0)
            }
            ShearLaw::EyringLss {
                tau_l0_bar,
                lambda_bar,
            } => {
                ShearLaw::Eyring.flow_factor_x(x, p)
                    * Self::saturation_factors(tau_l0_bar, lambda_bar, x, p).0
            }
        }
    }

    /// `eta / eta_y`: Eq. (3) as corrected in SPEC.md, `g(tau_m) / tau_m`: for Eyring
    /// `eta_y = eta tau_m / sinh(tau_m)`, so `eta / eta_y = x / asinh(x)`, which tends to 1 as
    /// `x -> 0`; times `(1 + r)^(1/2)` with the limit.
    #[inline]
    pub fn flow_factor_y(self, x: f64, p: f64) -> f64 {
        match self {
            ShearLaw::Newtonian => 1.0,
            ShearLaw::Eyring => {
                record(Effect::Eyring);
                if x.abs() < 1e-4 {
                    1.0 + x * x / 6.0
                } else {
                    x / eyring_stress(x)
                }
            }
            ShearLaw::EyringLss {
                tau_l0_bar,
                lambda_bar,
            } => {
                ShearLaw::Eyring.flow_factor_y(x, p)
                    * Self::saturation_factors(tau_l0_bar, lambda_bar, x, p).1
            }
        }
    }

    /// Poiseuille conductance along the sliding direction, `H^3 / eta_x_bar` (Eqs. 1-2), for
    /// film `h`, viscosity `eta`, `n_s = N S` and pressure `P`. For Eyring it is written
    /// `H^2 hypot(H / eta, N S)`, finite however large `eta` is; zero where `h <= 0`.
    #[inline]
    pub fn conductance_x(self, h: f64, eta: f64, n_s: f64, p: f64) -> f64 {
        if h <= 0.0 {
            return 0.0;
        }
        match self {
            ShearLaw::Newtonian => h * h * h / eta,
            // sqrt(a^2 + b^2) rather than hypot: a = H/eta <= H and b = N S are far from
            // overflow, and hypot's extra care costs a tenth of a solve.
            ShearLaw::Eyring => {
                record(Effect::Eyring);
                let a = h / eta;
                h * h * (a * a + n_s * n_s).sqrt()
            }
            ShearLaw::EyringLss {
                tau_l0_bar,
                lambda_bar,
            } => {
                let x = n_s * eta / h;
                ShearLaw::Eyring.conductance_x(h, eta, n_s, p)
                    * Self::saturation_factors(tau_l0_bar, lambda_bar, x, p).0
            }
        }
    }

    /// Poiseuille conductance across the sliding direction, `H^3 / eta_y_bar` (Eqs. 1, 3).
    /// For Eyring, with `x = N S eta / H`: `(H^3 / eta) x / asinh(x) = H^2 N S / asinh(x)`.
    #[inline]
    pub fn conductance_y(self, h: f64, eta: f64, n_s: f64, p: f64) -> f64 {
        if h <= 0.0 {
            return 0.0;
        }
        match self {
            ShearLaw::Newtonian => h * h * h / eta,
            ShearLaw::Eyring => {
                record(Effect::Eyring);
                let x = n_s * eta / h;
                if x < 1e-4 {
                    h * h * h / eta * (1.0 + x * x / 6.0)
                } else {
                    h * h * n_s / eyring_stress(x)
                }
            }
            ShearLaw::EyringLss {
                tau_l0_bar,
                lambda_bar,
            } => {
                let x = n_s * eta / h;
                ShearLaw::Eyring.conductance_y(h, eta, n_s, p)
                    * Self::saturation_factors(tau_l0_bar, lambda_bar, x, p).1
            }
        }
    }
}

/// The Eyring stress `asinh(x)` (Eq. 4), on the solver's hot path (every node of every
/// relaxation sweep): `ln(x + sqrt(1 + x^2))` from `x = 0.5` up, where its argument is at
/// least 1.6 and the logarithm's relative error stays below 3e-16 (the standard `asinh`
/// guards the whole range with `hypot` and `ln_1p`, a tenth of a cycle); `ln 2x` from 1e8 up
/// (error `1 / (4 x^2)`); below 0.5 the standard function's own form,
/// `ln_1p(x + x^2 / (1 + sqrt(1 + x^2)))`, without its `hypot` (`x^2 < 0.25` cannot
/// overflow, and underflows only where `ln_1p(x) = x` is exact): 2 % of a sweep's time was
/// `hypot`. The standard function for anything negative or not a number.
#[inline]
pub fn eyring_stress(x: f64) -> f64 {
    if x.is_nan() || x < 0.0 {
        x.asinh()
    } else if x < 0.5 {
        let x2 = x * x;
        (x + x2 / (1.0 + (1.0 + x2).sqrt())).ln_1p()
    } else if x < 1e8 {
        (x + x.mul_add(x, 1.0).sqrt()).ln()
    } else {
        std::f64::consts::LN_2 + x.ln()
    }
}

#[cfg(test)]
mod tests;
