//! The transform of Sec. IV: physical operating conditions of a traction measurement (or of a
//! user's contact) to the paper's friction parameters, the characteristic shear stress
//! `tau_c` of Eq. (12) and the reduced friction coefficient `mu-bar = mu p_H / tau0` of
//! Eq. (8).
//!
//! `tau_c = eta_bar(p_H) S-bar / Hc` (Eq. 12), with `S-bar` from Eq. (9), `eta_bar(p_H)` from
//! the lubricant's viscosity law or a measured value, and `Hc` the central film of a published
//! formula in Moes units: Eq. (10) for elliptical contacts (what the paper did for the data of
//! Klein-Meuleman et al.), Dowson-Higginson for line contacts (what it did for the data of
//! Evans and Johnson). Substituting the Moes units gives the physical reading of Eq. (12):
//! `tau_c = 2 eta(p_H) gamma_dot / tau0` with `gamma_dot = (u2 - u1) / h_c` the nominal shear
//! rate of the formula's central film; twice the Newtonian stress at the centre over `tau0`.
//!
//! The Hertz scales, Moes groups and viscosity laws are those of [`super::case`],
//! [`super::line_contact`] and [`super::viscosity`]: nothing is recomputed here.

use super::case::{CaseForm, LubricantSpec, PhysicalCase, Physics, Problem};
use super::checks::{field, positive, CaseError};
use super::density::DensityLaw;
use super::film::hc_eq10;
use super::hertz::Hertz;
use super::line_contact::{LineFilmFormula, LineHertz, LinePhysicalCase, LineProblem};
use super::lubricant::LubricantTable;
use super::rheology::Rheology;
use super::viscosity::ViscosityLaw;

/// Largest slide-to-roll ratio of the paper's isothermal computations (Table 2: S = 0.1, 0.5
/// and 2 %; Table 3 likewise). Sec. III B keeps slip "in a small range to ensure that [the
/// isothermal] assumption is justified", and the Conclusions warn that where "a significant
/// amount of sliding occurs, the predicted coefficients of friction will be too large". Above
/// this slip Eq. (14) is an extrapolation past the paper's evidence.
pub const ISOTHERMAL_SLIP_MAX: f64 = 0.02;

/// The contact geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// An elliptical (or circular) contact, `Rx <= Ry`.
    Elliptical {
        /// Reduced radius in the rolling direction, m.
        rx_m: f64,
        /// Reduced radius across the rolling direction, m.
        ry_m: f64,
    },
    /// A line contact (two discs without crown).
    Line {
        /// Reduced radius in the rolling direction, m.
        rx_m: f64,
    },
}

/// How the load is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// Maximum Hertzian pressure `p_H`, Pa.
    MaxPressure(f64),
    /// Normal load `f`, N (elliptical contacts).
    Force(f64),
    /// Load per unit length `w'`, N/m (line contacts).
    PerLength(f64),
}

/// How the rolling speed is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Speed {
    /// Mean velocity `u_m = (u1 + u2)/2`, m/s.
    Mean(f64),
    /// Sum velocity `u_s = u1 + u2`, m/s.
    Sum(f64),
}

impl Speed {
    /// `u_m`, m/s.
    pub fn mean(self) -> f64 {
        match self {
            Speed::Mean(u) => u,
            Speed::Sum(u) => 0.5 * u,
        }
    }
}

/// How the sliding is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sliding {
    /// Slide-to-roll ratio `S = 2 (u2 - u1) / (u2 + u1)`.
    Slip(f64),
    /// Nominal shear rate `gamma_dot = (u2 - u1) / h`, 1/s, as publications of two-disc data
    /// give it (Evans and Johnson). `film_m` is the film `h` the publication divided by; when
    /// absent, `h` is the central film of the case's [`FilmFormula`], which is how the paper
    /// read Evans and Johnson's data ("the value of the slip is extracted from gamma_dot using
    /// Dowson and Higginson's formula").
    ShearRate {
        /// `gamma_dot`, 1/s.
        per_s: f64,
        /// The film the shear rate was computed with, m.
        film_m: Option<f64>,
    },
}

/// Where `eta(p_H)` comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ViscosityAtPh {
    /// The law, with the lubricant's `alpha` and `eta0` ([`super::viscosity::Viscosity`]).
    Law(ViscosityLaw),
    /// A measured value, Pa s (the paper read it from Evans and Johnson's viscosity graphs).
    Given(f64),
}

/// The central-film formula of `Hc` in Eq. (12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FilmFormula {
    /// Eq. (10), `Hc = 1.7 M^{-1/9} L^{3/4}`: elliptical contacts.
    Eq10,
    /// A line-contact formula ([`LineFilmFormula`]); the paper used Dowson-Higginson.
    Line(LineFilmFormula),
}

impl FilmFormula {
    /// The name used in files and output.
    pub fn name(self) -> &'static str {
        match self {
            FilmFormula::Eq10 => "eq10",
            FilmFormula::Line(LineFilmFormula::DowsonHigginson) => "dowson-higginson",
            FilmFormula::Line(LineFilmFormula::Moes) => "moes",
            FilmFormula::Line(LineFilmFormula::DowsonToyoda) => "dowson-toyoda",
        }
    }

    /// The formula of a name (the inverse of [`FilmFormula::name`]).
    pub fn from_name(name: &str) -> Option<Self> {
        [
            FilmFormula::Eq10,
            FilmFormula::Line(LineFilmFormula::DowsonHigginson),
            FilmFormula::Line(LineFilmFormula::Moes),
            FilmFormula::Line(LineFilmFormula::DowsonToyoda),
        ]
        .into_iter()
        .find(|f| f.name() == name)
    }
}

/// Physical operating conditions of one contact, SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct OperatingPoint {
    /// Geometry.
    pub contact: Contact,
    /// Reduced modulus `E'`, Pa.
    pub e_prime_pa: f64,
    /// Load.
    pub load: Load,
    /// Lubricant `alpha` and `eta0` (at the test temperature).
    pub lubricant: LubricantSpec,
    /// Rolling speed.
    pub speed: Speed,
    /// Sliding.
    pub sliding: Sliding,
    /// Eyring stress `tau0`, Pa.
    pub tau0_pa: f64,
    /// Viscosity at `p_H`.
    pub viscosity: ViscosityAtPh,
    /// Film formula of `Hc`.
    pub film: FilmFormula,
}

/// An operating point in the paper's parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Characteristic {
    /// Characteristic shear stress `tau_c`, Eq. (12).
    pub tau_c: f64,
    /// Maximum Hertzian pressure, Pa.
    pub ph_pa: f64,
    /// Slide-to-roll ratio `S` (derived from the shear rate when that was given).
    pub slip: f64,
    /// Moes load parameter `M` (point- or line-contact form).
    pub m: f64,
    /// Moes lubricant parameter `L`.
    pub l: f64,
    /// Dimensionless slip `S-bar`, Eq. (9).
    pub s_bar: f64,
    /// `eta(p_H) / eta0`.
    pub eta_bar_ph: f64,
    /// `Hc` of the film formula, Moes units.
    pub hc_moes: f64,
    /// The same film, m.
    pub hc_m: f64,
}

impl Characteristic {
    /// Reduced friction coefficient, Eq. (8): `mu-bar = mu p_H / tau0`.
    pub fn reduced_friction(&self, mu: f64, tau0_pa: f64) -> f64 {
        mu * self.ph_pa / tau0_pa
    }

    /// Friction coefficient from a reduced one: `mu = mu-bar tau0 / p_H`.
    pub fn friction(&self, mu_bar: f64, tau0_pa: f64) -> f64 {
        mu_bar * tau0_pa / self.ph_pa
    }
}

/// What the film formula needs from either geometry: groups and the film unit.
struct ContactGroups {
    ph: f64,
    m: f64,
    l: f64,
    s_bar: f64,
    eta_bar_ph_law: f64,
    /// `Hc` (Moes) to metres.
    moes_to_m: f64,
}

/// The point's groups at slip `slip` (elliptical: through [`Problem`]; line: through
/// [`LineProblem`]).
fn resolve(
    point: &OperatingPoint,
    slip: f64,
    lubs: &LubricantTable,
) -> Result<ContactGroups, CaseError> {
    let e_prime = positive("e-prime", point.e_prime_pa)?;
    let um = positive("um", point.speed.mean())?;
    let law = match point.viscosity {
        ViscosityAtPh::Law(law) => law,
        // Only the groups are read; the law is not evaluated for a given eta(p_H).
        ViscosityAtPh::Given(_) => ViscosityLaw::Barus,
    };
    let physics = Physics {
        viscosity: law,
        density: DensityLaw::Incompressible,
        rheology: Rheology::Eyring,
    };
    match point.contact {
        Contact::Elliptical { rx_m, ry_m } => {
            let rx = positive("rx", rx_m)?;
            let ry = positive("ry", ry_m)?;
            let ph = match point.load {
                Load::MaxPressure(p) => p,
                Load::Force(f) => {
                    if rx > ry {
                        return Err(field("ry", format!("Rx/Ry must not exceed 1 (kappa in (0, 1]); got Rx = {rx}, Ry = {ry}")));
                    }
                    Hertz::from_load(positive("load", f)?, rx, ry, e_prime).ph
                }
                Load::PerLength(_) => {
                    return Err(field(
                        "load",
                        "a load per unit length needs a line contact; give p_H or the load in N",
                    ))
                }
            };
            let case = crate::physics::case::Case {
                spec: CaseForm::Physical(PhysicalCase {
                    lubricant: point.lubricant.clone(),
                    ph_pa: ph,
                    um_m_s: um,
                    slip,
                    tau0_pa: point.tau0_pa,
                    rx_m: rx,
                    ry_m: ry,
                    e_prime_pa: e_prime,
                }),
                physics,
            };
            let p = Problem::from_case(&case, lubs)?;
            let g = &p.groups;
            Ok(ContactGroups {
                ph,
                m: g.m,
                l: g.l,
                s_bar: g.s_bar,
                eta_bar_ph_law: p.viscosity.eta_bar(1.0),
                // moes_film_scale = c / (Rx sqrt U), so Rx sqrt U = c / moes_film_scale.
                moes_to_m: p.hertz.c / g.moes_film_scale,
            })
        }
        Contact::Line { rx_m } => {
            let rx = positive("rx", rx_m)?;
            let ph = match point.load {
                Load::MaxPressure(p) => p,
                Load::PerLength(w) => LineHertz::from_load(positive("load", w)?, rx, e_prime).ph,
                Load::Force(_) => {
                    return Err(field(
                        "load",
                        "a line contact takes the load per unit length (N/m) or p_H",
                    ))
                }
            };
            let state = point.lubricant.resolve(lubs)?;
            let p = LineProblem::from_physical(
                &LinePhysicalCase {
                    alpha_per_pa: state.alpha_per_pa,
                    eta0_pa_s: state.eta0_pa_s,
                    ph_pa: ph,
                    um_m_s: um,
                    slip,
                    tau0_pa: point.tau0_pa,
                    rx_m: rx,
                    e_prime_pa: e_prime,
                },
                physics,
            )?;
            let g = &p.groups;
            Ok(ContactGroups {
                ph,
                m: g.m,
                l: g.l,
                s_bar: g.s_bar,
                eta_bar_ph_law: p.viscosity.eta_bar(1.0),
                // moes_film_scale converts H = h Rx / a^2 to Moes units.
                moes_to_m: p.hertz.film_unit() / g.moes_film_scale,
            })
        }
    }
}

/// The Sec. IV transform: `tau_c` (Eq. 12) and the quantities it is made of, for a contact
/// given physically. Every field is checked; an error names it (`ph`, `um`, `slip`,
/// `shear-rate`, `tau0`, `rx`, `ry`, `e-prime`, `load`, `eta-ph`, `film`, or the lubricant).
pub fn characteristic(
    point: &OperatingPoint,
    lubs: &LubricantTable,
) -> Result<Characteristic, CaseError> {
    let hc_of = |r: &ContactGroups| {
        match (point.film, point.contact) {
        (FilmFormula::Eq10, Contact::Elliptical { .. }) => Ok(hc_eq10(r.m, r.l)),
        (FilmFormula::Line(f), Contact::Line { .. }) => Ok(f.hc(r.m, r.l)),
        (FilmFormula::Eq10, Contact::Line { .. }) => Err(field(
            "film",
            "Eq. (10) is a point-contact formula; a line contact takes dowson-higginson, moes or dowson-toyoda",
        )),
        (FilmFormula::Line(_), Contact::Elliptical { .. }) => Err(field(
            "film",
            "an elliptical contact takes Eq. (10) (eq10), the film of the paper's tau_c",
        )),
    }
    };
    let (resolved, slip) = match point.sliding {
        Sliding::Slip(s) => (resolve(point, s, lubs)?, s),
        Sliding::ShearRate { per_s, film_m } => {
            let rate = positive("shear-rate", per_s)?;
            // The groups other than S-bar do not depend on S: resolve at S = 0 for the film.
            let at_rest = resolve(point, 0.0, lubs)?;
            let h = match film_m {
                Some(h) => positive("shear-rate-film", h)?,
                None => hc_of(&at_rest)? * at_rest.moes_to_m,
            };
            // gamma_dot = (u2 - u1) / h and u2 - u1 = S u_m.
            let s = rate * h / point.speed.mean();
            if s > 2.0 {
                return Err(field(
                    "shear-rate",
                    format!("gives a slide-to-roll ratio S = gamma_dot h / u_m = {s:.4} above 2 (h = {h:.4e} m)"),
                ));
            }
            (resolve(point, s, lubs)?, s)
        }
    };
    let hc = hc_of(&resolved)?;
    let eta_bar_ph = match point.viscosity {
        ViscosityAtPh::Law(_) => resolved.eta_bar_ph_law,
        ViscosityAtPh::Given(eta) => {
            positive("eta-ph", eta)? / point.lubricant.resolve(lubs)?.eta0_pa_s
        }
    };
    Ok(Characteristic {
        tau_c: eta_bar_ph * resolved.s_bar / hc,
        ph_pa: resolved.ph,
        slip,
        m: resolved.m,
        l: resolved.l,
        s_bar: resolved.s_bar,
        eta_bar_ph,
        hc_moes: hc,
        hc_m: hc * resolved.moes_to_m,
    })
}

/// A measured friction coefficient transformed to the paper's parameters (Fig. 8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reduced {
    /// The operating point's `tau_c` and groups.
    pub characteristic: Characteristic,
    /// `mu-bar = mu p_H / tau0`, Eq. (8).
    pub mu_bar: f64,
}

/// Transforms a measured friction coefficient `mu` at `point` to `(tau_c, mu-bar)`.
pub fn reduce(
    point: &OperatingPoint,
    mu: f64,
    lubs: &LubricantTable,
) -> Result<Reduced, CaseError> {
    if !(mu >= 0.0 && mu.is_finite()) {
        return Err(field(
            "mu",
            format!("must be non-negative and finite, got {mu}"),
        ));
    }
    let c = characteristic(point, lubs)?;
    Ok(Reduced {
        mu_bar: c.reduced_friction(mu, positive("tau0", point.tau0_pa)?),
        characteristic: c,
    })
}

#[cfg(test)]
mod tests;
