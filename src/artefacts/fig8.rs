//! Fig. 8: measured friction transformed to `(tau_c, mu-bar)` by Sec. IV and drawn on
//! Eq. (13). The data are every `*.csv` under [`DATA_DIR`] (format: `docs/measured-data.md`);
//! nothing is computed or invented. When the folder holds no dataset the target still builds,
//! and its CSV, its SVG and its report entry say so and how to add one.

use super::csv::{num, quote, table};
use super::fit::{fit, mastercurve, PAPER_C};
use super::measured::{read_folder, transform, ReducedRow};
use super::plot::{self, render_svg, Curve, Figure, Marker, Scale, Series};
use super::targets::{Built, Context, FIT_TAU_C_MIN};
use crate::physics::lubricant::LubricantTable;
use crate::physics::traction::Contact;
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
                quote(&r.dataset),
                r.row.row.to_string(),
                quote(&r.row.series),
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
                quote(&r.row.source),
            ]
        })
        .collect();
    // Sources are quoted (they hold commas), which `table` refuses: join here.
    let mut out = comment;
    out.push_str(&table(&HEADER, &[]));
    for c in cells {
        out.push_str(&c.join(","));
        out.push('\n');
    }
    out
}

fn svg(rows: &[ReducedRow], fitted: Option<f64>) -> Result<String, String> {
    let mut series: Vec<Series> = Vec::new();
    for r in rows {
        let p = (r.reduced.characteristic.tau_c, r.reduced.mu_bar);
        match series.iter_mut().find(|s| s.label == r.row.series) {
            Some(s) => s.points.push(p),
            None => series.push(Series {
                label: r.row.series.clone(),
                points: vec![p],
                marker: Marker::nth(series.len()),
            }),
        }
    }
    let xs: Vec<f64> = rows
        .iter()
        .map(|r| r.reduced.characteristic.tau_c)
        .filter(|x| *x > 0.0 && x.is_finite())
        .collect();
    let (x_min, x_max) = if xs.is_empty() {
        // The range of the paper's Figs. 4-8, for the curve alone.
        (1.0, 1e4)
    } else {
        xs.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            })
    };
    let mut curves = vec![Curve {
        label: format!("Eq. (13): {} = asinh({}/5)", plot::MU_BAR, plot::TAU_C),
        ..plot::mastercurve(x_min, x_max, PAPER_C, 200)
    }];
    if let Some(c) = fitted {
        curves.push(Curve {
            dashed: false,
            ..plot::mastercurve(x_min, x_max, c, 200)
        });
    }
    let fig = Figure {
        title: "Fig. 8 — measured friction on the mastercurve (Sec. IV)".into(),
        x_label: format!("characteristic shear stress {}", plot::TAU_C),
        y_label: format!("measured reduced friction {}", plot::MU_BAR),
        x_scale: Scale::Log,
        y_scale: Scale::Linear,
        x_range: xs.is_empty().then_some((x_min, x_max)),
        y_range: xs.is_empty().then_some((0.0, 9.0)),
        series,
        curves,
        note: rows.is_empty().then(|| {
            "No measured dataset included: add CSV files to cases/fig8/ (docs/measured-data.md)"
                .to_string()
        }),
    };
    render_svg(&fig).map_err(|e| format!("fig8.svg: {e}"))
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
    let csv = super::targets::write(ctx, "fig8.csv", &csv_text(&rows, datasets.len()))?;
    let picture = super::targets::write(ctx, "fig8.svg", &svg(&rows, fit_all.map(|f| f.c))?)?;
    let ours = if rows.is_empty() {
        (ctx.warn)(format!("fig8: {NO_DATA}"));
        NO_DATA.to_string()
    } else {
        let dev = match fit_range {
            Some(f) => format!(
                "c = {:.2} over {} points with tau_c >= {FIT_TAU_C_MIN} (RMS deviation from Eq. 13 {:.1} %, largest {:.1} %)",
                f.c,
                f.points,
                100.0 * f.rms_rel_dev,
                100.0 * f.max_rel_dev
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
    })
}
