//! The checks of a case's inputs, for every form a case takes (point or line, physical or in
//! Moes groups): [`CaseError`], which names the offending field, and the range checks that
//! make one.

use super::datasheet::DatasheetError;
use super::lubricant::LubricantError;

/// A case that cannot be solved: names the field.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CaseError {
    /// A field is out of its physical range.
    #[error("{field}: {message}")]
    Field {
        /// The offending field (flag or case-file key).
        field: &'static str,
        /// What is expected.
        message: String,
    },
    /// The lubricant lookup failed.
    #[error(transparent)]
    Lubricant(#[from] LubricantError),
    /// A datasheet lubricant is inconsistent or asked outside its laws' range
    /// ([`DatasheetError::field`] names the key).
    #[error(transparent)]
    Datasheet(#[from] DatasheetError),
}

pub(super) fn field(field: &'static str, message: impl Into<String>) -> CaseError {
    CaseError::Field {
        field,
        message: message.into(),
    }
}

pub(super) fn positive(name: &'static str, v: f64) -> Result<f64, CaseError> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(field(name, format!("must be positive and finite, got {v}")))
    }
}

/// Range of the maximum Hertzian pressure (Pa) a case may have: 1 MPa (soft, barely
/// piezoviscous contacts) to 20 GPa (beyond every steel contact). Its purpose is to catch a
/// unit slip, e.g. `--ph 3` meant as GPa, which otherwise gives a problem no solver converges.
const PH_RANGE_PA: std::ops::RangeInclusive<f64> = 1e6..=2e10;

/// A maximum Hertzian pressure in Pa, inside [`PH_RANGE_PA`].
pub(super) fn hertzian_pressure(name: &'static str, v: f64) -> Result<f64, CaseError> {
    let v = positive(name, v)?;
    if PH_RANGE_PA.contains(&v) {
        Ok(v)
    } else {
        Err(field(
            name,
            format!(
                "p_H = {v} Pa is outside {:e}..={:e} Pa; it is in Pa (3 GPa is 3e9)",
                PH_RANGE_PA.start(),
                PH_RANGE_PA.end()
            ),
        ))
    }
}

pub(super) fn slip_in_range(name: &'static str, s: f64) -> Result<f64, CaseError> {
    if (0.0..=2.0).contains(&s) {
        Ok(s)
    } else {
        Err(field(
            name,
            format!("slide-to-roll ratio must lie in [0, 2], got {s}"),
        ))
    }
}

/// The checked Moes groups of a case given dimensionlessly, point or line contact: `M`,
/// `L`, `S-bar` and `S`, and `1/tau0 = S-bar / S` in the units `Rx = E' = 1`,
/// `U = eta0 u_s / (E' Rx) = 1` (zero without an Eyring stress, `S-bar = 0`).
pub(super) struct MoesInputs {
    pub m: f64,
    pub l: f64,
    pub slip: f64,
    pub tau0_inv: f64,
}

impl MoesInputs {
    /// Checks `M`, `L` (positive), `S-bar` (non-negative) and `S` (in `[0, 2]`, positive
    /// where `S-bar` is).
    pub(super) fn check(m: f64, l: f64, s_bar: f64, slip: f64) -> Result<Self, CaseError> {
        let m = positive("m", m)?;
        let l = positive("l", l)?;
        if !(s_bar >= 0.0 && s_bar.is_finite()) {
            return Err(field("s-bar", format!("must be >= 0, got {s_bar}")));
        }
        let slip = slip_in_range("slip", slip)?;
        if s_bar > 0.0 && slip == 0.0 {
            return Err(field("slip", "S-bar > 0 needs a slide-to-roll ratio S > 0"));
        }
        let tau0_inv = if s_bar > 0.0 { s_bar / slip } else { 0.0 };
        Ok(MoesInputs {
            m,
            l,
            slip,
            tau0_inv,
        })
    }
}
