//! Brandt's tau-extrapolation of a converged level, as a measurement beside the solve
//! ([`super::AccuracyParams::tau_extrapolation`]; docs/ACCURACY_NOTES.md, "Tau-extrapolation,
//! measured").
//!
//! The FAS coarse-grid problem of a converged top level carries the relative truncation error
//! `tau` between the two grids: its right-hand sides are the coarse discretisation of the
//! fine solution plus `tau` (Reynolds), the coarse deformation's difference from the fine one
//! (film) and the quadrature's (force balance). Where the scheme is of order `p`, scaling them
//! by `2^p / (2^p - 1)` makes the coarse problem approximate a discretisation of higher order;
//! its solution's change, interpolated to the top without relaxing after it (relaxation would
//! take the top back to its own equations), gives the extrapolated outputs. The top's pressure
//! and film constant are put back afterwards, so the solve's own outputs are unchanged.

use super::cycles::State;
use super::friction;
use super::multigrid::Hierarchy;
use super::Params;
use crate::solver::output::{Film, Friction};

/// The scheme's order the scaling assumes: second, the order the films converge at over most
/// of the envelope (docs/ACCURACY_NOTES.md, "The estimate, measured").
const ORDER: u32 = 2;

/// Cycles of the coarse problem, which starts from the restricted top. Against 40 cycles, on
/// seven cases of the estimate study at level 7: the extrapolated outputs within 7e-5 on six,
/// the central film within 2.3e-3 (1.3 % of its extrapolation's change of 18 %) on the heavy
/// mineral oil A at 100 C, 3 GPa, 7 m/s, whose coarse problem converges slowest (20 cycles:
/// 2e-4). Enough for the measurement it serves (docs/ACCURACY_NOTES.md, "Tau-extrapolation,
/// measured"); a product that reads it would stop on its outputs instead.
const COARSE_CYCLES: usize = 10;

/// The top level's outputs from its tau-extrapolated coarse-grid correction.
#[derive(Debug, Clone, PartialEq)]
pub struct TauExtrapolated {
    /// The extrapolated pressure on the top's grid: its difference from the top's is the
    /// local indicator of where the top's error is.
    pub p: Vec<f64>,
    /// The extrapolated film `H` on the top's grid.
    pub h: Vec<f64>,
    /// Central and minimum film.
    pub film: Film,
    /// Reduced friction.
    pub friction: Friction,
}

/// The outputs of the converged top level of `mg`, tau-extrapolated; `mg` as it was on return
/// (its top's pressure and film constant put back here, its coarser levels and force-balance
/// gain by [`Hierarchy::tau_extrapolate`]).
pub(super) fn extrapolated_outputs(
    mg: &mut Hierarchy,
    params: &Params,
    moes_film_scale: f64,
) -> TauExtrapolated {
    let top = mg.levels.len() - 1;
    let saved = State::of(mg, top);
    let factor = {
        let r = f64::from(2u32.pow(ORDER));
        r / (r - 1.0)
    };
    mg.tau_extrapolate(top, factor, COARSE_CYCLES);
    let fine = mg.finest();
    let out = TauExtrapolated {
        p: fine.p.clone(),
        h: fine.h.clone(),
        film: friction::film(fine, moes_film_scale),
        friction: friction::friction(fine, &mg.model, mg.rolling_scale, params.friction.region),
    };
    saved.restore(mg, top);
    mg.refresh(top);
    out
}
