//! Fig. 8: measured friction transformed to `(tau_c, mu-bar)` by Sec. IV and drawn on
//! Eq. (13). The data are every `*.csv` under [`DATA_DIR`] (format: `docs/measured-data.md`);
//! nothing is computed or invented. When the folder holds no dataset the target still builds,
//! and its CSV, its SVG and its report entry say so and how to add one.

pub mod measured;
pub mod picture;

use crate::paper::fig8::measured::{read_folder, transform, ReducedRow};
use crate::paper::mastercurve::fit::{fit, mastercurve, FIT_TAU_C_MIN, PAPER_C};
use crate::physics::lubricant::LubricantTable;
use crate::physics::traction::Contact;
use crate::pipeline::context::{write, Built, Context};
use crate::pipeline::csv::{num, table};
use std::path::Path;

/// Folder of the measured datasets, relative to the working directory (the repository root
/// for `make figures`).
pub const DATA_DIR: &str = "cases/fig8";

/// What the figure says when it holds no measured point.
pub const NO_DATA: &str = "No measured dataset is included: cases/fig8/ holds no *.csv file. To add one, write the measured points (each with its source) in the format of docs/measured-data.md to cases/fig8/NAME.csv and run `repro fig8`.";

const HEADER: [&str; 21] = [
    "dataset",
    "row",
    "series",
    "contact",
    "ph_pa",
    "temperature_c",
    "slip",
    "m",
    "l",
    "s_bar",
    "eta_bar_ph",
    "film_formula",
    "hc_moes",
    "hc_m",
    "tau0_pa",
    "mu",
    "tau_c_x",
    "mu_bar_y",
    "mu_bar_eq13",
    "rel_dev_eq13",
    "source",
];

fn csv_text(rows: &[ReducedRow], files: usize) -> String {
    let comment = if rows.is_empty() {
        format!("# fig8: {NO_DATA}\n")
    } else {
        format!(
            "# fig8: {} measured points from {files} file(s) in {DATA_DIR}/, transformed by Sec. IV (docs/measured-data.md); nothing here is computed by the solver\n",
            rows.len()
        )
    };
    let cells: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let c = &r.reduced.characteristic;
            let p = &r.row.point;
            let eq13 = mastercurve(c.tau_c, PAPER_C);
            vec![
                r.dataset.clone(),
                r.row.row.to_string(),
                r.row.series.clone(),
                match p.contact {
                    Contact::Elliptical { .. } => "elliptical".into(),
                    Contact::Line { .. } => "line".into(),
                },
                num(c.ph_pa),
                num(r.row.temperature_c),
                num(c.slip),
                num(c.m),
                num(c.l),
                num(c.s_bar),
                num(c.eta_bar_ph),
                p.film.name().into(),
                num(c.hc_moes),
                num(c.hc_m),
                num(p.tau0_pa),
                num(r.row.mu),
                num(c.tau_c),
                num(r.reduced.mu_bar),
                num(eq13),
                num(r.reduced.mu_bar / eq13 - 1.0),
                r.row.source.clone(),
            ]
        })
        .collect();
    comment + &table(&HEADER, &cells)
}

/// Builds Fig. 8 from the datasets of [`DATA_DIR`].
pub fn build(ctx: &Context) -> Result<Built, String> {
    build_from(Path::new(DATA_DIR), ctx)
}

/// Builds Fig. 8 from the datasets of `dir`.
pub fn build_from(dir: &Path, ctx: &Context) -> Result<Built, String> {
    let lubs = LubricantTable::table1();
    let datasets = read_folder(dir).map_err(|e| e.to_string())?;
    let mut rows = Vec::new();
    for d in &datasets {
        rows.extend(transform(d, &lubs).map_err(|e| e.to_string())?);
    }
    let points: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r.reduced.characteristic.tau_c, r.reduced.mu_bar))
        .collect();
    let fit_range = fit(&points
        .iter()
        .copied()
        .filter(|p| p.0 >= FIT_TAU_C_MIN)
        .collect::<Vec<_>>());
    let fit_all = fit(&points);
    let csv = write(ctx, "fig8.csv", &csv_text(&rows, datasets.len()))?;
    let svg = picture::svg(&rows, fit_all.map(|f| f.c))?;
    let picture = write(ctx, "fig8.svg", &svg)?;
    let ours = if rows.is_empty() {
        (ctx.warn)(format!("fig8: {NO_DATA}"));
        NO_DATA.to_string()
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
            "{} measured points from {} file(s); {dev}; c = {:.2} over all",
            rows.len(),
            datasets.len(),
            fit_all.map(|f| f.c).unwrap_or(f64::NAN)
        )
    };
    Ok(Built {
        name: "fig8",
        title: "Fig. 8: measured friction transformed to (tau_c, mu-bar)".into(),
        cases: rows.len(),
        solved: None,
        cached: None,
        level: None,
        fit: fit_range,
        fit_all,
        seconds: 0.0,
        files: vec![csv, picture],
        paper_claim: "measured two-disc friction (Evans and Johnson; Klein-Meuleman, Lubrecht and ten Napel) falls rather closely on Eq. (13)".into(),
        ours,
        refined: Vec::new(),
    })
}
