//! Jobs: each solve of a target as its cache key, a readable label, what to solve and the
//! job of the base it starts from. The one rule from a case to its solver parameters
//! ([`Params::for_problem`], and [`line::Params::for_problem`] for a line contact) is applied
//! here for every target's contacts ([`point_jobs`], [`line_job`]).

use super::base::base_of;
use super::keys::{case_key, line_key, line_revisions, point_revisions};
use super::label::case_label;
use super::outcome::{CaseOutcome, ThermalFailure};
use crate::physics::case::Physics;
use crate::physics::case::{Case, CaseError, CaseForm, Problem};
use crate::physics::line_contact::{LinePhysicalCase, LineProblem};
use crate::physics::lubricant::LubricantTable;
use crate::physics::thermal::{ThermalContact, TARGET_INPUTS};
use crate::pipeline::error::PipelineError;
use crate::solver::grid::Domain;
use crate::solver::point::{Edge, FrictionRegion, Params, Start};
use crate::solver::thermal::point_thermal;
use crate::solver::{line, point};

/// What a job solves, with its parameters.
#[derive(Debug, Clone)]
pub enum Solve {
    /// An elliptical contact (multigrid).
    Point {
        /// The dimensionless problem.
        problem: Problem,
        /// Solver parameters (boxed: they are most of the variant's size).
        params: Box<Params>,
        /// The thermal scales, where the case has them: the solution is post-processed with
        /// each of [`TARGET_INPUTS`].
        thermal: Option<Box<ThermalContact>>,
    },
    /// A line contact (1-D Newton).
    Line {
        /// The dimensionless problem.
        problem: LineProblem,
        /// Solver parameters.
        params: line::Params,
    },
}

impl Solve {
    /// Solves it (no progress observer), a point contact from `start` where one is given
    /// (its base's solution), and the start it gives its own members where `keep_start`.
    pub fn run(&self, start: Option<&Start>, keep_start: bool) -> (CaseOutcome, Option<Start>) {
        match self {
            Solve::Point {
                problem,
                params,
                thermal,
            } => {
                let r = match start {
                    Some(s) => point::solve_from(problem, params, s, None),
                    None => point::solve(problem, params, None),
                };
                let mut outcome = CaseOutcome::of(
                    r.as_ref()
                        .map(|s| (&s.film, &s.friction, &s.info, s.errors.as_ref())),
                );
                if let (Ok(s), Some(contact), CaseOutcome::Solved(solved)) =
                    (&r, thermal, &mut outcome)
                {
                    // A failed post-process leaves the isothermal numbers as they are and
                    // says why on the case's row.
                    match TARGET_INPUTS
                        .iter()
                        .map(|inputs| point_thermal(s, problem, contact, inputs))
                        .collect::<Result<_, _>>()
                    {
                        Ok(thermal) => solved.thermal = thermal,
                        Err(e) => solved.thermal_failure = Some(ThermalFailure::of(&e)),
                    }
                }
                let kept = keep_start.then(|| r.as_ref().ok().map(Start::of)).flatten();
                (outcome, kept)
            }
            Solve::Line { problem, params } => {
                let r = line::solve(problem, params, None);
                (
                    CaseOutcome::of(
                        r.as_ref()
                            .map(|s| (&s.film, &s.friction, &s.info, s.errors.as_ref())),
                    ),
                    None,
                )
            }
        }
    }

    /// The revisions its cache key holds ([`super::keys`]), recorded in its entry's stamp.
    pub fn revisions(&self) -> String {
        match self {
            Solve::Point { .. } => point_revisions(),
            Solve::Line { .. } => line_revisions(),
        }
    }

    /// The expected cost, for ordering the bases largest first: the heavier the load and the
    /// more viscous the lubricant, the longer a solve (the point contact's `M L`; line
    /// contacts last).
    pub fn weight(&self) -> f64 {
        match self {
            Solve::Point {
                problem, params, ..
            } => {
                problem.groups.m.max(1.0)
                    * problem.groups.l.max(1.0)
                    * 4f64.powi(params.level as i32)
            }
            Solve::Line { .. } => 0.0,
        }
    }
}

/// One solve of a target: its cache key, what it is in words, and what to solve.
#[derive(Debug, Clone)]
pub struct Job {
    /// The cache key ([`super::keys`]).
    pub key: String,
    /// The case in words, for listings of missing cases and shard logs.
    pub label: String,
    /// What to solve.
    pub solve: Solve,
    /// The job of the base it starts from ([`base_of`]), solved first.
    pub base: Option<Box<Job>>,
}

impl Job {
    /// The key of the family's root: the base at the end of the chain of bases (its own key
    /// where it has no base). Shards keep a family together.
    pub fn family(&self) -> &str {
        match &self.base {
            Some(b) => b.family(),
            None => &self.key,
        }
    }
}

/// The thermal scales of a case: a physical case with a Table 1 lubricant, else `None`.
pub fn thermal_contact(
    case: &Case,
    problem: &Problem,
    lubricants: &LubricantTable,
) -> Option<ThermalContact> {
    match &case.spec {
        CaseForm::Physical(p) => ThermalContact::of_point(p, problem, lubricants),
        CaseForm::Dimensionless(_) => None,
    }
}

/// The job of a point case at `params` (the one rule's, [`Params::for_problem`], or a
/// target's own on top of them), with the job of its base ([`base_of`]) at the same
/// parameters; `label` names it.
pub fn point_job(
    case: &Case,
    problem: &Problem,
    params: Params,
    label: String,
    lubricants: &LubricantTable,
) -> Result<Job, CaseError> {
    let base = match base_of(case) {
        Some(b) => {
            let bp = Problem::from_case(&b, lubricants)?;
            let label = format!("base {}", case_label(&b, params.level));
            Some(Box::new(point_job(
                &b,
                &bp,
                params.clone(),
                label,
                lubricants,
            )?))
        }
        None => None,
    };
    Ok(Job {
        key: case_key(case, &params, base.as_deref().map(|b| b.key.as_str())),
        label,
        solve: Solve::Point {
            problem: problem.clone(),
            params: Box::new(params),
            thermal: thermal_contact(case, problem, lubricants).map(Box::new),
        },
        base,
    })
}

/// The setup a point case is solved in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Setup {
    /// THE rule ([`Params::for_problem`]): the case's domain, the flooded far field, the
    /// loaded film's friction. Every result of the product.
    Rule,
    /// The paper's: its domain (`-2.5..1.5 x -2..2`), `P = 0` on the edge and Eq. (8) over
    /// every pressurised node, on top of the rule; drawn beside Fig. 6 to show what the
    /// paper's domain did to its light contacts (docs/RESULTS.md).
    Paper,
}

impl Setup {
    /// The solver parameters of `problem` at `level` in this setup.
    pub fn params(self, problem: &Problem, level: u32) -> Params {
        let rule = Params::for_problem(problem, level);
        match self {
            Setup::Rule => rule,
            Setup::Paper => {
                let mut paper = rule;
                paper.domain = Domain::default();
                paper.edge = Edge::Zero;
                paper.friction.region = FrictionRegion::Domain;
                paper
            }
        }
    }
}

/// A point case's job, with the problem and parameters it solves.
#[derive(Debug, Clone)]
pub struct PointJob {
    /// The job.
    pub job: Job,
    /// The case's dimensionless problem.
    pub problem: Problem,
    /// Its solver parameters.
    pub params: Params,
}

/// The jobs of `cases` at `level`, each with the parameters its problem calls for
/// ([`Params::for_problem`]), labelled `case 1`, `case 2`, ... in order. Cases that do not
/// resolve into a problem are an error (the sweep file is wrong).
pub fn point_jobs(cases: &[Case], level: u32) -> Result<Vec<PointJob>, PipelineError> {
    point_jobs_in(cases, level, Setup::Rule)
}

/// The jobs of `cases` at `level` in `setup` (as [`point_jobs`] for [`Setup::Rule`]).
pub fn point_jobs_in(
    cases: &[Case],
    level: u32,
    setup: Setup,
) -> Result<Vec<PointJob>, PipelineError> {
    let lubricants = LubricantTable::table1();
    cases
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let problem = Problem::from_case(c, &lubricants)
                .map_err(|e| PipelineError::case(format!("case {}", i + 1), e))?;
            let params = setup.params(&problem, level);
            let label = format!("case {} ({})", i + 1, case_label(c, params.level));
            let job = point_job(c, &problem, params.clone(), label, &lubricants)
                .map_err(|e| PipelineError::case(format!("case {}: base", i + 1), e))?;
            Ok(PointJob {
                job,
                problem,
                params,
            })
        })
        .collect()
}

/// A line contact's job, with the problem and parameters it solves.
#[derive(Debug, Clone)]
pub struct LineJob {
    /// The job.
    pub job: Job,
    /// The contact's dimensionless problem.
    pub problem: LineProblem,
    /// Its solver parameters.
    pub params: line::Params,
}

/// The job of the line contact `case` with `physics` at `level`, with the parameters its
/// problem calls for (the line solver's rule, [`line::Params::for_problem`]); `label` names it.
pub fn line_job(
    case: &LinePhysicalCase,
    physics: Physics,
    level: u32,
    label: String,
) -> Result<LineJob, CaseError> {
    let problem = LineProblem::from_physical(case, physics)?;
    let params = line::Params::for_problem(&problem, level);
    let job = Job {
        key: line_key(case, &physics, &params),
        label,
        solve: Solve::Line {
            problem: problem.clone(),
            params: params.clone(),
        },
        base: None,
    };
    Ok(LineJob {
        job,
        problem,
        params,
    })
}
