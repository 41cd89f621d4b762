//! The stress re-solved with the film temperature along one strip of nodes in the rolling
//! direction (a grid row), marching downstream: a node's flash temperatures depend on the heat
//! upstream of it and on its own, so each node is one scalar equation in its stress,
//!
//! `t = tau_m(x_iso exp(Delta(p, T_film(t))))`,
//!
//! with `t = tau / tau0`, `x_iso` the isothermal Couette argument of Eq. (4) and `T_film` the
//! closure's film temperature for the shear heat `q = t tau0 du`. The right-hand side falls as
//! `t` grows (more heat, thinner oil), so the root is unique; it lies between 0 and the stress
//! at the temperature of the upstream heat alone, and is found by the Illinois method.

use super::film::{film_node, FilmNode};
use super::flash::Flash;
use super::{Closure, ThermalError, ThermalViscosity};

/// The fields of one strip, node by node (the solver layer's grid row).
#[derive(Debug, Clone, Copy)]
pub struct Strip<'a> {
    /// Dimensionless pressure `P`.
    pub p: &'a [f64],
    /// Film thickness, m.
    pub h_m: &'a [f64],
    /// The isothermal Couette argument `x = eta du / (h tau0)` of Eq. (4).
    pub x_iso: &'a [f64],
    /// Whether the node carries load (the nodes Eq. (8) sums over): only they are sheared.
    pub loaded: &'a [bool],
}

/// What is fixed along a strip.
#[derive(Debug, Clone, Copy)]
pub struct Setting<'a> {
    /// Flash-temperature operators of surfaces 1 and 2.
    pub flash: (&'a Flash, &'a Flash),
    /// Film conductivity, W/(m K).
    pub k_film: f64,
    /// Which film temperature the viscosity sees.
    pub closure: Closure,
    /// The viscosity's temperature law.
    pub viscosity: &'a ThermalViscosity,
    /// Shear heat per unit of `tau_m / tau0`: `tau0 du`, W/m^2.
    pub heat_per_stress: f64,
}

/// A strip's thermal solution.
#[derive(Debug, Clone, PartialEq)]
pub struct StripSolution {
    /// `tau_m / tau0` at each node (0 where not loaded).
    pub stress: Vec<f64>,
    /// The partition and temperatures at each node.
    pub nodes: Vec<FilmNode>,
}

/// Iterations of the Illinois method: it converges superlinearly; 200 are never reached.
const MAX_ITERATIONS: usize = 200;

/// Solves the strip with the rheology's `stress(node, x)` (`tau_m / tau0` of a Couette
/// argument at a node). At each loaded node the stress is finally evaluated at the converged
/// film temperature, so that a zero temperature or coefficient gives back the isothermal
/// stress to the bit.
pub fn solve_strip(
    strip: &Strip,
    setting: &Setting,
    stress: impl Fn(usize, f64) -> f64,
) -> Result<StripSolution, ThermalError> {
    let n = strip.p.len();
    let (f1, f2) = setting.flash;
    let own = (f1.own(), f2.own());
    let mut q1 = vec![0.0; n];
    let mut q2 = vec![0.0; n];
    let mut out = StripSolution {
        stress: vec![0.0; n],
        nodes: Vec::with_capacity(n),
    };
    // No heat before the first loaded node: the flash sums start there.
    let first = strip.loaded.iter().position(|&l| l).unwrap_or(n);
    for i in 0..n {
        let upstream = (
            f1.upstream_from(&q1, i, first),
            f2.upstream_from(&q2, i, first),
        );
        if !strip.loaded[i] {
            out.nodes.push(film_node(
                setting.closure,
                0.0,
                1.0,
                setting.k_film,
                upstream,
                (0.0, 0.0),
            ));
            continue;
        }
        let h = strip.h_m[i];
        if h.is_nan() || h <= 0.0 {
            return Err(ThermalError::NoFilm { h_m: h });
        }
        let at = |t: f64| {
            film_node(
                setting.closure,
                t * setting.heat_per_stress,
                h,
                setting.k_film,
                upstream,
                own,
            )
        };
        let pressure_part = setting.viscosity.pressure_part(strip.p[i]);
        let thermal_stress = |node: &FilmNode| {
            let delta = setting
                .viscosity
                .delta_ln_eta_with(pressure_part, node.t_film);
            stress(i, strip.x_iso[i] * delta.exp())
        };
        // A trial stress's residual, with the node and stress it made: the root returns
        // those of the stress it stops at, so neither is made twice.
        let trial = |t: f64| {
            let node = at(t);
            let s = thermal_stress(&node);
            (t - s, (node, s))
        };
        let zero = trial(0.0);
        let hi = zero.1 .1;
        let (_, (node, s)) =
            root(trial, hi, zero).map_err(|why| ThermalError::Stress { node: i, why })?;
        if !(s.is_finite() && node.t_film.is_finite()) {
            return Err(ThermalError::Stress {
                node: i,
                why: format!("non-finite stress {s} or film temperature {}", node.t_film),
            });
        }
        q1[i] = node.q1;
        q2[i] = node.q2;
        out.stress[i] = s;
        out.nodes.push(node);
    }
    Ok(out)
}

/// The root of the increasing `g` on `[0, hi]` (`g(0) <= 0 <= g(hi)`), Illinois method, to a
/// bracket of 1e-14 of `hi`: the root and what `g` made with its residual there. `g(0)`,
/// `at_zero`, is the caller's (it is where `hi` came from).
fn root<M>(g: impl Fn(f64) -> (f64, M), hi: f64, at_zero: (f64, M)) -> Result<(f64, M), String> {
    if !(hi.is_finite() && hi >= 0.0) {
        return Err(format!("stress bound {hi}"));
    }
    let (mut ga, zero) = at_zero;
    if ga >= 0.0 {
        return Ok((0.0, zero));
    }
    let (mut gb, at_hi) = g(hi);
    if gb <= 0.0 {
        return Ok((hi, at_hi));
    }
    let (mut a, mut b) = (0.0, hi);
    let mut side = 0;
    for _ in 0..MAX_ITERATIONS {
        let c = (a * gb - b * ga) / (gb - ga);
        let (gc, made) = g(c);
        if !gc.is_finite() {
            return Err(format!("non-finite residual at stress {c}"));
        }
        if gc == 0.0 || (b - a) <= 1e-14 * hi {
            return Ok((c, made));
        }
        if gc < 0.0 {
            a = c;
            ga = gc;
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        } else {
            b = c;
            gb = gc;
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        }
    }
    Err(format!(
        "no convergence in {MAX_ITERATIONS} iterations (bracket {a}..{b})"
    ))
}

#[cfg(test)]
mod tests {
    use super::super::Solid;
    use super::*;
    use crate::physics::rheology::{eyring_stress, ShearLaw};

    /// A Hertzian strip across a 3 GPa-like contact: `n` nodes, film 0.1 um, the isothermal
    /// Couette argument of a heavily loaded mineral oil.
    fn strip_fields(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<bool>) {
        let p: Vec<f64> = (0..n)
            .map(|i| {
                let x = -1.5 + 3.0 * i as f64 / (n - 1) as f64;
                (1.0 - x * x).max(0.0).sqrt()
            })
            .collect();
        let h = vec![1e-7; n];
        let x = p.iter().map(|&p| 1e3 * (30.0 * p).exp()).collect();
        let loaded = p.iter().map(|&p| p > 0.0).collect();
        (p, h, x, loaded)
    }

    fn run(law: &ThermalViscosity, solid: &Solid, k_film: f64, closure: Closure) -> StripSolution {
        let n = 301;
        let (p, h, x, loaded) = strip_fields(n);
        let dx = 3.0 * 4e-4 / (n - 1) as f64;
        let f1 = Flash::new(solid, 11.9, dx, n);
        let f2 = Flash::new(solid, 12.1, dx, n);
        let strip = Strip {
            p: &p,
            h_m: &h,
            x_iso: &x,
            loaded: &loaded,
        };
        let setting = Setting {
            flash: (&f1, &f2),
            k_film,
            closure,
            viscosity: law,
            heat_per_stress: 4e6 * 0.2,
        };
        solve_strip(&strip, &setting, |i, x| {
            ShearLaw::Eyring.mean_shear_stress(x, p[i])
        })
        .unwrap()
    }

    #[test]
    fn limits_give_the_isothermal_stress_exactly_and_heating_lowers_it() {
        let law = ThermalViscosity::Exponential { beta0: 0.04 };
        let iso: Vec<f64> = strip_fields(301)
            .2
            .iter()
            .zip(strip_fields(301).3)
            .map(|(&x, l)| if l { eyring_stress(x) } else { 0.0 })
            .collect();
        // The isothermal stress is the solver's own Eyring stress, so the limits are bit for bit.
        // beta = 0: no viscosity change however hot the film.
        let cold_law = run(&law.scaled(0.0), &Solid::STEEL, 0.13, Closure::Mean);
        assert_eq!(cold_law.stress, iso);
        // Infinitely conducting bodies and film: no temperature rise.
        let conducting = Solid {
            conductivity_w_mk: f64::INFINITY,
            ..Solid::STEEL
        };
        let cold = run(&law, &conducting, f64::INFINITY, Closure::Mean);
        assert_eq!(cold.stress, iso);
        // Heating lowers every loaded stress, the mid-plane closure more than the mean one.
        let mean = run(&law, &Solid::STEEL, 0.13, Closure::Mean);
        let mid = run(&law, &Solid::STEEL, 0.13, Closure::MidPlane);
        for i in 0..iso.len() {
            assert!(
                mean.stress[i] <= iso[i] && mid.stress[i] <= mean.stress[i],
                "node {i}"
            );
        }
        let ratio = mean.stress.iter().sum::<f64>() / iso.iter().sum::<f64>();
        let t_max = mean.nodes.iter().map(|n| n.t_film).fold(0.0, f64::max);
        // A film some 10 K warmer takes beta0 * 10 K = 0.4 off ln eta, so off the stress
        // ln(2x) (about 37 at the centre) at most 0.4: a drop of about 1 % (0.96 % measured).
        assert!(
            ratio < 0.995 && ratio > 0.98,
            "ratio {ratio}, t_max {t_max}"
        );
        assert!(t_max > 5.0 && t_max < 20.0, "t_max {t_max}");
    }

    #[test]
    fn the_heat_balance_holds_and_each_node_solves_its_equation() {
        // The walls take the shear heat: sum (q1 + q2) = tau0 du sum tau_m, to the root's
        // tolerance (1e-14 of the bracket) and round-off over ~200 nodes: 1e-10 relative.
        let law = ThermalViscosity::Exponential { beta0: 0.04 };
        let s = run(&law, &Solid::STEEL, 0.13, Closure::Mean);
        let heat: f64 = s.nodes.iter().map(|n| n.q1 + n.q2).sum();
        let work: f64 = 4e6 * 0.2 * s.stress.iter().sum::<f64>();
        assert!((heat / work - 1.0).abs() < 1e-10, "{heat} vs {work}");
        // The surface temperatures are the flash integrals of the fluxes they took.
        let dx = 3.0 * 4e-4 / 300.0;
        let q1: Vec<f64> = s.nodes.iter().map(|n| n.q1).collect();
        let t1 = Flash::new(&Solid::STEEL, 11.9, dx, 301).temperatures(&q1);
        let t_max = t1.iter().cloned().fold(0.0, f64::max);
        for (n, t) in s.nodes.iter().zip(&t1) {
            assert!((n.t1 - t).abs() < 1e-9 * t_max);
        }
        // And downstream of the contact the surfaces stay warm (no heat is lost).
        assert!(s.nodes.last().unwrap().t1 > 0.0);
    }
}
