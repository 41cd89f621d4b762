//! The friction `repro predict` gives for a contact, Eq. (14) and the refined formula, with
//! the band that an estimated pressure-viscosity coefficient puts on it.
//!
//! When the lubricant's `alpha` comes from a correlation ([`crate::physics::datasheet`]:
//! AGMA 925 with its band), the prediction is evaluated again at the band's ends, with the
//! same `eta0` and `alpha` replaced: `alpha` enters through `L` (hence the Eq. (10) film),
//! through `eta(p_H)` of the viscosity law, so through `tau_c`, and through the refined
//! formula's groups. The band of each output is the range of its three values (low,
//! central, high `alpha`); every output is monotonic in `alpha` over the band for the
//! contacts tested here (a unit test samples the band), so the ends bound it. The refined
//! formula's band combines that range with the formula's own relative band
//! ([`REFINED_BAND`]) as an interval: `[min (1 - band), max (1 + band)]`, the conservative
//! combination (the two are not independent draws that could be added in quadrature: the
//! formula's residual was measured at known `alpha`).

pub mod contact;
pub mod heat;

use crate::paper::eq13::{eq13_mu_bar, PAPER_C};
use crate::paper::mastercurve::refined::{Features, REFINED, REFINED_BAND};
use crate::physics::case::{Case, CaseError, CaseForm, LubricantSpec, PhysicalCase, Problem};
use crate::physics::lubricant::LubricantTable;
use crate::physics::traction::{
    characteristic, Characteristic, Contact, FilmFormula, Load, OperatingPoint, Sliding, Speed,
    ViscosityAtPh,
};
use serde::Serialize;

/// The friction of one contact at one lubricant state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// `tau_c` (Eq. 12) and the groups and film it is made of.
    pub characteristic: Characteristic,
    /// Eq. (14): `mu-bar = asinh(tau_c / 5)`.
    pub mu_bar: f64,
    /// `mu = mu-bar tau0 / p_H`.
    pub mu: f64,
    /// The refined formula's `mu-bar` ([`REFINED`]).
    pub mu_bar_refined: f64,
    /// Its `mu`.
    pub mu_refined: f64,
}

impl Estimate {
    /// The estimate of a physical point-contact case: the Eq. (10) film, `eta(p_H)` from the
    /// case's viscosity law; also returns the case's problem (the refined formula's input).
    pub fn of(case: &Case, lubs: &LubricantTable) -> Result<(Self, Problem), CaseError> {
        let p = physical(case)?;
        let c = characteristic(&operating_point(case)?, lubs)?;
        let mu_bar = eq13_mu_bar(c.tau_c, PAPER_C);
        let problem = Problem::from_case(case, lubs)?;
        let mu_bar_refined = REFINED.predict(&Features::point(&problem));
        Ok((
            Estimate {
                characteristic: c,
                mu_bar,
                mu: c.friction(mu_bar, p.tau0_pa),
                mu_bar_refined,
                mu_refined: c.friction(mu_bar_refined, p.tau0_pa),
            },
            problem,
        ))
    }
}

/// The operating point of a physical point-contact case as the predictor reads it: the
/// Eq. (10) film, `eta(p_H)` from the case's viscosity law.
pub fn operating_point(case: &Case) -> Result<OperatingPoint, CaseError> {
    let p = physical(case)?;
    Ok(OperatingPoint {
        contact: Contact::Elliptical {
            rx_m: p.rx_m,
            ry_m: p.ry_m,
        },
        e_prime_pa: p.e_prime_pa,
        load: Load::MaxPressure(p.ph_pa),
        lubricant: p.lubricant.clone(),
        speed: Speed::Mean(p.um_m_s),
        sliding: Sliding::Slip(p.slip),
        tau0_pa: p.tau0_pa,
        viscosity: ViscosityAtPh::Law(case.physics.viscosity),
        film: FilmFormula::Eq10,
    })
}

/// A closed range `[low, high]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Band {
    /// Lower end.
    pub low: f64,
    /// Upper end.
    pub high: f64,
}

impl Band {
    /// The range of `values`.
    pub fn of(values: &[f64]) -> Self {
        Band {
            low: values.iter().copied().fold(f64::INFINITY, f64::min),
            high: values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        }
    }

    /// The range widened by a relative half-width `rel` on each side.
    pub fn widened(self, rel: f64) -> Self {
        Band {
            low: self.low * (1.0 - rel),
            high: self.high * (1.0 + rel),
        }
    }

    /// `[low, high]`, for JSON.
    pub fn pair(self) -> [f64; 2] {
        [self.low, self.high]
    }
}

/// A prediction with its bands.
#[derive(Debug, Clone, PartialEq)]
pub struct Prediction {
    /// At the lubricant's `alpha` (given, tabulated, or the correlation's central value).
    pub central: Estimate,
    /// The case's problem at that `alpha`.
    pub problem: Problem,
    /// The `alpha` band, 1/Pa, when `alpha` is a correlation's estimate.
    pub alpha_band: Option<Band>,
    /// The estimates at the `alpha` band's low and high ends.
    pub at_alpha_ends: Option<[Estimate; 2]>,
}

impl Prediction {
    /// The prediction of a physical point-contact case: at its lubricant's `alpha` and,
    /// when that is a correlation's estimate, at the ends of the estimate's band.
    pub fn of(case: &Case, lubs: &LubricantTable) -> Result<Self, CaseError> {
        let (central, problem) = Estimate::of(case, lubs)?;
        let p = physical(case)?;
        let correlated = match p.lubricant.datasheet_state() {
            Some(state) => state?.correlated,
            None => None,
        };
        let (alpha_band, at_alpha_ends) = match correlated {
            Some(est) => {
                let eta0_pa_s = p.lubricant.resolve(lubs)?.eta0_pa_s;
                let at = |alpha_per_pa: f64| {
                    Estimate::of(&with_alpha(case, alpha_per_pa, eta0_pa_s), lubs).map(|e| e.0)
                };
                (
                    Some(Band {
                        low: est.low_per_pa,
                        high: est.high_per_pa,
                    }),
                    Some([at(est.low_per_pa)?, at(est.high_per_pa)?]),
                )
            }
            None => (None, None),
        };
        Ok(Prediction {
            central,
            problem,
            alpha_band,
            at_alpha_ends,
        })
    }

    /// The range of an output over the `alpha` band; `None` when `alpha` is not estimated.
    pub fn over_alpha(&self, output: impl Fn(&Estimate) -> f64) -> Option<Band> {
        self.at_alpha_ends
            .as_ref()
            .map(|[lo, hi]| Band::of(&[output(lo), output(&self.central), output(hi)]))
    }

    /// Eq. (14)'s `mu` over the `alpha` band.
    pub fn mu_band(&self) -> Option<Band> {
        self.over_alpha(|e| e.mu)
    }

    /// Eq. (14)'s `mu-bar` over the `alpha` band.
    pub fn mu_bar_band(&self) -> Option<Band> {
        self.over_alpha(|e| e.mu_bar)
    }

    /// `tau_c` over the `alpha` band.
    pub fn tau_c_band(&self) -> Option<Band> {
        self.over_alpha(|e| e.characteristic.tau_c)
    }

    /// The Eq. (10) central film (m) over the `alpha` band.
    pub fn hc_m_band(&self) -> Option<Band> {
        self.over_alpha(|e| e.characteristic.hc_m)
    }

    /// The refined formula's `mu-bar` band: its own band around its range over the `alpha`
    /// band (around its central value when `alpha` is not estimated).
    pub fn mu_bar_refined_band(&self) -> Band {
        self.over_alpha(|e| e.mu_bar_refined)
            .unwrap_or(Band::of(&[self.central.mu_bar_refined]))
            .widened(REFINED_BAND)
    }

    /// The refined formula's `mu` band, as [`Prediction::mu_bar_refined_band`].
    pub fn mu_refined_band(&self) -> Band {
        self.over_alpha(|e| e.mu_refined)
            .unwrap_or(Band::of(&[self.central.mu_refined]))
            .widened(REFINED_BAND)
    }
}

fn physical(case: &Case) -> Result<&PhysicalCase, CaseError> {
    match &case.spec {
        CaseForm::Physical(p) => Ok(p),
        CaseForm::Dimensionless(_) => Err(CaseError::Field {
            field: "spec",
            message: "a prediction needs a contact given physically".into(),
        }),
    }
}

/// `case` with its lubricant's `alpha` replaced (and its `eta0` kept).
fn with_alpha(case: &Case, alpha_per_pa: f64, eta0_pa_s: f64) -> Case {
    let mut case = case.clone();
    if let CaseForm::Physical(p) = &mut case.spec {
        p.lubricant = LubricantSpec::Given {
            alpha_per_pa,
            eta0_pa_s,
        };
    }
    case
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::tests::{gear_oil, worked_case};

    /// The Appendix contact (3 GPa, 12 m/s, S 0.5 %, tau0 4 MPa) with another lubricant and
    /// load.
    fn contact(lubricant: LubricantSpec, ph_pa: f64) -> Case {
        let mut case = worked_case();
        if let CaseForm::Physical(p) = &mut case.spec {
            p.lubricant = lubricant;
            p.ph_pa = ph_pa;
        }
        case
    }

    #[test]
    fn a_tabulated_or_given_alpha_has_no_alpha_band() {
        let lubs = LubricantTable::table1();
        let p = Prediction::of(&worked_case(), &lubs).unwrap();
        assert!(p.alpha_band.is_none() && p.mu_band().is_none() && p.hc_m_band().is_none());
        // The refined band is the formula's own, as before the datasheet.
        let b = p.mu_bar_refined_band();
        let r = p.central.mu_bar_refined;
        assert_eq!(
            b.pair(),
            [r * (1.0 - REFINED_BAND), r * (1.0 + REFINED_BAND)]
        );
        // Central values are Eq. (14) of the problem's own tau_c (same code, round-off).
        assert!((p.central.characteristic.tau_c / p.problem.tau_c() - 1.0).abs() < 1e-14);
        assert_eq!(
            p.central.mu_bar,
            (p.central.characteristic.tau_c / 5.0).asinh()
        );
        // A datasheet with a given alpha: no alpha band either.
        let p = Prediction::of(&contact(gear_oil(Some(25.0)), 1e9), &lubs).unwrap();
        assert!(p.alpha_band.is_none());
    }

    #[test]
    fn a_correlated_alpha_bands_every_output_and_the_ends_bound_it() {
        let lubs = LubricantTable::table1();
        for ph in [0.6e9, 1.2e9, 2.5e9] {
            let case = contact(gear_oil(None), ph);
            let p = Prediction::of(&case, &lubs).unwrap();
            let alpha = p.alpha_band.unwrap();
            // The mineral band is [1, 1.65] x AGMA: the central alpha is its low end.
            let a0 = p.problem.groups.alpha_bar / ph;
            assert!((alpha.low / a0 - 1.0).abs() < 1e-12 && (alpha.high / a0 - 1.65).abs() < 1e-12);
            let [lo, hi] = p.at_alpha_ends.unwrap();
            // A larger alpha: thicker film, more viscous centre, larger tau_c and friction.
            assert!(hi.characteristic.hc_m > lo.characteristic.hc_m);
            assert!(hi.characteristic.tau_c > lo.characteristic.tau_c);
            assert!(hi.mu > lo.mu);
            // Sample the band: every output is monotonic in alpha, so the ends bound it.
            let eta0 = case_eta0(&case, &lubs);
            let outputs = |e: &Estimate| {
                [
                    e.mu,
                    e.mu_refined,
                    e.characteristic.hc_m,
                    e.characteristic.tau_c,
                ]
            };
            let samples: Vec<[f64; 4]> = (0..=20)
                .map(|i| {
                    let a = alpha.low + (alpha.high - alpha.low) * f64::from(i) / 20.0;
                    outputs(&Estimate::of(&with_alpha(&case, a, eta0), &lubs).unwrap().0)
                })
                .collect();
            for k in 0..4 {
                let rising = samples.windows(2).all(|w| w[1][k] >= w[0][k]);
                let falling = samples.windows(2).all(|w| w[1][k] <= w[0][k]);
                assert!(rising || falling, "p_H {ph}: output {k} not monotonic");
            }
            let mu = p.mu_band().unwrap();
            assert!(mu.low <= p.central.mu && p.central.mu <= mu.high && mu.low < mu.high);
            // The refined band holds the alpha range and the formula's own band.
            let r = p.mu_bar_refined_band();
            let range = p.over_alpha(|e| e.mu_bar_refined).unwrap();
            assert_eq!(r.low, range.low * (1.0 - REFINED_BAND));
            assert_eq!(r.high, range.high * (1.0 + REFINED_BAND));
        }
    }

    fn case_eta0(case: &Case, lubs: &LubricantTable) -> f64 {
        match &case.spec {
            CaseForm::Physical(p) => p.lubricant.resolve(lubs).unwrap().eta0_pa_s,
            CaseForm::Dimensionless(_) => unreachable!(),
        }
    }
}
