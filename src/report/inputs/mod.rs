//! The layer between the flags and the library: the inputs of one solve as plain data (the
//! command line's flags, the Python package's keywords), turned once into what the library
//! takes (a [`Case`], solver parameters, a line problem, the thermal post-process's inputs),
//! or into an [`InputError`] that names its [`Flag`]. Nothing below takes a flag; nothing
//! here solves.

mod error;
mod lubricant;

pub use error::{check_level, flag_error, Flag, InputError};
pub use lubricant::{lubricant_spec, physics, DatasheetInputs, RheologyChoice};

use crate::paper::target::WORKING_LEVEL;
use crate::physics::case::{Case, CaseForm, DimensionlessCase, PhysicalCase, Physics, Problem};
use crate::physics::density::DensityLaw;
use crate::physics::line_contact::{LineDimensionlessCase, LinePhysicalCase, LineProblem};
use crate::physics::lubricant::LubricantTable;
use crate::physics::thermal::{FilmProperties, Solid, ThermalInputs};
use crate::physics::viscosity::ViscosityLaw;
use crate::solver::grid::Domain;
use crate::solver::point::composite::Patch;
use crate::solver::{line, point};
use error::need;
use lubricant::rheology;

/// Returns the error that `flag` is wrong as the formatted message says.
macro_rules! bail {
    ($flag:expr, $($t:tt)*) => { return Err(InputError::invalid($flag, format!($($t)*))) };
}

/// What `repro solve` takes, as plain data: a contact in Moes groups or physically, its
/// lubricant, physics and numerics. `None` is a flag not given; [`Default`] is `repro solve`
/// with no flag.
#[derive(Debug, Clone)]
pub struct SolveInputs {
    /// Moes load parameter M (dimensionless form).
    pub m: Option<f64>,
    /// Moes lubricant parameter L.
    pub l: Option<f64>,
    /// Dimensionless slip S-bar, Eq. (9).
    pub s_bar: Option<f64>,
    /// Ellipticity ratio D = Rx/Ry in (0, 1] (default 1).
    pub d: Option<f64>,
    /// Lubricant of Table 1.
    pub lubricant: Option<String>,
    /// Temperature, C.
    pub temperature: Option<f64>,
    /// Pressure-viscosity coefficient, 1/Pa.
    pub alpha: Option<f64>,
    /// Maximum Hertzian pressure p_H, Pa.
    pub ph: Option<f64>,
    /// Mean velocity u_m, m/s.
    pub um: Option<f64>,
    /// Eyring stress tau0, Pa.
    pub tau0: Option<f64>,
    /// Reduced radius in the rolling direction Rx, m.
    pub rx: f64,
    /// Reduced radius across the rolling direction Ry, m (default: Rx).
    pub ry: Option<f64>,
    /// Reduced modulus E', Pa.
    pub e_prime: f64,
    /// A datasheet lubricant.
    pub datasheet: DatasheetInputs,
    /// Slide-to-roll ratio S.
    pub slip: Option<f64>,
    /// Ambient viscosity eta0, Pa s.
    pub eta0: Option<f64>,
    /// Viscosity-pressure law.
    pub viscosity: Option<ViscosityLaw>,
    /// Density-pressure law.
    pub density: Option<DensityLaw>,
    /// Rheology.
    pub rheology: Option<RheologyChoice>,
    /// Limiting shear stress's pressure slope Lambda.
    pub lambda_lss: Option<f64>,
    /// Limiting shear stress at ambient pressure tau_L0, Pa.
    pub tau_l0: Option<f64>,
    /// A line contact (Fig. 7) instead of an elliptical one.
    pub line: bool,
    /// Grid level (default 7; 8 for a line contact).
    pub level: Option<u32>,
    /// Solve exactly `level`: no finer level for the accuracy target or a closed film (a
    /// closed film is then an error naming the level it needs).
    pub exact_level: bool,
    /// The domain, over the rule's (`None`: the rule's).
    pub domain: Option<Domain>,
    /// The edge condition, over the rule's (`None`: the rule's).
    pub edge: Option<point::Edge>,
    /// A composite grid's patch (`None`: the rule's uniform grid or nested domains).
    pub patch: Option<Patch>,
    /// Most multigrid cycles on the finest level (Newton iterations of a line contact).
    pub max_cycles: usize,
    /// Most Newton steps per level of the Newton-Krylov finish.
    pub newton_steps: usize,
    /// Compute the rolling (Poiseuille) part of the friction.
    pub rolling_friction: bool,
    /// Solve from the Hertzian pressure alone, not from the case's base.
    pub cold: bool,
    /// Thermal conductivity of both solids, W/(m K).
    pub k_solid: f64,
    /// Thermal conductivity of the lubricant film, W/(m K).
    pub k_lubricant: f64,
}

impl Default for SolveInputs {
    fn default() -> Self {
        let params = point::Params::default();
        SolveInputs {
            m: None,
            l: None,
            s_bar: None,
            d: None,
            lubricant: None,
            temperature: None,
            alpha: None,
            ph: None,
            um: None,
            tau0: None,
            rx: 1.03875e-2,
            ry: None,
            e_prime: 226e9,
            datasheet: DatasheetInputs::default(),
            slip: None,
            eta0: None,
            viscosity: None,
            density: None,
            rheology: None,
            lambda_lss: None,
            tau_l0: None,
            line: false,
            level: None,
            exact_level: false,
            domain: None,
            edge: None,
            patch: None,
            max_cycles: params.multigrid.max_cycles,
            newton_steps: params.newton.steps,
            rolling_friction: true,
            cold: false,
            k_solid: 46.0,
            k_lubricant: 0.13,
        }
    }
}

impl SolveInputs {
    /// The case the inputs describe (which form, and its physics).
    pub fn case(&self) -> Result<Case, InputError> {
        let dimensionless = self.m.is_some() || self.l.is_some() || self.s_bar.is_some();
        // --ph and --eta0 belong to both forms (the dimensionless form takes them for
        // Roelands and Dowson-Higginson), so they decide nothing when --m/--l/--s-bar are
        // given; alone they ask for the physical form.
        let physical_only = self.lubricant.is_some()
            || self.temperature.is_some()
            || self.um.is_some()
            || self.tau0.is_some()
            || self.alpha.is_some()
            || self.datasheet.any();
        let physical =
            physical_only || (!dimensionless && (self.ph.is_some() || self.eta0.is_some()));
        let spec = match (dimensionless, physical) {
            (true, true) => return Err(InputError::Form("--m/--l/--s-bar (dimensionless form) and --lubricant/--temperature/--alpha/--um/--tau0 or a datasheet (physical form) cannot be mixed")),
            (false, false) => return Err(InputError::Form("give a case: --m, --l, --s-bar (dimensionless) or --lubricant, --temperature, --ph, --um, --slip, --tau0 (physical); see --help")),
            (true, false) => CaseForm::Dimensionless(DimensionlessCase {
                m: need(self.m, "m")?,
                l: need(self.l, "l")?,
                s_bar: need(self.s_bar, "s-bar")?,
                d: self.d.unwrap_or(1.0),
                slip: self.slip.unwrap_or(0.01),
                eta0_pa_s: self.eta0,
                ph_pa: self.ph,
            }),
            (false, true) => CaseForm::Physical(PhysicalCase {
                lubricant: lubricant_spec(self.lubricant.as_deref(), self.temperature, self.alpha, self.eta0, &self.datasheet)?,
                ph_pa: need(self.ph, "ph")?,
                um_m_s: need(self.um, "um")?,
                slip: need(self.slip, "slip")?,
                tau0_pa: need(self.tau0, "tau0")?,
                rx_m: self.rx,
                ry_m: self.ry.unwrap_or(self.rx),
                e_prime_pa: self.e_prime,
            }),
        };
        let defaults = if dimensionless {
            Physics::default()
        } else {
            Physics::figs_4_to_7()
        };
        let rheology = rheology(self.rheology, self.lambda_lss, self.tau_l0)?;
        let physics = physics(self.viscosity, self.density, rheology, defaults);
        Ok(Case { spec, physics })
    }

    /// Point-solver parameters for `problem`: the rule every command uses
    /// ([`point::Params::for_problem`]) at the level, with the numerics inputs on top
    /// (no domain and no edge keep the rule's; the others are expert overrides).
    pub fn params(&self, problem: &Problem) -> Result<point::Params, InputError> {
        let rule = point::Params::for_problem(
            problem,
            check_level("level", self.level.unwrap_or(WORKING_LEVEL))?,
        );
        let mut params = point::Params {
            domain: self.domain.unwrap_or(rule.domain),
            edge: self.edge.unwrap_or(rule.edge),
            ..rule
        };
        params.multigrid.max_cycles = self.max_cycles;
        params.newton.steps = self.newton_steps;
        params.friction.rolling = self.rolling_friction;
        if self.exact_level {
            params = params.exact_level();
        }
        if let Some(patch) = self.patch {
            if params.nested {
                bail!(
                    "patch",
                    "the composite grid's patches are for the paper's and the heavy-load \
                     domains (M from about 300 up), whose central film is made in the \
                     inlet and minimum film in the side lobes; this case is solved on \
                     nested domains already (drop --patch)"
                );
            }
            params.patch = Some(patch.set(params.level));
        }
        Ok(params)
    }

    /// The line-contact problem the inputs describe (`line`).
    pub fn line_problem(&self) -> Result<LineProblem, InputError> {
        self.reject_point_flags()?;
        let case = self.case()?;
        match &case.spec {
            CaseForm::Physical(ph) => {
                let line = LinePhysicalCase::from_point_case(ph, &LubricantTable::table1())
                    .map_err(flag_error)?;
                LineProblem::from_physical(&line, case.physics).map_err(flag_error)
            }
            CaseForm::Dimensionless(d) => {
                let line = LineDimensionlessCase {
                    m: d.m,
                    l: d.l,
                    s_bar: d.s_bar,
                    slip: d.slip,
                    eta0_pa_s: d.eta0_pa_s,
                    ph_pa: d.ph_pa,
                };
                LineProblem::from_dimensionless(&line, case.physics).map_err(flag_error)
            }
        }
    }

    /// Line-solver parameters for `problem`: the rule every command uses
    /// ([`line::Params::for_problem`]) at the level (default 8), with the numerics inputs on
    /// top.
    pub fn line_params(&self, problem: &LineProblem) -> Result<line::Params, InputError> {
        let level = self.level.unwrap_or(line::Params::default().level);
        if !(line::MIN_LEVEL..=line::MAX_LEVEL).contains(&level) {
            bail!(
                "level",
                "level {level} outside the line-contact range {}..={}",
                line::MIN_LEVEL,
                line::MAX_LEVEL
            );
        }
        let rule = line::Params::for_problem(problem, level);
        Ok(line::Params {
            max_iterations: self.max_cycles,
            rolling_friction: self.rolling_friction,
            refinement_levels: if self.exact_level {
                0
            } else {
                rule.refinement_levels
            },
            ..rule
        })
    }

    /// Inputs of the elliptical contact that a line contact cannot take.
    fn reject_point_flags(&self) -> Result<(), InputError> {
        if self.ry.is_some() {
            bail!(
                "ry",
                "a line contact has no Ry (it is infinite); drop --ry with --line"
            );
        }
        if self.d.is_some() {
            bail!(
                "d",
                "a line contact has D = Rx/Ry = 0; drop --d with --line"
            );
        }
        if self.domain.is_some() {
            bail!(
                "domain",
                "the line contact has its own domain (-4.5 <= X <= 1.5); drop --domain with --line"
            );
        }
        if self.edge.is_some() {
            bail!(
                "edge",
                "the line contact has its own edge (P = 0); drop --edge with --line"
            );
        }
        if self.patch.is_some() {
            bail!(
                "patch",
                "the composite grid is the point contact's; drop --patch with --line"
            );
        }
        Ok(())
    }

    /// The thermal post-process's inputs, checked.
    pub fn thermal_inputs(&self) -> Result<ThermalInputs, InputError> {
        thermal_inputs(self.k_solid, self.k_lubricant)
    }
}

/// The thermal post-process's inputs from the two conductivities, checked.
pub fn thermal_inputs(k_solid: f64, k_lubricant: f64) -> Result<ThermalInputs, InputError> {
    for (flag, v) in [("k-solid", k_solid), ("k-lubricant", k_lubricant)] {
        if v.is_nan() || v <= 0.0 {
            bail!(flag, "a conductivity must be positive, got {v}");
        }
    }
    Ok(ThermalInputs {
        solid: Solid {
            conductivity_w_mk: k_solid,
            ..Solid::STEEL
        },
        film: FilmProperties {
            conductivity_w_mk: k_lubricant,
            ..FilmProperties::OIL
        },
    })
}
