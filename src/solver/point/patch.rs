//! A composite grid's patches ([`super::composite`]): where they lie and how they are coupled
//! (the converged patches carried into the whole-domain level, [`carry_into`]).

use super::level::{LevelFields, Model};
use super::transfer::coarsen;
use super::{Params, MAX_LEVEL, MIN_LEVEL};
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::SolveError;

/// The patches a user can ask for (`repro solve --patch`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Patch {
    /// Over the inlet's pressure rise near the axis, where a heavy contact's central film is
    /// made ([`PatchSpec::inlet`]).
    Inlet,
    /// Over the side lobes, where a heavy contact's minimum film is ([`PatchSet::lobes`]).
    Lobes,
    /// Both: the inlet's and the side lobes' patches.
    InletAndLobes,
}

impl Patch {
    /// The patches at `level`.
    pub fn set(self, level: u32) -> PatchSet {
        let inlet = PatchSpec::inlet(level);
        match self {
            Patch::Inlet => PatchSet::fixed(vec![inlet]),
            Patch::Lobes => PatchSet::lobes(vec![], level),
            Patch::InletAndLobes => PatchSet::lobes(vec![inlet], level),
        }
    }
}

/// Where a patch lies and how it is coupled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchSpec {
    /// Its inlet: the whole-domain level's grid line nearest this `X`.
    pub x_start: f64,
    /// Its middle across the rolling direction: the grid line nearest this `Y` (0: symmetric
    /// about the axis; a tie rounds away from the domain's middle, so that `-Y` gives the
    /// mirror image), the patch moved into the domain where it would leave it.
    pub y_centre: f64,
    /// It spans `2^cells_level` cells of the whole-domain level in each direction: its own
    /// grid is level `cells_level` on its rectangle.
    pub cells_level: u32,
    /// The whole-domain nodes that take the patch's forcing: those at least this many cells
    /// inside its edge (1: every interior node; with 2 a ring of coarse equations under the
    /// patch made the rounds alternate).
    pub margin: usize,
    /// Width in whole-domain cells of the band around the patch over which the deformation
    /// by the outside pressure is taken at the patch's mesh ([`Surround::banded`]; 0: the
    /// wide cells split at the edge, [`Surround::new`]).
    ///
    /// [`Surround::banded`]: super::nested::Surround::banded
    /// [`Surround::new`]: super::nested::Surround::new
    pub band: usize,
}

impl PatchSpec {
    /// The heavy contact's inlet patch of the study: `-1.2` to about `-0.45` Hertzian radii on
    /// the heavy-load domain at any level (a quarter of the domain in each direction),
    /// interior forcing, a band of eight cells.
    pub fn inlet(level: u32) -> Self {
        PatchSpec {
            x_start: -1.2,
            y_centre: 0.0,
            cells_level: level - 1,
            margin: 1,
            band: 8,
        }
    }

    /// Whether this is a patch the composite at `params` can take.
    pub(super) fn check(&self, params: &Params) -> Result<(), SolveError> {
        if self.cells_level > params.level
            || self.cells_level < MIN_LEVEL
            || params.level > MAX_LEVEL
            || self.margin == 0
        {
            return Err(SolveError::InvalidParams(format!(
                "the composite grid takes a level up to {MAX_LEVEL}, a patch within the \
                 domain of level {MIN_LEVEL} or finer and a margin of at least one cell \
                 (level {}, patch level {}, margin {})",
                params.level, self.cells_level, self.margin
            )));
        }
        Ok(())
    }

    /// The patch's rectangle on `level`'s grid of `domain`, and its corner node there.
    pub fn rectangle(&self, domain: &Domain, level: u32) -> (Domain, [usize; 2]) {
        let coarse = Grid::level(domain, level);
        let cells = 1usize << self.cells_level;
        let nearest = |s: f64, n: usize| (s.round().max(0.0) as usize).min(n - cells);
        let i0 = nearest((self.x_start - coarse.x0) / coarse.hx, coarse.nx);
        // Rounded from the domain's middle, where `round` is symmetric in sign.
        let half = (coarse.ny / 2) as f64;
        let from_middle = ((self.y_centre - coarse.y0) / coarse.hy - half).round();
        let j0 = nearest(half + from_middle - (cells / 2) as f64, coarse.ny);
        let patch = Domain::spanning(
            [coarse.x(i0), coarse.x(i0 + cells)],
            [coarse.y(j0), coarse.y(j0 + cells)],
        );
        (patch, [i0, j0])
    }
}

/// The patches of a composite grid: rectangles given, and those the whole-domain solution
/// places.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchSet {
    /// Patches where they are given.
    pub fixed: Vec<PatchSpec>,
    /// Patches over the side lobes with this size and coupling, placed on the whole-domain
    /// level's minimum film ([`PatchSet::place`]; `x_start` and `y_centre` are set there).
    pub lobes: Option<PatchSpec>,
}

impl PatchSet {
    /// The patches `fixed`.
    pub fn fixed(fixed: Vec<PatchSpec>) -> Self {
        PatchSet { fixed, lobes: None }
    }

    /// `fixed` and the side lobes' patches of a quarter of the domain per direction at
    /// `level` (the inlet patch's size, a band of eight cells, interior forcing). Case 150
    /// at level 7: one such patch over a lobe gave that lobe's minimum film 0.6263 (Moes)
    /// against uniform level 8's 0.6292 and level 7's 0.4473 (docs/ACCURACY_NOTES.md,
    /// "Patches over the side lobes").
    pub fn lobes(fixed: Vec<PatchSpec>, level: u32) -> Self {
        PatchSet {
            fixed,
            lobes: Some(PatchSpec::inlet(level)),
        }
    }

    /// Whether every patch of the set is one the composite at `params` can take, before any
    /// solve (the lobes' by their size; where they lie is checked once they are placed).
    pub(super) fn check(&self, params: &Params) -> Result<(), SolveError> {
        self.fixed
            .iter()
            .chain(&self.lobes)
            .try_for_each(|spec| spec.check(params))
    }

    /// The levels of the set's patches (the lobes' before they are placed): the smallest
    /// bounds how many levels below the composite's own its estimate can solve.
    pub fn cells_levels(&self) -> impl Iterator<Item = u32> + '_ {
        self.fixed.iter().chain(&self.lobes).map(|s| s.cells_level)
    }

    /// The patches on `level`'s grid of `domain`, the lobes' placed by the whole-domain film
    /// `h` on that grid: centred along `X` on its minimum film, mirrored about the axis at
    /// the minimum's `|Y|` (one patch about the axis where the two would overlap), and moved
    /// downstream of a fixed patch they would overlap. Patches that still overlap are an
    /// error: a node takes the forcing of one patch.
    pub fn place(
        &self,
        domain: &Domain,
        level: u32,
        h: &[f64],
    ) -> Result<Vec<PatchSpec>, SolveError> {
        let mut specs = self.fixed.clone();
        let given: Vec<Domain> = specs.iter().map(|s| s.rectangle(domain, level).0).collect();
        if let Some(lobe) = self.lobes {
            let g = Grid::level(domain, level);
            let k = (0..g.len())
                .min_by(|&a, &b| h[a].total_cmp(&h[b]))
                .expect("a grid has nodes");
            let (x, y) = (g.x(k % g.px()), g.y(k / g.px()).abs());
            let cells = (1usize << lobe.cells_level) as f64;
            let (width, height) = (cells * g.hx, cells * g.hy);
            let centred = PatchSpec {
                x_start: x - 0.5 * width,
                y_centre: 0.0,
                ..lobe
            };
            let sides: &[f64] = if y < 0.5 * height { &[0.0] } else { &[y, -y] };
            for &y_centre in sides {
                let mut spec = PatchSpec {
                    y_centre,
                    ..centred
                };
                for fixed in &given {
                    if overlap(&spec.rectangle(domain, level).0, fixed) {
                        spec.x_start = fixed.x_end;
                    }
                }
                specs.push(spec);
            }
        }
        let rects: Vec<Domain> = specs.iter().map(|s| s.rectangle(domain, level).0).collect();
        for (n, a) in rects.iter().enumerate() {
            if let Some(b) = rects[n + 1..].iter().find(|b| overlap(a, b)) {
                return Err(SolveError::InvalidParams(format!(
                    "the composite grid's patches overlap ({a:?} and {b:?}): a node takes the \
                     forcing of one patch"
                )));
            }
        }
        Ok(specs)
    }
}

/// Whether the rectangles `a` and `b` share more than an edge.
fn overlap(a: &Domain, b: &Domain) -> bool {
    let tol = 1e-9;
    a.x_start < b.x_end - tol
        && b.x_start < a.x_end - tol
        && a.y_start() < b.y_end() - tol
        && b.y_start() < a.y_end() - tol
}

/// A converged patch as the whole-domain level takes it: its fields as a level, its film
/// constant, its corner node on the level, and the margin of its forcing.
pub(super) struct Carried<'a> {
    pub(super) fine: &'a LevelFields,
    pub(super) delta: f64,
    pub(super) corner: [usize; 2],
    pub(super) margin: usize,
}

/// Carries the converged patches into the whole-domain level `level`: at the level's nodes at
/// least `margin` cells inside a patch, the restricted pressure and the FAS forcing (`f`, and
/// the film-equation offset that reproduces the patch's film; elsewhere the film's right-hand
/// side is `geometry`); in the force balance, each patch's load less the level's own over it.
pub(super) fn carry_into(
    level: &mut LevelFields,
    patches: &[Carried],
    (model, geometry): (&Model, &[f64]),
) {
    let g = level.grid;
    let subs: Vec<LevelFields> = patches
        .iter()
        .map(|c| {
            let mut sub = LevelFields::new(c.fine.grid.coarser(), model);
            coarsen(c.fine, &mut sub, model, c.delta);
            sub
        })
        .collect();
    let forced = |sg: Grid, margin: usize| {
        (margin..=sg.ny - margin)
            .flat_map(move |jc| (margin..=sg.nx - margin).map(move |ic| (ic, jc)))
    };
    let at = |[i0, j0]: [usize; 2], ic: usize, jc: usize| g.idx(i0 + ic, j0 + jc);
    level.f.iter_mut().for_each(|v| *v = 0.0);
    for (c, sub) in patches.iter().zip(&subs) {
        let sg = sub.grid;
        for (ic, jc) in forced(sg, c.margin) {
            level.p[at(c.corner, ic, jc)] = sub.p[sg.idx(ic, jc)];
            level.f[at(c.corner, ic, jc)] = sub.f[sg.idx(ic, jc)];
        }
    }
    let mut w = g.zeros();
    level.deformation.apply(&level.p, &mut w);
    level.hrhs.copy_from_slice(geometry);
    let mut load_correction = 0.0;
    for (c, sub) in patches.iter().zip(&subs) {
        let sg = sub.grid;
        for (ic, jc) in forced(sg, c.margin) {
            let k = at(c.corner, ic, jc);
            level.hrhs[k] = sub.h[sg.idx(ic, jc)] - c.delta - w[k];
        }
        let mut under = sg.zeros();
        for jc in 0..=sg.ny {
            for ic in 0..=sg.nx {
                under[sg.idx(ic, jc)] = level.p[at(c.corner, ic, jc)];
            }
        }
        load_correction += c.fine.grid.integrate(&c.fine.p) - sg.integrate(&under);
    }
    level.load_correction = load_correction;
    level.rg = -(level.load - level.load_correction);
    level.invalidate();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lobes_are_placed_on_the_minimum_film_mirrored_and_clear_of_the_inlet() {
        // The heavy-load domain at level 5 (64 cells of 0.047 per direction), a film whose
        // minimum is at X 0.08, Y +-0.98 (case 150's side lobes): two patches of 16 cells
        // (0.75 wide) centred on it to within half a cell, one each side of the axis.
        let domain = Domain::heavy();
        let g = Grid::level(&domain, 5);
        let h = g.sample(|x, y| (x - 0.08).powi(2) + (y.abs() - 0.98).powi(2));
        let specs = Patch::InletAndLobes.set(5).place(&domain, 5, &h).unwrap();
        assert_eq!(specs.len(), 3);
        let rects: Vec<Domain> = specs.iter().map(|s| s.rectangle(&domain, 5).0).collect();
        let half_cell = 0.5 * g.hx + 1e-12;
        for (lobe, sign) in rects[1..].iter().zip([1.0, -1.0]) {
            let mid = 0.5 * (lobe.x_start + lobe.x_end);
            assert!((mid - 0.08).abs() <= half_cell, "{lobe:?}");
            assert!((lobe.y_centre - sign * 0.98).abs() <= half_cell, "{lobe:?}");
        }
        // A film whose minimum is on the axis, at X -0.9 inside the inlet patch's rectangle
        // (-1.22..-0.47 x 0.375 at this level): one patch about the axis, moved to start where
        // the inlet's ends.
        let on_axis = g.sample(|x, y| (x + 0.9).powi(2) + y * y);
        let specs = Patch::InletAndLobes
            .set(5)
            .place(&domain, 5, &on_axis)
            .unwrap();
        assert_eq!(specs.len(), 2);
        let (inlet, lobe) = (
            specs[0].rectangle(&domain, 5).0,
            specs[1].rectangle(&domain, 5).0,
        );
        assert_eq!(lobe.y_centre, 0.0);
        assert!(
            (lobe.x_start - inlet.x_end).abs() < 1e-12,
            "{lobe:?} after {inlet:?}"
        );
    }

    #[test]
    fn a_patch_and_its_mirror_lie_on_mirrored_grid_lines() {
        // The paper's domain at level 4 (mesh 0.125 across): a centre of +-0.9375 falls half
        // way between grid lines; rounded from the bottom edge the two patches of 8 cells came
        // out at 0.5..1.5 and -1.375..-0.375.
        let domain = Domain::default();
        let at = |y_centre: f64| {
            PatchSpec {
                x_start: -0.25,
                y_centre,
                cells_level: 3,
                margin: 1,
                band: 8,
            }
            .rectangle(&domain, 4)
            .0
        };
        for y in [0.9375, 0.9, 1.0, 1.6] {
            let (up, down) = (at(y), at(-y));
            assert!(
                (up.y_start() + down.y_end()).abs() < 1e-12,
                "{up:?} {down:?}"
            );
            assert!(
                (up.y_end() + down.y_start()).abs() < 1e-12,
                "{up:?} {down:?}"
            );
        }
        // Moved into the domain (|Y| <= 2) where it would leave it.
        assert!((at(1.9).y_end() - 2.0).abs() < 1e-12);
        assert_eq!(at(0.0).y_centre, 0.0);
    }

    #[test]
    fn overlapping_patches_are_refused() {
        let domain = Domain::heavy();
        let set = PatchSet::fixed(vec![PatchSpec::inlet(5), PatchSpec::inlet(5)]);
        let h = Grid::level(&domain, 5).zeros();
        assert!(matches!(
            set.place(&domain, 5, &h),
            Err(SolveError::InvalidParams(m)) if m.contains("overlap")
        ));
    }
}
