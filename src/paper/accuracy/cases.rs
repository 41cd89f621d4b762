//! The representative cases of the level study: each a problem with the parameter rule its
//! targets use, solved alone at any level.

use crate::paper::cases::shipped_sweep;
use crate::paper::figures::line::table3_line_cases;
use crate::paper::table4::Table4Case;
use crate::paper::REGISTRY;
use crate::physics::case::{Case, CaseForm, LubricantSpec, PhysicalCase, Physics, Problem};
use crate::physics::density::DensityLaw;
use crate::physics::line_contact::LineProblem;
use crate::physics::lubricant::LubricantTable;
use crate::physics::rheology::Rheology;
use crate::physics::viscosity::ViscosityLaw;
use crate::pipeline::error::PipelineError;
use crate::pipeline::sweep::PointSpec;
use crate::solver::line;
use crate::solver::output::SolveError;
use crate::solver::point;
use crate::solver::point::composite::Patch;

/// A point contact of the study: name, description, sweeps, case, parameters at a level,
/// the case whose reference it is measured against ([`AccuracyCase`]'s fields).
type PointEntry<'a> = (
    &'static str,
    &'static str,
    &'static [&'static str],
    &'a Case,
    fn(&Problem, u32) -> point::Params,
    Option<&'static str>,
);

/// A contact and how the pipeline solves it at a level.
#[derive(Debug, Clone)]
pub enum AccuracyProblem {
    /// An elliptical contact, solved by [`point::solve`] with `params(problem, level)`.
    Point {
        /// The problem.
        problem: Box<Problem>,
        /// Solver parameters of the problem at a level (the ones its targets use).
        params: fn(&Problem, u32) -> point::Params,
    },
    /// A line contact, solved by [`line::solve`] with `params(problem, level)`.
    Line {
        /// The problem.
        problem: Box<LineProblem>,
        /// Solver parameters of the problem at a level.
        params: fn(&LineProblem, u32) -> line::Params,
    },
}

/// What one solve at one level gave.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelOutputs {
    /// Central film in the solver's unit (`H = h/c` for the point contact), as the rule
    /// reports it: tau-extrapolated where the level's own estimate misses the film bound.
    pub h_central: f64,
    /// The grid's own central film ([`point::PointSolution::grid_h_central`]): the uniform
    /// level's, whose convergence the reference reads.
    pub h_central_grid: f64,
    /// Minimum film in the solver's unit, as the solve reports it: a top refined across the
    /// rolling direction's, where the rule added one ([`LevelOutputs::across`]).
    pub h_min: f64,
    /// Sliding reduced friction.
    pub mu_bar: f64,
    /// Finest-level cycles.
    pub cycles: usize,
    /// The level the solve ended on: the one asked for, or a finer one where the rule
    /// refined (a design with the rule's refinement, [`rule_params`]).
    pub level: u32,
    /// Whether the solve ended on a top refined across the rolling direction
    /// ([`crate::solver::grid::Grid::refined_y`]): twice the level's mesh across.
    pub across: bool,
}

impl LevelOutputs {
    /// The outputs of the point solution `s`.
    fn of_point(s: &point::PointSolution) -> Self {
        LevelOutputs {
            h_central: s.film.h_central,
            h_central_grid: s.grid_h_central(),
            h_min: s.film.h_min,
            mu_bar: s.friction.sliding,
            cycles: s.info.cycles,
            level: s.info.level,
            across: s.grid.is_refined_y(),
        }
    }
}

impl AccuracyProblem {
    /// Solves at `level`.
    pub fn solve(&self, level: u32) -> Result<LevelOutputs, SolveError> {
        match self {
            AccuracyProblem::Point { problem, params } => {
                point::solve(problem, &params(problem, level), None)
                    .map(|s| LevelOutputs::of_point(&s))
            }
            AccuracyProblem::Line { problem, params } => {
                line::solve(problem, &params(problem, level), None).map(|s| LevelOutputs {
                    h_central: s.film.h_central,
                    h_central_grid: s.film.h_central,
                    h_min: s.film.h_min,
                    mu_bar: s.friction.sliding,
                    cycles: s.info.cycles,
                    level,
                    across: false,
                })
            }
        }
    }

    /// The domain check of a point contact: solved at `level` with its parameters' domain's
    /// inlet and sides doubled ([`crate::solver::grid::Domain::doubled`]), on the mesh of
    /// `level - 1` on its own domain; `None` for a line contact.
    pub fn solve_doubled(&self, level: u32) -> Option<Result<LevelOutputs, SolveError>> {
        match self {
            AccuracyProblem::Point { problem, params } => {
                let rule = params(problem, level);
                let doubled = point::Params {
                    domain: rule.domain.doubled(),
                    ..rule
                };
                Some(point::solve(problem, &doubled, None).map(|s| LevelOutputs::of_point(&s)))
            }
            AccuracyProblem::Line { .. } => None,
        }
    }

    /// "point" or "line".
    pub fn kind(&self) -> &'static str {
        match self {
            AccuracyProblem::Point { .. } => "point",
            AccuracyProblem::Line { .. } => "line",
        }
    }

    /// Grid intervals of `level` (`2^(level+1)` per direction; twice as many across the
    /// rolling direction on a top refined `across` it), as written in the CSV.
    pub fn points(&self, level: u32, across: bool) -> String {
        let n = 1u64 << (level + 1);
        match self {
            AccuracyProblem::Point { .. } if across => format!("{n}x{}", 2 * n),
            AccuracyProblem::Point { .. } => format!("{n}x{n}"),
            AccuracyProblem::Line { .. } => format!("{n}"),
        }
    }
}

/// A case of the study.
#[derive(Debug, Clone)]
pub struct AccuracyCase {
    /// Short name (CSV and legend).
    pub name: &'static str,
    /// What it is.
    pub description: &'static str,
    /// The shipped sweeps it stands for (`cases/<name>.toml`): the level recommended for
    /// every target that draws one of them ([`AccuracyCase::targets`]).
    pub sweeps: &'static [&'static str],
    /// Added to the study's levels: a 1-D level costs so little that the line contact is
    /// studied on finer grids (its level `n + offset` stands beside the point level `n`).
    pub level_offset: u32,
    /// The contact.
    pub contact: AccuracyProblem,
    /// The case of the same contact on the rule's grid whose reference this one's errors are
    /// measured against, for a design of the grid (the inlet patch: issue 54's probes), so
    /// that its series compares with that case's; `None` for a case of its own.
    pub reference_from: Option<&'static str>,
}

impl AccuracyCase {
    /// The targets it stands for: those that draw one of its sweeps, in the registry's order
    /// (a figure added on a sweep the study covers is covered without a word here).
    pub fn targets(&self) -> Vec<&'static str> {
        REGISTRY
            .iter()
            .filter(|a| {
                a.sweep_file()
                    .is_some_and(|f| self.sweeps.contains(&f.name))
            })
            .map(|a| a.name())
            .collect()
    }
}

/// The parameters the figure targets use (the rule, [`point::Params::for_problem`]) on the
/// level given alone, as `repro solve --exact-level` solves it ([`point::Params::exact_level`]):
/// a point of the study is a solve on its own square level (a figure's closed film is
/// re-solved one level finer; here the level fails, and its point is left out, rather than a
/// finer level's time and error being shown under its name). The rule itself is a design of
/// the study ([`rule_params`]).
pub fn pipeline_params(problem: &Problem, level: u32) -> point::Params {
    point::Params::for_problem(problem, level).exact_level()
}

/// The rule itself ([`point::Params::for_problem`]), as a figure solves a case from the
/// level given: refined one level where the friction's estimate misses 1 % or the film
/// closes, and a top refined across the rolling direction added where the minimum film's
/// misses 10 % (issue 54's adopted design, measured against the square levels' reference).
pub fn rule_params(problem: &Problem, level: u32) -> point::Params {
    point::Params::for_problem(problem, level)
}

/// [`pipeline_params`] on the composite grid with the inlet patch (`repro solve --patch
/// inlet`): a design of the grid issue 54 measures against the rule's.
pub fn inlet_patch_params(problem: &Problem, level: u32) -> point::Params {
    point::Params {
        patch: Some(Patch::Inlet.set(level)),
        ..pipeline_params(problem, level)
    }
}

/// The line solver's rule ([`line::Params::for_problem`]) without its refinement, for the
/// same reason as [`pipeline_params`].
pub fn line_pipeline_params(problem: &LineProblem, level: u32) -> line::Params {
    line::Params {
        refinement_levels: 0,
        ..line::Params::for_problem(problem, level)
    }
}

/// The first physical case of the shipped sweep `sweep` that `matches`; `what` names it in
/// the error when there is none.
fn shipped_physical_case(
    sweep: &str,
    what: &str,
    matches: impl Fn(&PhysicalCase) -> bool,
) -> Result<Case, PipelineError> {
    shipped_sweep(sweep)?
        .cases
        .into_iter()
        .find(|c| matches!(&c.spec, CaseForm::Physical(p) if matches(p)))
        .ok_or_else(|| PipelineError::Input(format!("cases/{sweep}.toml: no {what}")))
}

/// The representative cases, cheapest first:
///
/// - `light-barus`: the lightest load of the Figs. 1-3 sweep (M 50, L 10, S-bar 0.1,
///   Barus, incompressible, Eyring; `cases/fig1-3.toml`), for fig1-fig3;
/// - `heavy-barus`: the heaviest corner of the same sweep (M 1000, L 15, alpha-bar about 55),
///   so that the most demanding case of fig1-fig3 decides their level;
/// - `table4`: the Appendix case (mineral oil A, 3 GPa, Roelands, Dowson-Higginson), the
///   heaviest physics of Figs. 4-6, for fig4-fig6. Solved with the figures' parameters, not
///   Table 4's: a level whose minimum film is not positive fails, as it does in a figure
///   (Table 4 itself reports its level-5 row anyway);
/// - `ellipse-1/5`: Rx/Ry = 1/5 at 3 GPa, 60 C (Table 3, `cases/fig7.toml`), for fig7;
/// - `light-far-field`: Fig. 6 case 23 (5P4E, 40 C, 1 GPa, 12 m/s, S 0.5 %, tau0 6 MPa; M 4.76,
///   L 57), the light, piezoviscous end of the Table 2 grid on its wide domain with the far
///   field, whose film and friction converge at order 1.1-1.4 (docs/ACCURACY_NOTES.md), for
///   fig4-fig6;
/// - `m1-l10`: M 1, L 10, S-bar 0.1 (Barus, incompressible, Eyring), the light end of the
///   envelope a study can reach (no figure has it: it stands for no target);
/// - `heavy-m19205`: Fig. 4 case 221 (mineral oil A, 100 C, 3 GPa, 2 m/s, S 0.5 %, tau0 6 MPa;
///   M 19 205), the heaviest load of Table 2, whose film closes below level 8, for fig4;
/// - `line` (with `with_line`): the line contact of Table 3 at 3 GPa, 40 C, for fig7, two
///   levels finer than the point contacts (the dense Newton solve of the 1-D solver is
///   O(n^3): level 10 takes about 1.5 s, level 11 7 s).
pub fn accuracy_cases(with_line: bool) -> Result<Vec<AccuracyCase>, PipelineError> {
    let lubs = LubricantTable::table1();
    // A dimensionless case of the Figs. 1-3 kind (S-bar 0.1, Barus, incompressible, Eyring).
    let barus = |m: f64, l: f64| {
        PointSpec {
            m: Some(m),
            l: Some(l),
            s_bar: Some(0.1),
            tau0_hat: Some(2.0),
            ..PointSpec::default()
        }
        .to_case(
            "accuracy",
            Physics {
                viscosity: ViscosityLaw::Barus,
                density: DensityLaw::Incompressible,
                rheology: Rheology::Eyring,
            },
        )
        .map_err(PipelineError::from)
    };
    let light = barus(50.0, 10.0)?;
    let heavy = barus(1000.0, 15.0)?;
    let m1 = barus(1.0, 10.0)?;
    let table4 = Table4Case::shipped()?.case;
    let ellipse = shipped_physical_case("fig7", "Rx/Ry = 1/5 case at 3 GPa, 60 C", |p| {
        (p.rx_m / p.ry_m - 0.2).abs() < 1e-9
            && (p.ph_pa - 3e9).abs() < 1.0
            && matches!(&p.lubricant, LubricantSpec::Named { temperature_c, .. } if (*temperature_c - 60.0).abs() < 1e-9)
    })?;
    // A case of a shipped Table 2 sweep by its lubricant and operating point.
    let table2_case = |sweep: &str,
                       lubricant: &str,
                       t: f64,
                       ph: f64,
                       um: f64,
                       slip: f64,
                       tau0: f64| {
        let what =
            format!("{lubricant} case at {t} C, {ph} Pa, {um} m/s, S {slip}, tau0 {tau0} Pa");
        shipped_physical_case(sweep, &what, |p| {
            matches!(&p.lubricant, LubricantSpec::Named { lubricant: l, temperature_c } if l == lubricant && (*temperature_c - t).abs() < 1e-9)
                && (p.ph_pa - ph).abs() < 1.0
                && (p.um_m_s - um).abs() < 1e-9
                && (p.slip - slip).abs() < 1e-12
                && (p.tau0_pa - tau0).abs() < 1e-3
        })
    };
    let case23 = table2_case("fig6", "5p4e", 40.0, 1e9, 12.0, 0.005, 6e6)?;
    let case221 = table2_case("fig4", "mineral-oil-a", 100.0, 3e9, 2.0, 0.005, 6e6)?;
    let case150 = table2_case("fig4", "mineral-oil-a", 60.0, 3e9, 7.0, 0.005, 8e6)?;
    let (rule, inlet, adopted) = (pipeline_params, inlet_patch_params, rule_params);
    // (name, description, sweeps, case, parameters, reference from): every point contact with
    // the figures' parameters, then issue 54's probes that are not among them (Fig. 4 case
    // 150), the inlet patch's designs of two of them and the rule as a figure solves them,
    // measured against their square levels'.
    #[rustfmt::skip]
    let points: [PointEntry; 12] = [
        ("light-barus", "M 50, L 10, S-bar 0.1, Barus, incompressible, Eyring (Figs. 1-3 sweep)", &["fig1-3"], &light, rule, None),
        ("heavy-barus", "M 1000, L 15, S-bar 0.1, Barus, incompressible, Eyring (Figs. 1-3 sweep, heaviest corner)", &["fig1-3"], &heavy, rule, None),
        ("table4", "Appendix case: mineral oil A, 3 GPa, 40 C, Roelands, Dowson-Higginson, Eyring", &["fig4", "fig5", "fig6"], &table4, rule, None),
        ("ellipse-1/5", "Rx/Ry = 1/5, mineral oil A, 3 GPa, 60 C, 12 m/s, S 0.1 %, tau0 4 MPa (Table 3)", &["fig7"], &ellipse, rule, None),
        ("light-far-field", "Fig. 6 case 23: 5P4E, 40 C, 1 GPa, 12 m/s, S 0.5 %, tau0 6 MPa (M 4.76, L 57, far field)", &["fig4", "fig5", "fig6"], &case23, rule, None),
        ("m1-l10", "M 1, L 10, S-bar 0.1, Barus, incompressible, Eyring (the light end of the envelope)", &[], &m1, rule, None),
        ("heavy-m19205", "Fig. 4 case 221: mineral oil A, 100 C, 3 GPa, 2 m/s, S 0.5 %, tau0 6 MPa (M 19 205)", &["fig4"], &case221, rule, None),
        ("case150", "Fig. 4 case 150: mineral oil A, 60 C, 3 GPa, 7 m/s, S 0.5 %, tau0 8 MPa (M 4 326; issue 54's probe)", &[], &case150, rule, None),
        ("table4-inlet-patch", "the Appendix case with the inlet patch (repro solve --patch inlet), against table4's reference", &[], &table4, inlet, Some("table4")),
        ("case150-inlet-patch", "Fig. 4 case 150 with the inlet patch (repro solve --patch inlet), against case150's reference", &[], &case150, inlet, Some("case150")),
        ("table4-rule", "the Appendix case as a figure solves it from the level (refined where the friction misses 1 %, the top refined across where the minimum film misses 10 %), against table4's reference", &[], &table4, adopted, Some("table4")),
        ("case150-rule", "Fig. 4 case 150 as a figure solves it from the level, against case150's reference", &[], &case150, adopted, Some("case150")),
    ];
    let mut cases = points
        .into_iter()
        .map(
            |(name, description, sweeps, case, params, reference_from)| {
                Ok(AccuracyCase {
                    name,
                    description,
                    sweeps,
                    level_offset: 0,
                    contact: AccuracyProblem::Point {
                        problem: Box::new(Problem::from_case(case, &lubs).map_err(|e| {
                            PipelineError::case(format!("accuracy case {name}"), e)
                        })?),
                        params,
                    },
                    reference_from,
                })
            },
        )
        .collect::<Result<Vec<_>, PipelineError>>()?;
    if with_line {
        // The heaviest line contact of Table 3 (3 GPa), from cases/fig7.toml.
        let (lines, physics) = table3_line_cases()?;
        let heaviest = lines
            .into_iter()
            .max_by(|a, b| a.ph_pa.total_cmp(&b.ph_pa))
            .ok_or_else(|| PipelineError::Input("cases/fig7.toml: no Table 3 case".into()))?;
        let problem = LineProblem::from_physical(&heaviest, physics)
            .map_err(|e| PipelineError::case("accuracy case line", e))?;
        cases.push(AccuracyCase {
            name: "line",
            description:
                "line contact, mineral oil A, 3 GPa, 40 C, 7 m/s, S 0.1 %, tau0 8 MPa (Table 3)",
            sweeps: &["fig7"],
            level_offset: 2,
            contact: AccuracyProblem::Line {
                problem: Box::new(problem),
                params: line_pipeline_params,
            },
            reference_from: None,
        });
    }
    Ok(cases)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each case stands for the figures that draw its sweeps, in the registry's order: the
    /// rows of `figures/accuracy_levels.csv` (fig1 to fig7) and the case that decides each
    /// come out as they did when the targets were listed by name, and the one case that stands
    /// for no figure (the light end of the envelope) stands for none.
    #[test]
    fn each_case_stands_for_the_figures_that_draw_its_sweeps() {
        let by_case: Vec<(&str, Vec<&str>)> = accuracy_cases(true)
            .unwrap()
            .iter()
            .map(|c| (c.name, c.targets()))
            .collect();
        let barus = vec!["fig1", "fig2", "fig3"];
        let table2 = vec!["fig4", "fig5", "fig6"];
        assert_eq!(
            by_case,
            vec![
                ("light-barus", barus.clone()),
                ("heavy-barus", barus),
                ("table4", table2.clone()),
                ("ellipse-1/5", vec!["fig7"]),
                ("light-far-field", table2),
                ("m1-l10", vec![]),
                ("heavy-m19205", vec!["fig4"]),
                ("case150", vec![]),
                ("table4-inlet-patch", vec![]),
                ("case150-inlet-patch", vec![]),
                ("table4-rule", vec![]),
                ("case150-rule", vec![]),
                ("line", vec!["fig7"]),
            ]
        );
    }
}
