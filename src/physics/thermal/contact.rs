//! The physical scales the thermal post-processor needs beyond the dimensionless problem:
//! lengths, surface speeds, the Eyring stress and the viscosity's temperature law.

use super::{Solid, ThermalViscosity};
use crate::physics::case::{LubricantSpec, PhysicalCase, Problem};
use crate::physics::lubricant::LubricantTable;

/// A physical point contact's thermal scales.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalContact {
    /// Hertzian semi-axis along the rolling direction `a`, m (`X = x / a`).
    pub a_m: f64,
    /// The film unit, m: `h = H film_scale_m` (the Hertzian approach `c`).
    pub film_scale_m: f64,
    /// Speed of surface 1, `u_m (1 - S/2)`, m/s.
    pub u1_m_s: f64,
    /// Speed of surface 2, `u_m (1 + S/2)`, m/s.
    pub u2_m_s: f64,
    /// Eyring stress, Pa.
    pub tau0_pa: f64,
    /// How the viscosity falls with temperature.
    pub viscosity: ThermalViscosity,
}

impl ThermalContact {
    /// The scales of a physical case and its problem; `None` where the lubricant is given by
    /// `alpha` and `eta0` alone (no temperature data to take a coefficient from).
    pub fn of_point(
        case: &PhysicalCase,
        problem: &Problem,
        lubricants: &LubricantTable,
    ) -> Option<Self> {
        let LubricantSpec::Named {
            lubricant,
            temperature_c,
        } = &case.lubricant
        else {
            return None;
        };
        let table = lubricants.get(lubricant).ok()?;
        let viscosity =
            ThermalViscosity::of_lubricant(lubricant, table, *temperature_c, &problem.viscosity)
                .ok()?;
        Some(ThermalContact {
            a_m: problem.hertz.a,
            film_scale_m: problem.hertz.c,
            u1_m_s: case.um_m_s * (1.0 - 0.5 * case.slip),
            u2_m_s: case.um_m_s * (1.0 + 0.5 * case.slip),
            tau0_pa: case.tau0_pa,
            viscosity,
        })
    }

    /// Sliding speed `du = u2 - u1 = S u_m`, m/s.
    pub fn sliding_speed(&self) -> f64 {
        self.u2_m_s - self.u1_m_s
    }

    /// The Peclet number of the slower surface, `u a / (2 kappa)`: Jaeger's high-Peclet
    /// flash temperature wants it above about 5.
    pub fn peclet(&self, solid: &Solid) -> f64 {
        self.u1_m_s.min(self.u2_m_s) * self.a_m / (2.0 * solid.diffusivity())
    }
}
