//! Uniform grids and the fields that live on them.
//!
//! Level `n` has `2^(n+1)` intervals per direction (the paper's "64x64" at level 5), nodes
//! `0..=nx` by `0..=ny`, stored with `i` (along `X`, the rolling direction) fastest so that a
//! line of constant `j` is contiguous.

use crate::physics::case::Problem;
use crate::physics::film::hc_nijenbanning;

/// The rectangular computational domain in `X = x/a`, `Y = y/b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Domain {
    /// Inlet boundary.
    pub x_start: f64,
    /// Outlet boundary.
    pub x_end: f64,
    /// Half-width in `Y` (the domain is `y_centre - y_half..y_centre + y_half`).
    pub y_half: f64,
    /// Middle of the `Y` range: 0 for a whole domain (the contact is symmetric about the
    /// rolling axis); a composite grid's patch may lie off the axis (`point::patch`).
    pub y_centre: f64,
}

impl Default for Domain {
    /// `-2.5 <= X <= 1.5`, `-2 <= Y <= 2`: the domain that reproduces the paper's Table 4
    /// (its level-6 and level-7 film and friction to 3-4 digits; the wider
    /// `-4.5..1.5 x -3..3` of Venner and Lubrecht's book gives a 30 % thinner level-6 film).
    fn default() -> Self {
        Domain {
            x_start: -2.5,
            x_end: 1.5,
            y_half: 2.0,
            y_centre: 0.0,
        }
    }
}

/// Moes load below which [`Domain::for_load`] takes the wide domain.
pub const LIGHT_LOAD_M: f64 = 300.0;

/// Moes load from which [`Domain::for_load`] takes the heavy-load domain.
pub const HEAVY_LOAD_M: f64 = 4000.0;

/// The largest `Delta / (m r^2)` the far-field edge may see ([`Domain::for_far_field`]): the
/// asymptote's second-order error there is about its square. With the fitted far field and
/// [`FAR_FIELD_LOAD_SHARE`], a battery of eleven cases (M 1-1000, L 1-60) moves film and
/// friction by at most 0.5 % when the inlet and sides are doubled at levels 7/8; at 0.15 two
/// of them missed by 1-3 % (`docs/DOMAIN_NOTES.md`).
pub const FAR_FIELD_GAP_RATIO: f64 = 0.06;

/// The largest estimated share of the load the far field may carry outside the domain
/// ([`Domain::for_far_field`]): at 0.15 M 5, L 10's friction moved 1.2 % with the domain,
/// at 0.08 0.14 % (`docs/DOMAIN_NOTES.md`).
pub const FAR_FIELD_LOAD_SHARE: f64 = 0.08;

impl Domain {
    /// The rectangle `x[0]..x[1]` by `y[0]..y[1]`. One about the axis to round-off is about it
    /// exactly, its half-width `-y[0]` (the bits a whole domain's grid gives).
    pub fn spanning(x: [f64; 2], y: [f64; 2]) -> Self {
        let y_centre = 0.5 * (y[0] + y[1]);
        let y_half = 0.5 * (y[1] - y[0]);
        let (y_half, y_centre) = if y_centre.abs() <= 1e-12 * y_half {
            (-y[0], 0.0)
        } else {
            (y_half, y_centre)
        };
        Domain {
            x_start: x[0],
            x_end: x[1],
            y_half,
            y_centre,
        }
    }

    /// The lowest `Y`.
    pub fn y_start(&self) -> f64 {
        self.y_centre - self.y_half
    }

    /// The highest `Y`.
    pub fn y_end(&self) -> f64 {
        self.y_centre + self.y_half
    }

    /// The domain a problem is solved on, by every command and pipeline (through
    /// [`crate::solver::point::Params::for_problem`], which puts the fitted far field on its
    /// edge): [`Domain::for_far_field`].
    pub fn for_problem(problem: &Problem) -> Domain {
        Domain::for_far_field(problem)
    }

    /// The domain a problem needs with the far-field edge (the rule of
    /// [`Domain::for_problem`], see `docs/DOMAIN_NOTES.md`): the base domain of its load
    /// ([`Domain::for_load`]), its inlet and sides pushed out where the estimated film constant `Delta` would make the
    /// rigid gap `m r^2` at the edge less than `Delta / FAR_FIELD_GAP_RATIO`, so that the
    /// far-field asymptote holds there (`point::far_field`), in steps of 0.5.
    /// `Delta` is estimated before the solve as the Nijenbanning-Venner-Moes central film
    /// (in `h/c`) less the Hertzian approach (1): it is the formula that covers the
    /// rigid regime, and it overestimates the Roelands films (a larger domain, never a
    /// smaller one).
    pub fn for_far_field(problem: &Problem) -> Self {
        Domain::for_far_field_with(problem, FAR_FIELD_GAP_RATIO, FAR_FIELD_LOAD_SHARE)
    }

    /// [`Domain::for_far_field`] with its two knobs given (the domain study's): the edge's
    /// largest `Delta / (m r^2)`, and the largest estimated share of the load outside, about
    /// `2 g(0) / R` with `g(0) = 0.8 lambda` (the circle's) against `2 pi / 3` (infinite
    /// turns it off).
    pub fn for_far_field_with(problem: &Problem, gap_ratio: f64, load_share: f64) -> Self {
        let g = &problem.groups;
        let base = Domain::for_load(g.m);
        let delta = hc_nijenbanning(g.m, g.l, g.d) / g.moes_film_scale - 1.0;
        let by_share = 1.6 * g.lambda / (load_share * 2.0 * std::f64::consts::PI / 3.0);
        let reach = |gap_factor: f64| {
            let by_gap = if delta > 0.0 {
                (delta / (gap_ratio * gap_factor)).sqrt()
            } else {
                0.0
            };
            (2.0 * by_gap.max(by_share)).ceil() / 2.0
        };
        // The outlet: the rigid regime's pressure reaches downstream of the centre too (at
        // M 0.83 an outlet at X = 1.5 instead of 13.5 moves the film 3 % and the friction
        // 20 %, DOMAIN_NOTES); half the inlet's reach, provisionally.
        let inlet = reach(problem.shape);
        Domain {
            x_start: base.x_start.min(-inlet),
            x_end: base.x_end.max((inlet / 2.0).ceil()),
            y_half: base.y_half.max(reach(1.0 - problem.shape)),
            y_centre: 0.0,
        }
    }

    /// This domain with its inlet and sides doubled at the same mesh size one level finer
    /// (the inlet grows by the domain's length, the half-width doubles, the outlet stays):
    /// the domain-convergence check of `docs/DOMAIN_NOTES.md` and `repro accuracy`.
    pub fn doubled(&self) -> Domain {
        Domain {
            x_start: 2.0 * self.x_start - self.x_end,
            x_end: self.x_end,
            y_half: 2.0 * self.y_half,
            y_centre: 0.0,
        }
    }

    /// The domain for a contact of Moes load `m`: the paper's ([`Domain::default`], which
    /// reproduces Table 4) from [`LIGHT_LOAD_M`] up, the wide one below. Lightly loaded
    /// contacts build up pressure far upstream and spread sideways; on the paper's domain the
    /// highly viscous ones among them (L = 15 at M = 50-200) end in a period-2 oscillation of a
    /// few side nodes that never meets the tolerance, while on the wide domain they converge
    /// in 20-30 cycles. Where both converge (M = 100-500) they agree within 1 % in
    /// sliding `mu-bar` at level 7. From [`HEAVY_LOAD_M`] up it is the narrower
    /// [`Domain::heavy`].
    pub fn for_load(m: f64) -> Self {
        if m < LIGHT_LOAD_M {
            Domain::wide()
        } else if m < HEAVY_LOAD_M {
            Domain::default()
        } else {
            Domain::heavy()
        }
    }

    /// `-1.75 <= X <= 1.25`, `-1.5 <= Y <= 1.5`: for heavily loaded contacts (M >= 4000),
    /// whose pressure outside the Hertzian circle lives in a short inlet zone, while their
    /// film (1e-3 of the approach `c` at M = 1e4) closes at the side lobes on the paper's
    /// domain at level 7 for want of resolution there. The same level resolves it with 3/4 of
    /// the mesh size. Measured (mineral oil A at 3 GPa, M = 4 326 and 6 666, levels 7 and
    /// 8, both domains): the Richardson-extrapolated central film agrees with the paper's
    /// domain within 0.2 % and sliding `mu-bar` within 0.03 %, the largest pressure within
    /// 0.15 of the boundary is 4e-5 `p_H`, and the level-7 errors against the extrapolated
    /// values fall from 28 % to 17 % (film) and from 1.1 % to 0.6 % (`mu-bar`); on the most
    /// viscous of them (Rx/Ry = 1/2, M = 5 008, L = 12.9) 0.4 % and 0.03 %, 8e-5 `p_H` at the
    /// inlet boundary. The heaviest Table 2 load (M = 19 205) still closes at level 7 here
    /// and opens at level 8 (the solver's film refinement). `X = 0` is not a node of this
    /// domain: the central film is interpolated ([`Grid::at_centre`]).
    pub fn heavy() -> Self {
        Domain {
            x_start: -1.75,
            x_end: 1.25,
            y_half: 1.5,
            y_centre: 0.0,
        }
    }

    /// `-4.5 <= X <= 1.5`, `-3 <= Y <= 3` (Venner and Lubrecht's circular contact): a longer
    /// inlet, fully flooded for lightly loaded contacts (M < 100), where the paper's domain
    /// thins the film by a few per cent.
    pub fn wide() -> Self {
        Domain {
            x_start: -4.5,
            x_end: 1.5,
            y_half: 3.0,
            y_centre: 0.0,
        }
    }
}

/// One uniform grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Intervals along `X`.
    pub nx: usize,
    /// Intervals along `Y`.
    pub ny: usize,
    /// `X` of node `i = 0`.
    pub x0: f64,
    /// `Y` of node `j = 0`.
    pub y0: f64,
    /// Mesh size along `X`.
    pub hx: f64,
    /// Mesh size along `Y`.
    pub hy: f64,
}

impl Grid {
    /// The grid of level `level` on `domain`: `2^(level+1)` intervals per direction.
    pub fn level(domain: &Domain, level: u32) -> Self {
        let n = 1usize << (level + 1);
        Grid {
            nx: n,
            ny: n,
            x0: domain.x_start,
            y0: domain.y_start(),
            hx: (domain.x_end - domain.x_start) / n as f64,
            hy: 2.0 * domain.y_half / n as f64,
        }
    }

    /// The level of a grid of [`Grid::level`] (`2^(level+1)` intervals along `X`).
    pub fn level_number(&self) -> u32 {
        self.nx.trailing_zeros() - 1
    }

    /// The next coarser grid (every second node).
    pub fn coarser(&self) -> Self {
        Grid {
            nx: self.nx / 2,
            ny: self.ny / 2,
            hx: 2.0 * self.hx,
            hy: 2.0 * self.hy,
            ..*self
        }
    }

    /// The same grid with twice the intervals along `Y` (the side lobes' minimum film is made
    /// across the rolling direction, docs/ACCURACY_NOTES.md, "The error by direction").
    pub fn refined_y(&self) -> Self {
        Grid {
            ny: 2 * self.ny,
            hy: 0.5 * self.hy,
            ..*self
        }
    }

    /// Whether this is a level refined across the rolling direction ([`Grid::refined_y`] of a
    /// square level: twice its intervals along `Y`).
    pub fn is_refined_y(&self) -> bool {
        self.ny == 2 * self.nx
    }

    /// The square level under a grid refined across the rolling direction (every second node
    /// along `Y`); the grid itself otherwise.
    pub fn unrefined_y(&self) -> Self {
        if !self.is_refined_y() {
            return *self;
        }
        Grid {
            ny: self.ny / 2,
            hy: 2.0 * self.hy,
            ..*self
        }
    }

    /// How many of this grid's intervals make one of `coarse`'s, along `X` and along `Y`: 2
    /// (full coarsening) or 1 (that direction kept, semi-coarsening).
    pub fn ratio_to(&self, coarse: &Grid) -> (usize, usize) {
        let ratio = |fine: usize, coarse: usize| {
            debug_assert!(fine == coarse || fine == 2 * coarse, "{fine} over {coarse}");
            fine / coarse
        };
        (ratio(self.nx, coarse.nx), ratio(self.ny, coarse.ny))
    }

    /// Nodes along `X`.
    pub fn px(&self) -> usize {
        self.nx + 1
    }

    /// Nodes along `Y`.
    pub fn py(&self) -> usize {
        self.ny + 1
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.px() * self.py()
    }

    /// Always false: a grid has at least one node.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Flat index of node `(i, j)`.
    #[inline]
    pub fn idx(&self, i: usize, j: usize) -> usize {
        j * self.px() + i
    }

    /// `X` of column `i`.
    #[inline]
    pub fn x(&self, i: usize) -> f64 {
        self.x0 + i as f64 * self.hx
    }

    /// `Y` of row `j`.
    #[inline]
    pub fn y(&self, j: usize) -> f64 {
        self.y0 + j as f64 * self.hy
    }

    /// The node nearest to `(x, y)`.
    pub fn nearest(&self, x: f64, y: f64) -> (usize, usize) {
        let i = ((x - self.x0) / self.hx).round().clamp(0.0, self.nx as f64) as usize;
        let j = ((y - self.y0) / self.hy).round().clamp(0.0, self.ny as f64) as usize;
        (i, j)
    }

    /// A field's value at `X = Y = 0`: at its node where it is one, otherwise linear in `X`
    /// between the two nodes beside it on the row `Y = 0` (nearest in `Y`).
    pub fn at_centre(&self, field: &[f64]) -> f64 {
        let (_, j) = self.nearest(0.0, 0.0);
        let s = (-self.x0 / self.hx).clamp(0.0, self.nx as f64);
        let i = (s.floor() as usize).min(self.nx - 1);
        let t = s - i as f64;
        if t < 1e-9 {
            return field[self.idx(i, j)];
        }
        if t > 1.0 - 1e-9 {
            return field[self.idx(i + 1, j)];
        }
        (1.0 - t) * field[self.idx(i, j)] + t * field[self.idx(i + 1, j)]
    }

    /// A field of zeros.
    pub fn zeros(&self) -> Vec<f64> {
        vec![0.0; self.len()]
    }

    /// A field sampled from `f(X, Y)`.
    pub fn sample(&self, f: impl Fn(f64, f64) -> f64) -> Vec<f64> {
        let mut v = self.zeros();
        for j in 0..self.py() {
            for i in 0..self.px() {
                v[self.idx(i, j)] = f(self.x(i), self.y(j));
            }
        }
        v
    }

    /// The domain this grid covers.
    pub fn domain(&self) -> Domain {
        Domain::spanning(
            [self.x0, self.x0 + self.nx as f64 * self.hx],
            [self.y0, self.y0 + self.ny as f64 * self.hy],
        )
    }

    /// The indices of the boundary nodes.
    pub fn boundary(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.py()).flat_map(move |j| {
            let edge_row = j == 0 || j == self.ny;
            let step = if edge_row { 1 } else { self.nx };
            (0..self.px()).step_by(step).map(move |i| self.idx(i, j))
        })
    }

    /// `f(X, Y)` at the boundary nodes, zero inside.
    pub fn sample_boundary(&self, f: impl Fn(f64, f64) -> f64) -> Vec<f64> {
        let mut v = vec![0.0; self.len()];
        for k in self.boundary() {
            let (i, j) = (k % self.px(), k / self.px());
            v[k] = f(self.x(i), self.y(j));
        }
        v
    }

    /// The trapezoidal rule `int v dX dY` over the domain: the interior nodes in storage
    /// order, then half of each edge node and a quarter of each corner. Where the boundary
    /// values are zero this is the plain `sum v hx hy`, bit for bit.
    pub fn integrate(&self, v: &[f64]) -> f64 {
        let mut sum = 0.0;
        for j in 1..self.ny {
            for i in 1..self.nx {
                sum += v[self.idx(i, j)];
            }
        }
        let mut edges = 0.0;
        for i in 1..self.nx {
            edges += v[self.idx(i, 0)] + v[self.idx(i, self.ny)];
        }
        for j in 1..self.ny {
            edges += v[self.idx(0, j)] + v[self.idx(self.nx, j)];
        }
        let corners = v[self.idx(0, 0)]
            + v[self.idx(self.nx, 0)]
            + v[self.idx(0, self.ny)]
            + v[self.idx(self.nx, self.ny)];
        (sum + 0.5 * edges + 0.25 * corners) * self.hx * self.hy
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The doubled domain one level finer has the same mesh and contains the original.
    #[test]
    fn a_doubled_domain_one_level_finer_keeps_the_mesh() {
        let d = Domain::for_load(20.0);
        let (a, b) = (Grid::level(&d, 6), Grid::level(&d.doubled(), 7));
        assert!((a.hx - b.hx).abs() < 1e-12 && (a.hy - b.hy).abs() < 1e-12);
        assert_eq!((b.x0, b.y0), (-10.5, -6.0));
    }

    #[test]
    fn levels_have_the_paper_point_counts_and_the_origin_is_a_node() {
        let d = Domain::default();
        for (level, n) in [(5, 64), (7, 256), (8, 512)] {
            let g = Grid::level(&d, level);
            assert_eq!((g.nx, g.ny), (n, n));
            let (i, j) = g.nearest(0.0, 0.0);
            assert!(g.x(i).abs() < 1e-12 && g.y(j).abs() < 1e-12);
        }
        let g = Grid::level(&d, 6);
        assert_eq!(g.coarser(), Grid::level(&d, 5));
        assert_eq!(g.ratio_to(&g.coarser()), (2, 2));
        let y = g.refined_y();
        assert_eq!((y.nx, y.ny, y.hx, y.hy), (g.nx, 2 * g.ny, g.hx, 0.5 * g.hy));
        assert_eq!(y.ratio_to(&g), (1, 2));
        assert!(y.is_refined_y() && !g.is_refined_y());
        assert_eq!((y.unrefined_y(), g.unrefined_y()), (g, g));
        // The refined grid's even rows are the coarse grid's rows.
        assert_eq!(y.y(2 * 5), g.y(5));
    }

    #[test]
    fn the_domain_follows_the_load() {
        assert_eq!(Domain::for_load(LIGHT_LOAD_M - 1.0), Domain::wide());
        assert_eq!(Domain::for_load(LIGHT_LOAD_M), Domain::default());
        assert_eq!(Domain::for_load(HEAVY_LOAD_M - 1.0), Domain::default());
        assert_eq!(Domain::for_load(HEAVY_LOAD_M), Domain::heavy());
    }

    #[test]
    fn the_centre_value_is_the_node_or_linear_between_two() {
        // A field linear in X takes its exact value at X = 0 whether 0 is a node (paper's
        // domain) or falls a third of a cell past one (heavy-load domain, X0 = -1.75).
        for d in [Domain::default(), Domain::heavy()] {
            let g = Grid::level(&d, 5);
            let mut f = g.zeros();
            for j in 0..=g.ny {
                for i in 0..=g.nx {
                    f[g.idx(i, j)] = 2.0 + 3.0 * g.x(i);
                }
            }
            assert!((g.at_centre(&f) - 2.0).abs() < 1e-12, "{d:?}");
        }
    }
}
