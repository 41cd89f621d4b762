//! What every solver returns: film thickness, reduced friction, convergence information, and
//! the typed failure that carries the residual history.

use crate::solver::richardson::{estimate, ErrorEstimate, FIRST_ORDER, SCHEME_ORDER};
use serde::Serialize;

mod failure;
pub use failure::SolveError;

/// Film thickness results.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Film {
    /// Central film thickness in the solver's dimensionless unit (`H = h/c` for the point
    /// contact, the paper's Table 4 "Hc").
    pub h_central: f64,
    /// Minimum film thickness, same unit.
    pub h_min: f64,
    /// Central film thickness in Moes units `(h/Rx) (eta0 u_s / (E' Rx))^{-1/2}`.
    pub hc_moes: f64,
    /// Minimum film thickness in Moes units.
    pub hmin_moes: f64,
}

impl Film {
    /// The film of a converged solution from its central value and its film field, in the
    /// solver's unit and (times `moes_scale`) in Moes units.
    pub(crate) fn of(h_central: f64, h: &[f64], moes_scale: f64) -> Film {
        let h_min = h.iter().cloned().fold(f64::INFINITY, f64::min);
        Film {
            h_central,
            h_min,
            hc_moes: h_central * moes_scale,
            hmin_moes: h_min * moes_scale,
        }
    }
}

/// Reduced friction `mu-bar = mu p_H / tau0`, Eq. (8), split into its parts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Friction {
    /// From the mean (Couette) shear stress `tau_m` only: Figs. 3-7.
    pub sliding: f64,
    /// From the Poiseuille shear `(h/2) dp/dx` on the surface; `None` when not asked for.
    pub rolling: Option<f64>,
}

impl Friction {
    /// Sliding plus rolling (Figs. 1-2); the sliding part alone when rolling was not computed.
    pub fn total(&self) -> f64 {
        self.sliding + self.rolling.unwrap_or(0.0)
    }
}

/// The outputs of one grid level, in the solver's unit (`H` for the films).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
pub struct LevelValues {
    /// Grid level.
    pub level: u32,
    /// Central film.
    pub h_central: f64,
    /// Minimum film.
    pub h_min: f64,
    /// Sliding `mu-bar`.
    pub mu_bar_sliding: f64,
    /// Sliding plus rolling `mu-bar` (the sliding part where rolling is not computed).
    pub mu_bar_total: f64,
}

impl LevelValues {
    /// The value of `output`.
    pub fn get(&self, output: Output) -> f64 {
        match output {
            Output::HCentral => self.h_central,
            Output::HMin => self.h_min,
            Output::MuBarSliding => self.mu_bar_sliding,
            Output::MuBarTotal => self.mu_bar_total,
        }
    }
}

/// An output that carries a discretisation error ([`OutputErrors::estimate`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// Central film.
    HCentral,
    /// Minimum film.
    HMin,
    /// Sliding `mu-bar`.
    MuBarSliding,
    /// Sliding plus rolling `mu-bar` (Figs. 1-2).
    MuBarTotal,
}

/// What the discretisation error of the outputs is made from: the finest level and the
/// coarser levels solved on their own. The estimates are arithmetic on these values
/// ([`OutputErrors::estimate`], [`crate::solver::richardson`]), made when read, so a cached
/// solve is estimated by the estimator as it is now.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct OutputErrors {
    /// The levels read, coarse to fine (the last is the solution's).
    pub levels: Vec<LevelValues>,
    /// Wall time of the coarser levels' solves, s: what the estimate costs.
    pub seconds: f64,
    /// Why the ladder of coarser levels ended before [`crate::solver::point::AccuracyParams::error_levels`]
    /// levels (`None` where it did not).
    #[serde(default)]
    pub stopped: Option<LadderStop>,
    /// The finest level's central film tau-extrapolated, where the solve reports it
    /// ([`crate::solver::point::AccuracyParams::tau_extrapolation`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tau_central: Option<f64>,
    /// The outputs of a top refined across the rolling direction above the finest of
    /// `levels`, where the solve added one for its minimum film
    /// ([`crate::solver::point::AccuracyTarget::h_min`]): the outputs reported
    /// ([`OutputErrors::estimate`] says how they are estimated).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub across: Option<AcrossValues>,
}

/// The outputs of a top refined across the rolling direction ([`OutputErrors::across`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
pub struct AcrossValues {
    /// The top's (`7y`: level 7 with twice its intervals along `Y`).
    pub top: LevelValues,
    /// The level under it refined the same way (`6y`), converged on its own; `None` where it
    /// did not converge or lies outside the asymptotic range.
    pub below: Option<LevelValues>,
}

/// Why a coarser level of the error estimate was not read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case", tag = "reason")]
pub enum LadderStop {
    /// Its film closed at the centre: too coarse for the load.
    FilmClosed {
        /// The level.
        level: u32,
    },
    /// It did not converge.
    NotConverged {
        /// The level.
        level: u32,
    },
    /// Its central film is open but less than [`RESOLVED_FILM_SHARE`] of the finest level's:
    /// a film its mesh does not resolve, outside the asymptotic range.
    FilmUnresolved {
        /// The level.
        level: u32,
    },
    /// Not solved: the case's base (the same contact at another slip or Eyring stress) found
    /// it outside the asymptotic range ([`LadderStop::FilmClosed`] or
    /// [`LadderStop::FilmUnresolved`]), and a family's films differ by 1e-4.
    OutsideAtBase {
        /// The level.
        level: u32,
    },
}

/// The share of the finest level's central film below which a coarser level's film is
/// unresolved. In the asymptotic range consecutive levels differ by a fraction of the value
/// (Fig. 7's line contacts from level 8 up: 1-30 % in film; the point contacts of the
/// estimate's sample from level 6 up: 1-35 %); a level at half the finest's or less has its
/// film closing under its mesh, and the differences it gives do not follow a power law.
/// Fig. 7's five line contacts (levels 5-11, docs/ACCURACY_NOTES.md, "The line contact's
/// ladder"): the levels read above this share give estimates that bracket the next finer
/// level, those read below it (line contact 2's level 7 at 20 % of level 9's film, 5's level
/// 6 at 14 % of level 8's) estimates that fall short of it. The point contacts: Fig. 4 case
/// 214's level 5 (central film 4.6 % of level 7's, friction 12.0 against 16.2) is the
/// coarsest level of an alternating ladder whose first-order bound overstates level 7's error
/// 90 times; without it levels 6-7 are 1.2 times level 9's distance.
pub const RESOLVED_FILM_SHARE: f64 = 0.5;

impl LadderStop {
    /// The level that was not read.
    pub fn level(self) -> u32 {
        match self {
            LadderStop::FilmClosed { level }
            | LadderStop::NotConverged { level }
            | LadderStop::FilmUnresolved { level }
            | LadderStop::OutsideAtBase { level } => level,
        }
    }

    /// Whether the level was left out of the asymptotic range (its film, or its base's),
    /// rather than unconverged.
    pub fn is_outside(self) -> bool {
        !matches!(self, LadderStop::NotConverged { .. })
    }

    /// Why `coarse` is outside the asymptotic range next to the `finest` level (its film
    /// closed at the centre, or under [`RESOLVED_FILM_SHARE`] of the finest's); `None` where
    /// it is inside.
    pub fn outside(coarse: &LevelValues, finest: &LevelValues) -> Option<LadderStop> {
        let level = coarse.level;
        if coarse.h_central <= 0.0 {
            Some(LadderStop::FilmClosed { level })
        } else if coarse.h_central < RESOLVED_FILM_SHARE * finest.h_central {
            Some(LadderStop::FilmUnresolved { level })
        } else {
            None
        }
    }
}

impl OutputErrors {
    /// The record of `levels` (consecutive, coarse to fine), solved in `seconds`.
    pub fn of(levels: Vec<LevelValues>, seconds: f64) -> Self {
        OutputErrors {
            levels,
            seconds,
            stopped: None,
            tau_central: None,
            across: None,
        }
    }

    /// The record of a solve refined one level up from the one this estimated, whose values
    /// there are `top`: this record's finest `levels` levels, then `top` (where the strategy
    /// solves its coarser levels afresh, they are the same: [`crate::solver::point`]'s nested
    /// chain). The time and where the ladder stopped are this record's.
    pub fn refined_to(&self, top: LevelValues, levels: u32) -> Self {
        let skip = self.levels.len().saturating_sub(levels as usize);
        OutputErrors {
            levels: self.levels[skip..].iter().copied().chain([top]).collect(),
            seconds: self.seconds,
            stopped: self.stopped,
            tau_central: None,
            across: None,
        }
    }

    /// This record with the outputs of a top refined across the rolling direction above its
    /// finest level ([`OutputErrors::across`]).
    pub fn with_across(self, across: AcrossValues) -> Self {
        OutputErrors {
            across: Some(across),
            ..self
        }
    }

    /// The discretisation error of the reported `output` ([`OutputErrors::value`]): the
    /// levels' ([`OutputErrors::level_estimate`]), read at [`OutputErrors::tau_central`] if
    /// given, else at the top refined across the rolling direction if there is one
    /// ([`across_estimate`]).
    pub fn estimate(&self, output: Output) -> Option<ErrorEstimate> {
        let levels = self.level_estimate(output)?;
        match (output, self.tau_central, self.across) {
            (Output::HCentral, Some(tau), _) => Some(levels.of_value(tau)),
            (_, _, Some(across)) => across_estimate(&levels, across, output),
            _ => Some(levels),
        }
    }

    /// The reported `output`: the finest level's, or the top's refined across the rolling
    /// direction where there is one; the central film tau-extrapolated if given.
    pub fn value(&self, output: Output) -> f64 {
        match (output, self.tau_central, self.across) {
            (Output::HCentral, Some(tau), _) => tau,
            (_, _, Some(across)) => across.top.get(output),
            _ => self.levels[self.levels.len() - 1].get(output),
        }
    }

    /// The discretisation error of the finest level's `output` (`None` with fewer than two
    /// levels). Two levels are read at the scheme's order where the ladder left a coarser
    /// level out of the asymptotic range (the heavy contacts, whose levels inside it converge
    /// at 1.9-2.4), else at first order ([`crate::solver::richardson`]).
    pub fn level_estimate(&self, output: Output) -> Option<ErrorEstimate> {
        let two_level_order = match self.stopped {
            Some(stop) if stop.is_outside() => SCHEME_ORDER,
            _ => FIRST_ORDER,
        };
        estimate(
            &self
                .levels
                .iter()
                .map(|v| v.get(output))
                .collect::<Vec<_>>(),
            two_level_order,
        )
    }
}

/// The discretisation error of the top refined across the rolling direction's `output`,
/// given the square levels' estimate `levels`: from the top and the level under it refined the
/// same way, a grid family of its own, at the order the square levels' estimate used (the two
/// families converge alike; the same safety as any two levels). Without that level, the top's
/// distance to the square levels' extrapolation: its error is exactly the finest square
/// level's plus its change from it ([`ErrorEstimate::of_value`]).
fn across_estimate(
    levels: &ErrorEstimate,
    across: AcrossValues,
    output: Output,
) -> Option<ErrorEstimate> {
    let top = across.top.get(output);
    match across.below {
        Some(below) => estimate(&[below.get(output), top], levels.order_used),
        None => Some(levels.of_value(top)),
    }
}

/// Which method produced the solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// The point contact's multigrid cycles alone.
    Cycles,
    /// The point contact's Newton-Krylov finish, grid-sequenced, after the cycles stalled
    /// or diverged.
    NewtonKrylov,
    /// The line contact's nested damped Newton iteration.
    Newton,
}

impl Method {
    /// The name printed and written to JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Cycles => "cycles",
            Method::NewtonKrylov => "newton-krylov",
            Method::Newton => "newton",
        }
    }
}

/// What one step of a solver was.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Step {
    /// A multigrid cycle of the point contact.
    Cycle,
    /// A Newton step of the point contact's Newton-Krylov finish, with the GMRES iterations
    /// it took.
    NewtonKrylov {
        /// GMRES iterations of the step.
        krylov_iterations: usize,
    },
    /// A damped Newton iteration of the line contact (dense Jacobian).
    Newton,
}

/// What a solver's observer is told after each step (cycle or Newton iteration), the same
/// for the point and the line contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// Level the step ran on.
    pub level: u32,
    /// Step number on that level and of that kind (from 1).
    pub count: usize,
    /// What the step was.
    pub step: Step,
    /// Mean absolute residual after the step.
    pub residual: f64,
    /// Relative force-balance error after the step.
    pub load_error: f64,
    /// Mean absolute change of `P` over the step.
    pub pressure_change: f64,
    /// Central film `H` after the step.
    pub h_central: f64,
    /// `(X, Y)` of the largest residual (`Y = 0` for the line contact).
    pub worst_at: (f64, f64),
}

/// Mean absolute difference of two pressure fields.
pub(crate) fn mean_change(p: &[f64], before: &[f64]) -> f64 {
    p.iter()
        .zip(before)
        .map(|(a, b)| (a - b).abs())
        .sum::<f64>()
        / p.len() as f64
}

/// How the solve went.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Info {
    /// The level of the grid solved on: the one asked for, or a finer one where the film
    /// needed it.
    pub level: u32,
    /// What converged the solve.
    pub method: Method,
    /// Multigrid cycles on the finest level (after the full-multigrid start), with those on
    /// any finer level the film asked for.
    pub cycles: usize,
    /// Newton steps of the point contact's Newton-Krylov finish, over every level of its
    /// grid sequence (0 when the cycles converged, and for the line contact, whose solver
    /// is Newton throughout).
    pub newton_steps: usize,
    /// GMRES iterations (Jacobian-vector products) over all those Newton steps.
    pub krylov_iterations: usize,
    /// Residual norm after each finest-level cycle, then after each Newton step of the
    /// finish (on every level of its grid sequence).
    pub residual_history: Vec<f64>,
    /// Relative force-balance error `|int P - target| / target` at the end.
    pub load_error: f64,
    /// Wall time, s.
    pub seconds: f64,
    /// Where the solve started: cold, warm from a related case's solution, or cold after a
    /// warm start failed.
    pub start: StartKind,
}

/// Where a solve started ([`crate::solver::point::solve_from`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum StartKind {
    /// From the Hertzian pressure (full multigrid), as asked.
    #[default]
    Cold,
    /// From a related case's converged solution.
    Warm,
    /// From the Hertzian pressure after the warm start failed.
    Fallback,
}

impl Info {
    /// The last residual (infinite when no cycle ran).
    pub fn residual(&self) -> f64 {
        self.residual_history
            .last()
            .copied()
            .unwrap_or(f64::INFINITY)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(level: u32, mu: f64) -> LevelValues {
        LevelValues {
            level,
            h_central: 1.0,
            h_min: 0.5,
            mu_bar_sliding: mu,
            mu_bar_total: mu,
        }
    }

    #[test]
    fn a_refined_record_reads_the_finest_levels_below_and_the_new_top() {
        let mut below = OutputErrors::of(vec![at(5, 9.0), at(6, 9.5), at(7, 9.75)], 1.5);
        below.stopped = Some(LadderStop::NotConverged { level: 4 });
        let refined = below.refined_to(at(8, 9.875), 2);
        let levels: Vec<u32> = refined.levels.iter().map(|v| v.level).collect();
        assert_eq!(levels, [6, 7, 8]);
        assert_eq!((refined.seconds, refined.stopped), (1.5, below.stopped));
        // A ladder that kept fewer levels than asked (it stopped at level 6) keeps them all.
        let short = OutputErrors::of(vec![at(7, 9.75)], 0.5).refined_to(at(8, 9.875), 2);
        let levels: Vec<u32> = short.levels.iter().map(|v| v.level).collect();
        assert_eq!(levels, [7, 8]);
    }

    #[test]
    fn a_top_refined_across_reports_its_outputs_at_their_distance_to_the_extrapolation() {
        // Levels 6-7 read at the scheme's order (level 5 outside the range): friction 9.0,
        // 9.6 extrapolate to 9.8; the top's 9.7 is 0.1 from it, times the assumed order's
        // safety 2.
        let mut levels = OutputErrors::of(vec![at(6, 9.0), at(7, 9.6)], 0.5);
        levels.stopped = Some(LadderStop::FilmUnresolved { level: 5 });
        let top = LevelValues {
            h_central: 1.01,
            ..at(7, 9.7)
        };
        let mut across = levels
            .clone()
            .with_across(AcrossValues { top, below: None });
        let e = across.estimate(Output::MuBarSliding).unwrap();
        assert!((across.value(Output::MuBarSliding) - 9.7).abs() < 1e-12);
        assert!((e.extrapolated - 9.8).abs() < 1e-12);
        assert!((e.error - 2.0 * 0.1).abs() < 1e-12, "{}", e.error);
        // The levels' own estimate is untouched: 1.25 x 0.6 / 3.
        let own = across.level_estimate(Output::MuBarSliding).unwrap();
        assert!((own.error - 0.25).abs() < 1e-12);
        // The central film: the top's, unless the level's tau-extrapolation is reported.
        assert!((across.value(Output::HCentral) - 1.01).abs() < 1e-12);
        across.tau_central = Some(1.02);
        assert!((across.value(Output::HCentral) - 1.02).abs() < 1e-12);
        // Without the top the finest level is reported.
        assert!((levels.value(Output::MuBarSliding) - 9.6).abs() < 1e-12);
        // With the level under the top refined the same way (9.5), the two at the square
        // levels' order: 1.25 x 0.2 / 3.
        let below = Some(at(6, 9.5));
        let pair = levels.with_across(AcrossValues { top, below });
        let e = pair.estimate(Output::MuBarSliding).unwrap();
        assert!((e.error - 1.25 * 0.2 / 3.0).abs() < 1e-12, "{}", e.error);
        assert!((e.extrapolated - (9.7 + 0.2 / 3.0)).abs() < 1e-12);
    }
}
