//! Film thickness and reduced friction, Eq. (8), from a converged line-contact solution.

use super::level::{LineLevelFields, LineModel};
use crate::solver::output::{Film, Friction};

/// Central film (at `X = 0`, a node of every level) and minimum film, in `H = h Rx / a^2` and
/// in Moes units.
pub(crate) fn film(level: &LineLevelFields, moes_scale: f64) -> Film {
    Film::of(level.h[level.nearest(0.0)], &level.h, moes_scale)
}

/// Eq. (8) in one dimension: `mu-bar = int tau_x dX / int P dX` over the pressurised region
/// (film, coefficients and pressure must be current).
///
/// Sliding part: the mean shear stress `tau_m` of the case's flow model (exact 1-D Eyring:
/// `asinh(x G / sinh G)`; perturbation: `asinh(x)`; Newtonian: `x`, with the Couette argument
/// `x = N S eta / H`). Rolling part (only when `rolling`): the Poiseuille shear on the surface,
/// `G = (h/2)(dp/dx)/tau0 = g_scale H dP/dX`, central differences.
pub(crate) fn friction(level: &LineLevelFields, model: &LineModel, rolling: bool) -> Friction {
    let (mut load, mut sliding, mut poiseuille) = (0.0, 0.0, 0.0);
    for i in 1..level.n {
        let p = level.p[i];
        if p <= 0.0 {
            continue;
        }
        load += p;
        let (tau_m, g) = node_stress(level, model, i, rolling);
        sliding += tau_m;
        poiseuille += g;
    }
    Friction {
        sliding: sliding / load,
        rolling: rolling.then(|| poiseuille / load),
    }
}

/// The mean shear stress field `tau_m / tau0` at the nodes of `level` (film and pressure
/// current): at a pressurised node the stress Eq. (8) integrates ([`friction`]), so its sum
/// over the interior nodes with `P > 0` over their `sum P` is the sliding `mu-bar`; 0 where
/// `P <= 0` (the cavitated outlet and the domain's ends), as Eq. (8) counts it, for the
/// solver's cavitation condition does not know how much of the ruptured gap is lubricant
/// (the point contact's field, [`crate::solver::point::mean_shear_stress`], likewise).
pub(crate) fn mean_shear_stress(level: &LineLevelFields, model: &LineModel) -> Vec<f64> {
    (0..=level.n)
        .map(|i| {
            if level.p[i] <= 0.0 {
                0.0
            } else {
                node_stress(level, model, i, false).0
            }
        })
        .collect()
}

/// At node `i` (`P > 0`): the mean shear stress `tau_m / tau0` of the case's flow model at
/// the Couette argument `x = N S eta / H`, and the Poiseuille `G` when the flow uses it or
/// `with_g` asks for it (0 otherwise).
fn node_stress(level: &LineLevelFields, model: &LineModel, i: usize, with_g: bool) -> (f64, f64) {
    let gradient = model.uses_gradient();
    let (p, h) = (level.p[i], level.h[i]);
    let g = if gradient || with_g {
        level.g(model, i)
    } else {
        0.0
    };
    let x = model.n_s * model.eta(p) / h;
    let tau_m = model
        .flow
        .mean_shear_stress(model.rheology, x, if gradient { g } else { 0.0 }, p);
    (tau_m, g)
}
