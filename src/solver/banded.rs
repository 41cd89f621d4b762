//! Banded linear systems by Gaussian elimination with partial pivoting: the line solves of
//! the line relaxation.

/// A square band matrix with `lower` sub-diagonals and `upper` super-diagonals, with room
/// for the fill-in that row interchanges create (`lower` more super-diagonals).
#[derive(Debug, Clone)]
pub struct BandMatrix {
    n: usize,
    lower: usize,
    width: usize,
    /// Row `i`, column `k` at `i * width + (k + lower - i)`, for `i - lower <= k <= i + upper + lower`.
    a: Vec<f64>,
    /// Whether an entry off the diagonal has been set since the last reset.
    coupled: bool,
}

impl BandMatrix {
    /// A zero matrix of order `n`.
    pub fn new(n: usize, lower: usize, upper: usize) -> Self {
        let width = 2 * lower + upper + 1;
        BandMatrix {
            n,
            lower,
            width,
            a: vec![0.0; n * width],
            coupled: false,
        }
    }

    /// Order of the matrix.
    pub fn order(&self) -> usize {
        self.n
    }

    /// Resets to zero for a system of order `n` (reusing the storage).
    pub fn reset(&mut self, n: usize) {
        self.n = n;
        self.coupled = false;
        self.a.clear();
        self.a.resize(n * self.width, 0.0);
    }

    #[inline]
    fn pos(&self, i: usize, k: usize) -> usize {
        i * self.width + (k + self.lower - i)
    }

    /// Sets entry `(i, k)`, which must lie in the band.
    #[inline]
    pub fn set(&mut self, i: usize, k: usize, v: f64) {
        let p = self.pos(i, k);
        self.a[p] = v;
        self.coupled |= i != k;
    }

    /// Entry `(i, k)` (zero outside the stored band).
    pub fn get(&self, i: usize, k: usize) -> f64 {
        if k + self.lower < i || k >= i + self.width - self.lower {
            0.0
        } else {
            self.a[self.pos(i, k)]
        }
    }

    /// Solves `A x = b` in place (`b` becomes `x`); destroys `A`. Returns false when a pivot
    /// is zero or non-finite (the caller then skips the line).
    pub fn solve(&mut self, b: &mut [f64]) -> bool {
        if !self.coupled {
            return self.solve_diagonal(b);
        }
        let b = &mut b[..self.n];
        match (self.lower, self.width) {
            // The line relaxation's band (3 lower, 2 upper diagonals): the elimination's loops
            // get constant lengths, unrolled, for a fifth of a cycle.
            (3, 9) => eliminate(&mut self.a, b, Fixed::<3, 9>),
            (lower, width) => eliminate(&mut self.a, b, Dynamic { lower, width }),
        }
    }

    /// [`BandMatrix::solve`] for a matrix with nothing set off its diagonal (the lines of
    /// the line relaxation outside the contact): the same quotients, without the
    /// elimination's passes over zeros.
    fn solve_diagonal(&self, b: &mut [f64]) -> bool {
        for (i, x) in b[..self.n].iter_mut().enumerate() {
            let d = self.a[i * self.width + self.lower];
            if !(d.abs() > 0.0 && d.is_finite()) {
                return false;
            }
            *x /= d;
        }
        b.iter().all(|v| v.is_finite())
    }
}

/// A band's lower bandwidth and row width, known when the code is compiled ([`Fixed`]) or
/// only when it runs ([`Dynamic`]): one elimination serves both.
trait Shape: Copy {
    fn lower(self) -> usize;
    fn width(self) -> usize;
}

#[derive(Debug, Clone, Copy)]
struct Fixed<const LOWER: usize, const WIDTH: usize>;

impl<const LOWER: usize, const WIDTH: usize> Shape for Fixed<LOWER, WIDTH> {
    #[inline(always)]
    fn lower(self) -> usize {
        LOWER
    }
    #[inline(always)]
    fn width(self) -> usize {
        WIDTH
    }
}

#[derive(Debug, Clone, Copy)]
struct Dynamic {
    lower: usize,
    width: usize,
}

impl Shape for Dynamic {
    fn lower(self) -> usize {
        self.lower
    }
    fn width(self) -> usize {
        self.width
    }
}

/// Gaussian elimination with partial pivoting of the band `a` (rows of `shape.width()`,
/// [`BandMatrix`]'s layout) against `b`, then back substitution: `b` becomes `x`.
///
/// Rows are addressed as slices of the band storage: entry `(r, k)` is `row_r[k + lower -
/// r]`, so row `r = i + s` holds column `k` at `s` places before row `i` does. Every row is
/// eliminated and swapped over its whole stored width, which near the last row includes
/// slots of columns past `n - 1`: they start at zero and are only ever combined with the
/// pivot rows' such slots, so they stay zero and are never read by the back substitution
/// (which stops at column `n - 1`); the other slots get the same operations in the same
/// order as when each row stopped at its last column.
#[inline(always)]
fn eliminate<S: Shape>(a: &mut [f64], b: &mut [f64], shape: S) -> bool {
    let (lower, width) = (shape.lower(), shape.width());
    let n = b.len();
    for i in 0..n {
        // Pivot: largest |a(r, i)| for r in i..=i+lower.
        let rmax = (i + lower).min(n - 1);
        let mut piv = i;
        let mut best = a[i * width + lower].abs();
        for r in i + 1..=rmax {
            let v = a[r * width + lower - (r - i)].abs();
            if v > best {
                best = v;
                piv = r;
            }
        }
        if !(best > 0.0 && best.is_finite()) {
            return false;
        }
        if piv != i {
            let s = piv - i;
            let (top, bottom) = a.split_at_mut(piv * width);
            let row_i = &mut top[i * width..(i + 1) * width];
            let row_p = &mut bottom[..width];
            for off in lower..width {
                std::mem::swap(&mut row_i[off], &mut row_p[off - s]);
            }
            b.swap(i, piv);
        }
        let (top, bottom) = a.split_at_mut((i + 1) * width);
        let row_i = &top[i * width..(i + 1) * width];
        let d = row_i[lower];
        for r in i + 1..=rmax {
            let s = r - i;
            let row_r = &mut bottom[(s - 1) * width..s * width];
            // Zero below the pivot (most rows of a line that is partly outside the
            // contact): nothing to eliminate, and no division to wait for.
            if row_r[lower - s] == 0.0 {
                continue;
            }
            let f = row_r[lower - s] / d;
            row_r[lower - s] = 0.0;
            for (x, y) in row_r[lower + 1 - s..width - s]
                .iter_mut()
                .zip(&row_i[lower + 1..width])
            {
                *x -= f * y;
            }
            b[r] -= f * b[i];
        }
    }
    for i in (0..n).rev() {
        let row = &a[i * width..(i + 1) * width];
        let mut s = b[i];
        for (a, x) in row[lower + 1..].iter().zip(&b[i + 1..]) {
            s -= a * x;
        }
        b[i] = s / row[lower];
    }
    b.iter().all(|v| v.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_band_system_that_needs_pivoting() {
        // A small diagonal with large sub-diagonals forces row interchanges.
        let n = 9;
        let (lo, up) = (3, 2);
        let mut m = BandMatrix::new(n, lo, up);
        let entry = |i: usize, k: usize| -> f64 {
            let d = k as f64 - i as f64;
            if i == k {
                1e-3 + 0.1 * i as f64
            } else {
                1.0 / (1.0 + d * d) + 0.05 * (i as f64) - 0.02 * k as f64
            }
        };
        let x: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin() + 0.3).collect();
        let mut b = vec![0.0; n];
        for i in 0..n {
            for k in i.saturating_sub(lo)..=(i + up).min(n - 1) {
                m.set(i, k, entry(i, k));
                b[i] += entry(i, k) * x[k];
            }
        }
        assert!(m.solve(&mut b));
        for i in 0..n {
            // Round-off of a well-conditioned 9x9 system.
            assert!((b[i] - x[i]).abs() < 1e-10, "{i}: {} vs {}", b[i], x[i]);
        }
    }

    #[test]
    fn a_diagonal_system_is_solved_like_a_banded_one() {
        let n = 7;
        let (mut diagonal, mut banded) = (BandMatrix::new(n, 3, 2), BandMatrix::new(n, 3, 2));
        let b: Vec<f64> = (0..n).map(|i| (i as f64 * 0.9).cos()).collect();
        let (mut x_diagonal, mut x_banded) = (b.clone(), b.clone());
        for i in 0..n {
            let d = 0.3 + 0.7 * i as f64;
            diagonal.set(i, i, d);
            banded.set(i, i, d);
        }
        // A zero set off the diagonal takes the general elimination.
        banded.set(3, 1, 0.0);
        assert!(diagonal.solve(&mut x_diagonal) && banded.solve(&mut x_banded));
        // The same quotients, bit for bit (the elimination subtracts only zeros).
        assert_eq!(x_diagonal, x_banded);
        let mut singular = BandMatrix::new(2, 3, 2);
        singular.set(0, 0, 1.0);
        assert!(!singular.solve(&mut [1.0, 1.0]));
    }

    #[test]
    fn the_fixed_band_eliminates_like_the_general_one() {
        // The relaxation's 3/2 band takes the compile-time shape; the same matrix through the
        // run-time shape must give the same bits, rows near the end (whose stored width
        // reaches past the last column) included.
        let n = 40;
        let mut a = BandMatrix::new(n, 3, 2);
        let mut b = vec![0.0; n];
        for i in 0..n {
            b[i] = (i as f64 * 0.37).sin();
            for k in i.saturating_sub(3)..=(i + 2).min(n - 1) {
                let v = ((i * 7 + k * 3) as f64 * 0.61).cos() + if i == k { 0.2 } else { 0.0 };
                a.set(i, k, v);
            }
        }
        let (mut fixed_a, mut fixed_b) = (a.a.clone(), b.clone());
        let (mut dynamic_a, mut dynamic_b) = (a.a.clone(), b.clone());
        assert!(eliminate(&mut fixed_a, &mut fixed_b, Fixed::<3, 9>));
        let shape = Dynamic { lower: 3, width: 9 };
        assert!(eliminate(&mut dynamic_a, &mut dynamic_b, shape));
        assert_eq!(fixed_b, dynamic_b);
        assert!(a.solve(&mut b));
        assert_eq!(b, fixed_b);
    }

    #[test]
    fn singular_system_is_reported() {
        let mut m = BandMatrix::new(3, 1, 1);
        let mut b = vec![1.0, 1.0, 1.0];
        assert!(!m.solve(&mut b));
    }
}
