//! Conduction across the film: walls at `T1` (z = 0) and `T2` (z = h), the shear heat `q`
//! generated uniformly across the film, no convection. The temperature is a parabola on a
//! line,
//!
//! `T(z) = T1 + (T2 - T1) z/h + (q h / (2 k_f)) (z/h)(1 - z/h)`,
//!
//! so the walls take `q1 = q/2 + k_f (T2 - T1)/h` and `q2 = q/2 - k_f (T2 - T1)/h` (their sum
//! is `q`: the heat balance), the film's mean is `(T1 + T2)/2 + q h/(12 k_f)` and its
//! mid-plane `(T1 + T2)/2 + q h/(8 k_f)`.
//!
//! The wall temperatures depend on their own flux through the flash temperature,
//! `T_i = A_i + W_i q_i` (upstream part `A_i`, own weight `W_i`), so the partition at a node is
//! one linear equation in `q1`.

use super::Closure;

/// A node's heat partition and temperatures (rises, K).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmNode {
    /// Heat into body 1, W/m^2.
    pub q1: f64,
    /// Heat into body 2, W/m^2.
    pub q2: f64,
    /// Surface 1's temperature rise.
    pub t1: f64,
    /// Surface 2's temperature rise.
    pub t2: f64,
    /// The film temperature rise of the closure.
    pub t_film: f64,
}

/// The film's rise above the mean of its walls for the shear heat `q` (W/m^2), film `h_m`
/// and conductivity `k_f`: `q h / (12 k_f)` (mean) or `q h / (8 k_f)` (mid-plane).
pub fn rise_across(closure: Closure, q: f64, h_m: f64, k_f: f64) -> f64 {
    let divisor = match closure {
        Closure::Mean => 12.0,
        Closure::MidPlane => 8.0,
    };
    q * h_m / (divisor * k_f)
}

/// The partition of `q` between the walls and the temperatures at a node whose walls' flash
/// temperatures are `upstream.i + own.i q_i`. An infinitely conducting film (`k_f = inf`)
/// makes the walls equally hot; infinitely conducting walls as well take half each.
pub fn film_node(
    closure: Closure,
    q: f64,
    h_m: f64,
    k_f: f64,
    upstream: (f64, f64),
    own: (f64, f64),
) -> FilmNode {
    // q1 = q/2 + G (T2 - T1), T2 - T1 = d - (W1 + W2) q1, d = A2 - A1 + W2 q, G = k_f / h.
    let g = k_f / h_m;
    let d = upstream.1 - upstream.0 + own.1 * q;
    let w = own.0 + own.1;
    let q1 = if g.is_finite() {
        (0.5 * q + g * d) / (1.0 + g * w)
    } else if w > 0.0 {
        d / w
    } else {
        0.5 * q
    };
    let q2 = q - q1;
    let t1 = upstream.0 + own.0 * q1;
    let t2 = upstream.1 + own.1 * q2;
    FilmNode {
        q1,
        q2,
        t1,
        t2,
        t_film: 0.5 * (t1 + t2) + rise_across(closure, q, h_m, k_f),
    }
}

/// The exact Couette flow of a Newtonian film whose viscosity falls as
/// `eta_w exp(-beta (T - T_w))`, between walls both held at `T_w` (Nahme 1940): the sliding
/// speed `du` (m/s) that carries the stress `tau` (Pa) across a film `h_m`, or `None` past
/// thermal runaway (no flow carries that stress).
///
/// With `phi = beta (T - T_w)` the energy equation `k phi'' = -beta tau^2 exp(phi) / eta_w` has
/// the solution `exp(phi) = cosh^2(s) / cosh^2(2 s z / h)` (z from the mid-plane) where
/// `s / cosh(s) = sqrt(Na / 8)`, `Na = beta tau^2 h^2 / (k eta_w)`, and the flow is
/// `du = (tau h / eta_w) sinh(2 s) / (2 s)`.
pub fn nahme_sliding_speed(tau: f64, h_m: f64, eta_w: f64, beta: f64, k: f64) -> Option<f64> {
    let target = (beta * tau * tau * h_m * h_m / (k * eta_w) / 8.0).sqrt();
    // s / cosh(s) rises from 0 to its maximum 0.6627 at s tanh(s) = 1 (s = 1.1997): the
    // smaller root, by bisection on [0, 1.1997].
    let (mut lo, mut hi) = (0.0_f64, 1.199_678_640_257_734_f64);
    if target > hi / hi.cosh() {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid / mid.cosh() < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let s = 0.5 * (lo + hi);
    let ratio = if s < 1e-8 {
        1.0
    } else {
        (2.0 * s).sinh() / (2.0 * s)
    };
    Some(tau * h_m / eta_w * ratio)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stress of the closure for the Newtonian exponential film of
    /// [`nahme_sliding_speed`] at sliding speed `du`, walls held at the bulk temperature:
    /// `tau = (eta_w du / h) exp(-beta T_film(tau du))`, by bisection.
    fn closure_stress(closure: Closure, du: f64, h: f64, eta_w: f64, beta: f64, k: f64) -> f64 {
        let tau_iso = eta_w * du / h;
        let (mut lo, mut hi) = (0.0, tau_iso);
        for _ in 0..200 {
            let tau = 0.5 * (lo + hi);
            let t = film_node(closure, tau * du, h, k, (0.0, 0.0), (0.0, 0.0)).t_film;
            if tau < tau_iso * (-beta * t).exp() {
                lo = tau;
            } else {
                hi = tau;
            }
        }
        0.5 * (lo + hi)
    }

    #[test]
    fn the_mean_closure_is_the_nahme_solution_to_second_order() {
        // Expanding both in the Nahme number Na: exact tau_iso/tau = 1 + Na/12 + Na^2/80,
        // mean closure 1 + Na/12 + Na^2/96, so they differ by Na^2/480 (relative); the
        // mid-plane closure's first-order term is Na/8, half again as much heating.
        let (h, eta_w, beta, k): (f64, f64, f64, f64) = (1e-7, 1.0, 0.03, 0.13);
        for na in [0.01_f64, 0.1, 0.5, 1.0, 2.0] {
            let tau = (na * k * eta_w / (beta * h * h)).sqrt();
            let du = nahme_sliding_speed(tau, h, eta_w, beta, k).unwrap();
            let mean = closure_stress(Closure::Mean, du, h, eta_w, beta, k);
            let mid = closure_stress(Closure::MidPlane, du, h, eta_w, beta, k);
            // Twice the Na^2/480 of the expansion: room for its higher-order terms.
            assert!(
                (mean / tau - 1.0).abs() < na * na / 240.0,
                "Na {na}: mean closure {mean} vs exact {tau}"
            );
            // The two closures bracket the exact flow: the mean one heats a little less (its
            // second-order term is smaller), the mid-plane one more (at Na = 1: +0.24 % and
            // -3.7 % in stress about the exact 9 % reduction).
            assert!(mid < tau && tau < mean, "Na {na}: {mid} < {tau} < {mean}");
        }
        // Past runaway (Na / 8 > 0.6627^2, Na > 3.51) no Couette flow carries the stress.
        let tau = (3.6 * k * eta_w / (beta * h * h)).sqrt();
        assert!(nahme_sliding_speed(tau, h, eta_w, beta, k).is_none());
    }

    #[test]
    fn the_partition_conserves_heat_and_matches_the_wall_conduction() {
        // Unequal walls (flash weights of a slow and a fast surface, some upstream heat):
        // q1 + q2 = q to round-off, and q1 - q/2 = k_f (T2 - T1)/h, the conduction of the
        // linear part of the profile (tolerance: round-off of terms of size q).
        let (q, h, k) = (2e8, 1e-7, 0.13);
        let n = film_node(Closure::Mean, q, h, k, (12.0, 3.0), (4e-8, 1e-8));
        assert!((n.q1 + n.q2 - q).abs() < 1e-9 * q);
        assert!((n.q1 - 0.5 * q - k * (n.t2 - n.t1) / h).abs() < 1e-6 * q);
        assert!((n.t1 - (12.0 + 4e-8 * n.q1)).abs() < 1e-12 * n.t1);
        // Conducting walls and film: no rise anywhere.
        let cold = film_node(
            Closure::MidPlane,
            q,
            h,
            f64::INFINITY,
            (0.0, 0.0),
            (0.0, 0.0),
        );
        assert_eq!((cold.t1, cold.t2, cold.t_film), (0.0, 0.0, 0.0));
    }
}
