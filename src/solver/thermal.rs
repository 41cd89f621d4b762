//! The thermal post-process of a converged point contact ([`crate::physics::thermal`]): each
//! grid row is a strip along the rolling direction, the thermal stress is assembled into
//! Eq. (8) over exactly the nodes and in exactly the order of the isothermal friction, so
//! that a zero temperature coefficient or infinitely conducting bodies and film give the
//! isothermal `mu-bar` to the bit.

use crate::physics::case::Problem;
use crate::physics::thermal::flash::Flash;
use crate::physics::thermal::strip::{solve_strip, Setting, Strip};
use crate::physics::thermal::{Closure, ThermalContact, ThermalError, ThermalInputs};
use crate::solver::grid::{Domain, Grid};
use crate::solver::point::{FrictionRegion, PointSolution, LOAD, LOADED_FILM_FACTOR};
use serde::{Deserialize, Serialize};

/// The thermal correction of one solve with one set of thermal inputs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Thermal {
    /// The solids' conductivity it was computed with, W/(m K).
    pub k_solid_w_mk: f64,
    /// Thermal sliding `mu-bar`, the film's mean temperature (the Nahme-consistent closure).
    pub mu_bar_sliding: f64,
    /// Thermal sliding `mu-bar` at the film's mid-plane temperature (the hottest layer: the
    /// upper bound of the correction).
    pub mu_bar_sliding_midplane: f64,
    /// Largest mean film temperature rise over the contact, K.
    pub dt_film_max_k: f64,
    /// Largest surface (flash) temperature rise of either body, K.
    pub dt_flash_max_k: f64,
    /// The lubricant's temperature-viscosity coefficient at ambient pressure and the case's
    /// temperature, 1/K.
    pub beta0_per_k: f64,
    /// Peclet number `u a / (2 kappa)` of the slower surface (Jaeger's form wants > 5).
    pub peclet: f64,
    /// The film's Peclet number at the centre, `rho c u_m h_c^2 / (k_f a)` (convection along
    /// the film over conduction across it; the conduction-only closure wants it small).
    pub film_peclet: f64,
}

impl Thermal {
    /// The relative correction of the sliding friction, `mu-bar_thermal / mu-bar - 1`.
    pub fn correction(&self, isothermal: f64) -> f64 {
        self.mu_bar_sliding / isothermal - 1.0
    }
}

/// What one closure gives over the grid.
struct Pass {
    mu_bar: f64,
    dt_film_max: f64,
    dt_flash_max: f64,
}

/// A point contact's fields on its grid: pressure `P`, film `H` and the central film.
#[derive(Debug, Clone, Copy)]
pub struct Fields<'a> {
    /// The grid.
    pub grid: &'a Grid,
    /// `P` at the nodes.
    pub p: &'a [f64],
    /// `H = h/c` at the nodes.
    pub h: &'a [f64],
    /// Central film `H`.
    pub h_central: f64,
    /// Where the friction is integrated: the isothermal friction's region, so that the
    /// correction compares like with like.
    pub region: FrictionRegion,
}

impl<'a> Fields<'a> {
    /// The fields of a converged solution.
    pub fn of(solution: &'a PointSolution) -> Self {
        Fields {
            grid: &solution.grid,
            p: &solution.p,
            h: &solution.h,
            h_central: solution.film.h_central,
            region: solution.friction_region,
        }
    }
}

/// The thermal correction of a converged `solution` (of `problem`, with the physical
/// `contact`) for `inputs`: both closures, every row of the grid.
pub fn point_thermal(
    solution: &PointSolution,
    problem: &Problem,
    contact: &ThermalContact,
    inputs: &ThermalInputs,
) -> Result<Thermal, ThermalError> {
    fields_thermal(&Fields::of(solution), problem, contact, inputs)
}

/// The flat-film estimate of the correction, without a solve: the Hertzian pressure and a
/// parallel film of Eq. (10)'s central thickness on the paper's domain at `level` (the
/// rough estimate `repro predict` gives; its isothermal friction is the flat-film one of
/// [`crate::physics::flat_film`]).
pub fn flat_film_thermal(
    problem: &Problem,
    contact: &ThermalContact,
    inputs: &ThermalInputs,
    level: u32,
) -> Result<(f64, Thermal), ThermalError> {
    let grid = Grid::level(&Domain::default(), level);
    let p = grid.sample(crate::physics::hertz::Hertz::pressure);
    let g = &problem.groups;
    let h_c = crate::physics::film::hc_eq10(g.m, g.l) / g.moes_film_scale;
    let h = vec![h_c; p.len()];
    let fields = Fields {
        grid: &grid,
        p: &p,
        h: &h,
        h_central: h_c,
        region: FrictionRegion::Domain,
    };
    let isothermal = fields_thermal(
        &fields,
        problem,
        &ThermalContact {
            viscosity: contact.viscosity.scaled(0.0),
            ..*contact
        },
        inputs,
    )?
    .mu_bar_sliding;
    Ok((
        isothermal,
        fields_thermal(&fields, problem, contact, inputs)?,
    ))
}

/// The thermal correction of `fields` (see [`point_thermal`]).
pub fn fields_thermal(
    solution: &Fields,
    problem: &Problem,
    contact: &ThermalContact,
    inputs: &ThermalInputs,
) -> Result<Thermal, ThermalError> {
    let g = solution.grid;
    let nodes = g.nx + 1;
    let dx = g.hx * contact.a_m;
    let f1 = Flash::of_surface(1, &inputs.solid, contact.u1_m_s, dx, nodes)?;
    let f2 = Flash::of_surface(2, &inputs.solid, contact.u2_m_s, dx, nodes)?;
    let n_s = problem.eyring_n_s();
    let shear = problem.shear;
    // The isothermal friction's region ([`FrictionRegion`]): the heat and the stress of the
    // loaded film, over the applied load, or of every pressurised node, over theirs.
    let h_limit = match solution.region {
        FrictionRegion::Domain => f64::INFINITY,
        FrictionRegion::LoadedFilm => LOADED_FILM_FACTOR * solution.h_central,
    };
    let pass = |closure: Closure| -> Result<Pass, ThermalError> {
        let setting = Setting {
            flash: (&f1, &f2),
            k_film: inputs.film.conductivity_w_mk,
            closure,
            viscosity: &contact.viscosity,
            heat_per_stress: contact.tau0_pa * contact.sliding_speed(),
        };
        let (mut load, mut sliding) = (0.0, 0.0);
        let (mut dt_film_max, mut dt_flash_max) = (0.0_f64, 0.0_f64);
        for j in 1..g.ny {
            let row = g.idx(0, j)..g.idx(0, j) + nodes;
            let p = &solution.p[row.clone()];
            let h = &solution.h[row];
            let loaded: Vec<bool> = (0..nodes)
                .map(|i| (1..g.nx).contains(&i) && p[i] > 0.0 && h[i] <= h_limit)
                .collect();
            let h_m: Vec<f64> = h.iter().map(|&h| h * contact.film_scale_m).collect();
            let x_iso: Vec<f64> = (0..nodes)
                .map(|i| {
                    if loaded[i] {
                        let eta = problem.viscosity.eta_bar_capped(p[i]);
                        n_s * eta / h[i]
                    } else {
                        0.0
                    }
                })
                .collect();
            let strip = Strip {
                p,
                h_m: &h_m,
                x_iso: &x_iso,
                loaded: &loaded,
            };
            let s = solve_strip(&strip, &setting, |i, x| shear.mean_shear_stress(x, p[i]))?;
            for i in 1..g.nx {
                if loaded[i] {
                    load += p[i];
                    sliding += s.stress[i];
                }
            }
            for n in &s.nodes {
                dt_film_max = dt_film_max.max(n.t_film);
                dt_flash_max = dt_flash_max.max(n.t1).max(n.t2);
            }
        }
        let load = match solution.region {
            FrictionRegion::Domain => load,
            FrictionRegion::LoadedFilm => LOAD / (g.hx * g.hy),
        };
        Ok(Pass {
            mu_bar: sliding / load,
            dt_film_max,
            dt_flash_max,
        })
    };
    let mean = pass(Closure::Mean)?;
    let midplane = pass(Closure::MidPlane)?;
    let um = 0.5 * (contact.u1_m_s + contact.u2_m_s);
    let h_c = solution.h_central * contact.film_scale_m;
    Ok(Thermal {
        k_solid_w_mk: inputs.solid.conductivity_w_mk,
        mu_bar_sliding: mean.mu_bar,
        mu_bar_sliding_midplane: midplane.mu_bar,
        dt_film_max_k: mean.dt_film_max,
        dt_flash_max_k: mean.dt_flash_max,
        beta0_per_k: contact.viscosity.beta0(),
        peclet: contact.peclet(&inputs.solid),
        film_peclet: inputs.film.heat_capacity_j_m3k * um * h_c * h_c
            / (inputs.film.conductivity_w_mk * contact.a_m),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::tests::{worked_case, worked_physical};
    use crate::physics::lubricant::LubricantTable;
    use crate::physics::thermal::{FilmProperties, Solid};
    use crate::solver::point::{solve, Params};

    #[test]
    fn limits_give_the_isothermal_friction_exactly_and_the_worked_case_is_corrected() {
        // The Appendix case at 1 GPa and 2 % slip (Table 2's largest), level 5: a film the
        // coarse grid resolves, solved in a fraction of a second.
        let lubs = LubricantTable::table1();
        let mut case = worked_case();
        let mut physical = worked_physical();
        physical.ph_pa = 1e9;
        physical.slip = 0.02;
        case.spec = crate::physics::case::CaseForm::Physical(physical.clone());
        let problem = Problem::from_case(&case, &lubs).unwrap();
        let s = solve(&problem, &Params::at_level(5), None).unwrap();
        let contact = ThermalContact::of_point(&physical, &problem, &lubs).unwrap();
        let iso = s.friction.sliding;
        // beta -> 0: the viscosity does not see the heat.
        let cold_law = ThermalContact {
            viscosity: contact.viscosity.scaled(0.0),
            ..contact
        };
        let t = point_thermal(&s, &problem, &cold_law, &ThermalInputs::default()).unwrap();
        assert_eq!(t.mu_bar_sliding, iso);
        assert_eq!(t.mu_bar_sliding_midplane, iso);
        // Infinitely conducting bodies and film: no temperature rise.
        let conducting = ThermalInputs {
            solid: Solid {
                conductivity_w_mk: f64::INFINITY,
                ..Solid::STEEL
            },
            film: FilmProperties {
                conductivity_w_mk: f64::INFINITY,
                ..FilmProperties::OIL
            },
        };
        let t = point_thermal(&s, &problem, &contact, &conducting).unwrap();
        assert_eq!(t.mu_bar_sliding, iso);
        assert_eq!(t.dt_film_max_k, 0.0);
        // Steel: a reduction of some per cent (5.8 % measured, with a film 4.9 K warmer at
        // most: at 1 GPa Roelands' beta is 4.5 times beta0), more with the mid-plane closure
        // and with the less conducting steel (6.6 %).
        let steel = point_thermal(&s, &problem, &contact, &ThermalInputs::default()).unwrap();
        let soft = point_thermal(
            &s,
            &problem,
            &contact,
            &ThermalInputs {
                solid: Solid::THROUGH_HARDENED,
                ..ThermalInputs::default()
            },
        )
        .unwrap();
        let c = steel.correction(iso);
        assert!((-0.15..-0.005).contains(&c), "correction {c}");
        assert!(steel.mu_bar_sliding_midplane < steel.mu_bar_sliding);
        assert!(soft.mu_bar_sliding < steel.mu_bar_sliding);
        assert!((2.0..20.0).contains(&steel.dt_film_max_k), "{steel:?}");
        assert!(steel.peclet > 5.0 && steel.film_peclet < 1.0, "{steel:?}");
    }
}
