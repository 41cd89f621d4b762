//! A composite grid's patch ([`super::composite`]): where it lies and how it is coupled
//! (the converged patch carried into the whole-domain level, [`carry_into`]).

use super::level::{LevelFields, Model};
use super::transfer::coarsen;
use crate::solver::grid::{Domain, Grid};

/// The patches a user can ask for (`repro solve --patch`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Patch {
    /// Over the inlet's pressure rise near the axis, where a heavy contact's central film is
    /// made ([`PatchSpec::inlet`]).
    Inlet,
}

impl Patch {
    /// The patch at `level`.
    pub fn spec(self, level: u32) -> PatchSpec {
        match self {
            Patch::Inlet => PatchSpec::inlet(level),
        }
    }
}

/// Where a patch lies and how it is coupled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchSpec {
    /// Its inlet: the whole-domain level's grid line nearest this `X`.
    pub x_start: f64,
    /// It spans `2^cells_level` cells of the whole-domain level in each direction,
    /// symmetric about `Y = 0`: its own grid is level `cells_level` on its rectangle.
    pub cells_level: u32,
    /// The whole-domain nodes that take the patch's forcing: those at least this many cells
    /// inside its edge (1: every interior node; with 2 a ring of coarse equations under the
    /// patch made the rounds alternate).
    pub margin: usize,
    /// Width in whole-domain cells of the band around the patch over which the deformation
    /// by the outside pressure is taken at the patch's mesh ([`Surround::banded`]; 0: the
    /// wide cells split at the edge, [`Surround::new`]).
    pub band: usize,
}

impl PatchSpec {
    /// The heavy contact's inlet patch of the study: `-1.2` to about `-0.45` Hertzian radii on
    /// the heavy-load domain at any level (a quarter of the domain in each direction),
    /// interior forcing, a band of eight cells.
    pub fn inlet(level: u32) -> Self {
        PatchSpec {
            x_start: -1.2,
            cells_level: level - 1,
            margin: 1,
            band: 8,
        }
    }

    /// The patch's rectangle on `level`'s grid of `domain`, and its corner node there.
    pub fn rectangle(&self, domain: &Domain, level: u32) -> (Domain, [usize; 2]) {
        let coarse = Grid::level(domain, level);
        let cells = 1usize << self.cells_level;
        let i0 = ((self.x_start - coarse.x0) / coarse.hx).round() as usize;
        let j0 = (coarse.ny - cells) / 2;
        let patch = Domain {
            x_start: coarse.x(i0),
            x_end: coarse.x(i0 + cells),
            y_half: -coarse.y(j0),
        };
        (patch, [i0, j0])
    }
}

/// Carries the converged patch `fine` (film constant `delta`) into the whole-domain level
/// `level`, its corner at node `[i0, j0]`: at the level's nodes at least `margin` cells inside
/// the patch, the restricted pressure and the FAS forcing (`f`, and the film-equation offset
/// that reproduces the patch's film; elsewhere the film's right-hand side is `geometry`); in
/// the force balance, the patch's load less the level's own over the patch.
pub(super) fn carry_into(
    level: &mut LevelFields,
    (fine, delta): (&LevelFields, f64),
    ([i0, j0], margin): ([usize; 2], usize),
    (model, geometry): (&Model, &[f64]),
) {
    let mut sub = LevelFields::new(fine.grid.coarser(), model);
    coarsen(fine, &mut sub, model, delta);
    let (g, sg) = (level.grid, sub.grid);
    let at = |ic: usize, jc: usize| g.idx(i0 + ic, j0 + jc);
    let forced = || {
        (margin..=sg.ny - margin)
            .flat_map(move |jc| (margin..=sg.nx - margin).map(move |ic| (ic, jc)))
    };
    level.f.iter_mut().for_each(|v| *v = 0.0);
    for (ic, jc) in forced() {
        level.p[at(ic, jc)] = sub.p[sg.idx(ic, jc)];
        level.f[at(ic, jc)] = sub.f[sg.idx(ic, jc)];
    }
    let mut w = g.zeros();
    level.deformation.apply(&level.p, &mut w);
    level.hrhs.copy_from_slice(geometry);
    for (ic, jc) in forced() {
        let k = at(ic, jc);
        level.hrhs[k] = sub.h[sg.idx(ic, jc)] - delta - w[k];
    }
    let mut under = sg.zeros();
    for jc in 0..=sg.ny {
        for ic in 0..=sg.nx {
            under[sg.idx(ic, jc)] = level.p[at(ic, jc)];
        }
    }
    level.load_correction = fine.grid.integrate(&fine.p) - sg.integrate(&under);
    level.rg = -(level.load - level.load_correction);
    level.invalidate();
}
