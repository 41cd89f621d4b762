//! Film thickness and reduced friction, Eq. (8), from a converged line-contact solution.

use super::level::{Level, Model};
use crate::solver::output::{Film, Friction};

/// Central film (at `X = 0`, a node of every level) and minimum film, in `H = h Rx / a^2` and
/// in Moes units.
pub(crate) fn film(level: &Level, moes_scale: f64) -> Film {
    Film::of(level.h[level.nearest(0.0)], &level.h, moes_scale)
}

/// Eq. (8) in one dimension: `mu-bar = int tau_x dX / int P dX` over the pressurised region
/// (film, coefficients and pressure must be current).
///
/// Sliding part: the mean shear stress `tau_m` of the case's flow model (exact 1-D Eyring:
/// `asinh(x G / sinh G)`; perturbation: `asinh(x)`; Newtonian: `x`, with the Couette argument
/// `x = N S eta / H`). Rolling part (only when `rolling`): the Poiseuille shear on the surface,
/// `G = (h/2)(dp/dx)/tau0 = g_scale H dP/dX`, central differences.
pub(crate) fn friction(level: &Level, model: &Model, rolling: bool) -> Friction {
    let gradient = model.uses_gradient();
    let (mut load, mut sliding, mut poiseuille) = (0.0, 0.0, 0.0);
    for i in 1..level.n {
        let p = level.p[i];
        if p <= 0.0 {
            continue;
        }
        let h = level.h[i];
        load += p;
        let g = if gradient || rolling {
            level.g(model, i)
        } else {
            0.0
        };
        let x = model.n_s * model.eta(p) / h;
        sliding +=
            model
                .flow
                .mean_shear_stress(model.rheology, x, if gradient { g } else { 0.0 }, p);
        poiseuille += g;
    }
    Friction {
        sliding: sliding / load,
        rolling: rolling.then(|| poiseuille / load),
    }
}
