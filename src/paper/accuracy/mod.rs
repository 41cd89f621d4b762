//! What accuracy costs in time: representative cases solved level by level, each level's
//! central film and sliding `mu-bar` compared with a Richardson extrapolation of the two
//! finest levels, against the wall time of its solve (`repro accuracy`).
//!
//! A case of the study is a [`StudyCase`]: a name, the targets it stands for, and a
//! [`Contact`] that knows how to solve itself at a level. Adding a case (the line contact of
//! Fig. 7, say) is adding one entry to [`study_cases`]; the rest (errors, CSV, figure, the
//! recommended level per target) is shared.
//!
//! The error estimate. The discretisation is second order, so with `X_n` the value at level
//! `n` and `f` the finest converged level, `X_R = X_f + (X_f - X_{f-1}) / 3` removes the
//! leading `h^2` term; each level's error is `|X_n / X_R - 1|`. The order observed over the
//! three finest levels, `log2 |X_{f-2} - X_{f-1}| / |X_{f-1} - X_f|`, is reported beside it as a
//! check of that assumption. Where fewer than two consecutive finest levels converged, the
//! finest level is the reference (and its own error is zero, which says nothing): the CSV names
//! the reference used.
//!
//! Timing: each solve runs alone, one after the other, on the calling thread (the point solver
//! is single-threaded), and with `repeats > 1` the median wall time is kept.

pub mod picture;

use crate::paper::figures::line::table3_line_cases;
use crate::paper::table4::Table4Case;
use crate::physics::case::{CaseForm, LubricantSpec, Physics, Problem};
use crate::physics::density::DensityLaw;
use crate::physics::line_contact::LineProblem;
use crate::physics::lubricant::LubricantTable;
use crate::physics::rheology::Rheology;
use crate::physics::viscosity::ViscosityLaw;
use crate::pipeline::csv::{rows, Decimals};
use crate::pipeline::sweep::{shipped_sweep, PointSpec};
use crate::solver::line;
use crate::solver::output::SolveError;
use crate::solver::point;
use serde::Serialize;
use std::time::Instant;

/// Error of `mu-bar` under which a level is taken as good enough for a target.
pub const MU_TOLERANCE: f64 = 0.01;

/// A contact and how the pipeline solves it at a level.
#[derive(Debug, Clone)]
pub enum Contact {
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
pub struct Measured {
    /// Central film in the solver's unit (`H = h/c` for the point contact).
    pub h_central: f64,
    /// Sliding reduced friction.
    pub mu_bar: f64,
    /// Finest-level cycles.
    pub cycles: usize,
}

impl Contact {
    /// Solves at `level`.
    pub fn solve(&self, level: u32) -> Result<Measured, SolveError> {
        match self {
            Contact::Point { problem, params } => {
                point::solve(problem, &params(problem, level), None).map(|s| Measured {
                    h_central: s.film.h_central,
                    mu_bar: s.friction.sliding,
                    cycles: s.info.cycles,
                })
            }
            Contact::Line { problem, params } => {
                line::solve(problem, &params(problem, level), None).map(|s| Measured {
                    h_central: s.film.h_central,
                    mu_bar: s.friction.sliding,
                    cycles: s.info.cycles,
                })
            }
        }
    }

    /// The domain check of a point contact: solved at `level` with its parameters' domain's
    /// inlet and sides doubled ([`crate::solver::grid::Domain::doubled`]), on the mesh of
    /// `level - 1` on its own domain; `None` for a line contact.
    pub fn solve_doubled(&self, level: u32) -> Option<Result<Measured, SolveError>> {
        match self {
            Contact::Point { problem, params } => {
                let rule = params(problem, level);
                let doubled = point::Params {
                    domain: rule.domain.doubled(),
                    ..rule
                };
                Some(point::solve(problem, &doubled, None).map(|s| Measured {
                    h_central: s.film.h_central,
                    mu_bar: s.friction.sliding,
                    cycles: s.info.cycles,
                }))
            }
            Contact::Line { .. } => None,
        }
    }

    /// "point" or "line".
    pub fn kind(&self) -> &'static str {
        match self {
            Contact::Point { .. } => "point",
            Contact::Line { .. } => "line",
        }
    }

    /// Grid points of `level` (`(2^(level+1) + 1)^2` nodes in 2-D, `2^(level+1) + 1` in 1-D),
    /// as written in the CSV.
    pub fn points(&self, level: u32) -> String {
        let n = 1u64 << (level + 1);
        match self {
            Contact::Point { .. } => format!("{n}x{n}"),
            Contact::Line { .. } => format!("{n}"),
        }
    }
}

/// A case of the study.
#[derive(Debug, Clone)]
pub struct StudyCase {
    /// Short name (CSV and legend).
    pub name: &'static str,
    /// What it is.
    pub description: &'static str,
    /// The targets it stands for when the level of each is recommended.
    pub targets: &'static [&'static str],
    /// Added to the study's levels: a 1-D level costs so little that the line contact is
    /// studied on finer grids (its level `n + offset` stands beside the point level `n`).
    pub level_offset: u32,
    /// The contact.
    pub contact: Contact,
}

/// The parameters the figure targets use (the rule, [`point::Params::for_problem`]),
/// without the film's refinement: a point of the study is a solve on its own level (a
/// figure's closed film is re-solved one level finer; here the level fails, and its point is
/// left out, rather than a finer level's time and error being shown under its name).
pub fn pipeline_params(problem: &Problem, level: u32) -> point::Params {
    point::Params {
        film_refinement_levels: 0,
        ..point::Params::for_problem(problem, level)
    }
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
/// - `line` (with `with_line`): the line contact of Table 3 at 3 GPa, 40 C, for fig7, two
///   levels finer than the point contacts (the dense Newton solve of the 1-D solver is
///   O(n^3): level 10 takes about 1.5 s, level 11 7 s).
pub fn study_cases(with_line: bool) -> Result<Vec<StudyCase>, String> {
    let lubs = LubricantTable::table1();
    let light = PointSpec {
        m: Some(50.0),
        l: Some(10.0),
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
    .map_err(|e| e.to_string())?;
    let heavy = PointSpec {
        m: Some(1000.0),
        l: Some(15.0),
        s_bar: Some(0.1),
        tau0_hat: Some(2.0),
        ..PointSpec::default()
    }
    .to_case("accuracy", light.physics)
    .map_err(|e| e.to_string())?;
    let table4 = Table4Case::shipped()?.case;
    let fig7 = shipped_sweep("fig7").map_err(|e| e.to_string())?;
    let ellipse = fig7
        .cases
        .iter()
        .find(|c| match &c.spec {
            CaseForm::Physical(p) => {
                (p.rx_m / p.ry_m - 0.2).abs() < 1e-9
                    && (p.ph_pa - 3e9).abs() < 1.0
                    && matches!(&p.lubricant, LubricantSpec::Named { temperature_c, .. } if (*temperature_c - 60.0).abs() < 1e-9)
            }
            CaseForm::Dimensionless(_) => false,
        })
        .cloned()
        .ok_or("cases/fig7.toml: no Rx/Ry = 1/5 case at 3 GPa, 60 C")?;
    let point = |case: &crate::physics::case::Case,
                 params: fn(&Problem, u32) -> point::Params|
     -> Result<Contact, String> {
        Ok(Contact::Point {
            problem: Box::new(Problem::from_case(case, &lubs).map_err(|e| e.to_string())?),
            params,
        })
    };
    let mut cases = vec![
        StudyCase {
            name: "light-barus",
            description: "M 50, L 10, S-bar 0.1, Barus, incompressible, Eyring (Figs. 1-3 sweep)",
            targets: &["fig1", "fig2", "fig3"],
            level_offset: 0,
            contact: point(&light, pipeline_params)?,
        },
        StudyCase {
            name: "heavy-barus",
            description: "M 1000, L 15, S-bar 0.1, Barus, incompressible, Eyring (Figs. 1-3 sweep, heaviest corner)",
            targets: &["fig1", "fig2", "fig3"],
            level_offset: 0,
            contact: point(&heavy, pipeline_params)?,
        },
        StudyCase {
            name: "table4",
            description: "Appendix case: mineral oil A, 3 GPa, 40 C, Roelands, Dowson-Higginson, Eyring",
            targets: &["fig4", "fig5", "fig6"],
            level_offset: 0,
            contact: point(&table4, pipeline_params)?,
        },
        StudyCase {
            name: "ellipse-1/5",
            description: "Rx/Ry = 1/5, mineral oil A, 3 GPa, 60 C, 12 m/s, S 0.1 %, tau0 4 MPa (Table 3)",
            targets: &["fig7"],
            level_offset: 0,
            contact: point(&ellipse, pipeline_params)?,
        },
    ];
    if with_line {
        // The heaviest line contact of Table 3 (3 GPa), from cases/fig7.toml.
        let (lines, physics) = table3_line_cases()?;
        let heaviest = lines
            .into_iter()
            .max_by(|a, b| a.ph_pa.total_cmp(&b.ph_pa))
            .ok_or("cases/fig7.toml: no Table 3 case")?;
        let problem = LineProblem::from_physical(&heaviest, physics).map_err(|e| e.to_string())?;
        cases.push(StudyCase {
            name: "line",
            description:
                "line contact, mineral oil A, 3 GPa, 40 C, 7 m/s, S 0.1 %, tau0 8 MPa (Table 3)",
            targets: &["fig7"],
            level_offset: 2,
            contact: Contact::Line {
                problem: Box::new(problem),
                params: line::Params::for_problem,
            },
        });
    }
    Ok(cases)
}

/// One level of one case.
#[derive(Debug, Clone)]
pub struct LevelRun {
    /// Grid level.
    pub level: u32,
    /// The solve, or why it failed.
    pub outcome: Result<Measured, SolveError>,
    /// Wall time, s (median over the repeats).
    pub seconds: f64,
}

/// The reference a case's errors are measured against.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    /// Central film.
    pub h_central: f64,
    /// Sliding `mu-bar`.
    pub mu_bar: f64,
    /// "richardson" (second order, two finest levels) or "finest".
    pub kind: &'static str,
    /// Order observed over the three finest levels, film and friction (when three
    /// consecutive finest levels converged and the differences are not zero).
    pub order: Option<(f64, f64)>,
}

/// A case and its levels.
#[derive(Debug, Clone)]
pub struct CaseStudy {
    /// Name.
    pub name: &'static str,
    /// Description.
    pub description: &'static str,
    /// "point" or "line".
    pub kind: &'static str,
    /// The targets it stands for.
    pub targets: &'static [&'static str],
    /// Its level offset (see [`StudyCase::level_offset`]).
    pub level_offset: u32,
    /// Levels, coarse to fine.
    pub levels: Vec<LevelRun>,
    /// The reference of the errors (`None` when nothing converged).
    pub reference: Option<Reference>,
    /// The domain check of a point contact ([`DomainCheck`]).
    pub domain: Option<DomainCheck>,
    /// Points per level (for the CSV).
    points: Vec<String>,
}

/// How much the domain moves a point contact's outputs: the case solved on its domain at
/// the second-finest level of the study against its inlet and sides doubled at the finest
/// (the same mesh).
#[derive(Debug, Clone)]
pub struct DomainCheck {
    /// The doubled domain's level.
    pub level: u32,
    /// The relative change of the central film and of sliding `mu-bar`, or why the doubled
    /// domain's solve failed.
    pub change: Result<(f64, f64), SolveError>,
}

impl DomainCheck {
    /// The check of `case` whose runs are `runs`: `None` for a line contact, or when the
    /// study has no two consecutive finest levels or the coarser one failed.
    fn of(case: &StudyCase, runs: &[LevelRun]) -> Option<DomainCheck> {
        let [.., coarse, fine] = runs else {
            return None;
        };
        let own = coarse.outcome.as_ref().ok()?;
        if fine.level != coarse.level + 1 {
            return None;
        }
        let doubled = case.contact.solve_doubled(fine.level)?;
        Some(DomainCheck {
            level: fine.level,
            change: doubled.map(|d| {
                (
                    (d.h_central / own.h_central - 1.0).abs(),
                    (d.mu_bar / own.mu_bar - 1.0).abs(),
                )
            }),
        })
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// Observed order `log2(|a - b| / |b - c|)` of three consecutive levels.
fn observed_order(a: f64, b: f64, c: f64) -> Option<f64> {
    let r = (a - b).abs() / (b - c).abs();
    (r.is_finite() && r > 0.0).then(|| r.log2())
}

/// The reference of a case from its converged levels.
pub fn reference(levels: &[LevelRun]) -> Option<Reference> {
    let ok: Vec<(u32, Measured)> = levels
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok().map(|m| (r.level, *m)))
        .collect();
    let (&(lf, f), rest) = ok.split_last()?;
    let prev = rest.last().filter(|(l, _)| *l + 1 == lf).map(|p| p.1);
    let Some(c) = prev else {
        return Some(Reference {
            h_central: f.h_central,
            mu_bar: f.mu_bar,
            kind: "finest",
            order: None,
        });
    };
    let order = (rest.len() >= 2 && rest[rest.len() - 2].0 + 2 == lf)
        .then(|| rest[rest.len() - 2].1)
        .and_then(|a| {
            Some((
                observed_order(a.h_central, c.h_central, f.h_central)?,
                observed_order(a.mu_bar, c.mu_bar, f.mu_bar)?,
            ))
        });
    Some(Reference {
        h_central: f.h_central + (f.h_central - c.h_central) / 3.0,
        mu_bar: f.mu_bar + (f.mu_bar - c.mu_bar) / 3.0,
        kind: "richardson",
        order,
    })
}

impl CaseStudy {
    /// Relative errors `(film, mu-bar)` of a level against the reference.
    pub fn errors(&self, run: &LevelRun) -> Option<(f64, f64)> {
        let r = self.reference?;
        let m = run.outcome.as_ref().ok()?;
        Some((
            (m.h_central / r.h_central - 1.0).abs(),
            (m.mu_bar / r.mu_bar - 1.0).abs(),
        ))
    }

    /// The cheapest level whose `mu-bar` error is within `tol`, and that of every finer level
    /// too (a level that is right by chance between two wrong ones is not a choice). `None`
    /// when no level qualifies.
    pub fn cheapest_within(&self, tol: f64) -> Option<&LevelRun> {
        let mut best = None;
        for run in self.levels.iter().rev() {
            match self.errors(run) {
                Some((_, e)) if e <= tol => best = Some(run),
                _ => break,
            }
        }
        best
    }
}

/// Runs the study: each case at `levels` (plus its offset), `repeats` solves per level (the
/// median time is kept); `progress` hears of each level as it finishes.
pub fn run(
    cases: &[StudyCase],
    levels: &[u32],
    repeats: usize,
    progress: &mut dyn FnMut(&StudyCase, &LevelRun),
) -> Vec<CaseStudy> {
    cases
        .iter()
        .map(|case| {
            let mut runs = Vec::new();
            for &l in levels {
                let level = l + case.level_offset;
                let mut times = Vec::new();
                let mut outcome = Err(SolveError::InvalidParams("no solve".into()));
                for _ in 0..repeats.max(1) {
                    let t = Instant::now();
                    outcome = case.contact.solve(level);
                    times.push(t.elapsed().as_secs_f64());
                }
                let run = LevelRun {
                    level,
                    outcome,
                    seconds: median(times),
                };
                progress(case, &run);
                runs.push(run);
            }
            CaseStudy {
                name: case.name,
                description: case.description,
                kind: case.contact.kind(),
                targets: case.targets,
                level_offset: case.level_offset,
                reference: reference(&runs),
                domain: DomainCheck::of(case, &runs),
                points: runs.iter().map(|r| case.contact.points(r.level)).collect(),
                levels: runs,
            }
        })
        .collect()
}

/// A row of `figures/accuracy.csv`: one case at one level.
#[derive(Debug, Default, Serialize)]
struct LevelRow<'a> {
    case: &'a str,
    contact: &'a str,
    level: u32,
    points: &'a str,
    h_central: Option<f64>,
    mu_bar_sliding: Option<f64>,
    reference: &'a str,
    h_central_ref: Option<f64>,
    mu_bar_ref: Option<f64>,
    h_central_error: Option<f64>,
    mu_bar_error: Option<f64>,
    observed_order_h: Option<f64>,
    observed_order_mu: Option<f64>,
    /// Finest-level cycles, or the length of a failure's residual history.
    cycles: usize,
    seconds: Decimals<3>,
    status: String,
    domain_h_central_change: Option<f64>,
    domain_mu_bar_change: Option<f64>,
}

/// `figures/accuracy.csv`: one row per case and level.
pub fn to_csv(studies: &[CaseStudy]) -> String {
    let mut out = Vec::new();
    for s in studies {
        let domain = s.domain.as_ref().and_then(|d| d.change.as_ref().ok());
        let r = s.reference;
        let order = r.and_then(|r| r.order);
        for (run, points) in s.levels.iter().zip(&s.points) {
            let e = s.errors(run);
            let row = LevelRow {
                case: s.name,
                contact: s.kind,
                level: run.level,
                points,
                reference: r.map_or("", |r| r.kind),
                h_central_ref: r.map(|r| r.h_central),
                mu_bar_ref: r.map(|r| r.mu_bar),
                h_central_error: e.map(|e| e.0),
                mu_bar_error: e.map(|e| e.1),
                observed_order_h: order.map(|o| o.0),
                observed_order_mu: order.map(|o| o.1),
                seconds: Decimals(run.seconds),
                domain_h_central_change: domain.map(|d| d.0),
                domain_mu_bar_change: domain.map(|d| d.1),
                ..LevelRow::default()
            };
            out.push(match &run.outcome {
                Ok(m) => LevelRow {
                    h_central: Some(m.h_central),
                    mu_bar_sliding: Some(m.mu_bar),
                    cycles: m.cycles,
                    status: "ok".to_string(),
                    ..row
                },
                Err(err) => LevelRow {
                    cycles: err.residual_history().len(),
                    // The message's first clause, its numbers included: a study that
                    // measures grids shows where a film collapsed.
                    status: format!(
                        "failed: {}",
                        err.to_string()
                            .split(':')
                            .next()
                            .unwrap_or("failed")
                            .replace(',', ";")
                    ),
                    ..row
                },
            });
        }
    }
    rows(out)
}

/// The recommended level of a target.
#[derive(Debug, Clone, PartialEq)]
pub struct Recommendation {
    /// Target name.
    pub target: &'static str,
    /// The case that decided it (the most demanding of those standing for the target).
    pub case: &'static str,
    /// Cheapest level with `mu-bar` within [`MU_TOLERANCE`] (`None`: none of the levels run).
    pub level: Option<u32>,
    /// Its `mu-bar` error.
    pub mu_error: Option<f64>,
    /// Its wall time, s.
    pub seconds: Option<f64>,
}

/// For each target the study's cases stand for, the cheapest level whose sliding `mu-bar` is
/// within `tol` of the reference for every case standing for it (the most demanding case
/// decides; a case with no qualifying level makes the target's level `None`).
pub fn recommend(studies: &[CaseStudy], tol: f64) -> Vec<Recommendation> {
    let mut targets: Vec<&'static str> = Vec::new();
    for s in studies {
        for t in s.targets {
            if !targets.contains(t) {
                targets.push(t);
            }
        }
    }
    targets
        .into_iter()
        .map(|target| {
            let mut rec = Recommendation {
                target,
                case: "",
                level: None,
                mu_error: None,
                seconds: None,
            };
            // Levels compared on the point scale (a line level stands beside the point level
            // `level_offset` below it): the most demanding case has the highest.
            let mut worst: Option<(i64, &CaseStudy, Option<&LevelRun>)> = None;
            for s in studies.iter().filter(|s| s.targets.contains(&target)) {
                let choice = s.cheapest_within(tol);
                let rank =
                    choice.map_or(i64::MAX, |r| i64::from(r.level) - i64::from(s.level_offset));
                if worst.as_ref().is_none_or(|w| rank > w.0) {
                    worst = Some((rank, s, choice));
                }
            }
            if let Some((_, s, choice)) = worst {
                rec.case = s.name;
                if let Some(r) = choice {
                    rec.level = Some(r.level);
                    rec.mu_error = s.errors(r).map(|e| e.1);
                    rec.seconds = Some(r.seconds);
                }
            }
            rec
        })
        .collect()
}

/// A row of `figures/accuracy_levels.csv`.
#[derive(Debug, Default, Serialize)]
struct RecommendationRow {
    target: &'static str,
    deciding_case: &'static str,
    level: Option<u32>,
    mu_bar_error: Option<f64>,
    seconds: Option<Decimals<3>>,
}

/// `figures/accuracy_levels.csv`: the recommended level per target.
pub fn recommendations_csv(recs: &[Recommendation]) -> String {
    rows(recs.iter().map(|r| RecommendationRow {
        target: r.target,
        deciding_case: r.case,
        level: r.level,
        mu_bar_error: r.mu_error,
        seconds: r.seconds.map(Decimals),
    }))
}

/// A readable summary.
pub fn to_text(studies: &[CaseStudy], recs: &[Recommendation]) -> String {
    let mut out = String::new();
    for s in studies {
        out.push_str(&format!("{} ({}): {}\n", s.name, s.kind, s.description));
        if let Some(r) = s.reference {
            out.push_str(&format!(
                "  reference ({}): Hc {:.5e}, mu-bar {:.5}{}\n",
                r.kind,
                r.h_central,
                r.mu_bar,
                r.order
                    .map(|o| format!(", observed order Hc {:.2}, mu-bar {:.2}", o.0, o.1))
                    .unwrap_or_default()
            ));
        }
        out.push_str("  level  Hc           mu-bar     err Hc    err mu-bar  cycles  time (s)\n");
        for run in &s.levels {
            match &run.outcome {
                Ok(m) => {
                    let e = s.errors(run);
                    out.push_str(&format!(
                        "  {:>5}  {:<11.5e}  {:<9.4}  {:>8}  {:>10}  {:>6}  {:>8.3}\n",
                        run.level,
                        m.h_central,
                        m.mu_bar,
                        e.map(|e| format!("{:.2e}", e.0)).unwrap_or_default(),
                        e.map(|e| format!("{:.2e}", e.1)).unwrap_or_default(),
                        m.cycles,
                        run.seconds
                    ));
                }
                Err(e) => out.push_str(&format!(
                    "  {:>5}  failed after {:.3} s: {e}\n",
                    run.level, run.seconds
                )),
            }
        }
        if let Some(d) = &s.domain {
            out.push_str(&format!(
                "  domain: inlet and sides doubled at level {}'s mesh (level {}): {}\n",
                d.level - 1,
                d.level,
                match &d.change {
                    Ok((h, mu)) => format!("Hc moves {:.2e}, mu-bar {:.2e}", h, mu),
                    Err(e) => format!("failed: {e}"),
                }
            ));
        }
    }
    out.push_str(&format!(
        "Cheapest level with sliding mu-bar within {} % (every finer level too):\n",
        100.0 * MU_TOLERANCE
    ));
    for r in recs {
        out.push_str(&format!(
            "  {:<6} level {} (decided by {}{})\n",
            r.target,
            r.level
                .map(|l| l.to_string())
                .unwrap_or_else(|| "none of those run".into()),
            r.case,
            r.mu_error
                .map(|e| format!(", error {:.2} %", 100.0 * e))
                .unwrap_or_default()
        ));
    }
    out
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A level that converged to `h` and `mu` in `0.1 level` seconds.
    pub(crate) fn run(level: u32, h: f64, mu: f64) -> LevelRun {
        LevelRun {
            level,
            outcome: Ok(Measured {
                h_central: h,
                mu_bar: mu,
                cycles: 10,
            }),
            seconds: 0.1 * f64::from(level),
        }
    }

    /// A point-contact study of `levels` that stands for Fig. 3.
    pub(crate) fn study(levels: Vec<LevelRun>) -> CaseStudy {
        CaseStudy {
            name: "t",
            description: "",
            kind: "point",
            targets: &["fig3"],
            level_offset: 0,
            reference: reference(&levels),
            domain: None,
            points: levels.iter().map(|_| String::new()).collect(),
            levels,
        }
    }

    #[test]
    fn richardson_removes_an_exact_second_order_error() {
        // X_n = 2 + 3 h^2 with h = 2^-n: the extrapolation is exact (to rounding) and the
        // observed order is 2.
        let x = |n: u32| 2.0 + 3.0 * 4f64.powi(-(n as i32));
        let levels: Vec<_> = (4..=7).map(|n| run(n, x(n), x(n))).collect();
        let r = reference(&levels).unwrap();
        assert_eq!(r.kind, "richardson");
        assert!((r.mu_bar - 2.0).abs() < 1e-14, "{}", r.mu_bar);
        let (oh, om) = r.order.unwrap();
        assert!((oh - 2.0).abs() < 1e-9 && (om - 2.0).abs() < 1e-9);
    }

    #[test]
    fn a_gap_below_the_finest_level_falls_back_to_the_finest() {
        let mut levels = vec![run(5, 1.0, 40.0), run(6, 1.1, 41.0), run(7, 1.2, 41.5)];
        levels[1].outcome = Err(SolveError::InvalidParams("x".into()));
        let r = reference(&levels).unwrap();
        assert_eq!(r.kind, "finest");
        assert_eq!(r.mu_bar, 41.5);
        assert!(reference(&[]).is_none());
    }

    #[test]
    fn the_cheapest_level_must_hold_for_every_finer_level() {
        // mu: 40.5 (in by chance), 38 (out), 40.1, 40.02, 40.0 -> reference 39.993...
        let levels = vec![
            run(4, 1.0, 40.5),
            run(5, 1.0, 38.0),
            run(6, 1.0, 40.1),
            run(7, 1.0, 40.02),
            run(8, 1.0, 40.0),
        ];
        let s = study(levels);
        assert_eq!(s.cheapest_within(0.01).map(|r| r.level), Some(6));
        assert_eq!(s.cheapest_within(1e-9).map(|r| r.level), None);
        let recs = recommend(&[s], 0.01);
        assert_eq!(recs.len(), 1);
        assert_eq!((recs[0].target, recs[0].level), ("fig3", Some(6)));
    }

    #[test]
    fn the_most_demanding_case_decides_a_target() {
        let easy = study(vec![
            run(4, 1.0, 40.0),
            run(5, 1.0, 40.0),
            run(6, 1.0, 40.0),
        ]);
        let hard = study(vec![
            run(4, 1.0, 30.0),
            run(5, 1.0, 39.0),
            run(6, 1.0, 40.0),
        ]);
        let recs = recommend(&[easy, hard], 0.01);
        assert_eq!(recs[0].level, Some(6));
    }

    #[test]
    fn the_csv_has_a_row_for_failed_levels_too() {
        let mut levels = vec![run(4, 1.0, 40.0), run(5, 1.0, 41.0), run(6, 1.0, 41.2)];
        levels[0].outcome = Err(SolveError::InvalidParams("x".into()));
        let s = study(levels);
        let csv = to_csv(std::slice::from_ref(&s));
        assert_eq!(csv.lines().count(), 4);
        assert!(csv.lines().nth(1).unwrap().contains("failed"));
    }
}
