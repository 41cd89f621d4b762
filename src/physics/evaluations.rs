//! Which optional physical effects a solve evaluated: "simulate only the effects a scene calls
//! for", checked.
//!
//! The effects a case does not ask for are already left out by construction: a case's
//! [`Viscosity`](super::viscosity::Viscosity), [`Density`](super::density::Density) and
//! [`Rheology`](super::rheology::Rheology) are enums built from its [`Physics`](super::case::Physics),
//! so a Barus case holds no Roelands parameters, and the rolling friction is an `Option` the
//! solver fills only when asked. What construction cannot show is that no code path evaluates
//! a law it was not given (say, a density table filled for every case "just in case", or
//! `tau_c` computed with Roelands). So each optional effect's evaluation calls [`record`], which
//! in the crate's own unit-test build counts per thread, and in every other build compiles to
//! nothing: the release solver pays nothing for the check.
//!
//! The counters are thread-local because the unit tests run in parallel threads and a
//! point-contact solve runs on the caller's thread; a test reads them with [`take`], which also
//! resets them.

/// An optional effect whose evaluations are counted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Effect {
    /// The Roelands viscosity law (Barus is the alternative).
    Roelands,
    /// The Dowson-Higginson density law (incompressible is the alternative).
    DowsonHigginson,
    /// Any Eyring function: mean stress, flow factors, conductances (Newtonian is the
    /// alternative).
    Eyring,
    /// The rolling (Poiseuille) part of the friction, one count per friction evaluation.
    RollingFriction,
    /// The limiting shear stress's saturation of the Eyring stress (plain Eyring is the
    /// alternative).
    LimitingShearStress,
}

/// Number of [`Effect`]s.
pub const EFFECTS: usize = 5;

/// Evaluations counted per effect, indexed by `Effect as usize`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EvaluationCounts(pub [u64; EFFECTS]);

impl EvaluationCounts {
    /// Evaluations of `effect`.
    pub fn of(&self, effect: Effect) -> u64 {
        self.0[effect as usize]
    }
}

#[cfg(test)]
thread_local! {
    static COUNTS: std::cell::Cell<[u64; EFFECTS]> = const { std::cell::Cell::new([0; EFFECTS]) };
}

/// Notes one evaluation of `effect` (counted in unit-test builds only).
#[inline(always)]
pub(crate) fn record(effect: Effect) {
    #[cfg(test)]
    COUNTS.with(|c| {
        let mut a = c.get();
        a[effect as usize] += 1;
        c.set(a);
    });
    #[cfg(not(test))]
    let _ = effect;
}

/// The counts of this thread since the last call, and resets them.
#[cfg(test)]
pub(crate) fn take() -> EvaluationCounts {
    EvaluationCounts(COUNTS.with(|c| c.replace([0; EFFECTS])))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::{Case, CaseForm, DimensionlessCase, Physics, Problem};
    use crate::physics::density::DensityLaw;
    use crate::physics::lubricant::LubricantTable;
    use crate::physics::rheology::{LimitingShearStress, Rheology};
    use crate::physics::viscosity::ViscosityLaw;
    use crate::solver::point::{solve, Params};

    /// A moderately loaded circular contact with the given physics (Roelands and
    /// Dowson-Higginson need the physical `eta0` and `p_H`, given here for every case so that
    /// the cases differ only in their physics).
    fn case(physics: Physics) -> Problem {
        let case = Case {
            spec: CaseForm::Dimensionless(DimensionlessCase {
                m: 100.0,
                l: 10.0,
                s_bar: 0.1,
                d: 1.0,
                slip: 0.01,
                eta0_pa_s: Some(0.05),
                ph_pa: Some(1e9),
            }),
            physics,
        };
        Problem::from_case(&case, &LubricantTable::table1()).unwrap()
    }

    /// Solves at level 4 (a 32 x 32 grid is enough to run every code path) and returns what
    /// was evaluated, from building the problem to the friction.
    fn evaluated(physics: Physics, rolling: bool) -> EvaluationCounts {
        evaluated_with_cycles(physics, rolling).0
    }

    /// The counts and the finest-level cycles of the solve.
    fn evaluated_with_cycles(physics: Physics, rolling: bool) -> (EvaluationCounts, usize) {
        take();
        let problem = case(physics);
        let params = {
            let mut params = Params::at_level(4);
            params.friction.rolling = rolling;
            params
        };
        let s = solve(&problem, &params, None).unwrap();
        let _ = problem.tau_c();
        assert_eq!(s.friction.rolling.is_some(), rolling);
        (take(), s.info.cycles)
    }

    #[test]
    fn a_case_evaluates_only_the_effects_it_asks_for() {
        let plain = Physics {
            viscosity: ViscosityLaw::Barus,
            density: DensityLaw::Incompressible,
            rheology: Rheology::Newtonian,
        };
        let counts = evaluated(plain, false);
        assert_eq!(
            counts,
            EvaluationCounts::default(),
            "Barus-incompressible-Newtonian"
        );

        // Each effect alone: only its own counter moves. This is also the control that the
        // counters are wired in (a counter that never counts would pass the line above).
        for (physics, rolling, effect) in [
            (
                Physics {
                    viscosity: ViscosityLaw::Roelands,
                    ..plain
                },
                false,
                Effect::Roelands,
            ),
            (
                Physics {
                    density: DensityLaw::DowsonHigginson,
                    ..plain
                },
                false,
                Effect::DowsonHigginson,
            ),
            (
                Physics {
                    rheology: Rheology::Eyring,
                    ..plain
                },
                false,
                Effect::Eyring,
            ),
            (plain, true, Effect::RollingFriction),
        ] {
            let counts = evaluated(physics, rolling);
            for other in [
                Effect::Roelands,
                Effect::DowsonHigginson,
                Effect::Eyring,
                Effect::RollingFriction,
                Effect::LimitingShearStress,
            ] {
                let n = counts.of(other);
                if other == effect {
                    assert!(n > 0, "{effect:?} asked for but never evaluated");
                } else {
                    assert_eq!(
                        n, 0,
                        "{other:?} evaluated by a case asking only for {effect:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_paper_physics_evaluates_every_effect_but_the_limit() {
        let (counts, cycles) = evaluated_with_cycles(Physics::figs_4_to_7(), true);
        for effect in [
            Effect::Roelands,
            Effect::DowsonHigginson,
            Effect::Eyring,
            Effect::RollingFriction,
        ] {
            assert!(counts.of(effect) > 0, "{effect:?}");
        }
        // The paper's Eyring never touches the limiting shear stress; a case that asks for it
        // evaluates it (the control that its counter is wired in).
        assert_eq!(counts.of(Effect::LimitingShearStress), 0);
        let lss = Physics {
            rheology: Rheology::EyringLss(LimitingShearStress {
                lambda: 0.05,
                tau_l0_pa: 2e6,
            }),
            ..Physics::figs_4_to_7()
        };
        assert!(evaluated(lss, false).of(Effect::LimitingShearStress) > 0);
        // The rolling friction is one pass over the solution after each finest cycle (the
        // stopping rule watches it) and one over the converged solution: never per sweep.
        assert_eq!(counts.of(Effect::RollingFriction), cycles as u64 + 1);
    }
}
