//! Fig. 8: measured friction transformed to `(tau_c, mu-bar)` by Sec. IV and drawn on
//! Eq. (13). The data are every `*.csv` under [`DATA_DIR`] (format: `docs/measured-data.md`);
//! nothing is computed or invented. When the folder holds no dataset the target still builds:
//! its CSV is the header alone, and its SVG, its sidecar and its report entry say so and how
//! to add one.

pub mod picture;
pub mod reader;

use crate::paper::eq13::{eq13_mu_bar, FIT_TAU_C_MIN, PAPER_C};
use crate::paper::fig8::reader::{read_folder, transform, ReducedRow};
use crate::paper::target::{Measure, Target, TargetReport};
use crate::physics::lubricant::LubricantTable;
use crate::physics::traction::Contact;
use crate::pipeline::context::Context;
use crate::pipeline::error::PipelineError;
use crate::pipeline::job::Job;
use crate::pipeline::provenance::{Provenance, SUFFIX};
use serde::Serialize;
use std::path::Path;

/// Folder of the measured datasets, relative to the working directory (the repository root
/// for `make figures`).
pub const DATA_DIR: &str = "cases/fig8";

/// What the figure says when it holds no measured point.
pub const NO_DATA: &str = "No measured dataset is included: cases/fig8/ holds no *.csv file. To add one, write the measured points (each with its source) in the format of docs/measured-data.md to cases/fig8/NAME.csv and run `repro fig8`.";

/// A row of `fig8.csv`: one measured point, its operating point, what Sec. IV makes of it
/// and its source.
#[derive(Debug, Default, Serialize)]
struct Fig8Row<'a> {
    dataset: &'a str,
    row: usize,
    series: &'a str,
    contact: &'static str,
    ph_pa: f64,
    temperature_c: f64,
    slip: f64,
    m: f64,
    l: f64,
    s_bar: f64,
    eta_bar_ph: f64,
    film_formula: &'static str,
    hc_moes: f64,
    hc_m: f64,
    tau0_pa: f64,
    mu: f64,
    tau_c_x: f64,
    mu_bar_y: f64,
    mu_bar_eq13: f64,
    rel_dev_eq13: f64,
    source: &'a str,
}

/// What `fig8.csv` holds, in words: for its sidecar and the report (the CSV itself has no
/// comment lines).
fn note(points: usize, files: usize) -> String {
    if points == 0 {
        NO_DATA.to_string()
    } else {
        format!(
            "{points} measured points from {files} file(s) in {DATA_DIR}/, transformed by Sec. IV (docs/measured-data.md); nothing here is computed by the solver"
        )
    }
}

/// `fig8.provenance.json`: the sidecar of a target without solves ([`Provenance::new`]) and
/// [`note`].
#[derive(Serialize)]
struct Sidecar {
    #[serde(flatten)]
    provenance: Provenance,
    note: String,
}

fn csv_text(rows: &[ReducedRow]) -> String {
    crate::pipeline::csv::rows(rows.iter().map(|r| {
        let c = &r.reduced.characteristic;
        let p = &r.row.point;
        let eq13 = eq13_mu_bar(c.tau_c, PAPER_C);
        Fig8Row {
            dataset: &r.dataset,
            row: r.row.row,
            series: &r.row.series,
            contact: match p.contact {
                Contact::Elliptical { .. } => "elliptical",
                Contact::Line { .. } => "line",
            },
            ph_pa: c.ph_pa,
            temperature_c: r.row.temperature_c,
            slip: c.slip,
            m: c.m,
            l: c.l,
            s_bar: c.s_bar,
            eta_bar_ph: c.eta_bar_ph,
            film_formula: p.film.name(),
            hc_moes: c.hc_moes,
            hc_m: c.hc_m,
            tau0_pa: p.tau0_pa,
            mu: r.row.mu,
            tau_c_x: c.tau_c,
            mu_bar_y: r.reduced.mu_bar,
            mu_bar_eq13: eq13,
            rel_dev_eq13: r.reduced.mu_bar / eq13 - 1.0,
            source: &r.row.source,
        }
    }))
}

/// Fig. 8: the measured datasets of [`DATA_DIR`], transformed.
pub struct Fig8;

impl Target for Fig8 {
    fn name(&self) -> &'static str {
        "fig8"
    }

    fn describe(&self) -> &'static str {
        "Measured friction transformed to (tau_c, mu-bar) by Sec. IV, on Eq. (13) (datasets of cases/fig8/)"
    }

    fn jobs(&self, _: &Context) -> Result<Vec<Job>, PipelineError> {
        Ok(Vec::new())
    }

    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        build_from(Path::new(DATA_DIR), ctx)
    }
}

/// Builds Fig. 8 from the datasets of `dir`.
pub fn build_from(dir: &Path, ctx: &Context) -> Result<TargetReport, PipelineError> {
    let lubs = LubricantTable::table1();
    let datasets = read_folder(dir).map_err(|e| PipelineError::Data(Box::new(e)))?;
    let mut rows = Vec::new();
    for d in &datasets {
        rows.extend(transform(d, &lubs).map_err(|e| PipelineError::Data(Box::new(e)))?);
    }
    let points: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r.reduced.characteristic.tau_c, r.reduced.mu_bar))
        .collect();
    let measures = Measure::eq13(&points);
    let fit_range = measures.iter().find_map(|m| match m {
        Measure::Eq13(f) => Some(*f),
        _ => None,
    });
    let c_all = measures.iter().find_map(|m| match m {
        Measure::Eq13AllPoints { c } => Some(*c),
        _ => None,
    });
    let note = note(rows.len(), datasets.len());
    let csv = ctx.write("fig8.csv", &csv_text(&rows))?;
    let svg = picture::svg(&rows, c_all)?;
    let picture = ctx.write("fig8.svg", &svg)?;
    let files = vec![csv, picture];
    let sidecar = Sidecar {
        provenance: Provenance::new("fig8", &files),
        note: note.clone(),
    };
    // Plain data of strings and numbers: serialising cannot fail.
    let sidecar = serde_json::to_string_pretty(&sidecar).unwrap_or_default() + "\n";
    let sidecar = ctx.write(&format!("fig8{SUFFIX}"), &sidecar)?;
    let ours = if rows.is_empty() {
        (ctx.warn)(format!("fig8: {NO_DATA}"));
        note
    } else {
        let dev = match fit_range {
            Some(f) => format!(
                "{} points with tau_c >= {FIT_TAU_C_MIN}: {}",
                f.points,
                f.describe()
            ),
            None => format!("no point with tau_c >= {FIT_TAU_C_MIN}"),
        };
        format!(
            "{note}; {dev}; c = {:.2} over all",
            c_all.unwrap_or(f64::NAN)
        )
    };
    Ok(TargetReport {
        paper_claim: "measured two-disc friction (Evans and Johnson; Klein-Meuleman, Lubrecht and ten Napel) falls rather closely on Eq. (13)".into(),
        ours,
        headline: fit_range.as_ref().map(|f| f.describe()),
        measures,
        ..TargetReport::emitted(
            "fig8",
            "Fig. 8: measured friction transformed to (tau_c, mu-bar)",
            rows.len(),
            files.into_iter().chain([sidecar]).collect(),
        )
    })
}
