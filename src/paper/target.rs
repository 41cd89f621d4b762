//! What every target of the paper is ([`Target`]) and what building one reports
//! ([`TargetReport`]). The targets (one module each) build on this file, the registry
//! (`paper/mod.rs`) lists them, the report reads what they report.

use crate::paper::eq13::{fit, Fit, FIT_TAU_C_MIN};
use crate::pipeline::context::Context;
use crate::pipeline::error::PipelineError;
use crate::pipeline::job::Job;
use crate::pipeline::sweep::{Sweep, SweepError};

/// The paper's working level (256 x 256), the default of every computed figure.
pub const WORKING_LEVEL: u32 = 7;

/// Level of the line contacts of Fig. 7 (512 intervals): sliding `mu-bar` within 0.2 % of
/// level 11 on the heaviest Table 3 case (docs/LINE_NOTES.md), a few tenths of a second per
/// case.
pub const LINE_LEVEL: u32 = 8;

/// A sweep file shipped in `cases/`, compiled in: `cases/<name>.toml`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShippedSweep {
    /// Its name, the stem of its file.
    pub name: &'static str,
    /// Its text.
    pub text: &'static str,
}

/// The [`ShippedSweep`] `cases/<name>.toml`, its text compiled in (the name written once, so
/// that the name and the file cannot disagree).
macro_rules! sweep_file {
    ($name:literal) => {
        $crate::paper::target::ShippedSweep {
            name: $name,
            text: include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/cases/",
                $name,
                ".toml"
            )),
        }
    };
}
pub(crate) use sweep_file;

impl ShippedSweep {
    /// Its path in the crate, as errors name it.
    pub fn path(&self) -> String {
        format!("cases/{}.toml", self.name)
    }

    /// Its sweep.
    pub fn parse(&self) -> Result<Sweep, SweepError> {
        Sweep::parse(&self.path(), self.text)
    }
}

/// A table or figure of the paper (or beyond it) as a named target: what `repro list` shows,
/// what `repro <name>`, `repro all`, `repro check`, `--shard` and `--offline` run.
pub trait Target: Sync {
    /// Name on the command line, and stem of its files.
    fn name(&self) -> &'static str;

    /// One line for `repro list` and the help of `repro <name>`.
    fn describe(&self) -> &'static str;

    /// Level of `repro <name>` without `--level`: the cheapest level whose sliding `mu-bar`
    /// is within 1 % of the Richardson extrapolation for the case that stands for the target
    /// in `repro accuracy` (figures/accuracy_levels.csv). `make figures` builds every target
    /// at the paper's working level instead. `None`: the target solves nothing, or at levels
    /// of its own.
    fn default_level(&self) -> Option<u32> {
        None
    }

    /// The sweep file of `cases/` it draws, if it draws one (the sweep figures): what
    /// [`crate::paper::cases::shipped`] lists.
    fn sweep_file(&self) -> Option<ShippedSweep> {
        None
    }

    /// Every solve it needs in the context, as jobs (none for the emitted tables and Fig. 8):
    /// what a shard divides and what `--offline` must find in the cache.
    fn jobs(&self, ctx: &Context) -> Result<Vec<Job>, PipelineError>;

    /// Computes it (its solves through the context's cache) and writes its files into the
    /// context's output folder.
    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError>;
}

/// A claim of the paper measured on a target's results, for the report's table of claims
/// and `figures/summary.csv`.
#[derive(Debug, Clone, PartialEq)]
pub enum Measure {
    /// The target's points with `tau_c >= FIT_TAU_C_MIN` against Eq. (13): the deviations and
    /// the least-squares `c` with its interval.
    Eq13(Fit),
    /// The least-squares `c` of Eq. (13) over every point of the target.
    Eq13AllPoints {
        /// The constant.
        c: f64,
    },
    /// The refined friction formula, fitted without `target`'s cases and tested on them
    /// (the `mastercurve` target measures it for each figure and for all of them).
    RefinedCrossValidation {
        /// The target whose cases were held out.
        target: &'static str,
        /// RMS relative deviation on them.
        rms_rel_dev: f64,
    },
    /// The discretisation error of the target's solved cases
    /// ([`crate::solver::richardson`]).
    DiscretisationError(ErrorSummary),
    /// The levels its solved cases ended on, `(level, cases)` in ascending level: a case
    /// ends finer than the level asked where the accuracy rule refines it.
    LevelsEnded(Vec<(u32, usize)>),
    /// The same cases solved in the paper's setup (`P = 0` on the paper's domain) against
    /// Eq. (13), over the same `tau_c` range as [`Measure::Eq13`]: Fig. 6 draws them beside
    /// the flooded contact.
    PaperSetupEq13(Fit),
    /// One case solved at each of a series of levels (Table 4), in ascending level.
    GridConvergence(Vec<LevelResult>),
}

/// One level of a grid-convergence study ([`Measure::GridConvergence`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelResult {
    /// Grid level.
    pub level: u32,
    /// Central film `H = h/c`, where solved.
    pub h_central: Option<f64>,
    /// Sliding `mu-bar`, where solved.
    pub mu_bar: Option<f64>,
    /// The solve's status as the table's CSV writes it (`ok`, `ok-film-nonpositive`,
    /// `failed`).
    pub status: &'static str,
    /// Wall time of the solve, s, where known.
    pub seconds: Option<f64>,
}

/// The median of `v` (NaN when empty).
pub fn median(mut v: Vec<f64>) -> f64 {
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

/// The spread of one output's relative discretisation error over a target's cases.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    /// Median relative error.
    pub median: f64,
    /// Largest relative error.
    pub worst: f64,
    /// The case (1-based, as in the target's CSV) of the largest.
    pub worst_case: usize,
}

impl Spread {
    /// The spread of `(case, relative error)` pairs; `None` when there are none.
    pub fn of(mut errors: Vec<(usize, f64)>) -> Option<Spread> {
        errors.retain(|e| e.1.is_finite());
        let &(worst_case, worst) = errors.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
        Some(Spread {
            median: median(errors.iter().map(|e| e.1).collect()),
            worst,
            worst_case,
        })
    }

    /// "median m %, worst w % (case c)".
    pub fn describe(&self) -> String {
        format!(
            "median {:.2} %, worst {:.2} % (case {})",
            100.0 * self.median,
            100.0 * self.worst,
            self.worst_case
        )
    }
}

/// The discretisation error of a target's outputs: central film, minimum film and the
/// friction its figure plots, over the cases that carry an estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorSummary {
    /// Cases with an estimate.
    pub estimated: usize,
    /// Central film.
    pub h_central: Option<Spread>,
    /// Minimum film.
    pub h_min: Option<Spread>,
    /// The plotted `mu-bar` (sliding, or total for Figs. 1-2).
    pub mu_bar: Option<Spread>,
}

impl Measure {
    /// The count of cases per level of `levels` (each a solved case's level).
    pub fn levels_ended(levels: impl IntoIterator<Item = u32>) -> Measure {
        let mut counts = std::collections::BTreeMap::new();
        for l in levels {
            *counts.entry(l).or_insert(0) += 1;
        }
        Measure::LevelsEnded(counts.into_iter().collect())
    }

    /// The measures of points `(tau_c, mu-bar)` against Eq. (13): the fit over the Eyring
    /// regime (`tau_c >= FIT_TAU_C_MIN`) and `c` over all, each where there are enough points.
    pub fn eq13(points: &[(f64, f64)]) -> Vec<Measure> {
        let mut out: Vec<Measure> = eq13_regime_fit(points)
            .map(Measure::Eq13)
            .into_iter()
            .collect();
        out.extend(fit(points).map(|f| Measure::Eq13AllPoints { c: f.c }));
        out
    }
}

/// The fit of Eq. (13) to the points `(tau_c, mu-bar)` of the Eyring regime
/// (`tau_c >= FIT_TAU_C_MIN`), where there are enough.
pub fn eq13_regime_fit(points: &[(f64, f64)]) -> Option<Fit> {
    let in_range: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|p| p.0 >= FIT_TAU_C_MIN)
        .collect();
    fit(&in_range)
}

/// What building a target reports: its row of `figures/summary.csv`, its line on stdout and
/// its section of `figures/index.html`.
#[derive(Debug, Clone)]
pub struct TargetReport {
    /// Target name (a registered target's, or the stem of a user's study).
    pub name: String,
    /// Title.
    pub title: String,
    /// Cases computed or emitted.
    pub cases: usize,
    /// Cases solved (computed targets).
    pub solved: Option<usize>,
    /// Of those, taken from the cache.
    pub cached: Option<usize>,
    /// Grid level.
    pub level: Option<u32>,
    /// Wall time, s.
    pub seconds: f64,
    /// Files written, relative to the output folder.
    pub files: Vec<String>,
    /// The paper's claim, for the report.
    pub paper_claim: String,
    /// Ours, for the report.
    pub ours: String,
    /// The result in a few words, for the line printed after the target is built.
    pub headline: Option<String>,
    /// The paper's claims measured on it (or, for the mastercurve's cross-validation, on
    /// other targets).
    pub measures: Vec<Measure>,
}

impl TargetReport {
    /// The report of a target that emits `files` from `cases/` data (no solves).
    pub fn emitted(name: &str, title: &str, cases: usize, files: Vec<String>) -> Self {
        TargetReport {
            name: name.to_string(),
            title: title.to_string(),
            cases,
            solved: None,
            cached: None,
            level: None,
            seconds: 0.0,
            files,
            paper_claim: String::new(),
            ours: "emitted from cases/".to_string(),
            headline: None,
            measures: Vec::new(),
        }
    }

    /// Its points with `tau_c >= FIT_TAU_C_MIN` against Eq. (13), if it has enough.
    pub fn eq13(&self) -> Option<&Fit> {
        self.measures.iter().find_map(|m| match m {
            Measure::Eq13(f) => Some(f),
            _ => None,
        })
    }

    /// The discretisation error of its cases, where they carry one.
    pub fn discretisation_error(&self) -> Option<&ErrorSummary> {
        self.measures.iter().find_map(|m| match m {
            Measure::DiscretisationError(e) => Some(e),
            _ => None,
        })
    }

    /// The levels its solved cases ended on, `(level, cases)`, where it counted them.
    pub fn levels_ended(&self) -> Option<&[(u32, usize)]> {
        self.measures.iter().find_map(|m| match m {
            Measure::LevelsEnded(l) => Some(l.as_slice()),
            _ => None,
        })
    }

    /// Adds `levels` (each a solved case's level) to the levels its cases ended on.
    pub fn count_levels(&mut self, levels: impl IntoIterator<Item = u32>) {
        let known = self.levels_ended().unwrap_or_default().iter();
        let all = known
            .flat_map(|&(l, n)| std::iter::repeat_n(l, n))
            .chain(levels)
            .collect::<Vec<u32>>();
        self.measures
            .retain(|m| !matches!(m, Measure::LevelsEnded(_)));
        self.measures.push(Measure::levels_ended(all));
    }

    /// The paper's setup against Eq. (13), where the target solved it.
    pub fn paper_setup_eq13(&self) -> Option<&Fit> {
        self.measures.iter().find_map(|m| match m {
            Measure::PaperSetupEq13(f) => Some(f),
            _ => None,
        })
    }

    /// Its grid-convergence study, if it is one.
    pub fn grid_convergence(&self) -> Option<&[LevelResult]> {
        self.measures.iter().find_map(|m| match m {
            Measure::GridConvergence(l) => Some(l.as_slice()),
            _ => None,
        })
    }

    /// The least-squares `c` of Eq. (13) over all its points, if it has enough.
    pub fn eq13_c_all(&self) -> Option<f64> {
        self.measures.iter().find_map(|m| match m {
            Measure::Eq13AllPoints { c } => Some(*c),
            _ => None,
        })
    }
}
