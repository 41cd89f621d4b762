//! The flooded inlet beyond the computational domain: the pressure's asymptote far from the
//! contact, the boundary values it gives the domain's edge and the load it carries outside.
//!
//! Far from the contact the gap is the rigid one, `H ~ S X^2 + (1 - S) Y^2`, the pressure
//! is small, and Eq. (1) becomes the Reynolds equation of an isoviscous fluid in the
//! reduced pressure `q = int_0^P dP' / eta_bar(P')` (exact for a Newtonian, incompressible
//! fluid; density and the Eyring correction of the conductances enter at relative order
//! `P` and `tau_m^2`, both vanishing far out). In `X`, `Y' = Y / kappa` that equation is
//! isotropic, `div(H^3 grad q) = lambda dH/dX`, with `H = r^2 m(theta)`,
//! `m = S cos^2 theta + (1 - S) kappa^2 sin^2 theta`, and it has the similarity solution
//! `q = g(theta) / r^3`:
//!
//! `(m^3 g')' - 9 m^3 g = 2 lambda S cos(theta)`.
//!
//! Upstream the pressure is positive; the film cavitates (Reynolds' condition `g = g' = 0`)
//! at the angle `psi = phi` from the upstream axis on either side, which the solution fixes
//! together with its amplitude. For the circle `g = 0.8 lambda (cos psi + sin(phi)
//! cosh(3 psi) / (3 sinh(3 phi)))` with `tan(phi) = -3 tanh(3 phi)`, `phi = 108.4` degrees:
//! the pressurised far field wraps a little past the normal to the rolling direction.
//!
//! The domain's edge takes its pressure from this asymptote instead of `P = 0`, and the
//! load the asymptote carries outside the domain is taken off the force balance: cutting the
//! far field off at the edge moves a fraction `~ 2 g(0) / (x_start * LOAD)` of the load
//! into the contact, a 1/distance error that made the friction of light, viscous contacts
//! depend on the domain by tens of per cent. The leading correction to the asymptote is the
//! film constant, relative order `Delta / (m r^2)`.

use super::nested::Surround;
use crate::physics::viscosity::Viscosity;
use crate::solver::grid::{Domain, Grid};
use std::sync::Arc;

/// Most refits of a fitted far field ([`super::Edge::FittedFarField`]) per level, each followed by
/// the cycles or a Newton-Krylov solve with the new edge.
pub(super) const FAR_FIELD_ROUNDS: usize = 8;
/// A fitted far field counts as settled when its fit moves the amplitude by less than this,
/// relative ...
pub(super) const FAR_FIELD_SETTLED: f64 = 1e-4;

/// Points of the tabulated angular profile `g` on `[0, phi]`.
const TABLE: usize = 512;
/// RK4 steps on `[0, pi]` of the search for the cavitation angle.
const SEARCH_STEPS: usize = 4096;

/// The far-field pressure of one problem.
#[derive(Debug, Clone)]
pub(crate) struct FarField {
    /// Cavitation angle from the upstream axis, in the `(X, Y')` plane.
    phi: f64,
    /// `g(psi)` at `psi = k phi / TABLE`, for `lambda`.
    g: Vec<f64>,
    /// `g'(psi)` at the same points.
    dg: Vec<f64>,
    /// The film constant's correction `g1` (the reduced pressure is
    /// `g / r^3 + Delta g1 / r^5`), at the same points.
    g1: Vec<f64>,
    /// `g1'` at the same points.
    dg1: Vec<f64>,
    /// Factor on the a-priori amplitude (`lambda`): 1 unless fitted to a solution
    /// ([`FarField::fit`]).
    amplitude: f64,
    /// The last fit on a grid: its `nx`, the amplitude it started from and the one it
    /// fitted, for the secant step of the next fit on that grid ([`FarField::fit`]).
    last_fit: Option<(usize, f64, f64)>,
    kappa: f64,
    viscosity: Viscosity,
    /// A wide solution that replaces the asymptote around a nested domain ([`Surround`]).
    surround: Option<Arc<Surround>>,
}

/// The gap's angular factor `m(psi) = S cos^2 + (1 - S) kappa^2 sin^2` and its derivative.
fn gap_factor(shape: f64, kappa2: f64, psi: f64) -> (f64, f64) {
    let (s, c) = psi.sin_cos();
    (
        shape * c * c + (1.0 - shape) * kappa2 * s * s,
        2.0 * s * c * ((1.0 - shape) * kappa2 - shape),
    )
}

/// `m(psi)^3`.
fn m3(shape: f64, kappa2: f64, psi: f64) -> f64 {
    gap_factor(shape, kappa2, psi).0.powi(3)
}

/// One RK4 step of the pair `(f, v = m^3 f')` of `(m^3 f')' - c m^3 f = force(psi)` from
/// `psi` over `dpsi`.
fn rk4(
    m3: &dyn Fn(f64) -> f64,
    c: f64,
    force: &dyn Fn(f64) -> f64,
    psi: f64,
    dpsi: f64,
    y: [f64; 2],
) -> [f64; 2] {
    let f = |t: f64, y: [f64; 2]| {
        let m = m3(t);
        [y[1] / m, c * m * y[0] + force(t)]
    };
    let k1 = f(psi, y);
    let k2 = f(
        psi + 0.5 * dpsi,
        [y[0] + 0.5 * dpsi * k1[0], y[1] + 0.5 * dpsi * k1[1]],
    );
    let k3 = f(
        psi + 0.5 * dpsi,
        [y[0] + 0.5 * dpsi * k2[0], y[1] + 0.5 * dpsi * k2[1]],
    );
    let k4 = f(psi + dpsi, [y[0] + dpsi * k3[0], y[1] + dpsi * k3[1]]);
    [
        y[0] + dpsi / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
        y[1] + dpsi / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
    ]
}

/// The solution of `(m^3 f')' - c m^3 f = force` on `[0, phi]` with `f'(0) = 0` and
/// `f(phi) = 0`, as `(f, f')` at `TABLE + 1` equal steps: the homogeneous solution from
/// `(1, 0)` and the forced one from `(0, 0)`, combined.
fn tabulate(
    m3: &dyn Fn(f64) -> f64,
    c: f64,
    force: &dyn Fn(f64) -> f64,
    phi: f64,
) -> (Vec<f64>, Vec<f64>) {
    let h = phi / TABLE as f64;
    let zero = |_: f64| 0.0;
    let (mut yh, mut yp) = ([1.0, 0.0], [0.0, 0.0]);
    let (mut th, mut tp) = (vec![yh], vec![yp]);
    for k in 0..TABLE {
        let psi = k as f64 * h;
        yh = rk4(m3, c, &zero, psi, h, yh);
        yp = rk4(m3, c, force, psi, h, yp);
        th.push(yh);
        tp.push(yp);
    }
    let a = -tp[TABLE][0] / th[TABLE][0];
    let f = th.iter().zip(&tp).map(|(u, v)| a * u[0] + v[0]).collect();
    let df = th
        .iter()
        .zip(&tp)
        .enumerate()
        .map(|(k, (u, v))| (a * u[1] + v[1]) / m3(k as f64 * h))
        .collect();
    (f, df)
}

/// Cubic Hermite interpolation of `(f, f')` tabulated at `TABLE + 1` equal steps on
/// `[0, phi]`: the value and the derivative at `psi`, zero beyond `phi`.
fn hermite(f: &[f64], df: &[f64], phi: f64, psi: f64) -> (f64, f64) {
    let psi = psi.abs();
    if psi >= phi {
        return (0.0, 0.0);
    }
    let step = phi / TABLE as f64;
    let t = psi / step;
    let k = (t as usize).min(TABLE - 1);
    let w = t - k as f64;
    let (w2, w3) = (w * w, w * w * w);
    let value = (2.0 * w3 - 3.0 * w2 + 1.0) * f[k]
        + (w3 - 2.0 * w2 + w) * step * df[k]
        + (-2.0 * w3 + 3.0 * w2) * f[k + 1]
        + (w3 - w2) * step * df[k + 1];
    let slope = ((6.0 * w2 - 6.0 * w) * f[k]
        + (3.0 * w2 - 4.0 * w + 1.0) * step * df[k]
        + (-6.0 * w2 + 6.0 * w) * f[k + 1]
        + (3.0 * w2 - 2.0 * w) * step * df[k + 1])
        / step;
    (value, slope)
}

impl FarField {
    /// The far field of a contact of shape factor `shape` (Eq. 6), `kappa = a/b`, speed
    /// parameter `lambda` and viscosity law `viscosity`.
    ///
    /// Psi is measured from the upstream axis, where the forcing is `-2 lambda S cos psi`
    /// and `g'(0) = 0` by symmetry. With `g = g0 g_h + g_p` (homogeneous from `(1, 0)`,
    /// forced from `(0, 0)`), Reynolds' condition at `phi` asks
    /// `g_h v_p - g_p v_h = 0`, whose derivative is `-2 S cos(psi) g_h`: `phi` is the
    /// first zero of `int_0^psi cos(s) g_h(s) ds` past `pi/2`.
    ///
    /// The film constant `Delta` in `H = Delta + m r^2` adds `Delta g1 / r^5`: with
    /// `H^3 = m^3 r^6 + 3 m^2 Delta r^4 + ...`, the order `1/r` of the equation gives
    /// `(m^3 g1')' - 5 m^3 g1 = 9 m^2 g - 3 (m^2 g')'`, with `g1'(0) = 0` and `g1(phi) = 0`
    /// (the cavitation angle's own shift leaves `g1` free there since `g'(phi) = 0`).
    pub fn new(shape: f64, kappa: f64, lambda: f64, viscosity: Viscosity) -> Self {
        let kappa2 = kappa * kappa;
        let cube = |t: f64| m3(shape, kappa2, t);
        let forcing = |t: f64| -2.0 * shape * t.cos();
        let zero = |_: f64| 0.0;
        let dpsi = std::f64::consts::PI / SEARCH_STEPS as f64;
        let mut gh = [1.0, 0.0];
        let mut integral = 0.0;
        let mut phi = std::f64::consts::PI;
        for k in 0..SEARCH_STEPS {
            let psi = k as f64 * dpsi;
            let next = rk4(&cube, 9.0, &zero, psi, dpsi, gh);
            // Trapezoid step of int cos(s) g_h(s) ds; the zero by linear interpolation.
            let step = 0.5 * dpsi * (psi.cos() * gh[0] + (psi + dpsi).cos() * next[0]);
            if integral + step < 0.0 && psi > 0.0 {
                phi = psi + dpsi * integral / (integral - (integral + step));
                break;
            }
            integral += step;
            gh = next;
        }
        let (g, dg) = tabulate(&cube, 9.0, &forcing, phi);
        // g'' from g's own equation: m^3 g'' = 9 m^3 g + force - 3 m^2 m' g'.
        let correction_force = |t: f64| {
            let (gv, gd) = hermite(&g, &dg, phi, t);
            let (m, dm) = gap_factor(shape, kappa2, t);
            let m2 = m * m;
            let gdd = (9.0 * m2 * m * gv + forcing(t) - 3.0 * m2 * dm * gd) / (m2 * m);
            9.0 * m2 * gv - 3.0 * (2.0 * m * dm * gd + m2 * gdd)
        };
        let (g1, dg1) = tabulate(&cube, 5.0, &correction_force, phi);
        let scaled = |v: Vec<f64>| v.into_iter().map(|x| lambda * x).collect::<Vec<_>>();
        FarField {
            phi,
            g: scaled(g),
            dg: scaled(dg),
            g1: scaled(g1),
            dg1: scaled(dg1),
            amplitude: 1.0,
            last_fit: None,
            kappa,
            viscosity,
            surround: None,
        }
    }

    /// This far field with the surroundings `surround` in place of the asymptote: the
    /// edge's pressure, the outside load and the film offset come from a wide solution.
    pub fn with_surround(mut self, surround: Option<Arc<Surround>>) -> Self {
        self.surround = surround;
        self
    }

    /// What the film equation adds to the gap at `(X, Y)`: the deformation by the
    /// surroundings' pressure (zero for the asymptote, whose deformation is left out).
    pub fn film_offset(&self, x: f64, y: f64) -> f64 {
        self.surround.as_ref().map_or(0.0, |s| s.film_offset(x, y))
    }

    /// The cavitation angle `phi` from the upstream axis, in the `(X, Y / kappa)` plane.
    #[cfg(test)]
    pub fn cavitation_angle(&self) -> f64 {
        self.phi
    }

    /// `g` on the upstream axis: the reduced pressure there is `g(0) / |X|^3`.
    #[cfg(test)]
    pub fn axis_amplitude(&self) -> f64 {
        self.g[0]
    }

    /// `g(psi)`, 0 beyond `phi`.
    fn g_at(&self, psi: f64) -> f64 {
        hermite(&self.g, &self.dg, self.phi, psi).0
    }

    /// `g1(psi)`, 0 beyond `phi`.
    fn g1_at(&self, psi: f64) -> f64 {
        hermite(&self.g1, &self.dg1, self.phi, psi).0
    }

    /// The reduced pressure `q = g / r^3 + delta g1 / r^5` of the asymptote at `(X, Y)` for
    /// the film constant `delta`.
    pub fn reduced_pressure(&self, x: f64, y: f64, delta: f64) -> f64 {
        let yp = y / self.kappa;
        let r2 = x * x + yp * yp;
        if r2 == 0.0 {
            return 0.0;
        }
        // Angle from the upstream axis (-X).
        let psi = yp.atan2(-x);
        let r3 = r2 * r2.sqrt();
        self.amplitude * (self.g_at(psi) / r3 + delta * self.g1_at(psi) / (r3 * r2))
    }

    /// The pressure `P` of the asymptote at `(X, Y)` for the film constant `delta`: the
    /// reduced pressure mapped back through the viscosity law.
    pub fn pressure(&self, x: f64, y: f64, delta: f64) -> f64 {
        if let Some(s) = &self.surround {
            return s.pressure(x, y);
        }
        self.pressure_of_reduced(self.reduced_pressure(x, y, delta))
    }

    /// `P` with `int_0^P dP'/eta_bar(P') = q`: for Barus `-ln(1 - alpha_bar q)/alpha_bar`,
    /// for any law by Newton's method on a five-point Gauss-Legendre integral. Where `q`
    /// reaches the law's range (the fluid could not carry it at any pressure), the
    /// asymptote does not hold and `P` is `+inf`.
    pub fn pressure_of_reduced(&self, q: f64) -> f64 {
        if q <= 0.0 {
            return 0.0;
        }
        if let Viscosity::Barus { alpha_bar } = self.viscosity {
            let a = alpha_bar * q;
            return if alpha_bar == 0.0 {
                q
            } else if a >= 1.0 {
                f64::INFINITY
            } else {
                -(-a).ln_1p() / alpha_bar
            };
        }
        let mut p = q;
        for _ in 0..50 {
            let f = self.reduced_of(p) - q;
            let dp = f * self.viscosity.eta_bar(p);
            p -= dp;
            if !p.is_finite() || p <= 0.0 {
                return f64::INFINITY;
            }
            if dp.abs() <= 1e-15 * p {
                break;
            }
        }
        p
    }

    /// Fits the amplitude to a solution: the least-squares factor between the reduced
    /// pressures `q(P)` of the pressurised nodes `RING` cells inside the edge of `grid` and
    /// the asymptote's there (film constant `delta`). Returns that factor's distance from 1,
    /// how far the solution is from agreeing with its edge. Only the asymptote's shape is
    /// then assumed, not its amplitude: where the far field carries much of the load
    /// (`lambda` of order 1 and above) the a-priori amplitude's error would decide the
    /// contact.
    ///
    /// The fitted amplitude `F(A)` of a solution converged with the edge at amplitude `A`
    /// is close to affine in `A`, with a slope that is the edge's own share of the pressure
    /// at the ring (about 0.7 at M 20, L 30: plain refitting took eight rounds and did not
    /// settle to 1e-4). So the second fit on a grid takes the secant step to the fixed point
    /// `F(A) = A` through the last two, where their slope lies in `0..0.9`; otherwise, and
    /// on the first fit on a grid, the fitted amplitude itself.
    pub fn fit(&mut self, grid: &Grid, p: &[f64], delta: f64) -> f64 {
        const RING: usize = 4;
        let (mut num, mut den) = (0.0, 0.0);
        for j in RING..=grid.ny - RING {
            for i in RING..=grid.nx - RING {
                let on_ring = i == RING || j == RING || i == grid.nx - RING || j == grid.ny - RING;
                let k = grid.idx(i, j);
                if !on_ring || p[k] <= 0.0 {
                    continue;
                }
                let s = self.reduced_pressure(grid.x(i), grid.y(j), delta);
                if s <= 0.0 {
                    continue;
                }
                num += self.reduced_of(p[k]) * s;
                den += s * s;
            }
        }
        if den == 0.0 || num <= 0.0 {
            return 0.0;
        }
        let factor = num / den;
        let fitted = self.amplitude * factor;
        let next = match self.last_fit {
            Some((nx, from, to)) if nx == grid.nx && (self.amplitude - from).abs() > 0.0 => {
                let slope = (fitted - to) / (self.amplitude - from);
                if (0.0..0.9).contains(&slope) {
                    self.amplitude + (fitted - self.amplitude) / (1.0 - slope)
                } else {
                    fitted
                }
            }
            _ => fitted,
        };
        self.last_fit = Some((grid.nx, self.amplitude, fitted));
        self.amplitude = next;
        (factor - 1.0).abs()
    }

    /// `int_0^p dP / eta_bar(P)` by five-point Gauss-Legendre.
    fn reduced_of(&self, p: f64) -> f64 {
        const NODES: [(f64, f64); 5] = [
            (0.0, 0.568_888_888_888_888_9),
            (0.538_469_310_105_683, 0.478_628_670_499_366_5),
            (-0.538_469_310_105_683, 0.478_628_670_499_366_5),
            (0.906_179_845_938_664, 0.236_926_885_056_189_1),
            (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        ];
        let half = 0.5 * p;
        NODES
            .iter()
            .map(|&(t, w)| w * (-self.viscosity.ln_eta_bar(half * (1.0 + t))).exp())
            .sum::<f64>()
            * half
    }

    /// The load `int P dX dY` of the asymptote outside `domain`: along each ray from the
    /// centre, from the domain's edge at distance `b` (in `X`, `Y'`) to infinity,
    /// `int_b^inf P(g / r^3) r dr = int_0^1 P(g t^3 / b^3) b^2 / t^3 dt` (`t = b / r`;
    /// the integrand tends to `g / b`), Gauss-Legendre in `t` and the midpoint rule in the
    /// angle, times `kappa` for `dY = kappa dY'`.
    pub fn outside_load(&self, domain: &Domain, delta: f64) -> f64 {
        if let Some(s) = &self.surround {
            return s.outside_load();
        }
        const ANGLES: usize = 720;
        let (x0, x1, y1) = (domain.x_start, domain.x_end, domain.y_half / self.kappa);
        let dpsi = 2.0 * self.phi / ANGLES as f64;
        let mut load = 0.0;
        for k in 0..ANGLES {
            let psi = -self.phi + (k as f64 + 0.5) * dpsi;
            // Direction of the ray: angle pi + psi from +X.
            let (dx, dy) = (-psi.cos(), -psi.sin());
            let to_edge = |d: f64, lo: f64, hi: f64| {
                if d > 0.0 {
                    hi / d
                } else if d < 0.0 {
                    lo / d
                } else {
                    f64::INFINITY
                }
            };
            let b = to_edge(dx, x0, x1).min(to_edge(dy, -y1, y1));
            let (g, g1) = (self.g_at(psi), delta * self.g1_at(psi));
            load += self.ray_integral(self.amplitude * g, self.amplitude * g1, b) * dpsi;
        }
        load * self.kappa
    }

    /// `int_0^1 P(g t^3 / b^3 + g1 t^5 / b^5) b^2 / t^3 dt` by eight-point Gauss-Legendre.
    fn ray_integral(&self, g: f64, g1: f64, b: f64) -> f64 {
        const NODES: [(f64, f64); 4] = [
            (0.183_434_642_495_649_8, 0.362_683_783_378_362),
            (0.525_532_409_916_329, 0.313_706_645_877_887_3),
            (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
            (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
        ];
        if g <= 0.0 {
            return 0.0;
        }
        let f = |t: f64| {
            let tb = t / b;
            let q = g * tb * tb * tb + g1 * tb.powi(5);
            let p = self.pressure_of_reduced(q);
            if q == 0.0 {
                g / b
            } else {
                p * b * b / (t * t * t)
            }
        };
        NODES
            .iter()
            .map(|&(s, w)| w * (f(0.5 * (1.0 + s)) + f(0.5 * (1.0 - s))))
            .sum::<f64>()
            * 0.5
    }
}

#[cfg(test)]
mod tests;
