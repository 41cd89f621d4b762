//! The `thermal` target (beyond the paper; its second future-work item): how much shear
//! heating lowers the sliding friction of Figs. 4-6, and where the paper's isothermal
//! assumption holds (a correction under [`ISOTHERMAL_CORRECTION_MAX`]). The correction is the
//! post-process of each figure's own solves ([`crate::physics::thermal`]), cached with them:
//! this target solves nothing its figures do not.
//!
//! Files: `thermal.csv` (one row per case: isothermal and thermal `mu-bar` with steel of
//! 46 and 21 W/(m K), the mid-plane bound, temperature rises), `thermal.svg` (isothermal and
//! thermal `mu-bar` against `tau_c`, Eq. 13 dashed).

use crate::paper::eq13::PAPER_C;
use crate::paper::figures::rows::Operating;
use crate::paper::figures::{SweepFigure, FIG4, FIG5, FIG6};
use crate::paper::picture::{eq13_curve, MU_BAR, TAU_C};
use crate::paper::table4::Table4Case;
use crate::paper::target::{Measure, Target, TargetReport};
use crate::physics::case::CaseForm;
use crate::physics::thermal::ISOTHERMAL_CORRECTION_MAX;
use crate::pipeline::context::Context;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::PointRun;
use crate::pipeline::job::Job;
use crate::plot::{render_svg, Figure, Marker, Scale, Series};
use serde::Serialize;

/// The figures corrected: figure, sweep, lubricant as named in the summary.
const FIGURES: [(&SweepFigure, &str); 3] = [
    (&FIG4, "mineral oil A"),
    (&FIG5, "traction fluid"),
    (&FIG6, "5P4E"),
];

/// The `thermal` target.
pub struct ShearHeating;

impl Target for ShearHeating {
    fn name(&self) -> &'static str {
        "thermal"
    }

    fn describe(&self) -> &'static str {
        "Beyond the paper: the shear-heating correction of Figs. 4-6 (isothermal vs thermal mu-bar, where the isothermal assumption holds)"
    }

    /// Figs. 4-6's solves: the correction is their post-process.
    fn jobs(&self, ctx: &Context) -> Result<Vec<Job>, PipelineError> {
        let mut all = Vec::new();
        for (fig, _) in FIGURES {
            all.extend(fig.jobs(ctx)?);
        }
        Ok(all)
    }

    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        build(ctx)
    }
}

/// One corrected case.
struct CorrectedCase<'a> {
    figure: &'static str,
    case: usize,
    run: &'a PointRun,
}

impl CorrectedCase<'_> {
    /// The correction with steel (46) and through-hardened steel (21), relative.
    fn corrections(&self) -> Option<(f64, f64)> {
        let r = self.run.solved()?;
        match r.thermal.as_slice() {
            [steel, hardened, ..] => Some((
                steel.correction(r.mu_bar_sliding),
                hardened.correction(r.mu_bar_sliding),
            )),
            _ => None,
        }
    }

    fn operating_point(&self) -> String {
        match &self.run.case.spec {
            CaseForm::Physical(p) => {
                let t = p
                    .lubricant
                    .temperature_c()
                    .map(|t| format!("{t} C, "))
                    .unwrap_or_default();
                format!(
                    "{t}{} GPa, {} m/s, S {} %, tau0 {} MPa",
                    p.ph_pa / 1e9,
                    p.um_m_s,
                    100.0 * p.slip,
                    p.tau0_pa / 1e6
                )
            }
            CaseForm::Dimensionless(_) => String::new(),
        }
    }
}

/// A row of `thermal.csv`: the case, its isothermal and thermal friction with the two solids,
/// the temperature rises and the thermal groups.
#[derive(Debug, Default, Serialize)]
struct ThermalRow<'a> {
    figure: &'a str,
    case: usize,
    #[serde(flatten)]
    operating: Operating,
    slip: f64,
    tau0_mpa: Option<f64>,
    tau_c: f64,
    mu_bar_sliding: Option<f64>,
    mu_bar_thermal: Option<f64>,
    rel_dev_thermal: Option<f64>,
    mu_bar_thermal_midplane: Option<f64>,
    rel_dev_thermal_midplane: Option<f64>,
    mu_bar_thermal_k21: Option<f64>,
    rel_dev_thermal_k21: Option<f64>,
    dt_film_k: Option<f64>,
    dt_flash_k: Option<f64>,
    dt_film_k21: Option<f64>,
    beta0_per_k: Option<f64>,
    peclet: Option<f64>,
    film_peclet: Option<f64>,
    isothermal_holds: &'a str,
}

fn csv(rows: &[CorrectedCase]) -> String {
    crate::pipeline::csv::rows(rows.iter().map(|row| {
        let r = row.run;
        let (operating, tau0_mpa) = Operating::of(&r.case);
        let out = ThermalRow {
            figure: row.figure,
            case: row.case,
            operating,
            slip: r.problem.groups.slip,
            tau0_mpa,
            tau_c: r.problem.tau_c(),
            ..ThermalRow::default()
        };
        let solved = r.solved();
        match (solved, solved.map(|x| x.thermal.as_slice())) {
            (Some(solved), Some([steel, hardened, ..])) => {
                let iso = solved.mu_bar_sliding;
                let c = steel.correction(iso);
                ThermalRow {
                    mu_bar_sliding: Some(iso),
                    mu_bar_thermal: Some(steel.mu_bar_sliding),
                    rel_dev_thermal: Some(c),
                    mu_bar_thermal_midplane: Some(steel.mu_bar_sliding_midplane),
                    rel_dev_thermal_midplane: Some(steel.mu_bar_sliding_midplane / iso - 1.0),
                    mu_bar_thermal_k21: Some(hardened.mu_bar_sliding),
                    rel_dev_thermal_k21: Some(hardened.correction(iso)),
                    dt_film_k: Some(steel.dt_film_max_k),
                    dt_flash_k: Some(steel.dt_flash_max_k),
                    dt_film_k21: Some(hardened.dt_film_max_k),
                    beta0_per_k: Some(steel.beta0_per_k),
                    peclet: Some(steel.peclet),
                    film_peclet: Some(steel.film_peclet),
                    isothermal_holds: if c.abs() < ISOTHERMAL_CORRECTION_MAX {
                        "yes"
                    } else {
                        "no"
                    },
                    ..out
                }
            }
            (Some(solved), _) => ThermalRow {
                mu_bar_sliding: Some(solved.mu_bar_sliding),
                ..out
            },
            (None, _) => out,
        }
    }))
}

fn svg(rows: &[CorrectedCase]) -> Result<Option<String>, PipelineError> {
    let mut series = Vec::new();
    for (k, (fig, lubricant)) in FIGURES.iter().enumerate() {
        let mine = || rows.iter().filter(|r| r.figure == fig.name);
        let point = |thermal: bool| {
            mine()
                .filter_map(|r| {
                    let rec = r.run.solved()?;
                    let y = if thermal {
                        rec.thermal()?.mu_bar_sliding
                    } else {
                        rec.mu_bar_sliding
                    };
                    Some((r.run.problem.tau_c(), y))
                })
                .collect::<Vec<_>>()
        };
        series.push(Series {
            label: format!("{lubricant}, isothermal"),
            points: point(false),
            marker: Marker::nth(2 * k),
            ..Series::default()
        });
        series.push(Series {
            label: format!("{lubricant}, thermal (steel)"),
            points: point(true),
            marker: Marker::nth(2 * k + 1),
            ..Series::default()
        });
    }
    let xs: Vec<f64> = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.0))
        .collect();
    if xs.is_empty() {
        return Ok(None);
    }
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let fig = Figure {
        title: "Beyond the paper: shear heating, Figs. 4-6 isothermal and thermal".into(),
        x_label: TAU_C.into(),
        y_label: MU_BAR.into(),
        x_scale: Scale::Log,
        y_scale: Scale::Linear,
        series,
        curves: vec![eq13_curve(lo, hi, PAPER_C, 200)],
        ..Figure::default()
    };
    render_svg(&fig)
        .map(Some)
        .map_err(|e| PipelineError::plot("thermal.svg", e))
}

/// One lubricant's summary: where the isothermal assumption holds, the worst case and its
/// sensitivity to the solid's conductivity.
fn summary(
    rows: &[CorrectedCase],
    figure: &str,
    lubricant: &str,
    table4: Option<&CorrectedCase>,
) -> String {
    let mine: Vec<(&CorrectedCase, (f64, f64))> = rows
        .iter()
        .filter(|r| r.figure == figure)
        .filter_map(|r| r.corrections().map(|c| (r, c)))
        .collect();
    let holds = mine
        .iter()
        .filter(|(_, c)| c.0.abs() < ISOTHERMAL_CORRECTION_MAX)
        .count();
    let worst = mine.iter().min_by(|a, b| a.1 .0.total_cmp(&b.1 .0));
    let mut text = format!(
        "{lubricant}: isothermal within {:.0} % in {holds} of {} cases",
        100.0 * ISOTHERMAL_CORRECTION_MAX,
        mine.len()
    );
    if let Some((r, (steel, hardened))) = worst {
        text.push_str(&format!(
            ", largest correction {:+.1} % (21 W/mK: {:+.1} %) at {}",
            100.0 * steel,
            100.0 * hardened,
            r.operating_point()
        ));
    }
    // Where the film's Peclet number exceeds 1, convection along the film is not negligible
    // and the conduction-only closure overstates the rise (thick, viscous films).
    let convective = rows
        .iter()
        .filter(|r| r.figure == figure)
        .filter_map(|r| r.run.solved()?.thermal())
        .filter(|t| t.film_peclet > 1.0)
        .count();
    if convective > 0 {
        text.push_str(&format!(
            " ({convective} with a film Peclet number above 1, where the conduction-only closure overstates the heating)"
        ));
    }
    if let Some((steel, hardened)) = table4.and_then(|r| r.corrections()) {
        text.push_str(&format!(
            "; the Table 4 case {:+.1} % (21 W/mK: {:+.1} %)",
            100.0 * steel,
            100.0 * hardened
        ));
    }
    text
}

fn build(ctx: &Context) -> Result<TargetReport, PipelineError> {
    let mut runs = Vec::new();
    let mut level = None;
    for (fig, _) in FIGURES {
        let (r, l) = fig.run("thermal", ctx)?;
        level = Some(l);
        runs.push((fig.name, r));
    }
    let rows: Vec<CorrectedCase> = runs
        .iter()
        .flat_map(|(name, r)| {
            r.iter().enumerate().map(|(i, run)| CorrectedCase {
                figure: name,
                case: i + 1,
                run,
            })
        })
        .collect();
    let appendix = Table4Case::shipped()?.case;
    let table4 = rows.iter().find(|r| r.run.case == appendix);
    let mut files = vec![ctx.write("thermal.csv", &csv(&rows))?];
    if let Some(s) = svg(&rows)? {
        files.push(ctx.write("thermal.svg", &s)?);
    }
    let ours = FIGURES
        .iter()
        .map(|(fig, lubricant)| {
            summary(
                &rows,
                fig.name,
                lubricant,
                table4.filter(|r| r.figure == fig.name),
            )
        })
        .collect::<Vec<_>>()
        .join("; ");
    let solved = rows.iter().filter(|r| r.run.solved().is_some()).count();
    Ok(TargetReport {
        solved: Some(solved),
        cached: Some(rows.iter().filter(|r| r.run.cached).count()),
        level,
        paper_claim: "isothermal contact; with significant sliding Eq. (14) predicts too much friction (Conclusions)".into(),
        ours,
        measures: vec![Measure::levels_ended(
            rows.iter().filter_map(|r| r.run.solved().map(|s| s.level)),
        )],
        ..TargetReport::emitted(
            "thermal",
            "Beyond the paper: the shear-heating correction of Figs. 4-6",
            rows.len(),
            files,
        )
    })
}
