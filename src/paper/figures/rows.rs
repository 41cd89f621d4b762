//! The per-case CSV of a sweep figure: the case, its groups, `tau_c` and Eq. (13), what the
//! solve gave (or why it failed), the figure's x and y, the flat-film oracle and the thermal
//! post-process.

use super::estimate::EstimateCells;
use super::plot::Plot;
use crate::paper::eq13::{eq13_mu_bar, PAPER_C};
use crate::paper::mastercurve::oracle::point_flat;
use crate::physics::case::{Case, CaseForm, LubricantSpec};
use crate::pipeline::csv::rows_renamed;
use crate::pipeline::executor::PointRun;
use crate::pipeline::outcome::{CaseOutcome, Output, SolvedCase};
use serde::Serialize;

/// A row of a figure's CSV (`x` and `y` are named after what the figure plots).
#[derive(Debug, Default, Serialize)]
struct FigureRow {
    case: usize,
    #[serde(flatten)]
    operating: Operating,
    slip: f64,
    tau0_mpa: Option<f64>,
    d: f64,
    m: f64,
    l: f64,
    s_bar: f64,
    alpha_bar: f64,
    lambda: f64,
    kappa: f64,
    n: f64,
    tau_c: f64,
    mu_bar_eq13: f64,
    hc: Option<f64>,
    hc_moes: Option<f64>,
    hmin: Option<f64>,
    mu_bar_sliding: Option<f64>,
    mu_bar_rolling: Option<f64>,
    mu_bar_total: Option<f64>,
    mu_bar_flat: Option<f64>,
    x: Option<f64>,
    y: Option<f64>,
    rel_dev_eq13: Option<f64>,
    rel_dev_flat: Option<f64>,
    level: Option<u32>,
    /// Finest-level cycles; for a failure the length of its residual history (cycles and
    /// Newton steps are not told apart there).
    cycles: Option<usize>,
    newton_steps: Option<usize>,
    residual: Option<f64>,
    #[serde(flatten)]
    errors: ErrorCells,
    #[serde(flatten)]
    thermal: ThermalCells,
    status: String,
}

/// The discretisation error of a case ([`crate::solver::richardson`]): the relative error of
/// the central film, the minimum film and the sliding `mu-bar`, the extrapolated central film
/// (Moes) and sliding `mu-bar`, the absolute error of the figure's `y` (its error bar), blank
/// where not estimated; and the levels the estimate read with its status ([`EstimateCells`]).
#[derive(Debug, Default, Serialize)]
struct ErrorCells {
    hc_rel_error: Option<f64>,
    hmin_rel_error: Option<f64>,
    mu_bar_sliding_rel_error: Option<f64>,
    hc_moes_extrapolated: Option<f64>,
    mu_bar_sliding_extrapolated: Option<f64>,
    y_error: Option<f64>,
    #[serde(flatten)]
    estimate: EstimateCells,
}

impl ErrorCells {
    /// The cells of a case: `solved`, or `None` where it failed (the status alone).
    fn of(solved: Option<&SolvedCase>, plot: Plot) -> Self {
        let estimate = EstimateCells::of(solved);
        let Some(s) = solved else {
            return ErrorCells {
                estimate,
                ..ErrorCells::default()
            };
        };
        let moes = s.hc_moes / s.h_central;
        ErrorCells {
            hc_rel_error: s.relative_error(Output::HCentral),
            hmin_rel_error: s.relative_error(Output::HMin),
            mu_bar_sliding_rel_error: s.relative_error(Output::MuBarSliding),
            hc_moes_extrapolated: s.estimate(Output::HCentral).map(|e| e.extrapolated * moes),
            mu_bar_sliding_extrapolated: s.estimate(Output::MuBarSliding).map(|e| e.extrapolated),
            y_error: plot.y_error(s),
            estimate,
        }
    }
}

/// The physical operating point of a case: lubricant, temperature (C), `p_H` (GPa), `u_m`
/// (m/s); blank for a dimensionless case (its `tau0`, MPa, stands after the slip).
#[derive(Debug, Default, Serialize)]
pub struct Operating {
    pub lubricant: String,
    pub temperature_c: Option<f64>,
    pub ph_gpa: Option<f64>,
    pub um_m_s: Option<f64>,
}

impl Operating {
    /// The operating point of `case` and its Eyring stress, MPa (blank when dimensionless).
    pub fn of(case: &Case) -> (Self, Option<f64>) {
        match &case.spec {
            CaseForm::Physical(p) => {
                let (lubricant, temperature_c) = match &p.lubricant {
                    LubricantSpec::Named {
                        lubricant,
                        temperature_c,
                    } => (lubricant.clone(), Some(*temperature_c)),
                    LubricantSpec::Given { .. } => ("given".to_string(), None),
                    LubricantSpec::Datasheet {
                        datasheet,
                        temperature_c,
                        ..
                    } => (datasheet.label(), Some(*temperature_c)),
                };
                let point = Operating {
                    lubricant,
                    temperature_c,
                    ph_gpa: Some(p.ph_pa / 1e9),
                    um_m_s: Some(p.um_m_s),
                };
                (point, Some(p.tau0_pa / 1e6))
            }
            CaseForm::Dimensionless(_) => (Operating::default(), None),
        }
    }
}

/// The thermal columns of a case (steel, [`crate::physics::thermal::TARGET_INPUTS`]'s
/// first): thermal sliding `mu-bar` (mean-temperature closure), its relative correction, the
/// mid-plane closure's `mu-bar`, the largest film and surface temperature rises (K); blank
/// where not computed (dimensionless cases, failures).
#[derive(Debug, Default, Serialize)]
struct ThermalCells {
    mu_bar_thermal: Option<f64>,
    rel_dev_thermal: Option<f64>,
    mu_bar_thermal_midplane: Option<f64>,
    dt_film_k: Option<f64>,
    dt_flash_k: Option<f64>,
}

impl ThermalCells {
    fn of(solved: Option<&SolvedCase>) -> Self {
        match solved.and_then(|r| r.thermal().map(|t| (r, t))) {
            Some((r, t)) => ThermalCells {
                mu_bar_thermal: Some(t.mu_bar_sliding),
                rel_dev_thermal: Some(t.correction(r.mu_bar_sliding)),
                mu_bar_thermal_midplane: Some(t.mu_bar_sliding_midplane),
                dt_film_k: Some(t.dt_film_max_k),
                dt_flash_k: Some(t.dt_flash_max_k),
            },
            None => ThermalCells::default(),
        }
    }
}

impl FigureRow {
    /// The row of run `r`, the `i`-th case (from 0) of a figure that plots `plot`.
    fn of(i: usize, r: &PointRun, plot: Plot) -> Self {
        let g = &r.problem.groups;
        let tau_c = r.problem.tau_c();
        let eq13 = eq13_mu_bar(tau_c, PAPER_C);
        let (operating, tau0_mpa) = Operating::of(&r.case);
        let row = FigureRow {
            case: i + 1,
            operating,
            slip: g.slip,
            tau0_mpa,
            d: g.d,
            m: g.m,
            l: g.l,
            s_bar: g.s_bar,
            alpha_bar: g.alpha_bar,
            lambda: g.lambda,
            kappa: g.kappa,
            n: g.n,
            tau_c,
            mu_bar_eq13: eq13,
            errors: ErrorCells::of(r.solved(), plot),
            thermal: ThermalCells::of(r.solved()),
            status: r.outcome.status(),
            ..FigureRow::default()
        };
        match &r.outcome {
            CaseOutcome::Solved(s) => {
                let flat = point_flat(&r.problem, s.h_central);
                let point = plot.xy(r);
                FigureRow {
                    hc: Some(s.h_central),
                    hc_moes: Some(s.hc_moes),
                    hmin: Some(s.h_min),
                    mu_bar_sliding: Some(s.mu_bar_sliding),
                    mu_bar_rolling: s.mu_bar_rolling,
                    mu_bar_total: Some(s.mu_bar_total()),
                    mu_bar_flat: Some(flat),
                    x: point.map(|p| p.0),
                    y: point.map(|p| p.1),
                    rel_dev_eq13: point.map(|p| p.1 / eq13 - 1.0),
                    rel_dev_flat: Some(s.mu_bar_sliding / flat - 1.0),
                    level: Some(s.level),
                    cycles: Some(s.cycles),
                    newton_steps: Some(s.newton_steps),
                    residual: Some(s.residual),
                    ..row
                }
            }
            CaseOutcome::Failed(f) => FigureRow {
                cycles: Some(f.residual_history.len()),
                residual: f.residual_history.last().copied(),
                ..row
            },
        }
    }
}

/// The figure's CSV, its x and y columns named for what `plot` draws.
pub fn csv(runs: &[PointRun], plot: Plot) -> String {
    let (x, y) = plot.columns();
    rows_renamed(
        runs.iter()
            .enumerate()
            .map(|(i, r)| FigureRow::of(i, r, plot)),
        &[("x", x), ("y", y)],
    )
}
