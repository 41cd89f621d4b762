//! Shear heating on a prediction: the thermal post-process of a solve, or its flat-film
//! estimate without one, as a relative correction of the isothermal friction; and the
//! warnings where the paper's Eq. (14) is not to be trusted.

use crate::paper::eq13::FIT_TAU_C_MIN;
use crate::physics::case::{Case, Problem};
use crate::physics::lubricant::LubricantTable;
use crate::physics::thermal::{ThermalError, ThermalInputs, ISOTHERMAL_CORRECTION_MAX};
use crate::physics::traction::{Characteristic, ISOTHERMAL_SLIP_MAX};
use crate::pipeline::job::thermal_contact;
use crate::solver::point::PointSolution;
use crate::solver::thermal::{flat_film_thermal, point_thermal, Thermal};
use std::time::Instant;

/// Grid level of the flat-film estimate without a solve (a Hertzian pressure and an Eq. (10)
/// film): 64 x 64 points, a few milliseconds.
const FLAT_LEVEL: u32 = 5;

/// The shear-heating correction of a contact's sliding friction.
#[derive(Debug, Clone)]
pub struct HeatCorrection {
    /// The post-process.
    pub thermal: Thermal,
    /// The isothermal sliding `mu-bar` it corrects.
    pub isothermal: f64,
    /// Where it comes from: the solve, or the flat-film estimate.
    pub source: &'static str,
    /// Its wall time, s.
    pub seconds: f64,
}

/// A correction, why it could not be computed, or `None` where the case has no thermal
/// scales (a dimensionless case, or a lubricant given by `alpha` and `eta0` alone).
pub type MaybeHeat = Option<Result<HeatCorrection, ThermalError>>;

impl HeatCorrection {
    /// The post-process of a solve.
    pub fn of_solution(
        case: &Case,
        problem: &Problem,
        s: &PointSolution,
        inputs: &ThermalInputs,
    ) -> MaybeHeat {
        let contact = thermal_contact(case, problem, &LubricantTable::table1())?;
        let start = Instant::now();
        Some(
            point_thermal(s, problem, &contact, inputs).map(|thermal| HeatCorrection {
                thermal,
                isothermal: s.friction.sliding,
                source: "post-process of the solve",
                seconds: start.elapsed().as_secs_f64(),
            }),
        )
    }

    /// The flat-film estimate without a solve.
    pub fn flat_estimate(case: &Case, problem: &Problem, inputs: &ThermalInputs) -> MaybeHeat {
        let contact = thermal_contact(case, problem, &LubricantTable::table1())?;
        let start = Instant::now();
        Some(
            flat_film_thermal(problem, &contact, inputs, FLAT_LEVEL).map(
                |(isothermal, thermal)| HeatCorrection {
                    thermal,
                    isothermal,
                    source: "flat-film estimate (Hertzian pressure, Eq. 10 film)",
                    seconds: start.elapsed().as_secs_f64(),
                },
            ),
        )
    }

    /// `mu-bar_thermal / mu-bar - 1`.
    pub fn correction(&self) -> f64 {
        self.thermal.correction(self.isothermal)
    }

    /// `mu_bar` (Eq. 14's) with the correction applied.
    pub fn corrected(&self, mu_bar: f64) -> f64 {
        mu_bar * (1.0 + self.correction())
    }

    /// The warning where the correction exceeds [`ISOTHERMAL_CORRECTION_MAX`].
    pub fn warning(&self) -> Option<String> {
        let c = self.correction();
        (c.abs() > ISOTHERMAL_CORRECTION_MAX).then(|| {
            format!(
                "shear heating changes the sliding friction by {:+.1} % ({}), more than {:.0} %: the paper's isothermal assumption does not hold here, and the isothermal mu-bar is too large (Conclusions)",
                100.0 * c,
                self.source,
                100.0 * ISOTHERMAL_CORRECTION_MAX
            )
        })
    }
}

/// What the paper says about where Eq. (14) does not hold, for this contact: low `tau_c`,
/// and shear heating beyond [`ISOTHERMAL_CORRECTION_MAX`] (where the correction could not be
/// estimated, the paper's largest slip instead).
pub fn warnings(c: &Characteristic, heat: &MaybeHeat) -> Vec<String> {
    let mut w = Vec::new();
    if c.tau_c < FIT_TAU_C_MIN {
        w.push(format!(
            "tau_c = {:.3e} is below {FIT_TAU_C_MIN}: at low tau_c the paper finds friction straying from the mastercurve because rolling friction dominates (Sec. III A, Figs. 2-3); Eq. (14) gives the sliding friction only",
            c.tau_c
        ));
    }
    if let Some(Ok(h)) = heat {
        w.extend(h.warning());
    }
    if heat.is_none() && c.slip > ISOTHERMAL_SLIP_MAX {
        w.push(format!(
            "S = {} is above {ISOTHERMAL_SLIP_MAX}, the largest slip of the paper's isothermal runs (Table 2, Sec. III B): with significant sliding, shear heating makes Eq. (14) predict too large a friction (Conclusions)",
            c.slip
        ));
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paper::prediction::Prediction;
    use crate::physics::case::tests::worked_case;
    use crate::physics::case::{CaseForm, LubricantSpec};
    use crate::physics::thermal::{FilmProperties, Solid};

    fn steel() -> ThermalInputs {
        ThermalInputs {
            solid: Solid::STEEL,
            film: FilmProperties::OIL,
        }
    }

    /// The Appendix contact with slip `slip`: its prediction and flat-film correction.
    fn at_slip(slip: f64) -> (Characteristic, MaybeHeat) {
        let mut case = worked_case();
        if let CaseForm::Physical(p) = &mut case.spec {
            p.slip = slip;
        }
        let lubs = LubricantTable::table1();
        let p = Prediction::of(&case, &lubs).unwrap();
        let heat = HeatCorrection::flat_estimate(&case, &p.problem, &steel());
        (p.central.characteristic, heat)
    }

    /// Heating lowers the friction, the more the faster the sliding; the corrected Eq. (14)
    /// scales with it; only a correction beyond the isothermal bound is warned of.
    #[test]
    fn shear_heating_lowers_friction_more_at_larger_slip() {
        let (_, slow) = at_slip(0.001);
        let (c_fast, fast) = at_slip(0.05);
        let (slow, fast) = (slow.unwrap().unwrap(), fast.unwrap().unwrap());
        assert!(slow.correction() < 0.0 && fast.correction() < slow.correction());
        assert_eq!(fast.corrected(40.0), 40.0 * (1.0 + fast.correction()));
        let warned = warnings(&c_fast, &Some(Ok(fast.clone())));
        assert_eq!(
            warned.len(),
            usize::from(fast.correction().abs() > ISOTHERMAL_CORRECTION_MAX)
        );
    }

    /// Without thermal scales (a lubricant given by alpha and eta0) there is no correction,
    /// and a slip beyond the paper's isothermal runs is warned of instead.
    #[test]
    fn without_thermal_scales_large_slip_is_warned_of() {
        let mut case = worked_case();
        if let CaseForm::Physical(p) = &mut case.spec {
            p.lubricant = LubricantSpec::Given {
                alpha_per_pa: 2e-8,
                eta0_pa_s: 0.01,
            };
            p.slip = 0.05;
        }
        let lubs = LubricantTable::table1();
        let p = Prediction::of(&case, &lubs).unwrap();
        let heat = HeatCorrection::flat_estimate(&case, &p.problem, &steel());
        assert!(heat.is_none());
        let w = warnings(&p.central.characteristic, &heat);
        assert_eq!(w.len(), 1);
        assert!(w[0].starts_with("S = 0.05 is above"), "{}", w[0]);
    }

    #[test]
    fn low_tau_c_is_warned_of() {
        let (mut c, _) = at_slip(0.005);
        c.tau_c = FIT_TAU_C_MIN / 2.0;
        let w = warnings(&c, &None);
        assert!(w[0].starts_with("tau_c = 5.000e1 is below 100"), "{w:?}");
    }
}
