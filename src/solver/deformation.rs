//! Elastic deformation, the integral of Eq. (6):
//! `W(X, Y) = 1/(pi K) int int P(X', Y') / sqrt(kappa^2 (X - X')^2 + (Y - Y')^2) dX' dY'`,
//! discretised with the pressure piecewise constant on the cells around the nodes, so that
//! `W_ij = sum_kl D(|i-k|, |j-l|) P_kl` with the cell integrals `D` in closed form.
//!
//! The sum is a discrete convolution. [`Deformation`] evaluates it exactly by FFT on a
//! zero-padded periodic grid (no approximation beyond round-off); [`direct_sum`] is the
//! obviously correct O(n^4) reference the tests hold it to.

use super::grid::Grid;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::f64::consts::PI;
use std::sync::{Arc, Mutex};

/// `int_0^x int_0^y dx dy / sqrt(x^2 + y^2)` for `x, y >= 0`:
/// `x asinh(y/x) + y asinh(x/y)`.
fn corner(x: f64, y: f64) -> f64 {
    let a = if x > 0.0 { x * (y / x).asinh() } else { 0.0 };
    let b = if y > 0.0 { y * (x / y).asinh() } else { 0.0 };
    a + b
}

/// The same integral for any signs (odd in `x` and in `y`, since `1/r` is even).
fn corner_signed(x: f64, y: f64) -> f64 {
    x.signum() * y.signum() * corner(x.abs(), y.abs())
}

/// Influence coefficients `D(k, l)` of one grid, `k <= nx`, `l <= ny`.
#[derive(Debug, Clone)]
pub struct Kernel {
    /// Columns (`k`) per row.
    width: usize,
    /// `D(k, l)` at `l * width + k`.
    values: Vec<f64>,
}

impl Kernel {
    /// Cell integrals of `1 / (pi K sqrt(kappa^2 X^2 + Y^2))` for the grid's mesh sizes.
    /// With `u = kappa X` the cell is `kappa hx` wide and the integral carries `1/kappa`.
    pub fn new(grid: &Grid, kappa: f64, ell_k: f64) -> Self {
        let width = grid.nx + 2;
        let rows = grid.ny + 2;
        let hu = kappa * grid.hx;
        let hy = grid.hy;
        let scale = 1.0 / (PI * ell_k * kappa);
        let mut values = vec![0.0; width * rows];
        for l in 0..rows {
            let (y1, y2) = ((l as f64 - 0.5) * hy, (l as f64 + 0.5) * hy);
            for k in 0..width {
                let (x1, x2) = ((k as f64 - 0.5) * hu, (k as f64 + 0.5) * hu);
                let cell = corner_signed(x2, y2) - corner_signed(x1, y2) - corner_signed(x2, y1)
                    + corner_signed(x1, y1);
                values[l * width + k] = scale * cell;
            }
        }
        Kernel { width, values }
    }

    /// `D(|k|, |l|)`: the deformation at a node per unit pressure at a node `(k, l)` away.
    #[inline]
    pub fn at(&self, k: isize, l: isize) -> f64 {
        self.values[l.unsigned_abs() * self.width + k.unsigned_abs()]
    }
}

/// `W = D * P` by direct summation over every pair of nodes: the reference for tests.
pub fn direct_sum(grid: &Grid, kernel: &Kernel, p: &[f64]) -> Vec<f64> {
    let mut w = grid.zeros();
    for j in 0..grid.py() {
        for i in 0..grid.px() {
            let mut s = 0.0;
            for l in 0..grid.py() {
                for k in 0..grid.px() {
                    s += kernel.at(i as isize - k as isize, j as isize - l as isize)
                        * p[grid.idx(k, l)];
                }
            }
            w[grid.idx(i, j)] = s;
        }
    }
    w
}

/// Exact fast evaluation of the deformation on one grid by zero-padded FFT convolution.
///
/// The pressure vanishes on the boundary nodes, so the sources are the interior nodes
/// `1..nx` and the targets all nodes `0..=nx`: every offset lies in `-(nx-1)..=nx-1`, and a
/// periodic grid of `2 nx` points holds the linear convolution without wrap-around.
///
/// Rows are transformed real-to-complex (only the `ny - 1` rows that carry pressure), the
/// half spectrum is kept column-major so that the column transforms run on contiguous data,
/// and only the `ny + 1` rows of the grid are transformed back.
pub struct Deformation {
    grid: Grid,
    n1: usize,
    n2: usize,
    /// What depends on the mesh and the ellipse alone, shared ([`influence`]).
    shared: Arc<Influence>,
    /// Work space: one padded real row, one half-spectrum row, the column-major spectrum.
    row: Vec<f64>,
    half: Vec<Complex<f64>>,
    cols: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

/// The part of a grid's deformation that depends only on its mesh (`nx`, `ny`, `hx`, `hy`)
/// and the ellipse (`kappa`, `K`): the influence coefficients, their spectrum and the FFT
/// plans. It is the same for every solve on that mesh (the cases of a family, and the
/// circular contacts of a sweep on one domain), and making it (an `asinh` per coefficient,
/// a transform, the plans) was 2-3 % of a sweep's time, so it is made once ([`influence`]).
struct Influence {
    kernel: Kernel,
    /// Kernel spectrum, column-major: `(kx, ky)` at `kx * n2 + ky`, `kx <= n1/2`.
    spectrum: Vec<Complex<f64>>,
    row_fwd: Arc<dyn RealToComplex<f64>>,
    row_inv: Arc<dyn ComplexToReal<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
}

/// The mesh and ellipse an [`Influence`] is made for, by their bits.
type InfluenceKey = (usize, usize, u64, u64, u64, u64);

/// Influences kept: the last few meshes (a family's levels 4-8 and its neighbours'; level 8
/// holds about 10 MB).
const INFLUENCES_KEPT: usize = 24;

/// The [`Influence`] of `grid` for `kappa`, `ell_k`: made, or taken from the last ones made
/// (the same bits either way: the same arithmetic on the same inputs).
fn influence(grid: &Grid, kappa: f64, ell_k: f64) -> Arc<Influence> {
    static MADE: Mutex<Vec<(InfluenceKey, Arc<Influence>)>> = Mutex::new(Vec::new());
    let key = (
        grid.nx,
        grid.ny,
        grid.hx.to_bits(),
        grid.hy.to_bits(),
        kappa.to_bits(),
        ell_k.to_bits(),
    );
    let made = |m: &[(InfluenceKey, Arc<Influence>)]| {
        m.iter()
            .find(|(k, _)| *k == key)
            .map(|(_, i)| Arc::clone(i))
    };
    if let Some(i) = made(&MADE.lock().unwrap_or_else(|e| e.into_inner())) {
        return i;
    }
    let new = Arc::new(Influence::new(grid, kappa, ell_k));
    let mut m = MADE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(i) = made(&m) {
        return i;
    }
    if m.len() >= INFLUENCES_KEPT {
        m.remove(0);
    }
    m.push((key, Arc::clone(&new)));
    new
}

impl Influence {
    /// Plans the FFTs and transforms the kernel of `grid`.
    fn new(grid: &Grid, kappa: f64, ell_k: f64) -> Self {
        let kernel = Kernel::new(grid, kappa, ell_k);
        let (n1, n2) = (2 * grid.nx, 2 * grid.ny);
        let mut real_planner = RealFftPlanner::<f64>::new();
        let mut planner = FftPlanner::new();
        let mut i = Influence {
            kernel,
            spectrum: Vec::new(),
            row_fwd: real_planner.plan_fft_forward(n1),
            row_inv: real_planner.plan_fft_inverse(n1),
            col_fwd: planner.plan_fft_forward(n2),
            col_inv: planner.plan_fft_inverse(n2),
        };
        // The periodic kernel: offset k at index k, offset -k at index n - k.
        let wrap = |k: usize, n: usize, m: usize| {
            if k <= m {
                k as isize
            } else {
                k as isize - n as isize
            }
        };
        let mut image = vec![0.0; n1 * n2];
        for l in 0..n2 {
            for k in 0..n1 {
                image[l * n1 + k] = i.kernel.at(wrap(k, n1, grid.nx), wrap(l, n2, grid.ny));
            }
        }
        let mut d = Deformation::with(*grid, Arc::new(i));
        d.forward(|l| Some(&image[l * n1..(l + 1) * n1]));
        let norm = 1.0 / (n1 * n2) as f64;
        let spectrum = d.cols.iter().map(|c| c * norm).collect();
        i = Arc::into_inner(d.shared).expect("the influence is not shared yet");
        i.spectrum = spectrum;
        i
    }
}

impl std::fmt::Debug for Deformation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Deformation")
            .field("grid", &self.grid)
            .field("n1", &self.n1)
            .field("n2", &self.n2)
            .finish()
    }
}

impl Deformation {
    /// The evaluator of `grid` for the ellipse `kappa`, `K` (its influence made once per
    /// mesh, [`influence`]).
    pub fn new(grid: &Grid, kappa: f64, ell_k: f64) -> Self {
        Self::with(*grid, influence(grid, kappa, ell_k))
    }

    /// The evaluator of `grid` on `shared`, with its own work space.
    fn with(grid: Grid, shared: Arc<Influence>) -> Self {
        let (n1, n2) = (2 * grid.nx, 2 * grid.ny);
        let scratch_len = shared
            .col_fwd
            .get_inplace_scratch_len()
            .max(shared.col_inv.get_inplace_scratch_len());
        let zero = Complex::new(0.0, 0.0);
        Deformation {
            grid,
            n1,
            n2,
            shared,
            row: vec![0.0; n1],
            half: vec![zero; n1 / 2 + 1],
            cols: vec![zero; (n1 / 2 + 1) * n2],
            scratch: vec![zero; scratch_len],
        }
    }

    /// The influence coefficients (for the relaxation's Jacobian).
    pub fn kernel(&self) -> &Kernel {
        &self.shared.kernel
    }

    /// The grid this evaluator serves.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// 2-D forward transform into `cols` of the padded rows `row(l)` (`None`: a zero row).
    fn forward<'a>(&mut self, row: impl Fn(usize) -> Option<&'a [f64]>) {
        let (n2, h) = (self.n2, self.n1 / 2 + 1);
        self.cols
            .iter_mut()
            .for_each(|c| *c = Complex::new(0.0, 0.0));
        for l in 0..n2 {
            let Some(r) = row(l) else { continue };
            self.row.copy_from_slice(r);
            // Lengths match by construction; an error here is a programming defect.
            self.shared
                .row_fwd
                .process(&mut self.row, &mut self.half)
                .expect("row FFT lengths");
            for (kx, v) in self.half.iter().enumerate() {
                self.cols[kx * n2 + l] = *v;
            }
        }
        for kx in 0..h {
            self.shared
                .col_fwd
                .process_with_scratch(&mut self.cols[kx * n2..(kx + 1) * n2], &mut self.scratch);
        }
    }

    /// `W = D * P` at every node of the grid (boundary values of `p` are ignored: they are
    /// zero by the boundary condition).
    pub fn apply(&mut self, p: &[f64], w: &mut [f64]) {
        let g = self.grid;
        let (n2, h) = (self.n2, self.n1 / 2 + 1);
        self.cols
            .iter_mut()
            .for_each(|c| *c = Complex::new(0.0, 0.0));
        for j in 1..g.ny {
            self.row.iter_mut().for_each(|v| *v = 0.0);
            self.row[1..g.nx].copy_from_slice(&p[g.idx(1, j)..g.idx(g.nx, j)]);
            self.shared
                .row_fwd
                .process(&mut self.row, &mut self.half)
                .expect("row FFT lengths");
            for (kx, v) in self.half.iter().enumerate() {
                self.cols[kx * n2 + j] = *v;
            }
        }
        for kx in 0..h {
            let col = &mut self.cols[kx * n2..(kx + 1) * n2];
            self.shared
                .col_fwd
                .process_with_scratch(col, &mut self.scratch);
            col.iter_mut()
                .zip(&self.shared.spectrum[kx * n2..(kx + 1) * n2])
                .for_each(|(c, s)| *c *= s);
            self.shared
                .col_inv
                .process_with_scratch(col, &mut self.scratch);
        }
        for j in 0..g.py() {
            for kx in 0..h {
                self.half[kx] = self.cols[kx * n2 + j];
            }
            // The inverse real transform ignores the imaginary parts of the DC and Nyquist
            // terms, which are round-off here.
            self.half[0].im = 0.0;
            self.half[h - 1].im = 0.0;
            self.shared
                .row_inv
                .process(&mut self.half, &mut self.row)
                .expect("row FFT lengths");
            w[g.idx(0, j)..=g.idx(g.nx, j)].copy_from_slice(&self.row[..=g.nx]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::hertz::{elliptic_integrals, kappa_from_ratio, shape_factor, Hertz};
    use crate::solver::grid::Domain;

    #[test]
    fn cell_integral_of_the_centre_cell_is_the_closed_form() {
        // Square cell of side h around the singularity: int int 1/r = 4 h asinh(1) (exact).
        let g = Grid {
            nx: 4,
            ny: 4,
            x0: 0.0,
            y0: 0.0,
            hx: 0.1,
            hy: 0.1,
        };
        let k = Kernel::new(&g, 1.0, PI / 2.0);
        let expect = 4.0 * 0.1 * 1f64.asinh() / (PI * PI / 2.0);
        assert!((k.at(0, 0) - expect).abs() < 1e-15);
        // Far cells tend to the point value h^2 / (pi K r).
        let far = 0.01 / (PI * PI / 2.0 * 0.3);
        assert!((k.at(3, 0) / far - 1.0).abs() < 5e-3);
    }

    #[test]
    fn fft_convolution_equals_the_direct_sum() {
        // Exactness of the zero-padded FFT: any pressure with zero boundary values, an
        // elliptical kernel; round-off only (1e-12 of the largest value).
        let d = Domain {
            x_start: -2.0,
            x_end: 1.0,
            y_half: 1.2,
            y_centre: 0.0,
        };
        let g = Grid::level(&d, 3);
        let kappa = 0.4;
        let (ell_k, _) = elliptic_integrals(kappa);
        let p = g.sample(|x, y| {
            let r = (1.0 - x * x - y * y).max(0.0);
            r.sqrt() * (1.0 + 0.3 * (3.0 * x).sin() * y)
        });
        let mut p0 = p.clone();
        for j in 0..g.py() {
            for i in 0..g.px() {
                if i == 0 || j == 0 || i == g.nx || j == g.ny {
                    p0[g.idx(i, j)] = 0.0;
                }
            }
        }
        let mut fast = Deformation::new(&g, kappa, ell_k);
        let mut w = g.zeros();
        fast.apply(&p0, &mut w);
        let slow = direct_sum(&g, fast.kernel(), &p0);
        let max = slow.iter().cloned().fold(0.0, f64::max);
        for (a, b) in w.iter().zip(&slow) {
            assert!((a - b).abs() < 1e-12 * max, "{a} vs {b}");
        }
    }

    /// The dry Hertz oracle: the Hertzian pressure's deformation plus the gap geometry is
    /// flat inside the contact ellipse, at the value `-Delta = 1` (the approach `c`).
    fn dry_contact_flatness(d_ratio: f64, level: u32) -> (f64, f64) {
        let kappa = kappa_from_ratio(d_ratio);
        let (ell_k, _) = elliptic_integrals(kappa);
        let s = shape_factor(kappa);
        let dom = Domain {
            x_start: -1.5,
            x_end: 1.5,
            y_half: 1.5,
            y_centre: 0.0,
        };
        let g = Grid::level(&dom, level);
        let p = g.sample(Hertz::pressure);
        let mut def = Deformation::new(&g, kappa, ell_k);
        let mut w = g.zeros();
        def.apply(&p, &mut w);
        let (mut lo, mut hi) = (f64::MAX, f64::MIN);
        for j in 0..g.py() {
            for i in 0..g.px() {
                let (x, y) = (g.x(i), g.y(j));
                if x * x + y * y < 0.8 * 0.8 {
                    let v = w[g.idx(i, j)] + s * x * x + (1.0 - s) * y * y;
                    lo = lo.min(v);
                    hi = hi.max(v);
                }
            }
        }
        (lo, hi)
    }

    #[test]
    fn dry_hertz_contact_is_flat_inside_the_ellipse() {
        // Inside 0.8 of the ellipse the sum W + S X^2 + (1-S) Y^2 must equal 1 (the approach)
        // up to the midpoint-rule error of the piecewise-constant pressure, second order in h:
        // measured spreads are 1.3e-4..3.2e-4 at level 5 and 3e-5..4.5e-5 at level 6
        // (h = 3/128). A wrong shape factor or kernel scale gives errors of order 1e-2.
        for d in [1.0, 0.5, 0.2] {
            let (lo5, hi5) = dry_contact_flatness(d, 5);
            let (lo6, hi6) = dry_contact_flatness(d, 6);
            assert!(hi6 - lo6 < 1e-4, "D = {d}: spread {}", hi6 - lo6);
            // Second order would give 0.25; 0.4 leaves room for the edge of the ellipse.
            assert!(
                hi6 - lo6 < 0.4 * (hi5 - lo5),
                "D = {d}: no second-order convergence"
            );
            let mid = 0.5 * (lo6 + hi6);
            assert!((mid - 1.0).abs() < 1e-4, "D = {d}: approach {mid}");
        }
    }
}
