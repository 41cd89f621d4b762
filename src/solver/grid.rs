//! Uniform grids and the fields that live on them.
//!
//! Level `n` has `2^(n+1)` intervals per direction (the paper's "64x64" at level 5), nodes
//! `0..=nx` by `0..=ny`, stored with `i` (along `X`, the rolling direction) fastest so that a
//! line of constant `j` is contiguous.

/// The rectangular computational domain in `X = x/a`, `Y = y/b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Domain {
    /// Inlet boundary.
    pub x_start: f64,
    /// Outlet boundary.
    pub x_end: f64,
    /// Half-width in `Y` (the domain is `-y_half..y_half`).
    pub y_half: f64,
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
        }
    }
}

/// Moes load below which [`Domain::for_load`] takes the wide domain.
pub const LIGHT_LOAD_M: f64 = 300.0;

impl Domain {
    /// The domain for a contact of Moes load `m`: the paper's ([`Domain::default`], which
    /// reproduces Table 4) from [`LIGHT_LOAD_M`] up, the wide one below. Lightly loaded
    /// contacts build up pressure far upstream and spread sideways; on the paper's domain the
    /// highly viscous ones among them (L = 15 at M = 50-200) end in a period-2 oscillation of a
    /// few side nodes that never meets the tolerance, while on the wide domain they converge
    /// in 20-30 cycles. Where both converge (M = 100-500) they agree within 1 % in
    /// sliding `mu-bar` at level 7.
    pub fn for_load(m: f64) -> Self {
        if m < LIGHT_LOAD_M {
            Domain::wide()
        } else {
            Domain::default()
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
            y0: -domain.y_half,
            hx: (domain.x_end - domain.x_start) / n as f64,
            hy: 2.0 * domain.y_half / n as f64,
        }
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

    /// Trapezoid-free sum `sum v hx hy` (boundary values are zero for the pressure).
    pub fn integrate(&self, v: &[f64]) -> f64 {
        v.iter().sum::<f64>() * self.hx * self.hy
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
    }
}
