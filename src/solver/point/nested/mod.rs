//! A nested domain (prototype of issue 39): the contact solved on a smaller domain at a finer
//! mesh, inside a converged solution of the whole domain that gives it its surroundings.
//!
//! The nested solve keeps the whole domain's solution fixed outside its own rectangle (a
//! one-way nesting): its edge takes that solution's pressure, its force balance the load that
//! solution carries outside, and its film the deformation by that outside pressure. The
//! rectangle's edges lie on the whole domain's grid lines, so the split of the wide
//! solution's cells between inside and outside is exact up to the half cell along the edge,
//! which the nested grid's own boundary nodes cover ([`Surround::new`]).

use super::model::Model;
use crate::physics::case::Problem;
use crate::physics::hertz::DIMENSIONLESS_LOAD as LOAD;
use crate::solver::deformation::Deformation;
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::Friction;

/// A converged whole-domain solution as the surroundings of a nested rectangle.
pub struct Surround {
    wide: Grid,
    p: Vec<f64>,
    h: Vec<f64>,
    /// The deformation at the wide nodes by the pressure outside the nested rectangle.
    w_outside: Vec<f64>,
    /// Each wide node's share that the nested grid's interior cells do not cover (the
    /// outside, and the half cell of the nested grid along its edge).
    cover_share: Vec<f64>,
    inner: Domain,
    outside_load: f64,
    /// The wide solution's film constant: the nested solve's start.
    delta: f64,
    /// A deformation at the nested grid's own mesh added to the film offset at its nodes
    /// (the composite grid's band, [`super::composite`]).
    near: Option<(Grid, Vec<f64>)>,
}

impl std::fmt::Debug for Surround {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Surround")
            .field("wide", &self.wide)
            .field("inner", &self.inner)
            .field("outside_load", &self.outside_load)
            .finish()
    }
}

/// The inside share of a wide coordinate `x` in `lo..hi` along one axis: 1 inside, 0 outside,
/// `edge` on the edge.
fn inside_share(x: f64, lo: f64, hi: f64, tol: f64, edge: f64) -> f64 {
    if (x - lo).abs() < tol || (x - hi).abs() < tol {
        edge
    } else if x > lo && x < hi {
        1.0
    } else {
        0.0
    }
}

/// Catmull-Rom weights of the four nodes around `t` in `0..1`.
fn cubic_weights(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ]
}

/// Bicubic (Catmull-Rom) interpolation of the nodal `field` of `g` at `(x, y)`; at the
/// grid's edge the stencil repeats the edge node (exact at every node).
fn bicubic(g: &Grid, field: &[f64], x: f64, y: f64) -> f64 {
    let locate = |s: f64, n: usize| {
        let i = (s.floor() as isize).clamp(0, n as isize - 1);
        let nodes = [i - 1, i, i + 1, i + 2].map(|m| m.clamp(0, n as isize) as usize);
        (nodes, cubic_weights(s - i as f64))
    };
    let (ii, wx) = locate((x - g.x0) / g.hx, g.nx);
    let (jj, wy) = locate((y - g.y0) / g.hy, g.ny);
    let mut v = 0.0;
    for (j, wyb) in jj.iter().zip(wy) {
        for (i, wxa) in ii.iter().zip(wx) {
            v += wxa * wyb * field[g.idx(*i, *j)];
        }
    }
    v
}

impl Surround {
    /// The surroundings of the rectangle `inner` (its edges on grid lines of `wide`) from the
    /// wide solution `p`, `h`, `delta`, for a nested top grid of mesh `(hx, hy)`.
    pub fn new(
        problem: &Problem,
        wide: &Grid,
        (p, h, delta): (&[f64], &[f64], f64),
        inner: &Domain,
        fine: (f64, f64),
    ) -> Self {
        let tol = 1e-6 * wide.hx.min(wide.hy);
        let (y0, y1) = (inner.y_start(), inner.y_end());
        // On the edge, the nested grid's interior cells start half a fine cell inside.
        let (ex, ey) = (0.5 - 0.5 * fine.0 / wide.hx, 0.5 - 0.5 * fine.1 / wide.hy);
        let mut load_share = wide.zeros();
        let mut cover_share = wide.zeros();
        for j in 0..wide.py() {
            for i in 0..wide.px() {
                let (x, y) = (wide.x(i), wide.y(j));
                let k = wide.idx(i, j);
                // A wide boundary node's trapezoid cell is its inner half already.
                let (hx_edge, hy_edge) = (
                    if i == 0 || i == wide.nx { 1.0 } else { 0.5 },
                    if j == 0 || j == wide.ny { 1.0 } else { 0.5 },
                );
                let (lx, ly) = (
                    inside_share(x, inner.x_start, inner.x_end, tol, hx_edge),
                    inside_share(y, y0, y1, tol, hy_edge),
                );
                load_share[k] = 1.0 - lx * ly;
                let (cx, cy) = (
                    inside_share(x, inner.x_start, inner.x_end, tol, ex),
                    inside_share(y, y0, y1, tol, ey),
                );
                cover_share[k] = 1.0 - cx * cy;
            }
        }
        let g = &problem.groups;
        let masked: Vec<f64> = p.iter().zip(&cover_share).map(|(a, b)| a * b).collect();
        let mut w_outside = wide.zeros();
        Deformation::new(wide, g.kappa, problem.ell_k).apply(&masked, &mut w_outside);
        let inside: Vec<f64> = p
            .iter()
            .zip(&load_share)
            .map(|(a, s)| a * (1.0 - s))
            .collect();
        let outside_load = LOAD - wide.integrate(&inside);
        Surround {
            wide: *wide,
            p: p.to_vec(),
            h: h.to_vec(),
            w_outside,
            cover_share,
            inner: *inner,
            outside_load,
            delta,
            near: None,
        }
    }

    /// The surroundings of a patch `fine` of `wide`'s grid at half its mesh, its corner at
    /// the wide node `corner`, whose edge may lie where the pressure is high (the composite
    /// grid, [`super::composite`]): the deformation by the pressure outside the patch is
    /// computed at the patch's own mesh over a band of `band` wide cells around it (the wide
    /// pressure interpolated there and on the patch's edge, which its own FFT leaves out), and
    /// by the wide grid only beyond the band. Splitting the wide cells at a high-pressure edge
    /// ([`Surround::new`]) errs there by about a heavy contact's film. Its outside load and
    /// friction are those outside the band's rectangle: the patch's are [`Surround::new`]'s.
    pub fn banded(
        problem: &Problem,
        wide: &Grid,
        state: (&[f64], &[f64], f64),
        (fine, [i0, j0]): (&Grid, [usize; 2]),
        band: usize,
    ) -> Self {
        let cells = fine.nx / 2;
        debug_assert!(
            (2.0 * fine.hx - wide.hx).abs() < 1e-9 && (2.0 * fine.hy - wide.hy).abs() < 1e-9,
            "a patch has half the wide mesh"
        );
        let b = band
            .min(i0)
            .min(j0)
            .min(wide.nx - i0 - cells)
            .min(wide.ny - j0 - cells);
        let ext_domain = Domain::spanning(
            [wide.x(i0 - b), wide.x(i0 + cells + b)],
            [wide.y(j0 - b), wide.y(j0 + cells + b)],
        );
        let ext = Grid {
            nx: fine.nx + 4 * b,
            ny: fine.ny + 4 * b,
            x0: fine.x0 - 2.0 * b as f64 * fine.hx,
            y0: fine.y0 - 2.0 * b as f64 * fine.hy,
            ..*fine
        };
        let far = Surround::new(problem, wide, state, &ext_domain, (fine.hx, fine.hy));
        // The band's pressure: the wide one, interpolated, outside the patch's interior.
        let offset = 2 * b as isize;
        let p_band = {
            let mut v = ext.zeros();
            for j in 0..=ext.ny {
                for i in 0..=ext.nx {
                    let (pi, pj) = (i as isize - offset, j as isize - offset);
                    let interior =
                        pi > 0 && pj > 0 && pi < fine.nx as isize && pj < fine.ny as isize;
                    if !interior {
                        v[ext.idx(i, j)] = far.pressure(ext.x(i), ext.y(j));
                    }
                }
            }
            v
        };
        let g = &problem.groups;
        let mut w_band = ext.zeros();
        Deformation::new(&ext, g.kappa, problem.ell_k).apply(&p_band, &mut w_band);
        let near = fine.sample(|x, y| {
            let (i, j) = ext.nearest(x, y);
            w_band[ext.idx(i, j)]
        });
        far.with_near_field(*fine, near)
    }

    /// These surroundings with `w` on `grid` added to the film offset at `grid`'s nodes
    /// (nearest node; the nested grids are `grid` and its coarsenings).
    pub fn with_near_field(mut self, grid: Grid, w: Vec<f64>) -> Self {
        self.near = Some((grid, w));
        self
    }

    /// The wide solution's pressure at `(x, y)` (the nested edge), never negative.
    pub fn pressure(&self, x: f64, y: f64) -> f64 {
        bicubic(&self.wide, &self.p, x, y).max(0.0)
    }

    /// The deformation at `(x, y)` by the pressure outside the nested rectangle.
    pub fn film_offset(&self, x: f64, y: f64) -> f64 {
        let near = self.near.as_ref().map_or(0.0, |(g, w)| {
            let (i, j) = g.nearest(x, y);
            w[g.idx(i, j)]
        });
        bicubic(&self.wide, &self.w_outside, x, y) + near
    }

    /// The load the wide solution carries outside the nested rectangle.
    pub fn outside_load(&self) -> f64 {
        self.outside_load
    }

    /// The wide solution's film constant `Delta`.
    pub fn delta(&self) -> f64 {
        self.delta
    }

    /// The nested rectangle.
    pub fn inner(&self) -> Domain {
        self.inner
    }

    /// The sliding `mu-bar` the wide solution adds outside the nested grid's interior cells,
    /// over the loaded film `H <= h_limit` (Eq. 8, over the applied load).
    pub fn outside_sliding(&self, problem: &Problem, h_limit: f64) -> f64 {
        self.outside_friction(problem, h_limit, false).0
    }

    /// [`Surround::outside_sliding`] and, where `rolling`, the rolling part likewise (the
    /// Poiseuille shear on the surface, central differences, as the solver's own).
    pub fn outside_friction(
        &self,
        problem: &Problem,
        h_limit: f64,
        rolling: bool,
    ) -> (f64, Option<f64>) {
        Surround::outside_all(&[self], problem, h_limit, rolling)
    }

    /// [`Surround::outside_friction`] outside every rectangle of `parts`: surroundings of one
    /// wide solution whose rectangles do not overlap (a composite grid's patches), so that a
    /// wide node's share outside them all is the product of its shares outside each.
    pub fn outside_all(
        parts: &[&Surround],
        problem: &Problem,
        h_limit: f64,
        rolling: bool,
    ) -> (f64, Option<f64>) {
        let model = Model::new(problem);
        let first = parts[0];
        let g = &first.wide;
        let (mut sliding, mut poiseuille) = (0.0, 0.0);
        for j in 1..g.ny {
            for i in 1..g.nx {
                let k = g.idx(i, j);
                let (p, h) = (first.p[k], first.h[k]);
                let share: f64 = parts.iter().map(|s| s.cover_share[k]).product();
                if p <= 0.0 || h > h_limit || share == 0.0 {
                    continue;
                }
                sliding += share * model.mean_shear_stress(p, h);
                poiseuille += share * h * (first.p[k + 1] - first.p[k - 1]) / (2.0 * g.hx);
            }
        }
        let area = g.hx * g.hy / LOAD;
        let scale = problem.groups.rolling_stress_scale();
        (sliding * area, rolling.then_some(scale * poiseuille * area))
    }

    /// `inner`, the friction of the grid inside, plus these surroundings' outside it
    /// ([`Surround::outside_friction`]; rolling where `inner` has it).
    pub fn plus_outside(&self, problem: &Problem, h_limit: f64, inner: Friction) -> Friction {
        Surround::plus_outside_all(&[self], problem, h_limit, inner)
    }

    /// `inner`, the friction of the grids inside the rectangles of `parts`, plus the wide
    /// solution's outside them all ([`Surround::outside_all`]).
    pub fn plus_outside_all(
        parts: &[&Surround],
        problem: &Problem,
        h_limit: f64,
        inner: Friction,
    ) -> Friction {
        let (sliding, rolling) =
            Surround::outside_all(parts, problem, h_limit, inner.rolling.is_some());
        Friction {
            sliding: inner.sliding + sliding,
            rolling: inner.rolling.map(|r| r + rolling.unwrap_or(0.0)),
        }
    }
}

#[cfg(test)]
mod tests;
