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
        }
    }

    /// Order of the matrix.
    pub fn order(&self) -> usize {
        self.n
    }

    /// Resets to zero for a system of order `n` (reusing the storage).
    pub fn reset(&mut self, n: usize) {
        self.n = n;
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
        let n = self.n;
        let lower = self.lower;
        let last_col = |i: usize| (i + self.width - lower - 1).min(n - 1);
        for i in 0..n {
            // Pivot: largest |a(r, i)| for r in i..=i+lower.
            let rmax = (i + lower).min(n - 1);
            let mut piv = i;
            let mut best = self.a[self.pos(i, i)].abs();
            for r in i + 1..=rmax {
                let v = self.a[self.pos(r, i)].abs();
                if v > best {
                    best = v;
                    piv = r;
                }
            }
            if !(best > 0.0 && best.is_finite()) {
                return false;
            }
            if piv != i {
                for k in i..=last_col(i) {
                    let (pa, pb) = (self.pos(i, k), self.pos(piv, k));
                    self.a.swap(pa, pb);
                }
                b.swap(i, piv);
            }
            let d = self.a[self.pos(i, i)];
            for r in i + 1..=rmax {
                let pr = self.pos(r, i);
                let f = self.a[pr] / d;
                if f == 0.0 {
                    continue;
                }
                self.a[pr] = 0.0;
                for k in i + 1..=last_col(i) {
                    let (pi, pk) = (self.pos(i, k), self.pos(r, k));
                    self.a[pk] -= f * self.a[pi];
                }
                b[r] -= f * b[i];
            }
        }
        for i in (0..n).rev() {
            let mut s = b[i];
            for k in i + 1..=last_col(i) {
                s -= self.a[self.pos(i, k)] * b[k];
            }
            b[i] = s / self.a[self.pos(i, i)];
        }
        b.iter().all(|v| v.is_finite())
    }
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
    fn singular_system_is_reported() {
        let mut m = BandMatrix::new(3, 1, 1);
        let mut b = vec![1.0, 1.0, 1.0];
        assert!(!m.solve(&mut b));
    }
}
