//! A case: what a user asks to be solved, physically or in Moes groups, and the dimensionless
//! problem it becomes. The dimensionless numbers (M, L, S-bar, alpha-bar, lambda, kappa, N)
//! are computed here and nowhere else.

pub use super::checks::CaseError;
use super::checks::{field, hertzian_pressure, positive, slip_in_range, MoesInputs};
use super::datasheet::{Datasheet, DatasheetState};
use super::density::{Density, DensityLaw};
use super::hertz::Hertz;
use super::lubricant::{LubricantState, LubricantTable};
use super::rheology::{Rheology, ShearLaw};
use super::viscosity::{Viscosity, ViscosityLaw};
use serde::{Deserialize, Serialize};

/// The physics a case asks for; the solver composes only these.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct Physics {
    /// Viscosity-pressure law.
    pub viscosity: ViscosityLaw,
    /// Density-pressure law.
    pub density: DensityLaw,
    /// Rheology.
    pub rheology: Rheology,
}

impl Physics {
    /// The physics a problem composes, read back from its laws (point and line problems).
    pub fn of(viscosity: &Viscosity, density: &Density, rheology: Rheology) -> Self {
        Physics {
            viscosity: viscosity.law(),
            density: density.law(),
            rheology,
        }
    }

    /// The physics of Figs. 4-7 and of the Appendix case: Roelands, Dowson-Higginson, Eyring.
    pub fn figs_4_to_7() -> Self {
        Physics {
            viscosity: ViscosityLaw::Roelands,
            density: DensityLaw::DowsonHigginson,
            rheology: Rheology::Eyring,
        }
    }
}

/// Where the lubricant's `alpha` and `eta0` come from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum LubricantSpec {
    /// A lubricant of Table 1 (`cases/lubricants.toml`) at a temperature.
    Named {
        /// Name in the table.
        lubricant: String,
        /// Temperature, C.
        temperature_c: f64,
    },
    /// Properties given directly.
    Given {
        /// Pressure-viscosity coefficient, 1/Pa.
        alpha_per_pa: f64,
        /// Ambient viscosity, Pa s.
        eta0_pa_s: f64,
    },
    /// A lubricant's datasheet at a temperature: `eta0 = nu rho` by ASTM D341 and D1250,
    /// `alpha` the user's or AGMA 925's ([`super::datasheet`]). The whole datasheet is part
    /// of the case, so the case alone determines its cache key.
    Datasheet {
        /// The datasheet (its keys flattened: `iso_vg`, `rho15_kg_m3`, ...).
        #[serde(flatten)]
        datasheet: Datasheet,
        /// Temperature, C.
        temperature_c: f64,
        /// Pressure-viscosity coefficient the user knows, 1/GPa: used instead of the
        /// correlation.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        alpha_per_gpa: Option<f64>,
    },
}

impl LubricantSpec {
    /// `alpha` and `eta0` in SI units: looked up in the table at the temperature, or checked
    /// (positive, finite) when given.
    pub fn resolve(&self, lubs: &LubricantTable) -> Result<LubricantState, CaseError> {
        match self {
            LubricantSpec::Named {
                lubricant,
                temperature_c,
            } => Ok(lubs.state(lubricant, *temperature_c)?),
            LubricantSpec::Given {
                alpha_per_pa,
                eta0_pa_s,
            } => Ok(LubricantState {
                alpha_per_pa: positive("alpha", *alpha_per_pa)?,
                eta0_pa_s: positive("eta0", *eta0_pa_s)?,
            }),
            LubricantSpec::Datasheet {
                datasheet,
                temperature_c,
                alpha_per_gpa,
            } => Ok(datasheet_at(datasheet, *temperature_c, *alpha_per_gpa)?.state),
        }
    }

    /// The temperature the lubricant is taken at, C; `None` when `alpha` and `eta0` are given.
    pub fn temperature_c(&self) -> Option<f64> {
        match self {
            LubricantSpec::Named { temperature_c, .. }
            | LubricantSpec::Datasheet { temperature_c, .. } => Some(*temperature_c),
            LubricantSpec::Given { .. } => None,
        }
    }

    /// For a datasheet lubricant, what the solver does not need and a report shows: the
    /// viscosity and density at the temperature, and whether `alpha` was correlated (with
    /// the correlation's band and source) or given; `None` for the other lubricants.
    pub fn datasheet_state(&self) -> Option<Result<DatasheetState, CaseError>> {
        let LubricantSpec::Datasheet {
            datasheet,
            temperature_c,
            alpha_per_gpa,
        } = self
        else {
            return None;
        };
        Some(datasheet_at(datasheet, *temperature_c, *alpha_per_gpa))
    }
}

fn datasheet_at(
    datasheet: &Datasheet,
    temperature_c: f64,
    alpha_per_gpa: Option<f64>,
) -> Result<DatasheetState, CaseError> {
    Ok(datasheet.resolve()?.at(temperature_c, alpha_per_gpa)?)
}

/// A contact given by its physical operating conditions (SI units).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PhysicalCase {
    /// Lubricant.
    #[serde(flatten)]
    pub lubricant: LubricantSpec,
    /// Maximum Hertzian pressure, Pa.
    pub ph_pa: f64,
    /// Mean velocity `u_m = (u1 + u2)/2`, m/s.
    pub um_m_s: f64,
    /// Slide-to-roll ratio `S = 2 (u2 - u1) / (u2 + u1)`.
    pub slip: f64,
    /// Eyring stress, Pa.
    pub tau0_pa: f64,
    /// Reduced radius in the rolling direction, m.
    pub rx_m: f64,
    /// Reduced radius across the rolling direction, m.
    pub ry_m: f64,
    /// Reduced modulus `E'`, Pa.
    pub e_prime_pa: f64,
}

/// A contact given by its Moes groups.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DimensionlessCase {
    /// Moes load parameter.
    pub m: f64,
    /// Moes lubricant parameter.
    pub l: f64,
    /// Dimensionless slip, Eq. (9).
    pub s_bar: f64,
    /// Ellipticity ratio `Rx/Ry`.
    pub d: f64,
    /// Slide-to-roll ratio: with `S-bar` it fixes `tau0`, hence the scale of the rolling
    /// friction in `mu-bar` (the Moes groups alone do not).
    pub slip: f64,
    /// Ambient viscosity, Pa s: needed only by Roelands.
    pub eta0_pa_s: Option<f64>,
    /// Maximum Hertzian pressure, Pa: needed only by Roelands and Dowson-Higginson.
    pub ph_pa: Option<f64>,
}

/// How a case is specified.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum CaseForm {
    /// Physical operating conditions.
    Physical(PhysicalCase),
    /// Moes groups.
    Dimensionless(DimensionlessCase),
}

/// A case: a specification and the physics to solve it with.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Case {
    /// Operating conditions.
    pub spec: CaseForm,
    /// Physics.
    pub physics: Physics,
}

impl Case {
    /// The circular contact of the Moes groups `m`, `l` and `s_bar` at 1 % slip with the
    /// default physics (Barus, incompressible, Eyring): the form of Figs. 1-3's cases.
    pub fn circular(m: f64, l: f64, s_bar: f64) -> Case {
        Case {
            spec: CaseForm::Dimensionless(DimensionlessCase {
                m,
                l,
                s_bar,
                d: 1.0,
                slip: 0.01,
                eta0_pa_s: None,
                ph_pa: None,
            }),
            physics: Physics::default(),
        }
    }
}

/// The physical `p_H` (Pa) and `eta0` (Pa s) of a case given in Moes groups, point or line
/// contact: checked when given, required by the laws that need them (Roelands both,
/// Dowson-Higginson `p_H`), NaN when no law asked for them.
pub(super) fn physical_scales(
    physics: Physics,
    ph_pa: Option<f64>,
    eta0_pa_s: Option<f64>,
) -> Result<(f64, f64), CaseError> {
    let needs_ph = physics.viscosity == ViscosityLaw::Roelands
        || physics.density == DensityLaw::DowsonHigginson;
    let ph_pa = match ph_pa {
        Some(v) => hertzian_pressure("ph", v)?,
        None if needs_ph => return Err(field(
            "ph",
            "Roelands and Dowson-Higginson need the physical p_H (Pa) in the dimensionless form",
        )),
        None => f64::NAN,
    };
    let eta0 = match eta0_pa_s {
        Some(v) => positive("eta0", v)?,
        None if physics.viscosity == ViscosityLaw::Roelands => {
            return Err(field(
                "eta0",
                "Roelands needs the ambient viscosity (Pa s) in the dimensionless form",
            ))
        }
        None => f64::NAN,
    };
    Ok((ph_pa, eta0))
}

/// The dimensionless groups of a case (Sec. II and Nomenclature).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Groups {
    /// Moes load parameter `M`.
    pub m: f64,
    /// Moes lubricant parameter `L`.
    pub l: f64,
    /// Dimensionless slip `S-bar`, Eq. (9).
    pub s_bar: f64,
    /// Ellipticity ratio `D = Rx/Ry`.
    pub d: f64,
    /// `alpha-bar = alpha p_H`.
    pub alpha_bar: f64,
    /// Speed parameter `lambda = 6 eta0 u_s a / (c^2 p_H)`.
    pub lambda: f64,
    /// `kappa = a/b`.
    pub kappa: f64,
    /// Eyring parameter `N = lambda p_H^2 K / (6 E' tau0)`.
    pub n: f64,
    /// Slide-to-roll ratio `S`.
    pub slip: f64,
    /// `c / (Rx sqrt(U))`, `U = eta0 u_s / (E' Rx)`: converts `H = h/c` to Moes units.
    pub moes_film_scale: f64,
}

impl Groups {
    /// Computes every group from the Hertz scales, `eta0 u_s` (Pa m), `alpha` (1/Pa),
    /// `1/tau0` (1/Pa, zero for an infinite Eyring stress) and `S`.
    pub fn new(hz: &Hertz, eta0_us: f64, alpha: f64, tau0_inv: f64, slip: f64) -> Self {
        let u = eta0_us / (hz.e_prime * hz.rx);
        Groups {
            m: hz.load / (hz.e_prime * hz.rx * hz.rx) * u.powf(-0.75),
            l: alpha * hz.e_prime * u.powf(0.25),
            s_bar: slip * (eta0_us * hz.e_prime / hz.rx).sqrt() * tau0_inv,
            d: hz.rx / hz.ry,
            alpha_bar: alpha * hz.ph,
            lambda: 6.0 * eta0_us * hz.a / (hz.c * hz.c * hz.ph),
            kappa: hz.kappa,
            n: eta0_us / (2.0 * hz.c) * tau0_inv,
            slip,
            moes_film_scale: hz.c / hz.rx / u.sqrt(),
        }
    }

    /// The coefficient of the rolling (Poiseuille) shear stress on the surface,
    /// `(h/2)(dp/dx)/tau0 = (6 N / lambda) H dP/dX`.
    pub fn rolling_stress_scale(&self) -> f64 {
        6.0 * self.n / self.lambda
    }
}

/// The dimensionless shear law of a case's rheology, point or line contact: `tau0_over_ph`
/// is `tau0 / p_H` (infinite when the case has no Eyring stress, `S-bar = 0`), `ph_pa` the
/// physical `p_H` in Pa (NaN when a dimensionless case does not give it). The limiting
/// shear stress needs both: its `tau_L0` is in Pa.
pub(super) fn shear_law(
    rheology: Rheology,
    tau0_over_ph: f64,
    ph_pa: f64,
) -> Result<ShearLaw, CaseError> {
    let Rheology::EyringLss(lss) = rheology else {
        return Ok(ShearLaw::of_plain(rheology).expect("a rheology without parameters"));
    };
    let lss = lss
        .checked()
        .map_err(|(name, message)| field(name, message))?;
    if !tau0_over_ph.is_finite() {
        return Err(field(
            "s-bar",
            "the limiting shear stress needs an Eyring stress: S-bar > 0",
        ));
    }
    if !ph_pa.is_finite() {
        return Err(field(
            "ph",
            "the limiting shear stress (tau_L0 in Pa) needs the physical p_H (Pa) in the dimensionless form",
        ));
    }
    Ok(lss.shear_law(tau0_over_ph * ph_pa, ph_pa))
}

/// `N S` of a point or line contact: the Couette stress argument of Eq. (4) is
/// `N S eta_bar / H`, so the solvers take this product once.
pub(super) fn eyring_n_s(n: f64, slip: f64) -> f64 {
    n * slip
}

/// The dimensionless point-contact problem of Eqs. (1)-(8), what the solver consumes.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// Dimensionless groups.
    pub groups: Groups,
    /// Elliptic integral `K` at `kappa` (the deformation integral's factor `1/(pi K)`).
    pub ell_k: f64,
    /// Shape factor `S(kappa)` of Eq. (6).
    pub shape: f64,
    /// Viscosity law.
    pub viscosity: Viscosity,
    /// Density law.
    pub density: Density,
    /// Rheology, as the case states it.
    pub rheology: Rheology,
    /// The rheology's dimensionless law, what the solver evaluates.
    pub shear: ShearLaw,
    /// The Hertz scales (physical for a physical case; in units of `Rx`, `E'` for a
    /// dimensionless one).
    pub hertz: Hertz,
}

impl Problem {
    /// The circular contact of the groups `m`, `l`, `s_bar` at 1 % slip with the default
    /// physics: the unit tests' contact.
    #[cfg(test)]
    pub(crate) fn circular(m: f64, l: f64, s_bar: f64) -> Problem {
        let case = Case::circular(m, l, s_bar);
        Problem::from_case(&case, &LubricantTable::table1()).expect("a valid contact")
    }

    /// Resolves a case against the lubricant table and checks every field.
    pub fn from_case(case: &Case, lubricants: &LubricantTable) -> Result<Self, CaseError> {
        match &case.spec {
            CaseForm::Physical(p) => Self::from_physical(p, case.physics, lubricants),
            CaseForm::Dimensionless(d) => Self::from_dimensionless(d, case.physics),
        }
    }

    fn from_physical(
        p: &PhysicalCase,
        physics: Physics,
        lubs: &LubricantTable,
    ) -> Result<Self, CaseError> {
        let state = p.lubricant.resolve(lubs)?;
        let (alpha, eta0) = (state.alpha_per_pa, state.eta0_pa_s);
        let ph = hertzian_pressure("ph", p.ph_pa)?;
        let um = positive("um", p.um_m_s)?;
        let slip = slip_in_range("slip", p.slip)?;
        let tau0 = positive("tau0", p.tau0_pa)?;
        let rx = positive("rx", p.rx_m)?;
        let ry = positive("ry", p.ry_m)?;
        let e_prime = positive("e-prime", p.e_prime_pa)?;
        if rx > ry {
            return Err(field(
                "ry",
                format!("Rx/Ry must not exceed 1 (kappa in (0, 1]); got Rx = {rx}, Ry = {ry}"),
            ));
        }
        let hz = Hertz::from_ph(ph, rx, ry, e_prime);
        let groups = Groups::new(&hz, eta0 * 2.0 * um, alpha, 1.0 / tau0, slip);
        let shear = shear_law(physics.rheology, tau0 / ph, ph)?;
        Ok(Self::assemble(groups, hz, physics, shear, eta0, alpha, ph))
    }

    fn from_dimensionless(d: &DimensionlessCase, physics: Physics) -> Result<Self, CaseError> {
        let MoesInputs {
            m,
            l,
            slip,
            tau0_inv,
        } = MoesInputs::check(d.m, d.l, d.s_bar, d.slip)?;
        let ratio = positive("d", d.d)?;
        if ratio > 1.0 {
            return Err(field(
                "d",
                format!("Rx/Ry must lie in (0, 1] (kappa in (0, 1]), got {ratio}"),
            ));
        }
        // In units Rx = E' = 1 and U = eta0 u_s / (E' Rx) = 1 the load is M and alpha is L;
        // every dimensionless group is independent of U (Moes' similarity).
        let hz = Hertz::from_load(m, 1.0, 1.0 / ratio, 1.0);
        let groups = Groups::new(&hz, 1.0, l, tau0_inv, slip);
        let (ph_pa, eta0) = physical_scales(physics, d.ph_pa, d.eta0_pa_s)?;
        let shear = shear_law(physics.rheology, 1.0 / (tau0_inv * hz.ph), ph_pa)?;
        Ok(Self::assemble(
            groups,
            hz,
            physics,
            shear,
            eta0,
            groups.alpha_bar / ph_pa,
            ph_pa,
        ))
    }

    fn assemble(
        groups: Groups,
        hertz: Hertz,
        physics: Physics,
        shear: ShearLaw,
        eta0: f64,
        alpha: f64,
        ph: f64,
    ) -> Self {
        Problem {
            groups,
            ell_k: hertz.ell_k,
            shape: hertz.shape_factor(),
            viscosity: match physics.viscosity {
                ViscosityLaw::Barus => Viscosity::barus(groups.alpha_bar),
                ViscosityLaw::Roelands => Viscosity::roelands(eta0, alpha, ph),
            },
            density: Density::new(physics.density, ph),
            rheology: physics.rheology,
            shear,
            hertz,
        }
    }

    /// The physics this problem composes.
    pub fn physics(&self) -> Physics {
        Physics::of(&self.viscosity, &self.density, self.rheology)
    }

    /// `N S`: the Couette stress argument is `N S eta_bar / H` (Eq. 4).
    pub fn eyring_n_s(&self) -> f64 {
        eyring_n_s(self.groups.n, self.groups.slip)
    }

    /// Characteristic shear stress, Eq. (12): `tau_c = eta_bar(p_H) S-bar / Hc` with `Hc`
    /// from Eq. (10) and `eta_bar(p_H)` from the case's own viscosity law.
    pub fn tau_c(&self) -> f64 {
        self.viscosity.eta_bar(1.0) * self.groups.s_bar
            / super::film::hc_eq10(self.groups.m, self.groups.l)
    }
}

#[cfg(test)]
pub(crate) mod tests;
