//! One contact solved as `repro solve` solves it, for every caller (the command line, the
//! Python package): its inputs ([`SolveInputs`], the flags as plain data) turned once into a
//! [`Case`] and solver parameters by the one case -> parameters rule, solved (from the case's
//! base, as every sweep, unless `cold`), and reported ([`Solved::json`], [`Solved::text`]).
//! The same inputs give the same bits whoever asks.

mod report;
mod thermal;

pub use crate::report::inputs::{InputError, SolveInputs};

use crate::report::inputs::flag_error;
pub use report::{line_report, point_report, rolling_text, SolveReport};
pub use thermal::{describe as thermal_text, json_of as thermal_json};

use crate::paper::prediction::heat::{HeatCorrection, MaybeHeat};
use crate::physics::case::{Case, Problem};
use crate::physics::line_contact::LineProblem;
use crate::physics::lubricant::LubricantTable;
use crate::pipeline::base::solve_case;
use crate::pipeline::error::PipelineError;
use crate::solver::line::{self, LineSolution};
use crate::solver::output::{Progress, SolveError};
use crate::solver::point::{self, PointSolution};

/// Why [`solve`] gave no result: its inputs (naming the flag), the solver, or the pipeline
/// around it (the base's lubricant, ...).
#[derive(Debug, thiserror::Error)]
pub enum SolveFailure {
    /// An input is missing, out of range or mixed with one it cannot go with.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The solve did not produce a trustworthy answer (with its residual history).
    #[error(transparent)]
    Solve(SolveError),
    /// The pipeline could not run the solve.
    #[error(transparent)]
    Pipeline(PipelineError),
}

impl From<PipelineError> for SolveFailure {
    fn from(e: PipelineError) -> Self {
        match e {
            PipelineError::Solve(e) => SolveFailure::Solve(e),
            e => SolveFailure::Pipeline(e),
        }
    }
}

/// An elliptical contact solved: what it was, and its solution and heat correction.
pub struct PointSolved {
    /// The case the inputs describe.
    pub case: Case,
    /// The dimensionless problem solved.
    pub problem: Problem,
    /// The solver's parameters (the rule's, with the numerics inputs on top).
    pub params: point::Params,
    /// The solution: fields, film, friction, how the solve went.
    pub solution: PointSolution,
    /// The shear-heating correction of its sliding friction, where it can be computed.
    pub heat: MaybeHeat,
}

/// A line contact solved.
pub struct LineSolved {
    /// The dimensionless problem solved.
    pub problem: LineProblem,
    /// The solver's parameters.
    pub params: line::Params,
    /// The solution.
    pub solution: LineSolution,
}

/// A contact solved, point or line.
pub enum Solved {
    /// An elliptical contact (multigrid).
    Point(Box<PointSolved>),
    /// A line contact (Newton).
    Line(Box<LineSolved>),
}

impl Solved {
    /// The object of `repro solve --json`.
    pub fn json(&self) -> serde_json::Value {
        match self {
            Solved::Point(p) => {
                let mut v = point_report(&p.problem, &p.solution).json();
                v["thermal"] = thermal::json_of(&p.heat);
                if let Some(patches) = report::patches_json(&p.solution) {
                    v["patches"] = patches;
                }
                if let Some(nested) = report::nested_json(&p.solution) {
                    v["nested"] = nested;
                }
                v
            }
            Solved::Line(l) => line_report(&l.problem, &l.solution).json(),
        }
    }

    /// The summary of `repro solve` and its warning (the thermal correction's, printed on
    /// stderr).
    pub fn text(&self) -> (String, Option<String>) {
        match self {
            Solved::Point(p) => {
                let (line, warning) = thermal::describe(&p.heat);
                (report::point_text(&p.problem, &p.solution) + &line, warning)
            }
            Solved::Line(l) => (report::line_text(&l.problem, &l.solution), None),
        }
    }
}

/// Solves the contact `inputs` describe, as `repro solve` does: a point contact through its
/// base ([`solve_case`]; from the Hertzian pressure alone when `cold`), a line contact
/// (`line`) by Newton. `on_base` hears of each base solved first (with the level),
/// `observer` of every solver step. The inputs are checked in the order the command line
/// checks its flags, so the first error is the same.
pub fn solve(
    inputs: &SolveInputs,
    on_base: &mut dyn FnMut(&Case, u32),
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<Solved, SolveFailure> {
    let lubricants = LubricantTable::table1();
    if inputs.line {
        let problem = inputs.line_problem()?;
        let params = inputs.line_params(&problem)?;
        let solution = line::solve(&problem, &params, observer).map_err(SolveFailure::Solve)?;
        return Ok(Solved::Line(Box::new(LineSolved {
            problem,
            params,
            solution,
        })));
    }
    let case = inputs.case()?;
    let problem = Problem::from_case(&case, &lubricants).map_err(flag_error)?;
    let params = inputs.params(&problem)?;
    let thermal = inputs.thermal_inputs()?;
    // A composite grid starts cold (its whole-domain level from the Hertzian pressure): a
    // base would be solved for nothing.
    let solution = if inputs.cold || params.patch.is_some() {
        point::solve(&problem, &params, observer).map_err(SolveFailure::Solve)?
    } else {
        let level = params.level;
        let mut said = |b: &Case| on_base(b, level);
        solve_case(&case, &problem, &params, &lubricants, &mut said, observer)?
    };
    let heat = HeatCorrection::of_solution(&case, &problem, &solution, &thermal);
    Ok(Solved::Point(Box::new(PointSolved {
        case,
        problem,
        params,
        solution,
        heat,
    })))
}
