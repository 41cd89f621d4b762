//! Film thickness and reduced friction, Eq. (8), from a converged point-contact solution.

use super::level::{LevelFields, Model, LOAD};
use super::PointSolution;
use crate::physics::case::Problem;
use crate::physics::evaluations::{record, Effect};
use crate::solver::output::{Film, Friction};

/// Central film (at `X = Y = 0`) and minimum film, in `H = h/c` and in Moes units.
pub(crate) fn film(level: &LevelFields, moes_scale: f64) -> Film {
    Film::of(level.h_central(), &level.h, moes_scale)
}

/// Films thicker than this many central films are not the loaded film
/// ([`FrictionRegion::LoadedFilm`]).
pub const LOADED_FILM_FACTOR: f64 = 4.0;

/// Where Eq. (8) integrates the shear stress. In a flooded inlet the Couette stress falls like
/// `1/H ~ 1/r^2`, so its integral over an ever larger domain grows like `ln r`: the region
/// is a definition, stated here, not left to the domain's edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrictionRegion {
    /// Every pressurised node of the computational domain, over their load: Eq. (8) as the
    /// paper has it, which depends on the domain where the inlet matters.
    Domain,
    /// The loaded film: pressurised nodes with `H <= LOADED_FILM_FACTOR * Hc`, over the
    /// applied load `2 pi / 3` (the friction coefficient `F / W`). Measured
    /// (`docs/DOMAIN_NOTES.md`): the Table 4 case moves 1e-6 against the whole domain, Fig. 6
    /// case 23 0.05 % between 2 and 10 central films.
    LoadedFilm,
}

/// Eq. (8): `mu-bar = int tau_x dA / W` over the region `region` ([`FrictionRegion`]).
///
/// Sliding part: the mean shear stress `tau_m = asinh(N eta S / H)` (Eq. 4; `N eta S / H`
/// for a Newtonian fluid). Rolling part (only when `rolling` is set): the Poiseuille shear
/// on the surface, `(h/2) dp/dx / tau0 = (6 N / lambda) H dP/dX`, central differences.
pub(crate) fn friction(
    level: &LevelFields,
    model: &Model,
    rolling_scale: Option<f64>,
    region: FrictionRegion,
) -> Friction {
    if rolling_scale.is_some() {
        record(Effect::RollingFriction);
    }
    let g = &level.grid;
    let h_limit = match region {
        FrictionRegion::Domain => f64::INFINITY,
        FrictionRegion::LoadedFilm => LOADED_FILM_FACTOR * level.h_central(),
    };
    let (mut load, mut sliding, mut rolling) = (0.0, 0.0, 0.0);
    for j in 1..g.ny {
        for i in 1..g.nx {
            let k = g.idx(i, j);
            let p = level.p[k];
            if p <= 0.0 {
                continue;
            }
            let h = level.h[k];
            load += p;
            if h > h_limit {
                continue;
            }
            sliding += model.mean_shear_stress(p, h);
            if rolling_scale.is_some() {
                rolling += h * (level.p[k + 1] - level.p[k - 1]) / (2.0 * g.hx);
            }
        }
    }
    // The applied load, or the load of the pressurised nodes (sum P, cell area cancels).
    let load = match region {
        FrictionRegion::Domain => load,
        FrictionRegion::LoadedFilm => LOAD / (g.hx * g.hy),
    };
    Friction {
        sliding: sliding / load,
        rolling: rolling_scale.map(|s| s * rolling / load),
    }
}

/// The mean shear stress field `tau_m / tau0` of `solution` (a solution of `problem`), at the
/// nodes of its grid in the order of `p` and `h`: at every pressurised node the stress Eq. (8)
/// integrates ([`Model::mean_shear_stress`]: Eq. 4 at the Couette argument
/// `N S eta_bar(P) / H`), inside [`friction`]'s region or not. Summed over that region (the
/// interior nodes; with [`FrictionRegion::LoadedFilm`] those with `H <= 4 Hc`) and divided
/// by its load it is the solution's sliding `mu-bar`; on nested domains the reported
/// friction adds the surroundings' stress outside this grid ([`super::chain`]).
///
/// Where `P <= 0` (the cavitated outlet and the domain's edge) it is 0, as Eq. (8) counts it:
/// the solver's cavitation condition (`P = 0`, no film content) does not know what fraction
/// of the ruptured gap is lubricant, so the Couette stress of a full gap would be a number
/// the model cannot back, and 0 keeps the field's integral the friction the solver reports.
pub fn mean_shear_stress(problem: &Problem, solution: &PointSolution) -> Vec<f64> {
    let model = Model::new(problem);
    solution
        .p
        .iter()
        .zip(&solution.h)
        .map(|(&p, &h)| {
            if p <= 0.0 {
                0.0
            } else {
                model.mean_shear_stress(p, h)
            }
        })
        .collect()
}
