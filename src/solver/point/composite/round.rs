//! A composite round's outputs: the film and friction of the patches and of the whole-domain
//! level outside them, and when the rounds have settled.

use crate::physics::case::Problem;
use crate::solver::output::Friction;
use crate::solver::point::level::LevelFields;
use crate::solver::point::nested::Surround;
use crate::solver::point::{PointSolution, LOADED_FILM_FACTOR};

/// The outputs after one round of the composite iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeRound {
    /// Central film (Moes), on the patch where the centre is inside one, else on the
    /// whole-domain level.
    pub hc_moes: f64,
    /// The same in `h/c`.
    pub h_central: f64,
    /// The minimum film below in `h/c`.
    pub h_min: f64,
    /// The smallest of the patches' minimum films and the whole-domain level's outside them
    /// (Moes).
    pub hmin_moes: f64,
    /// The patches' own minimum film (Moes), the smallest.
    pub patch_hmin_moes: f64,
    /// `mu-bar`: the patches' loaded film plus the whole-domain level's outside them (rolling
    /// where it is computed).
    pub friction: Friction,
    /// The film constant.
    pub delta: f64,
    /// The largest change of a patch's pressure from the round before (0 in the first).
    pub patch_change: f64,
    /// The whole-domain level's mean residual at the round's start (with the forcing of the
    /// round before).
    pub residual: f64,
    /// Seconds since the start of the composite solve.
    pub seconds: f64,
}

/// A patch solved in a round: its corner node on the whole-domain level, its solution, its
/// surroundings ([`Surround::new`], the split of the friction) and its solution of the round
/// before.
pub(super) struct Solved<'a> {
    pub(super) corner: [usize; 2],
    pub(super) sol: &'a PointSolution,
    pub(super) outside: &'a Surround,
    pub(super) previous: Option<&'a PointSolution>,
}

/// Whether the last two rounds' central film and friction agree within `tolerance`.
pub(super) fn settled(rounds: &[CompositeRound], tolerance: f64) -> bool {
    let [.., a, b] = rounds else {
        return false;
    };
    let close = |x: f64, y: f64| (x - y).abs() <= tolerance * y.abs();
    close(a.hc_moes, b.hc_moes) && close(a.friction.sliding, b.friction.sliding)
}

/// A round's central and minimum film and friction from the whole-domain level `coarse` and
/// the patches solved on it (which do not overlap), and the largest change of a patch's
/// pressure from the round before.
pub(super) fn round_outputs(
    problem: &Problem,
    coarse: &LevelFields,
    patches: &[Solved],
) -> CompositeRound {
    let holds_centre = |s: &&Solved| {
        let r = s.outside.inner();
        r.x_start < 0.0 && r.x_end > 0.0 && r.y_start() < 0.0 && r.y_end() > 0.0
    };
    let hc = patches
        .iter()
        .find(holds_centre)
        .map_or_else(|| coarse.h_central(), |s| s.sol.film.h_central);
    let g = coarse.grid;
    let under = |i: usize, j: usize| {
        patches.iter().any(|s| {
            let ([i0, j0], cells) = (s.corner, s.sol.grid.nx / 2);
            (i0..=i0 + cells).contains(&i) && (j0..=j0 + cells).contains(&j)
        })
    };
    let outside_min = (0..g.len())
        .filter(|&k| !under(k % g.px(), k / g.px()))
        .map(|k| coarse.h[k])
        .fold(f64::INFINITY, f64::min);
    let scale = problem.groups.moes_film_scale;
    let inside = patches[1..]
        .iter()
        .fold(patches[0].sol.friction, |f, s| Friction {
            sliding: f.sliding + s.sol.friction.sliding,
            rolling: f.rolling.zip(s.sol.friction.rolling).map(|(a, b)| a + b),
        });
    let outsides: Vec<&Surround> = patches.iter().map(|s| s.outside).collect();
    let friction = Surround::plus_outside_all(&outsides, problem, LOADED_FILM_FACTOR * hc, inside);
    let patch_min = patches
        .iter()
        .map(|s| s.sol.film.h_min)
        .fold(f64::INFINITY, f64::min);
    let h_min = patch_min.min(outside_min);
    CompositeRound {
        hc_moes: hc * scale,
        h_central: hc,
        h_min,
        hmin_moes: h_min * scale,
        patch_hmin_moes: patch_min * scale,
        friction,
        delta: patches[0].sol.delta,
        patch_change: patches
            .iter()
            .map(|s| {
                s.previous.map_or(0.0, |q| {
                    q.p.iter()
                        .zip(&s.sol.p)
                        .map(|(a, b)| (a - b).abs())
                        .fold(0.0, f64::max)
                })
            })
            .fold(0.0, f64::max),
        residual: 0.0,
        seconds: 0.0,
    }
}
