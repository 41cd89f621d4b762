//! Shear heating of the film: a thermal post-processor on a converged isothermal solution
//! (the paper's second future-work item), not a thermal EHL solver. The pressure and film of
//! the isothermal solve are kept; only the shear stress is re-solved with the temperature the
//! shear heat raises.
//!
//! The model, node by node along the rolling direction `x` (one strip per grid row `Y`):
//!
//! 1. Shear heat `q = tau du` (W/m^2) with `tau` the Couette mean stress of Eq. (4) and
//!    `du = u2 - u1 = S u_m`; the Poiseuille (rolling) dissipation is left out, as it is from
//!    the sliding friction.
//! 2. Both surfaces take heat `q1 + q2 = q`. Each surface's flash temperature is Jaeger's
//!    moving heat source at high Peclet number ([`flash`]): conduction into the body normal to
//!    its surface only, `T_i(x) = int q_i(s) ds / sqrt(pi k rho c u_i (x - s))` over `s < x`.
//! 3. Across the film: conduction only (the film's Peclet number is reported), uniform heat
//!    generation `q / h` between walls at `T1`, `T2`: a parabola on a line, which fixes the
//!    partition `q1 = q/2 + k_f (T2 - T1)/h` and the film temperature ([`film`]): the mean
//!    closure `(T1 + T2)/2 + q h/(12 k_f)` (the first-order Nahme-Couette result) or the
//!    mid-plane closure `(T1 + T2)/2 + q h/(8 k_f)` (the hottest layer, an upper bound).
//! 4. The viscosity at that film temperature, `eta(p, T)` ([`viscosity`]): Roelands' (1966)
//!    temperature-pressure law, its temperature index fitted to the lubricant's own `eta0` at
//!    the tabulated temperatures, so that the temperature coefficient grows with pressure as
//!    the Roelands law gives it; the stress re-solved at each node with it ([`strip`]).
//! 5. The thermal `mu-bar` assembled as Eq. (8) over the same nodes as the isothermal one.
//!
//! Every temperature here is a rise over the case's (bulk) temperature, in kelvin. Pure
//! functions, no I/O; the fields come from the solver layer (`solver::thermal`).

pub mod contact;
pub mod film;
pub mod flash;
pub mod strip;
pub mod viscosity;

pub use contact::ThermalContact;
pub use viscosity::ThermalViscosity;

use serde::{Deserialize, Serialize};

/// Revision of the thermal model: part of every point-contact cache key, raised whenever a
/// change can move a thermal result.
pub const THERMAL_REVISION: &str = "thermal-4";

/// The largest thermal correction of the sliding friction (mean-temperature closure, relative)
/// under which the paper's isothermal assumption is taken to hold: 5 %, about the scatter of
/// the computed points about the refined formula (95 % within 4.5 %) and a third of their
/// scatter about Eq. (13).
pub const ISOTHERMAL_CORRECTION_MAX: f64 = 0.05;

/// A solid body's thermal properties (both bodies of a contact are taken alike).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Solid {
    /// Thermal conductivity, W/(m K).
    pub conductivity_w_mk: f64,
    /// Density, kg/m^3.
    pub density_kg_m3: f64,
    /// Specific heat, J/(kg K).
    pub specific_heat_j_kgk: f64,
}

impl Solid {
    /// Bearing steel (AISI 52100 class), the default: 46 W/(m K), 7850 kg/m^3, 470 J/(kg K).
    pub const STEEL: Solid = Solid {
        conductivity_w_mk: 46.0,
        density_kg_m3: 7850.0,
        specific_heat_j_kgk: 470.0,
    };
    /// Through-hardened steel, the low-conductivity alternative: 21 W/(m K), otherwise as
    /// [`Solid::STEEL`].
    pub const THROUGH_HARDENED: Solid = Solid {
        conductivity_w_mk: 21.0,
        ..Solid::STEEL
    };

    /// `k rho c`, W^2 s/(m^4 K^2): the thermal effusivity squared, which alone sets the flash
    /// temperature at high Peclet number.
    pub fn k_rho_c(&self) -> f64 {
        self.conductivity_w_mk * self.density_kg_m3 * self.specific_heat_j_kgk
    }

    /// Thermal diffusivity `k / (rho c)`, m^2/s.
    pub fn diffusivity(&self) -> f64 {
        self.conductivity_w_mk / (self.density_kg_m3 * self.specific_heat_j_kgk)
    }
}

/// The lubricant film's thermal properties (taken independent of pressure and temperature).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FilmProperties {
    /// Thermal conductivity, W/(m K).
    pub conductivity_w_mk: f64,
    /// Volumetric heat capacity `rho c`, J/(m^3 K): enters only the film's Peclet number,
    /// the check of the conduction-only closure.
    pub heat_capacity_j_m3k: f64,
}

impl FilmProperties {
    /// A mineral-oil-like film, the default for every lubricant: 0.13 W/(m K) and
    /// 870 kg/m^3 x 2000 J/(kg K).
    pub const OIL: FilmProperties = FilmProperties {
        conductivity_w_mk: 0.13,
        heat_capacity_j_m3k: 1.74e6,
    };
}

/// The thermal inputs of a post-process.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ThermalInputs {
    /// Both bodies.
    pub solid: Solid,
    /// The film.
    pub film: FilmProperties,
}

impl Default for ThermalInputs {
    /// Steel bodies and an oil film.
    fn default() -> Self {
        ThermalInputs {
            solid: Solid::STEEL,
            film: FilmProperties::OIL,
        }
    }
}

/// What the targets compute for every physical point contact, in this order: the default
/// (steel, 46 W/(m K)) and the through-hardened alternative (21 W/(m K)), the sensitivity to
/// the solid's conductivity.
pub const TARGET_INPUTS: [ThermalInputs; 2] = [
    ThermalInputs {
        solid: Solid::STEEL,
        film: FilmProperties::OIL,
    },
    ThermalInputs {
        solid: Solid::THROUGH_HARDENED,
        film: FilmProperties::OIL,
    },
];

/// Which film temperature the viscosity is taken at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Closure {
    /// The film's mean temperature: matches the exact Couette (Nahme) solution to first order
    /// in the Nahme number.
    Mean,
    /// The mid-plane (hottest) temperature: an upper bound of the heating's effect.
    MidPlane,
}

/// A thermal post-process that cannot give a trustworthy number.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ThermalError {
    /// An input outside its physical range.
    #[error("thermal input {what}: {message}")]
    Input {
        /// Which input.
        what: &'static str,
        /// What is expected.
        message: String,
    },
    /// A surface does not move: Jaeger's high-Peclet flash temperature does not apply.
    #[error(
        "surface {surface} does not move (u = {speed_m_s} m/s): no high-Peclet flash temperature"
    )]
    StationarySurface {
        /// 1 or 2.
        surface: u8,
        /// Its speed, m/s.
        speed_m_s: f64,
    },
    /// A loaded node with a non-positive film.
    #[error("film thickness {h_m:.3e} m at a loaded node: no film to conduct across")]
    NoFilm {
        /// The film, m.
        h_m: f64,
    },
    /// The stress equation at a node did not converge or gave a non-finite value.
    #[error("thermal stress not resolved at node {node}: {why}")]
    Stress {
        /// Node index along the strip.
        node: usize,
        /// What went wrong.
        why: String,
    },
}
