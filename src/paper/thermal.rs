//! The `thermal` target (beyond the paper; its second future-work item): how much shear
//! heating lowers the sliding friction of Figs. 4-6, and where the paper's isothermal
//! assumption holds (a correction under [`ISOTHERMAL_CORRECTION_MAX`]). The correction is the
//! post-process of each figure's own solves ([`crate::physics::thermal`]), cached with them:
//! this target solves nothing its figures do not.
//!
//! Files: `thermal.csv` (one row per case: isothermal and thermal `mu-bar` with steel of
//! 46 and 21 W/(m K), the mid-plane bound, temperature rises), `thermal.svg` (isothermal and
//! thermal `mu-bar` against `tau_c`, Eq. 13 dashed).

use crate::paper::figures::{self, operating_cells, run_sweep};
use crate::paper::mastercurve::fit::PAPER_C;
use crate::paper::picture::{mastercurve as eq13_curve, MU_BAR, TAU_C};
use crate::paper::table4::Table4Case;
use crate::paper::target as registry_target;
use crate::physics::case::Spec;
use crate::physics::thermal::ISOTHERMAL_CORRECTION_MAX;
use crate::pipeline::context::{write, Built, Context};
use crate::pipeline::csv::{num, table};
use crate::pipeline::run::{CaseRun, Job};
use crate::pipeline::sweep::shipped_sweep;
use crate::plot::{render_svg, Figure, Marker, Scale, Series};

/// The figures corrected: figure, sweep, lubricant as named in the summary.
const FIGURES: [(&str, &str); 3] = [
    ("fig4", "mineral oil A"),
    ("fig5", "traction fluid"),
    ("fig6", "5P4E"),
];

/// Every solve of the target: Figs. 4-6's.
pub fn jobs(ctx: &Context) -> Result<Vec<Job>, String> {
    let mut all = Vec::new();
    for (name, _) in FIGURES {
        let level = registry_target(name).and_then(|t| t.default_level);
        all.extend(figures::jobs(name, level, ctx)?);
    }
    Ok(all)
}

/// One corrected case.
struct Row<'a> {
    figure: &'static str,
    case: usize,
    run: &'a CaseRun,
}

impl Row<'_> {
    /// The correction with steel (46) and through-hardened steel (21), relative.
    fn corrections(&self) -> Option<(f64, f64)> {
        let r = self.run.record()?;
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
            Spec::Physical(p) => {
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
            Spec::Dimensionless(_) => String::new(),
        }
    }
}

fn csv(rows: &[Row]) -> String {
    let header = [
        "figure",
        "case",
        "lubricant",
        "temperature_c",
        "ph_gpa",
        "um_m_s",
        "slip",
        "tau0_mpa",
        "tau_c",
        "mu_bar_sliding",
        "mu_bar_thermal",
        "rel_dev_thermal",
        "mu_bar_thermal_midplane",
        "rel_dev_thermal_midplane",
        "mu_bar_thermal_k21",
        "rel_dev_thermal_k21",
        "dt_film_k",
        "dt_flash_k",
        "dt_film_k21",
        "beta0_per_k",
        "peclet",
        "film_peclet",
        "isothermal_holds",
    ];
    let cells = rows.iter().map(|row| {
        let r = row.run;
        let [lub, temp, ph, um, tau0] = operating_cells(&r.case);
        let mut out = vec![
            row.figure.to_string(),
            row.case.to_string(),
            lub,
            temp,
            ph,
            um,
            num(r.problem.groups.slip),
            tau0,
            num(r.problem.tau_c()),
        ];
        let rec = r.record();
        match (rec, rec.map(|x| x.thermal.as_slice())) {
            (Some(rec), Some([steel, hardened, ..])) => {
                let iso = rec.mu_bar_sliding;
                let c = steel.correction(iso);
                out.extend([
                    num(iso),
                    num(steel.mu_bar_sliding),
                    num(c),
                    num(steel.mu_bar_sliding_midplane),
                    num(steel.mu_bar_sliding_midplane / iso - 1.0),
                    num(hardened.mu_bar_sliding),
                    num(hardened.correction(iso)),
                    num(steel.dt_film_max_k),
                    num(steel.dt_flash_max_k),
                    num(hardened.dt_film_max_k),
                    num(steel.beta0_per_k),
                    num(steel.peclet),
                    num(steel.film_peclet),
                    if c.abs() < ISOTHERMAL_CORRECTION_MAX {
                        "yes".into()
                    } else {
                        "no".into()
                    },
                ]);
            }
            (Some(rec), _) => {
                out.push(num(rec.mu_bar_sliding));
                out.extend(std::iter::repeat_n(String::new(), 13));
            }
            (None, _) => out.extend(std::iter::repeat_n(String::new(), 14)),
        }
        out
    });
    table(&header, cells)
}

fn svg(rows: &[Row]) -> Result<Option<String>, String> {
    let mut series = Vec::new();
    for (k, (name, lubricant)) in FIGURES.iter().enumerate() {
        let mine = || rows.iter().filter(|r| r.figure == *name);
        let point = |thermal: bool| {
            mine()
                .filter_map(|r| {
                    let rec = r.run.record()?;
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
        .map_err(|e| format!("thermal.svg: {e}"))
}

/// One lubricant's summary: where the isothermal assumption holds, the worst case and its
/// sensitivity to the solid's conductivity.
fn summary(rows: &[Row], figure: &str, lubricant: &str, table4: Option<&Row>) -> String {
    let mine: Vec<(&Row, (f64, f64))> = rows
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
        .filter_map(|r| r.run.record()?.thermal())
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

/// Builds the target.
pub fn build(ctx: &Context) -> Result<Built, String> {
    let mut runs = Vec::new();
    let mut level = None;
    for (name, _) in FIGURES {
        let sweep = shipped_sweep(name).map_err(|e| e.to_string())?;
        let default_level = registry_target(name).and_then(|t| t.default_level);
        let (r, l) = run_sweep("thermal", &sweep, default_level, ctx)?;
        level = Some(l);
        runs.push((name, r));
    }
    let rows: Vec<Row> = runs
        .iter()
        .flat_map(|(name, r)| {
            r.iter().enumerate().map(|(i, run)| Row {
                figure: name,
                case: i + 1,
                run,
            })
        })
        .collect();
    let appendix = Table4Case::shipped()?.case;
    let table4 = rows.iter().find(|r| r.run.case == appendix);
    let mut files = vec![write(ctx, "thermal.csv", &csv(&rows))?];
    if let Some(s) = svg(&rows)? {
        files.push(write(ctx, "thermal.svg", &s)?);
    }
    let ours = FIGURES
        .iter()
        .map(|(name, lubricant)| {
            summary(&rows, name, lubricant, table4.filter(|r| r.figure == *name))
        })
        .collect::<Vec<_>>()
        .join("; ");
    let solved = rows.iter().filter(|r| r.run.record().is_some()).count();
    Ok(Built {
        name: "thermal",
        title: "Beyond the paper: the shear-heating correction of Figs. 4-6".into(),
        cases: rows.len(),
        solved: Some(solved),
        cached: Some(rows.iter().filter(|r| r.run.cached).count()),
        level,
        fit: None,
        fit_all: None,
        seconds: 0.0,
        files,
        paper_claim: "isothermal contact; with significant sliding Eq. (14) predicts too much friction (Conclusions)".into(),
        ours,
        refined: Vec::new(),
    })
}
