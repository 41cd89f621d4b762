//! When the cycles may stop: the algebraic error of the outputs, estimated from their change
//! per cycle and the observed convergence factor, against the accuracy the level can give.
//!
//! A cycle that changes an output `x` (central film, minimum film, sliding and rolling
//! friction) by
//! `d_n = x_n - x_(n-1)` leaves, at a convergence factor `rho = |d_n / d_(n-1)|`, an error of
//! about `|d_n| rho / (1 - rho)` (the geometric tail). Where the changes alternate in sign
//! the limit lies between the last two iterates, so the error is at most `|d_n|` (the
//! cavitation boundary of light cases flips a few nodes in and out every cycle: a
//! residual that never falls below 1e-4 while every output has settled to 1e-6).
//!
//! Settled outputs end the cycles only while the residual still falls
//! ([`residual_falls`]); otherwise, where the Newton-Krylov finish is allowed, it takes over
//! from the cycles' best state. A residual below its tolerance does not end them while the
//! outputs have not settled: a heavy contact's side-lobe minimum film can still be 2 % off
//! there.
//!
//! The bound [`OUTPUT_TOLERANCE`] is set by what the level can resolve. Level 7's own
//! discretisation error, from levels 7 and 8 by Richardson extrapolation, is about 6 % in
//! the central film and 0.13 % in `mu-bar` on the Table 4 case (the paper's own levels 7
//! and 8 differ by 5 % and 0.1 %), and larger on every heavier case; an algebraic error of
//! 5e-4 is a hundredth of the film's and a third of the friction's. Iterating below it buys
//! digits the grid does not have: on the Table 4 case the rule stops after 17 cycles, where
//! the 3 more cycles to a mean residual of 1e-6 would move the film by 2.0e-4 and `mu-bar` by
//! 6e-7.

/// Relative algebraic error of every output at which the cycles stop (module documentation).
pub(crate) const OUTPUT_TOLERANCE: f64 = 5e-4;

/// Convergence factor at which the tail estimate is capped: an output that creeps (or whose
/// changes are round-off noise of a settled solution) is charged twenty times its last
/// change, so that it stops the cycles only where that change is itself 20 times below the
/// tolerance.
const RHO_MAX: f64 = 0.95;

/// Cycles [`residual_falls`] needs to judge: the last and the one two before it.
pub(crate) const FALL_WINDOW: usize = 3;

/// Values of a warm start's history before its cycles may stop: its own outputs and two
/// cycles' (point-33; three cycles before). Its first cycle moves the outputs from the base's
/// solution towards the member's, the second shows how fast they converge, and the residual's
/// fall over it bounds the factor ([`tail`]).
const WARM_VALUES: usize = 3;

/// Factor by which the residual must have fallen over the last two cycles for settled
/// outputs (or a settled pressure) to end the cycles ([`residual_falls`]).
const RESIDUAL_FALL: f64 = 0.8;

/// Whether the residual fell over the last two cycles to at most [`RESIDUAL_FALL`] of its
/// value before them. Settled outputs mean a converged solution only while the cycles still
/// converge: they can also settle on a fixed point of the cycle that is not a solution of
/// the discrete equations (the `P = max(P, 0)` projection at the cavitation boundary), where
/// the pressure change keeps falling geometrically while the residual stands still. On Fig.
/// 5's traction fluid at 40 C, 3 GPa, 12 m/s, S 2 % (4 MPa) the residual stood at 3.3e-4
/// (ratio 0.99 over two cycles) and the rolling friction was 2 % off the Newton-Krylov
/// solution at level 7, 6 % at level 6. Every case of the 16-case battery that the cycles
/// converge still had its residual falling by 0.47-0.81 per cycle (0.22-0.66 over two) where
/// the outputs settled, as have the light cases whose outputs settle in five cycles.
///
/// After two cycles (a warm start's shortest solve, [`OutputHistory::new`]) the last must be
/// at most `sqrt(RESIDUAL_FALL)` of the first, the same fall per cycle.
pub(crate) fn residual_falls(history: &[f64]) -> bool {
    const { assert!(FALL_WINDOW == 3, "the pattern below reads three values") };
    match history {
        [.., before, _, last] => *last <= RESIDUAL_FALL * *before,
        [first, last] => *last <= RESIDUAL_FALL.sqrt() * *first,
        _ => false,
    }
}

/// Share of a coarser level's distance to the next finer level (in each output) that its
/// algebraic error may reach when it is converged for the discretisation error's ladder
/// ([`Known::finer`]). The estimate reads the differences between levels: an algebraic error
/// of a tenth of a difference moves that difference, and the error estimate, by at most a
/// tenth, inside the 25 % margin of the estimate's own safety factor
/// ([`crate::solver::richardson`]). Measured on Fig. 3's 125 cases at level 7: the ladder's
/// level-6 and level-5 cycles fell from 8.5 and 9.7 per solve to 6.7 and 5.7; over Figs. 1-7
/// the error estimates moved by 0.02-0.09 % of themselves (median per figure) and 7 % at
/// most (docs/ACCURACY_NOTES.md). The rolling part keeps the tolerance (of the total
/// friction on the rung under a top: [`Finer::rolling_of_total`]): a share of the total's
/// distance let Fig. 1's total `mu-bar` estimates move up to fifteenfold.
pub(crate) const FINER_DISTANCE_SHARE: f64 = 0.1;

/// What the cycles' stopping rule knows of the solution beyond its own iterates.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Known {
    /// The converged related solution the cycles start from ([`super::warm`]).
    pub start: Option<WarmStop>,
    /// The central and minimum film, sliding and total `mu-bar` of the next finer level,
    /// converged, where this level is converged for the discretisation error's ladder (the
    /// outputs the estimate reads): each output needs an algebraic error below
    /// [`FINER_DISTANCE_SHARE`] of the distance of what it enters to them, or below the
    /// tolerance where that is larger. The sliding and rolling parts both enter the total,
    /// so each may take half of its share.
    pub finer: Option<Finer>,
}

/// The next finer level's outputs a coarser level of the ladder is converged against
/// ([`Known::finer`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Finer {
    /// Its central and minimum film, sliding and total `mu-bar`.
    pub outputs: [f64; 4],
    /// Whether the rolling part is held to the tolerance of the total friction rather than of
    /// itself: on the rung under a top refined across the rolling direction, which the
    /// estimate reads through the total alone and no tau-extrapolation reads at all. Held to
    /// the tolerance of itself, a heavy member's rung, whose rolling part is a ten-thousandth
    /// of the total, cycled 5 times where 2 settled everything else (the M 11 070 member).
    /// The square rungs keep it: relaxed there too (`point-42`, reverted), the rungs stopped
    /// on the films' own share and the tau-extrapolated central film moved by up to 1.9 %.
    pub rolling_of_total: bool,
}

/// What the warm cycles' stopping rule knows of the start: a converged solution is a point
/// of the sequence the estimate reads, and its residual says where a warm start's fixed
/// point lies ([`super::warm`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct WarmStop {
    /// The start's central and minimum film, sliding and rolling `mu-bar`.
    pub outputs: [f64; 4],
    /// The base's accepted residual.
    pub residual: f64,
}

/// The residual a warm solve's settled outputs are accepted at, as a multiple of the base's
/// accepted residual ([`super::warm`]: without it the heaviest members, M 11 070, took a
/// Newton-Krylov detour and were slower than cold).
const WARM_RESIDUAL_FACTOR: f64 = 2.0;

impl WarmStop {
    /// Whether settled outputs at `residual` end the cycles although the residual no longer
    /// falls.
    pub fn accepts(&self, residual: f64) -> bool {
        residual <= WARM_RESIDUAL_FACTOR * self.residual
    }
}

/// The outputs after each cycle.
#[derive(Debug, Default)]
pub(crate) struct OutputHistory {
    values: Vec<[f64; 4]>,
    /// The residual after each cycle (a warm start's own not among them).
    residuals: Vec<f64>,
    /// Values before the estimate may be made (0 for the default, five; 3 from a warm start).
    needed: usize,
    /// The next finer level's outputs ([`Known::finer`]).
    finer: Option<Finer>,
}

impl OutputHistory {
    /// A history for cycles that know `known`. A warm start's outputs are its first entry:
    /// the start is a converged solution, so its outputs belong to the sequence the estimate
    /// reads, and two cycles after it (a window of three values, [`WARM_VALUES`]) may end the
    /// solve.
    pub fn new(known: &Known) -> Self {
        let (values, needed) = match known.start {
            Some(w) => (vec![w.outputs], WARM_VALUES),
            None => (Vec::new(), 0),
        };
        OutputHistory {
            values,
            residuals: Vec::new(),
            needed,
            finer: known.finer,
        }
    }

    /// Records the central film, minimum film, sliding and rolling `mu-bar` after a cycle
    /// (the rolling part 0 where it is not computed) and the cycle's residual.
    pub fn push(&mut self, [h_central, h_min, sliding, rolling]: [f64; 4], residual: f64) {
        self.values.push([h_central, h_min, sliding, rolling]);
        self.residuals.push(residual);
    }

    /// The largest estimated relative algebraic error over the outputs, after this cycle and
    /// after the one before (a minimum film whose place moves can stand still for a cycle
    /// before it turns); infinite until five cycles are recorded.
    #[cfg(test)]
    fn relative_error(&self) -> f64 {
        self.worst(|_, _| 1.0)
    }

    /// Whether every output's estimated algebraic error is below `tolerance`, relative, or
    /// below its share of the distance to the finer level where that is larger
    /// ([`Known::finer`]).
    pub fn settled(&self, tolerance: f64) -> bool {
        let Some(Finer {
            outputs: f,
            rolling_of_total,
        }) = self.finer
        else {
            return self.worst(|_, _| tolerance) < 1.0;
        };
        let allowed = |o: usize, v: &[f64; 4]| {
            let distance = |finer: f64, now: f64| (finer - now).abs();
            let total = distance(f[3], v[2] + v[3]);
            let absolute = match o {
                0..=2 => distance(f[o], v[o]),
                _ => 0.0,
            };
            // The sliding part also enters the total where rolling is computed.
            let absolute = if o == 2 && v[3] != 0.0 {
                absolute.min(total)
            } else {
                absolute
            };
            if v[o] == 0.0 {
                tolerance
            } else if o == 3 && rolling_of_total {
                tolerance * ((v[2] + v[3]) / v[3]).abs().max(1.0)
            } else {
                tolerance.max(FINER_DISTANCE_SHARE * absolute / v[o].abs())
            }
        };
        self.worst(allowed) < 1.0
    }

    /// The largest relative error over the outputs, each divided by `allowed(output,
    /// values)`, after this cycle and after the one before; infinite until enough values.
    fn worst(&self, allowed: impl Fn(usize, &[f64; 4]) -> f64) -> f64 {
        let n = self.values.len();
        // The default history needs five values (two windows).
        let needed = if self.needed == 0 { 5 } else { self.needed };
        if n < needed {
            return f64::INFINITY;
        }
        if n == WARM_VALUES {
            // A warm start's first window: two changes, and the residual's fall over the
            // second cycle as the least convergence factor ([`tail`]).
            let contraction = match self.residuals[..] {
                [.., before, last] if before > 0.0 => last / before,
                _ => RHO_MAX,
            };
            return window_error(&self.values, contraction, &allowed);
        }
        let last = window_error(&self.values[n - 4..], 0.0, &allowed);
        if n < 5 {
            return last;
        }
        last.max(window_error(&self.values[n - 5..n - 1], 0.0, &allowed))
    }
}

/// The largest relative error over the outputs estimated from three or four successive
/// values (a factor of at least `least` where there are three), each divided by
/// `allowed(output, values)`.
fn window_error(v: &[[f64; 4]], least: f64, allowed: &impl Fn(usize, &[f64; 4]) -> f64) -> f64 {
    let top = &v[v.len() - 1];
    (0..4)
        .map(|o| {
            let d: Vec<f64> = v.windows(2).map(|w| w[1][o] - w[0][o]).collect();
            let e = tail(&d, least);
            if e == 0.0 {
                0.0
            } else {
                e / top[o].abs() / allowed(o, top)
            }
        })
        .fold(0.0, f64::max)
}

/// The estimated remaining error after the last changes `d` of an output (module
/// documentation). With three changes the convergence factor is the larger of the last two
/// ratios, so that one lucky cycle does not stop the iteration; with two (a warm start's
/// first window) the larger of their ratio and `least`, the residual's fall over the last
/// cycle: the outputs' first change holds the step from the base to the member, and their
/// ratio alone can be lucky.
fn tail(d: &[f64], least: f64) -> f64 {
    let n = d.len();
    let last = d[n - 1];
    if last == 0.0 {
        return 0.0;
    }
    if d[n - 2] * last < 0.0 {
        return last.abs();
    }
    let before = if n >= 3 {
        (d[n - 2] / d[n - 3]).abs()
    } else {
        least
    };
    let rho = (last / d[n - 2]).abs().max(before).min(RHO_MAX);
    last.abs() * rho / (1.0 - rho)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sequence converging geometrically to `limit` at factor `rho` (signed).
    fn sequence(limit: f64, rho: f64, n: usize) -> Vec<f64> {
        (0..n).map(|k| limit + 0.1 * rho.powi(k as i32)).collect()
    }

    #[test]
    fn the_tail_estimate_is_exact_for_a_geometric_sequence() {
        for rho in [0.3, 0.65, 0.9] {
            let x = sequence(2.0, rho, 8);
            let mut h = OutputHistory::default();
            for v in &x {
                h.push([*v, *v, *v, *v], 1.0);
            }
            // The estimate is the larger of the errors after the last two cycles: the one
            // before the last, for a decreasing sequence. A geometric sequence's tail is the
            // estimate exactly; round-off only.
            let truth = (x[6] - 2.0).abs() / x[6];
            assert!(
                (h.relative_error() - truth).abs() < 1e-12 * truth.max(1e-3),
                "rho {rho}: {} vs {truth}",
                h.relative_error()
            );
        }
    }

    #[test]
    fn an_oscillating_sequence_is_bounded_by_its_last_change() {
        let x = sequence(1.0, -0.5, 6);
        let mut h = OutputHistory::default();
        for v in &x {
            h.push([1.0, *v, 1.0, 0.0], 1.0);
        }
        // The bound is the larger of the last two changes (the one before the last here),
        // relative to the value each ends at; each is at least the true error then.
        let bound = (x[4] - x[3]).abs() / x[4];
        let truth = (x[5] - 1.0).abs() / x[5];
        let e = h.relative_error();
        assert!((e - bound).abs() < 1e-15 && e >= truth);
    }

    #[test]
    fn a_residual_standing_still_is_not_falling() {
        // The last cycles of the traction-fluid case above (level 7): the pressure
        // change fell from 2.2e-6 to 7.5e-7 over these cycles, the residual did not.
        let stalled = [3.388e-4, 3.390e-4, 3.353e-4, 3.378e-4];
        assert!(!residual_falls(&stalled));
        // The Table 4 case's and the slowest battery case's last cycles where they stop.
        let table4 = [8.146e-6, 5.297e-6, 3.480e-6];
        let slow = [1.515e-6, 1.053e-6, 8.578e-7];
        assert!(residual_falls(&table4) && residual_falls(&slow));
        // Two cycles (a warm start's shortest solve) are judged by the same fall per cycle,
        // sqrt(0.8) = 0.894; one is too few to tell.
        assert!(residual_falls(&[1e-3, 8.9e-4]) && !residual_falls(&[1e-3, 9e-4]));
        assert!(!residual_falls(&[1e-3]), "one cycle is too few to tell");
    }

    /// A warm start's outputs after two cycles: the first change is the step from the base,
    /// the second a tenth of it. Settled where the residual halved over the second cycle
    /// (factor 0.5: the tail is the last change, 1e-4), not where it fell by only 0.95
    /// (the tail is then 19 times the last change): the outputs' own ratio alone would
    /// have stopped both.
    #[test]
    fn a_warm_start_stops_after_two_cycles_only_where_its_residual_falls_too() {
        let known = Known {
            start: Some(WarmStop {
                outputs: [1.0; 4],
                residual: 1e-6,
            }),
            finer: None,
        };
        let history = |second_residual: f64| {
            let mut h = OutputHistory::new(&known);
            h.push([1.001; 4], 1e-3);
            assert!(!h.settled(5e-4), "one cycle is too few");
            h.push([1.0011; 4], second_residual);
            h
        };
        assert!(history(5e-4).settled(5e-4));
        let slow = history(9.5e-4);
        assert!(!slow.settled(5e-4));
        // With a third cycle the window of four values judges as before.
        let mut h = slow;
        h.push([1.00111; 4], 9e-4);
        assert!(h.settled(5e-4));
    }

    /// Six cycles' outputs `1 + 0.01 / 2^k`: an algebraic error of about 6e-4 after the last,
    /// above the tolerance 5e-4 and below a tenth of a 1 % distance.
    fn cycle_values() -> Vec<f64> {
        (0..6).map(|k| 1.0 + 0.01 * 0.5f64.powi(k)).collect()
    }

    /// A finer level's value 1 % from the last of [`cycle_values`].
    fn one_percent_on() -> f64 {
        1.01 * cycle_values()[5]
    }

    /// The history of [`cycle_values`], each output alike but the rolling part, `rolling(v)`,
    /// against `finer` (its outputs, and whether the rolling part is held to the tolerance of
    /// the total).
    fn converging(finer: Option<([f64; 4], bool)>, rolling: impl Fn(f64) -> f64) -> OutputHistory {
        let mut h = OutputHistory::new(&Known {
            start: None,
            finer: finer.map(|(outputs, rolling_of_total)| Finer {
                outputs,
                rolling_of_total,
            }),
        });
        for v in cycle_values() {
            h.push([v, v, v, rolling(v)], 1.0);
        }
        h
    }

    #[test]
    fn a_coarser_level_is_settled_at_a_share_of_its_distance_to_the_finer_one() {
        // Films and sliding friction 1 % from the finer level's, their algebraic error about
        // 6e-4: above the tolerance 5e-4, below a tenth of the distance (1e-3). Rolling
        // friction not computed (0), or converged alongside.
        let f = one_percent_on();
        let none = |_| 0.0;
        let far = converging(Some(([f, f, f, f], false)), none);
        let near = converging(Some(([1.0; 4], false)), none);
        let alone = converging(None, none);
        let error = alone.relative_error();
        assert!(error > 5e-4 && error < 1e-3, "{error}");
        assert!(far.settled(5e-4), "a tenth of 1 % allows it");
        assert!(
            !alone.settled(5e-4) && !near.settled(5e-4),
            "the tolerance does not"
        );
        // A rolling part keeps the tolerance, however far the finer total.
        let rolling = converging(Some(([f, f, f, 1.1 * f], false)), |v| 0.1 * v);
        assert!(
            !rolling.settled(5e-4),
            "rolling friction is held to the tolerance"
        );
    }

    #[test]
    fn the_rung_under_a_top_holds_its_rolling_part_to_the_tolerance_of_the_total() {
        // Every output's algebraic error about 6e-4 of itself (as above), the finer level 1 %
        // away: the films and the sliding part settle on their share of the distance; the
        // rolling part's 6e-4 of itself is 5.5e-5 of the total where it is a tenth of the
        // sliding part, and 5.5e-4 of it where it is ten times the sliding part.
        let f = one_percent_on();
        let history = |share: f64, rolling_of_total| {
            let finer = ([f, f, f, (1.0 + share) * f], rolling_of_total);
            converging(Some(finer), |v| share * v)
        };
        assert!(
            history(0.1, true).settled(5e-4),
            "a tenth of the sliding part"
        );
        assert!(
            !history(10.0, true).settled(5e-4),
            "ten times the sliding part"
        );
        assert!(
            !history(0.1, false).settled(5e-4),
            "a square rung holds it to the tolerance of itself"
        );
    }

    #[test]
    fn slow_outputs_are_charged_twenty_times_their_change() {
        let x = sequence(1.0, 0.99, 6);
        let mut h = OutputHistory::default();
        for v in &x {
            h.push([1.0, 1.0, *v, 0.0], 1.0);
        }
        // The change before the last is the larger one: rho capped at 0.95, the estimate is
        // 19 times it (round-off only).
        let last = (x[4] - x[3]).abs() / x[4];
        assert!((h.relative_error() / last - 19.0).abs() < 1e-9);
        let mut h = OutputHistory::default();
        for _ in 0..4 {
            h.push([1.0, 1.0, 1.0, 0.0], 1.0);
        }
        assert!(
            h.relative_error().is_infinite(),
            "too few cycles to estimate"
        );
    }
}
