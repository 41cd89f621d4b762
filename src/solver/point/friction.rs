//! Film thickness and reduced friction, Eq. (8), from a converged point-contact solution.

use super::level::{Level, Model};
use crate::physics::evaluations::{record, Effect};
use crate::solver::output::{Film, Friction};

/// Central film (at `X = Y = 0`) and minimum film, in `H = h/c` and in Moes units.
pub(crate) fn film(level: &Level, moes_scale: f64) -> Film {
    Film::of(level.h_central(), &level.h, moes_scale)
}

/// Eq. (8): `mu-bar = int tau_x dA / int P dA` over the pressurised region.
///
/// Sliding part: the mean shear stress `tau_m = asinh(N eta S / H)` (Eq. 4; `N eta S / H`
/// for a Newtonian fluid). Rolling part (only when `rolling` is set): the Poiseuille shear
/// on the surface, `(h/2) dp/dx / tau0 = (6 N / lambda) H dP/dX`, central differences.
pub(crate) fn friction(level: &Level, model: &Model, rolling_scale: Option<f64>) -> Friction {
    if rolling_scale.is_some() {
        record(Effect::RollingFriction);
    }
    let g = &level.grid;
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
            sliding += model
                .rheology
                .mean_shear_stress(model.n_s * model.eta(p) / h, p);
            if rolling_scale.is_some() {
                rolling += h * (level.p[k + 1] - level.p[k - 1]) / (2.0 * g.hx);
            }
        }
    }
    Friction {
        sliding: sliding / load,
        rolling: rolling_scale.map(|s| s * rolling / load),
    }
}
