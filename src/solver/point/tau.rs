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

/// The coarse problem's cycles, which start from the restricted top, stop where the central
/// film's change still to come is below this share of the film: that change is estimated from
/// the last change as a geometric series (`|d_n| r / (1 - r)`), its ratio `r` the larger of the
/// last two ratios of changes where there are three changes (`|d_n / d_(n-1)|` and
/// `|d_(n-1) / d_(n-2)|`), so that two changes that happen to shrink in a sequence that does
/// not yet contract do not stop it (as the cycles' own rule reads its outputs,
/// [`super::stopping`]).
/// A hundredth of the 1 % the estimate reads at the least (the central film's error after the
/// extrapolation is 0.04-1.7 % at level 7, docs/ACCURACY_NOTES.md, "Tau-extrapolation,
/// measured"). Measured: the Table 4 case at level 7 (mineral oil A, 100 C, 2 GPa, 12 m/s)
/// changes by 1 % in the first cycle and by 2e-7 of itself in the eighth; the heavy mineral
/// oil A at 100 C, 3 GPa, 7 m/s contracts by 0.8 a cycle at level 7 (10 cycles, the fixed
/// count this replaced, left 0.22 % of its 7.4 % to come) and by 0.6 at level 8.
const CENTRAL_FILM_TOLERANCE: f64 = 1e-4;

/// Cycles before the stopping rule is read: two changes show a contraction, the third
/// confirms it.
const MIN_COARSE_CYCLES: usize = 3;

/// Cycles at most: where the coarse problem does not contract, its extrapolation stands as
/// it is, and its estimate ([`crate::solver::richardson::ErrorEstimate::of_value`]) says how far
/// off it is.
const MAX_COARSE_CYCLES: usize = 40;

/// Whether the coarse problem's cycles may stop with the central films `films` after each
/// cycle ([`CENTRAL_FILM_TOLERANCE`]).
fn converged(films: &[f64]) -> bool {
    let n = films.len();
    if n >= MAX_COARSE_CYCLES {
        return true;
    }
    if n < MIN_COARSE_CYCLES {
        return false;
    }
    let change = |k: usize| films[k] - films[k - 1];
    let (last, before) = (change(n - 1), change(n - 2));
    let mut r = (last / before).abs();
    if n > MIN_COARSE_CYCLES {
        r = r.max((before / change(n - 3)).abs());
    }
    let to_come = if r < 1.0 {
        last.abs() * r / (1.0 - r)
    } else {
        f64::INFINITY
    };
    // An exact repeat (r NaN from 0/0) has nothing to come.
    last == 0.0 || to_come <= CENTRAL_FILM_TOLERANCE * films[n - 1].abs()
}

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
    /// Cycles of the coarse problem.
    pub coarse_cycles: usize,
    /// The coarse problem's solution as a change from the restricted top: where a related
    /// case (a member of this solution's family) is extrapolated on the same grid, its coarse
    /// problem starts from it.
    pub coarse: CoarseChange,
}

/// A tau-extrapolated coarse problem's solution as a change from the restricted top, `P_c -
/// R P` at the coarse nodes and the film constant's change: continuation for the coarse
/// problem ([`super::warm`]). A member's coarse problem differs from its base's by about
/// what their solutions do (a central film 1e-4 apart over a family), so, started from its
/// base's change, it meets [`CENTRAL_FILM_TOLERANCE`] in fewer cycles: Fig. 4 case 214's
/// member at S 2 % from its base at S 0.5 %, level 7, in 3 cycles where from the restricted
/// top it took 7 (tests/tau_extrapolation.rs); the family at 60 C, 2 GPa, 2 m/s at level 8
/// in 3 where it took 8-9, the family's solve in 19.4 s instead of 30.3 s.
#[derive(Debug, Clone, PartialEq)]
pub struct CoarseChange {
    /// `P_c - R P` at the coarse level's nodes.
    pub p: Vec<f64>,
    /// The film constant's change.
    pub delta: f64,
}

/// The outputs of the converged top level of `mg`, tau-extrapolated, its coarse problem
/// started from `start` where given and of its size; `mg` as it was on return (its top's
/// pressure and film constant put back here, its coarser levels and force-balance gain by
/// [`Hierarchy::tau_extrapolate`]).
pub(super) fn extrapolated_outputs(
    mg: &mut Hierarchy,
    params: &Params,
    moes_film_scale: f64,
    start: Option<&CoarseChange>,
) -> TauExtrapolated {
    let top = mg.levels.len() - 1;
    let saved = State::of(mg, top);
    let factor = {
        let r = f64::from(2u32.pow(ORDER));
        r / (r - 1.0)
    };
    let mut films = Vec::new();
    let start = start.map(|c| (c.p.as_slice(), c.delta));
    let (p, delta) = mg.tau_extrapolate(top, factor, start, |coarse| {
        films.push(coarse.h_central());
        converged(&films)
    });
    let fine = mg.finest();
    let out = TauExtrapolated {
        p: fine.p.clone(),
        h: fine.h.clone(),
        film: friction::film(fine, moes_film_scale),
        friction: friction::friction(fine, &mg.model, mg.rolling_scale, params.friction.region),
        coarse_cycles: films.len(),
        coarse: CoarseChange { p, delta },
    };
    saved.restore(mg, top);
    mg.refresh(top);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_coarse_cycles_stop_where_the_film_still_to_come_is_below_the_tolerance() {
        // Contracting by a half: what is to come equals the last change.
        let film = |n: usize, step: f64| -> Vec<f64> {
            (0..n).map(|i| 1.0 - step * 0.5f64.powi(i as i32)).collect()
        };
        assert!(!converged(&film(2, 1e-9)), "two cycles show no contraction");
        assert!(converged(&film(3, 1e-6)));
        assert!(!converged(&film(3, 1e-3)));
        // Not contracting: on to the cap.
        let growing: Vec<f64> = (0..10).map(|i| 1.0 + 1e-3 * i as f64).collect();
        assert!(!converged(&growing));
        let capped: Vec<f64> = (0..MAX_COARSE_CYCLES)
            .map(|i| 1.0 + 1e-3 * i as f64)
            .collect();
        assert!(converged(&capped));
        assert!(
            converged(&[1.0, 1.1, 1.1]),
            "an exact repeat has nothing to come"
        );
        // Changes of 1e-2, -2e-2, 1e-5: the last ratio alone (5e-4) says 5e-9 is to come, but
        // the sequence grew the cycle before; one more cycle is asked for.
        let erratic = [1.0, 1.01, 0.99, 0.99001];
        assert!(!converged(&erratic));
        // The same last two changes after a contracting one stop it.
        let contracting = [1.0, 1.04, 1.02, 1.02001];
        assert!(converged(&contracting));
    }
}
