//! What a sweep figure plots: its x ([`Abscissa`]) against its y ([`FrictionAxis`]), and how
//! its cases split into series ([`SeriesBy`]).

use crate::paper::target::{ErrorSummary, Spread};
use crate::physics::case::{Case, CaseForm, Problem};
use crate::pipeline::executor::PointRun;
use crate::pipeline::outcome::{Output, SolvedCase};

/// The x of a sweep figure, on a log axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Abscissa {
    /// The characteristic shear stress `tau_c`, with Eq. (13) drawn and measured against
    /// (Figs. 2-7, a study).
    TauC,
    /// The paper's severity group `S-bar^(1/4) M L^3` (Fig. 1); Eq. (13) is not a curve
    /// of it, so it is neither drawn nor measured.
    Severity,
}

/// The reduced friction on the y axis of a sweep figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrictionAxis {
    /// Sliding `mu-bar` (Figs. 3-7, a study).
    Sliding,
    /// Sliding plus rolling `mu-bar` (Figs. 1-2).
    Total,
}

impl FrictionAxis {
    /// The output it reads from a solved case.
    pub fn output(self) -> Output {
        match self {
            FrictionAxis::Sliding => Output::MuBarSliding,
            FrictionAxis::Total => Output::MuBarTotal,
        }
    }

    /// Its value for a solved case.
    pub fn of(self, solved: &SolvedCase) -> f64 {
        match self {
            FrictionAxis::Sliding => solved.mu_bar_sliding,
            FrictionAxis::Total => solved.mu_bar_total(),
        }
    }
}

/// What a sweep figure plots: `y` against `x`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plot {
    /// The x axis.
    pub x: Abscissa,
    /// The y axis.
    pub y: FrictionAxis,
}

impl Plot {
    /// Sliding `mu-bar` against `tau_c`: Figs. 3-7 and a user's study.
    pub const SLIDING: Plot = Plot {
        x: Abscissa::TauC,
        y: FrictionAxis::Sliding,
    };

    /// Whether its points are measured against Eq. (13) and the curve drawn over them: only
    /// where x is `tau_c`, the variable of Eq. (13).
    pub fn on_eq13(self) -> bool {
        self.x == Abscissa::TauC
    }

    /// The x and y of a case on the figure (`None` where it failed).
    pub fn xy(self, run: &PointRun) -> Option<(f64, f64)> {
        let solved = run.solved()?;
        let g = &run.problem.groups;
        let x = match self.x {
            Abscissa::TauC => run.problem.tau_c(),
            Abscissa::Severity => g.s_bar.powf(0.25) * g.m * g.l.powi(3),
        };
        Some((x, self.y.of(solved)))
    }

    /// The discretisation error over `runs` (each case numbered from 1, as in the CSV) of
    /// the central and minimum film and the friction it plots; `None` when no case carries
    /// an estimate.
    pub fn error_summary(self, runs: &[PointRun]) -> Option<ErrorSummary> {
        let spread = |output: Output| {
            Spread::of(
                runs.iter()
                    .enumerate()
                    .filter_map(|(i, r)| Some((i + 1, r.solved()?.relative_error(output)?)))
                    .collect(),
            )
        };
        let estimated = runs
            .iter()
            .filter(|r| r.solved().is_some_and(|s| s.errors.is_some()))
            .count();
        (estimated > 0).then(|| ErrorSummary {
            estimated,
            h_central: spread(Output::HCentral),
            h_min: spread(Output::HMin),
            mu_bar: spread(self.y.output()),
        })
    }

    /// The absolute discretisation error of the `y` it plots for a solved case (`None` where
    /// not estimated).
    pub fn y_error(self, solved: &SolvedCase) -> Option<f64> {
        solved.estimate(self.y.output()).map(|e| e.error)
    }

    /// The names of the `x` and `y` columns of the figure's CSV: what they plot, the `y`
    /// (and `tau_c`'s `x`) with a suffix, for the row has that output's own column too.
    pub fn columns(self) -> (&'static str, &'static str) {
        let x = match self.x {
            Abscissa::Severity => "s_bar_quarter_m_l3",
            Abscissa::TauC => "tau_c_x",
        };
        let y = match self.y {
            FrictionAxis::Total => "mu_bar_total_y",
            FrictionAxis::Sliding => "mu_bar_sliding_y",
        };
        (x, y)
    }

    /// The axis labels of the picture, x then y.
    pub fn labels(self) -> (&'static str, &'static str) {
        let x = match self.x {
            Abscissa::TauC => "characteristic shear stress τ̄_{c}",
            Abscissa::Severity => "S̄^{1/4} M L^{3}",
        };
        let y = match self.y {
            FrictionAxis::Sliding => "sliding reduced friction μ̄",
            FrictionAxis::Total => "total reduced friction μ̄",
        };
        (x, y)
    }
}

/// How a sweep figure splits its cases into series (one marker each), so that the collapse
/// (or not) of the parameter the sweep varies is visible.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesBy {
    /// Moes' `L` (Figs. 1-3: the dimensionless Barus sweep).
    MoesL,
    /// The lubricant's temperature (Figs. 4-6, a study); "given lubricant" where the case
    /// gives its lubricant by its properties, "dimensionless" for a case in Moes groups.
    Temperature,
    /// The ellipticity `Rx/Ry` (Fig. 7), written 1/2 and 1/5 where it is one of those.
    RadiusRatio,
}

impl SeriesBy {
    /// The series label of a case (whose problem is `problem`).
    pub fn key(self, case: &Case, problem: &Problem) -> String {
        let g = &problem.groups;
        match self {
            SeriesBy::MoesL => format!("L = {}", g.l),
            SeriesBy::RadiusRatio => {
                let ratio = if (g.d - 0.5).abs() < 1e-9 {
                    "1/2".to_string()
                } else if (g.d - 0.2).abs() < 1e-9 {
                    "1/5".to_string()
                } else {
                    format!("{:.3}", g.d)
                };
                format!("Rx/Ry = {ratio}")
            }
            SeriesBy::Temperature => match &case.spec {
                CaseForm::Physical(p) => match p.lubricant.temperature_c() {
                    Some(t) => format!("{t} °C"),
                    None => "given lubricant".into(),
                },
                CaseForm::Dimensionless(_) => "dimensionless".into(),
            },
        }
    }
}
