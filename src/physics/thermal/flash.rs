//! Jaeger's moving heat source at high Peclet number: the surface temperature rise of a body
//! moving at speed `u` under a heat flux `q(x)` that is fixed in space,
//!
//! `T(x) = (1 / sqrt(pi k rho c u)) int_{-inf}^{x} q(s) / sqrt(x - s) ds`,
//!
//! the one-dimensional (normal to the surface) conduction of a surface element that has been
//! under the source for the time `(x - s)/u` (Jaeger 1942; Carslaw and Jaeger, "Conduction of
//! Heat in Solids", Sec. 10.7). It holds for Peclet numbers `u a / (2 kappa)` above about 5.
//!
//! On a uniform grid of spacing `dx` the flux is taken constant over each node's cell
//! `[x_k - dx/2, x_k + dx/2]` and the kernel integrated exactly over it: a uniform strip whose
//! edges are cell faces is reproduced exactly, and the weights depend on `i - k` only.

use super::{Solid, ThermalError};
use std::f64::consts::PI;

/// The flash-temperature operator of one body on one grid spacing.
#[derive(Debug, Clone)]
pub struct Flash {
    /// `sqrt(dx / (pi k rho c u))`, K m^2/W.
    scale: f64,
    /// The weights from the farthest to the nearest: `w_(n-1)`, ..., `w_1`, `w_0`, with `w_0 =
    /// sqrt(2)` (the node's own half cell) and `w_k = 2 (sqrt(k + 1/2) - sqrt(k - 1/2))`. Read
    /// in this order, the weights of node `i`'s upstream nodes `i - m`, ..., `i - 1` are one
    /// slice that runs the same way as the flux's ([`lane_dot`]).
    reversed: Vec<f64>,
}

/// Independent partial sums of an upstream sum. One running sum waits for its last addition
/// before each term: the thermal post-process of a level-8 solve took 0.47 s, a level-7 one
/// 0.053 s (2-core AMD EPYC, one thread, mineral oil A at 40 C, 3 GPa, 2 m/s), and on that
/// family the running sums were 5.3 % of the samples. Eight lanes, which the compiler makes
/// into vector multiply-adds, brought them to 2.3 % (docs/ACCURACY_NOTES.md, "Eight lanes").
const LANES: usize = 8;

/// `sum a_j b_j` over two slices of one length, in [`LANES`] partial sums (each in the
/// slices' order) added pairwise, then the rest in order: a fixed order, so the same bits
/// on every machine. An empty sum is `-0.0`, the neutral element of `f64`'s `Sum`.
fn lane_dot(a: &[f64], b: &[f64]) -> f64 {
    debug_assert_eq!(a.len(), b.len());
    let mut lanes = [-0.0; LANES];
    let (a_chunks, b_chunks) = (a.chunks_exact(LANES), b.chunks_exact(LANES));
    let rest = a_chunks.remainder().iter().zip(b_chunks.remainder());
    for (x, y) in a_chunks.zip(b_chunks) {
        for l in 0..LANES {
            lanes[l] += x[l] * y[l];
        }
    }
    let mut width = LANES;
    while width > 1 {
        width /= 2;
        for l in 0..width {
            lanes[l] += lanes[l + width];
        }
    }
    rest.fold(lanes[0], |sum, (x, y)| sum + x * y)
}

impl Flash {
    /// The operator of `solid` moving at `speed_m_s` on a grid of spacing `dx_m` with `nodes`
    /// nodes. An infinitely conducting solid gives zero temperatures.
    pub fn new(solid: &Solid, speed_m_s: f64, dx_m: f64, nodes: usize) -> Self {
        let reversed = (0..nodes)
            .rev()
            .map(|k| {
                if k == 0 {
                    std::f64::consts::SQRT_2
                } else {
                    let k = k as f64;
                    2.0 * ((k + 0.5).sqrt() - (k - 0.5).sqrt())
                }
            })
            .collect();
        Flash {
            scale: (dx_m / (PI * solid.k_rho_c() * speed_m_s)).sqrt(),
            reversed,
        }
    }

    /// The operator for surface `surface` (1 or 2) moving at `speed_m_s`, refused where the
    /// surface stands still.
    pub fn of_surface(
        surface: u8,
        solid: &Solid,
        speed_m_s: f64,
        dx_m: f64,
        nodes: usize,
    ) -> Result<Self, ThermalError> {
        if speed_m_s > 0.0 && speed_m_s.is_finite() {
            Ok(Self::new(solid, speed_m_s, dx_m, nodes))
        } else {
            Err(ThermalError::StationarySurface { surface, speed_m_s })
        }
    }

    /// The rise at node `i` due to the flux upstream of it, `q[0..i]` (K).
    pub fn upstream(&self, q: &[f64], i: usize) -> f64 {
        self.upstream_from(q, i, 0)
    }

    /// [`Flash::upstream`] where `q` is zero before node `first`: the sum without its zero
    /// terms, `w_1 q_(i-1) + ... + w_m q_(i-m)` with `m = i - first`, in [`LANES`] partial
    /// sums ([`lane_dot`]).
    pub fn upstream_from(&self, q: &[f64], i: usize, first: usize) -> f64 {
        let m = i.saturating_sub(first);
        let nearest = self.reversed.len() - 1;
        self.scale * lane_dot(&self.reversed[nearest - m..nearest], &q[i - m..i])
    }

    /// The rise at a node per unit of its own flux (K m^2/W).
    pub fn own(&self) -> f64 {
        self.scale * self.reversed[self.reversed.len() - 1]
    }

    /// The rise at every node under the flux `q` (K).
    pub fn temperatures(&self, q: &[f64]) -> Vec<f64> {
        (0..q.len())
            .map(|i| self.upstream(q, i) + self.own() * q[i])
            .collect()
    }
}

/// Jaeger's closed form for a uniform strip of flux `q` from `x_start` to `x_end` on a body
/// of `solid` moving at `speed_m_s`: `T(x) = 2 q (sqrt(x - x_start) - sqrt(x - x_end)) /
/// sqrt(pi k rho c u)` (each root taken where its argument is positive). Its largest value,
/// at the trailing edge, is `2 q sqrt(2 b) / sqrt(pi k rho c u)` for a strip `2b` wide, the
/// `1.13 q b / (k sqrt(Pe))` of Jaeger with `Pe = u b / (2 kappa)`.
pub fn jaeger_uniform_strip(
    solid: &Solid,
    speed_m_s: f64,
    q: f64,
    x_start: f64,
    x_end: f64,
    x: f64,
) -> f64 {
    let root = |d: f64| if d > 0.0 { d.sqrt() } else { 0.0 };
    2.0 * q * (root(x - x_start) - root(x - x_end)) / (PI * solid.k_rho_c() * speed_m_s).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lane_sum_is_the_sum_in_order_to_round_off() {
        // Fluxes with zeros before `first` and a sign-varied, many-decade body, every node
        // (every count of terms: whole lanes, a rest, none): the lane sum is the same
        // products summed in another order, so it may differ from the sum in order by
        // round-off alone: each order's error is within (terms - 1) eps / 2 of the sum of the
        // terms' magnitudes (Higham, "Accuracy and Stability of Numerical Algorithms", 4.2),
        // their difference within (terms - 1) eps of it. A term left out or counted twice
        // is the size of a term.
        let n = 97;
        let f = Flash::new(&Solid::STEEL, 11.9, 1e-6, n);
        let first = 9;
        let q: Vec<f64> = (0..n)
            .map(|k| {
                if k < first {
                    0.0
                } else {
                    (0.7 * k as f64).sin() * 10f64.powi((k % 13) as i32)
                }
            })
            .collect();
        let w = |k: usize| f.reversed[n - 1 - k];
        for i in 0..n {
            let terms: Vec<f64> = (1..=i).map(|k| w(k) * q[i - k]).collect();
            let in_order: f64 = terms.iter().sum();
            let size: f64 = terms.iter().map(|t| t.abs()).sum();
            // With the zero terms before `first` and without them (other lanes, other bits).
            for lanes in [f.upstream_from(&q, i, first), f.upstream(&q, i)].map(|t| t / f.scale) {
                assert!(
                    (lanes - in_order).abs() <= i.saturating_sub(1) as f64 * f64::EPSILON * size,
                    "node {i}: {lanes} vs {in_order}"
                );
            }
        }
        // An empty sum keeps its sign.
        assert!(lane_dot(&[], &[]).is_sign_negative());
    }

    #[test]
    fn a_uniform_strip_gives_jaegers_closed_form() {
        // A strip of 2b = 0.4 mm at 1 GW/m^2 on steel at 5 m/s, edges on cell faces: the
        // piecewise-constant flux is the strip itself and the cell integrals are exact, so
        // only round-off remains (the sums run over some 400 terms: 1e-12 relative).
        let solid = Solid::STEEL;
        let (u, q, dx) = (5.0, 1e9, 1e-6);
        let n = 1000;
        let x = |i: usize| i as f64 * dx;
        let (first, last) = (200, 599);
        let flux: Vec<f64> = (0..n)
            .map(|i| if (first..=last).contains(&i) { q } else { 0.0 })
            .collect();
        let t = Flash::new(&solid, u, dx, n).temperatures(&flux);
        let (start, end) = (x(first) - 0.5 * dx, x(last) + 0.5 * dx);
        let t_max = jaeger_uniform_strip(&solid, u, q, start, end, end);
        for (i, ti) in t.iter().enumerate() {
            let exact = jaeger_uniform_strip(&solid, u, q, start, end, x(i));
            assert!(
                (ti - exact).abs() < 1e-12 * t_max,
                "node {i}: {ti} vs {exact}"
            );
        }
        // The classical form of the maximum: 1.128 q b / (k sqrt(Pe)), Pe = u b / (2 kappa).
        let b = 0.5 * (end - start);
        let pe = u * b / (2.0 * solid.diffusivity());
        let classical = 2.0 / PI.sqrt() * q * b / (solid.conductivity_w_mk * pe.sqrt());
        assert!(
            (t_max / classical - 1.0).abs() < 1e-12,
            "{t_max} vs {classical}"
        );
    }

    #[test]
    fn a_smooth_flux_converges_at_the_order_of_the_rule() {
        // A Hertzian-shaped flux q0 sqrt(1 - (x/b)^2), sampled at the nodes: the rule's error
        // at the trailing edge is first order in dx (the cells at the square-root edges
        // misplace O(dx) of the flux): it falls by more than 1.8 per halving (2 expected), and
        // at 128 cells across the contact (the level-7 resolution) it is 0.54 %, held below
        // 0.6 %.
        let solid = Solid::STEEL;
        let (u, q0, b) = (10.0, 1e9, 2e-4);
        let at_edge = |cells: usize| {
            let dx = 2.0 * b / cells as f64;
            let n = cells + 1;
            let flux: Vec<f64> = (0..n)
                .map(|i| {
                    let s = -b + i as f64 * dx;
                    q0 * (1.0 - (s / b).powi(2)).max(0.0).sqrt()
                })
                .collect();
            *Flash::new(&solid, u, dx, n)
                .temperatures(&flux)
                .last()
                .unwrap()
        };
        let reference = at_edge(1 << 14);
        let errors: Vec<f64> = [64, 128, 256]
            .iter()
            .map(|&c| (at_edge(c) / reference - 1.0).abs())
            .collect();
        assert!(errors[1] < 6e-3, "{errors:?}");
        assert!(
            errors[0] / errors[1] > 1.8 && errors[1] / errors[2] > 1.8,
            "{errors:?}"
        );
    }

    #[test]
    fn a_standing_surface_is_refused() {
        assert!(matches!(
            Flash::of_surface(1, &Solid::STEEL, 0.0, 1e-6, 10),
            Err(ThermalError::StationarySurface { surface: 1, .. })
        ));
    }
}
