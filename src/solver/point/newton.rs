//! Damped semi-smooth Newton-Krylov iteration for the point contact on one grid: the finish
//! of a solve whose multigrid cycles stall or diverge (the most heavily loaded, most
//! piezoviscous cases).
//!
//! Unknowns: `P` at the interior nodes and `Delta`. Equations: at each interior node the
//! complementarity form of Reynolds with cavitation, `min(P, r / c) = 0` with `r = f - L(P)`
//! the residual of [`LevelFields::residual`] (the multigrid's own finest-level equations) and `c`
//! the magnitude of its own diagonal (so `r / c` is a pressure): either `P = 0` and the fluid
//! would cavitate, or `P > 0` and Reynolds holds. Plus the force balance. The step
//! linearises `min(P, r / c)` semi-smoothly: a Reynolds row where `r / c < P` (the
//! pressurised nodes, and the dry ones whose residual asks for pressure), the identity where
//! a pressurised node has `P <= r / c` (it cavitates: the full step sets it to zero
//! exactly); the dry nodes with `r / c >= 0` stay at `P = 0`.
//!
//! The Jacobian is full, because every pressure moves every film value through the elastic
//! kernel; it is never formed. Each Newton system is solved by right-preconditioned GMRES
//! ([`gmres`]) with the exact Jacobian-vector product of [`Jacobian::apply`] (the film
//! coupling by the FFT deformation), to the Eisenstat-Walker forcing term, preconditioned by
//! the same Jacobian with the kernel truncated to a box around each node, bordered by the
//! `Delta` column and the force balance and factorised by a sparse LU
//! ([`Jacobian::preconditioner`]). Globalisation: backtracking on the residual norm with
//! projection on `P >= 0`.

use super::jacobian::{wedge_weights, Jacobian};
use super::level::{LevelFields, Model, LOAD};
use super::params::{NewtonParams, StoppingParams};
use crate::solver::bordered_lu::LuStorage;
use crate::solver::gmres::KrylovParams;
use crate::solver::{gmres, line_search};
pub(crate) use lagged::KeptFactor;
use lagged::Preconditioner;
use std::sync::{Mutex, MutexGuard, PoisonError};

/// Held by the finish of a level-9 solve ([`super::MAX_LEVEL`]) while it iterates: its
/// factorisations peak at about 13 GB (the 7 x 7 box of [`NewtonParams::finest_box_radius`];
/// docs/hard-cases.md), so two at once, a sweep's two threads each on a heavy contact, would
/// pass a 24 GiB machine's memory. They take turns, and none keeps its factor after it
/// ([`HANDED_LEVELS`]); every other finish runs freely.
static FINEST_FINISH: Mutex<()> = Mutex::new(());

/// The turn of a finish on `level`: [`FINEST_FINISH`] held on level 9, nothing elsewhere.
fn finest_turn(level: u32) -> Option<MutexGuard<'static, ()>> {
    // A finish that panicked while holding it left nothing to repair: the lock guards no data.
    (level >= super::MAX_LEVEL)
        .then(|| FINEST_FINISH.lock().unwrap_or_else(PoisonError::into_inner))
}

/// `|dL/dP|` at every interior node: the Poiseuille stencil and the wedge term's own kernel
/// coefficient. Dividing the residual by it makes a pressure.
fn row_scales(level: &LevelFields) -> Vec<f64> {
    let g = level.grid;
    let d0 = level.deformation.kernel().at(0, 0);
    let mut c = vec![1.0; g.len()];
    for j in 1..g.ny {
        for i in 1..g.nx {
            let k = g.idx(i, j);
            let wedge = wedge_weights(i)[0].1 * level.rho[k] * d0 / g.hx;
            c[k] = (level.xi(i, j).iter().sum::<f64>() + wedge).max(1e-12);
        }
    }
    c
}

/// The complementarity residual: `min(P, r / c)` per interior node and the relative load
/// error, and the Euclidean norm of all of them.
struct Eval {
    phi: Vec<f64>,
    load: f64,
    norm: f64,
}

fn evaluate(level: &mut LevelFields, model: &Model, delta: f64, scale: &[f64]) -> Eval {
    level.refresh(delta, model);
    let g = level.grid;
    let mut phi = vec![0.0; g.len()];
    let mut sum = 0.0;
    for j in 1..g.ny {
        for i in 1..g.nx {
            let k = g.idx(i, j);
            phi[k] = level.p[k].min(level.residual(i, j) / scale[k]);
            sum += phi[k] * phi[k];
        }
    }
    let load = level.load_defect() / LOAD;
    Eval {
        phi,
        load,
        norm: (sum + load * load).sqrt(),
    }
}

/// A converged level's last factor, handed on with its solution to the solves that start
/// from it ([`HANDED_ITERATIONS`]): shared by them, each preconditioning with its own copy.
#[derive(Clone, Debug)]
pub struct HandedFactor(std::sync::Arc<KeptFactor>);

impl HandedFactor {
    pub(crate) fn new(factor: KeptFactor) -> Self {
        HandedFactor(std::sync::Arc::new(factor))
    }

    /// A copy to precondition with.
    pub(crate) fn copy(&self) -> KeptFactor {
        (*self.0).clone()
    }
}

/// The same factor: a start is equal to another only with the very one.
impl PartialEq for HandedFactor {
    fn eq(&self, other: &Self) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0)
    }
}

/// Outcome of [`iterate`].
pub(crate) struct NewtonKrylovRun {
    /// Whether the tolerances were met.
    pub converged: bool,
    /// Newton steps taken.
    pub iterations: usize,
    /// New preconditioner factors made (the rest of the steps kept, mapped or were handed
    /// one).
    pub factorisations: usize,
    /// GMRES iterations (Jacobian-vector products) over all steps.
    pub krylov_iterations: usize,
}

/// What [`iterate`] reports after each step.
pub(crate) struct NewtonStep {
    /// Mean absolute Reynolds residual.
    pub residual: f64,
    /// `(X, Y)` of the largest residual.
    pub worst_at: (f64, f64),
    /// Relative force-balance error.
    pub load_error: f64,
    /// GMRES iterations of the step.
    pub krylov_iterations: usize,
}

/// Eisenstat and Walker's (1996) forcing term, their choice 2 with `gamma = 0.9`,
/// `alpha = 2` and its safeguard: the linear systems are solved loosely while the Newton
/// residual falls slowly and ever more tightly as it converges, which keeps the quadratic
/// convergence at the end without oversolving the first steps.
fn forcing(previous: f64, norm: f64, norm_before: f64) -> f64 {
    const GAMMA: f64 = 0.9;
    const MAX: f64 = 0.5;
    const MIN: f64 = 1e-10;
    let mut eta = GAMMA * (norm / norm_before).powi(2);
    let floor = GAMMA * previous * previous;
    if floor > 0.1 {
        eta = eta.max(floor);
    }
    eta.clamp(MIN, MAX)
}

/// A new factor of `jac`'s preconditioner at `level`'s state, in `storage`.
fn fresh(
    jac: &Jacobian,
    level: &LevelFields,
    newton: &NewtonParams,
    storage: LuStorage,
) -> Option<Preconditioner> {
    jac.preconditioner(
        level,
        newton.box_radius_on(level.grid.level_number()),
        true,
        storage,
    )
    .map(|lu| Preconditioner::fresh(lu, &jac.active, &jac.cavitating))
}

/// Newton steps on `level` (its own equations: the top of the hierarchy) from its current
/// pressure and `delta` until both tolerances of `stopping` are met, within `newton`'s steps;
/// the first step's forcing term is `first_forcing` ([`FIRST_FORCING`], or
/// [`warm_first_forcing`] from a warm start). `handed`, a factor made on this grid by an
/// earlier solve near this state ([`HANDED_ITERATIONS`]), preconditions the first step
/// where it still does. `report` hears of every step. Returns the outcome and, where it
/// converged, the last step's factor.
pub(crate) fn iterate(
    level: &mut LevelFields,
    model: &Model,
    delta: &mut f64,
    (newton, stopping): (&NewtonParams, &StoppingParams),
    first_forcing: f64,
    handed: Option<KeptFactor>,
    report: &mut dyn FnMut(&LevelFields, &NewtonStep),
) -> (NewtonKrylovRun, Option<KeptFactor>) {
    let g = level.grid;
    let _turn = finest_turn(g.level_number());
    // The row scales are those of this state: a level just interpolated (the next level of
    // a grid sequence, a refined level) holds the coefficients of its last relaxation, or
    // none at all (scaled by its wedge term alone, the first step of a refined level made
    // little progress: 6 Newton steps at level 8 instead of 5).
    level.refresh(*delta, model);
    let mut scale = row_scales(level);
    let mut ev = evaluate(level, model, *delta, &scale);
    let mut eta = first_forcing;
    let mut norm_before = f64::NAN;
    let mut stalled = 0;
    // The factorisation's arrays, kept from one step to the next; and the last step's
    // factor itself, with the unknowns it was made for ([`lagged`], [`LAG_ITERATIONS`]).
    let mut storage = LuStorage::default();
    let mut kept: Option<KeptFactor> = handed;
    let mut outcome = NewtonKrylovRun {
        converged: false,
        iterations: 0,
        factorisations: 0,
        krylov_iterations: 0,
    };
    for it in 1..=newton.steps {
        if it > 1 {
            eta = forcing(eta, ev.norm, norm_before);
        }
        // The semi-smooth linearisation of min(P, r / c): a Reynolds row at the nodes
        // where r / c < P (pressurised ones, and dry ones whose residual asks for
        // pressure), the identity at the pressurised nodes where P <= r / c (the node
        // cavitates: the full step sets it to zero); the dry nodes with r / c >= 0 stay dry.
        let active: Vec<usize> = (1..g.ny)
            .flat_map(|j| (1..g.nx).map(move |i| g.idx(i, j)))
            .filter(|&k| level.p[k] > 0.0 || ev.phi[k] < 0.0)
            .collect();
        let cavitating: Vec<bool> = active
            .iter()
            .map(|&k| level.p[k] > 0.0 && ev.phi[k] == level.p[k])
            .collect();
        let mut jac = Jacobian::new(level, model, active, cavitating, scale.clone());
        // The last step's factor where the unknowns are its own, or, in the quadratic regime
        // ([`REMAP_FORCING`]), have moved at a few nodes; else a new one.
        let is_handed = it == 1 && kept.is_some();
        let moved = eta <= REMAP_FORCING || is_handed;
        let lagged = match kept
            .take()
            .map(|k| k.remap(&jac.active, &jac.cavitating, moved))
        {
            Some(Ok(preconditioner)) => Some(preconditioner),
            Some(Err(kept_storage)) => {
                storage = *kept_storage;
                None
            }
            None => None,
        };
        let is_lagged = lagged.is_some();
        let mut preconditioner = match lagged {
            Some(p) => p,
            None => {
                outcome.factorisations += 1;
                match fresh(&jac, level, newton, std::mem::take(&mut storage)) {
                    Some(p) => p,
                    None => return (outcome, None),
                }
            }
        };
        let n = jac.len();
        let mut rhs: Vec<f64> = jac.active.iter().map(|&k| -ev.phi[k]).collect();
        rhs.push(-ev.load);
        let mut step = vec![0.0; n];
        // A handed factor's system is given the iterations it may take in place of a new
        // factor; a lagged one is judged by its count after the solve.
        let krylov_params = if is_lagged && is_handed {
            KrylovParams {
                max_iterations: newton.krylov.max_iterations.min(HANDED_ITERATIONS),
                ..newton.krylov
            }
        } else {
            newton.krylov
        };
        let mut krylov = gmres::solve(
            &rhs,
            &mut step,
            &krylov_params,
            eta,
            |v, out| jac.apply(level, v, out),
            |v, out| preconditioner.solve(v, out),
        );
        if is_lagged
            && ((krylov.iterations > LAG_ITERATIONS && !is_handed)
                || krylov.relative_residual.is_nan()
                || krylov.relative_residual > eta)
        {
            // The lagged factor no longer preconditions this Jacobian: a new one, and the
            // system solved again.
            outcome.krylov_iterations += krylov.iterations;
            outcome.factorisations += 1;
            preconditioner = match fresh(&jac, level, newton, preconditioner.into_storage()) {
                Some(p) => p,
                None => return (outcome, None),
            };
            krylov = gmres::solve(
                &rhs,
                &mut step,
                &newton.krylov,
                eta,
                |v, out| jac.apply(level, v, out),
                |v, out| preconditioner.solve(v, out),
            );
        }
        outcome.iterations = it;
        outcome.krylov_iterations += krylov.iterations;
        if !step.iter().all(|v| v.is_finite()) {
            return (outcome, None);
        }
        // Backtracking on |phi|: halve the step until it decreases (or the smallest damping).
        let p_old = level.p.clone();
        let delta_old = *delta;
        kept = Some(preconditioner.into_kept());
        let (column, cavitating) = (&jac.column, &jac.cavitating);
        let omega = line_search::backtrack(ev.norm, |omega| {
            for (k, &c) in column.iter().enumerate() {
                if c == usize::MAX {
                    continue;
                }
                // A cavitating node's step is -P exactly (GMRES solves its identity row
                // only to the forcing term): the full step sets it to zero.
                level.p[k] = if cavitating[c] {
                    (1.0 - omega) * p_old[k]
                } else {
                    (p_old[k] + omega * step[c]).max(0.0)
                };
            }
            *delta = delta_old + omega * step[n - 1];
            evaluate(level, model, *delta, &scale).norm
        });
        norm_before = ev.norm;
        scale = row_scales(level);
        ev = evaluate(level, model, *delta, &scale);
        let (residual, worst_at) = level.residual_norm();
        let load_error = ev.load.abs();
        report(
            level,
            &NewtonStep {
                residual,
                worst_at,
                load_error,
                krylov_iterations: krylov.iterations,
            },
        );
        if !residual.is_finite() {
            return (outcome, None);
        }
        if residual < stopping.tolerance && load_error < stopping.load_tolerance {
            outcome.converged = true;
            return (outcome, kept);
        }
        // Steps the line search can only take at its smallest damping make no progress
        // (each moves the state by 1/256 of a step that does not reduce `min(P, r / c)`):
        // the semi-smooth linearisation cycles between active sets at the cavitation
        // boundary. The caller relaxes the state and tries again rather than spend the
        // remaining steps (M 0.13, L 47, lambda 170 at level 6: 28 such steps, the
        // residual falling 0.4 % per step).
        stalled = if omega <= line_search::MIN_DAMPING {
            stalled + 1
        } else {
            0
        };
        if stalled >= STALLED_STEPS {
            return (outcome, None);
        }
    }
    (outcome, None)
}

/// Most GMRES iterations of a first step preconditioned by a handed factor (one made by an
/// earlier solve on the grid: the base of a family for its member, or the level's last
/// finish for its edge round), past which a new factor is made and the system solved again.
/// A fresh factor takes about 56 iterations on the M = 19 205 members at level 8 (forcing
/// 1e-4), and its factorisation costs what about 35-45 iterations do there; the base's
/// factor took 77-80, so it is worth keeping up to about 100 (docs/ACCURACY_NOTES.md,
/// "The base's factor at level 8").
pub(crate) const HANDED_ITERATIONS: usize = 100;

/// The levels on which a converged finish hands its factor on: at level 8 a member's step
/// is one factorisation and about 56 GMRES iterations, and the base's factor saves the
/// factorisation (the M = 19 205 family: 0.88 of its CPU time); at level 7 it cost more
/// iterations than it saved (the 5P4E family at 40 C, 2 GPa, 7 m/s: 1.31 times the time). Not
/// on level 9: its factor is gigabytes, and kept with a base's solution beside another
/// family's level-9 finish (which [`FINEST_FINISH`] lets run only after the first) it took a
/// two-thread sweep of two such families past 24 GiB (killed for memory at 24.4 GB).
pub(crate) const HANDED_LEVELS: std::ops::RangeInclusive<u32> = 8..=8;

/// Consecutive steps at the smallest damping after which [`iterate`] gives up.
const STALLED_STEPS: usize = 3;

/// The forcing term of the first step: its linear system solved to a tenth.
pub(crate) const FIRST_FORCING: f64 = 0.1;

/// The forcing term of the first step from a warm start ([`super::warm`]) on a finest level
/// `level`. Near the solution a first step solved to a tenth leaves about a tenth of the
/// distance for the next ones, where a step solved to a hundredth is in the quadratic regime
/// at once; the stopping rule is the same. How far to go is a trade of GMRES iterations
/// against factorisations, and a factorisation's share grows with the level. Measured at
/// level 7 (four Figs. 4-6 families, members from their base): 0.01 takes Newton steps
/// 22-33 -> 16-29 per family and the members' time -9 to -27 % against 0.1; 1e-3 gains
/// nothing more (-6 to +4 %), 1e-4 and 1e-6 cost 9-24 % more than 0.01 (more GMRES
/// iterations than the steps they save). At
/// level 8 (the M 19 205 family) 1e-4 solves every member in one Newton step instead of two,
/// the members' time -34 % against 0.01, outputs within 1e-6 of solves to 1e-11.
pub(crate) fn warm_first_forcing(level: u32) -> f64 {
    if level >= 8 {
        1e-4
    } else {
        0.01
    }
}

/// GMRES iterations above which a step's lagged factor (the last step's, kept where the
/// active set has not changed) gives way to a new one, the system solved again. A fresh
/// factor takes 1-16 iterations on the hard cases; a factorisation costs what 30-100
/// iterations do at level 7 (0.15-0.4 s against 4-5 ms per Jacobian-vector product), so a
/// factor that still preconditions within 20 saves the factorisation, and one that does not
/// costs those 20 products at most. Far from the solution the Jacobian changes too fast for
/// a lagged factor (a kept factorisation failed on the cold solves before); near it, as a
/// warm start is, it changes little.
const LAG_ITERATIONS: usize = 20;

/// Largest forcing term at which the last step's factor preconditions a system whose
/// unknowns have moved ([`lagged`]): 0.05, the last step having cut the residual fourfold
/// or more (the forcing term is `0.9 (|F_k| / |F_k-1|)^2`). Far from the solution a mapped
/// factor's steps, solved only to their loose forcing term, no longer converge: the cold 5P4E
/// base at 40 C, 2 GPa, 7 m/s, mapped at any forcing term, took 29 Newton steps on its level 6
/// instead of 7 and its family of nine 1.6 times as long. From 0.05 that family took 0.92 of its
/// time (`farm-bench -n 4`, one thread, 2-core AMD EPYC), 45 factorisations instead of 55.
const REMAP_FORCING: f64 = 0.05;

mod lagged;
#[cfg(test)]
mod tests;
