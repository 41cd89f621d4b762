//! The report of a run of every target: `figures/summary.csv` (one row per target) and
//! `figures/index.html`, every table and figure beside the paper's claim and our result, one
//! self-contained page that opens from disk (figures are linked by relative path, no scripts,
//! no fonts, no network).

pub mod html;
pub mod solve;

use crate::paper::target::{ErrorSummary, Measure, Spread, Target, TargetReport};
use crate::paper::{build, find};
use crate::pipeline::context::Context;
use crate::pipeline::csv::{rows, Decimals};
use crate::pipeline::error::PipelineError;
use crate::pipeline::provenance;
use html::{csv_table, escape, human};
use serde::Serialize;

/// Builds every target in order and writes `summary.csv` and the report `index.html`; stops at the first target that
/// cannot be built (a solve that fails is a result, not a stop).
pub fn build_all(
    targets: &[&dyn Target],
    ctx: &Context,
) -> Result<Vec<TargetReport>, PipelineError> {
    let mut built = Vec::new();
    for a in targets {
        built.push(build(*a, ctx)?);
    }
    ctx.write("summary.csv", &summary_csv(&built))?;
    let read = |f: &str| std::fs::read_to_string(ctx.out.join(f)).ok();
    ctx.write("index.html", &index_html(&built, &read))?;
    Ok(built)
}

/// A row of `figures/summary.csv`.
#[derive(Default, Serialize)]
struct SummaryRow<'a> {
    target: &'a str,
    cases: usize,
    solved: Option<usize>,
    cached: Option<usize>,
    level: Option<u32>,
    /// RMS of `mu-bar - asinh(tau_c / 5)` over `tau_c >= 100`, mu-bar units.
    rms_abs_dev: Option<f64>,
    max_abs_dev: Option<f64>,
    rms_rel_dev: Option<f64>,
    max_rel_dev: Option<f64>,
    fitted_c: Option<f64>,
    /// Bootstrap 95 % interval of `fitted_c`.
    fitted_c_low: Option<f64>,
    fitted_c_high: Option<f64>,
    fitted_c_all: Option<f64>,
    /// The refined formula's cross-validated RMS relative deviation (the `mastercurve` target).
    refined_rms_rel_dev: Option<f64>,
    /// The discretisation error of the cases: median and worst relative error of the central
    /// film, the minimum film and the plotted `mu-bar`, and the case of the worst.
    hc_err_median: Option<f64>,
    hc_err_worst: Option<f64>,
    hc_err_worst_case: Option<usize>,
    hmin_err_median: Option<f64>,
    hmin_err_worst: Option<f64>,
    hmin_err_worst_case: Option<usize>,
    mu_err_median: Option<f64>,
    mu_err_worst: Option<f64>,
    mu_err_worst_case: Option<usize>,
    /// Wall time, s, to the hundredth.
    seconds: Decimals<2>,
}

/// The refined formula's cross-validated RMS for target `name`, from whichever target
/// measured it.
fn refined_rms(built: &[TargetReport], name: &str) -> Option<f64> {
    built
        .iter()
        .flat_map(|b| &b.measures)
        .find_map(|m| match m {
            Measure::RefinedCrossValidation {
                target,
                rms_rel_dev,
            } if *target == name => Some(*rms_rel_dev),
            _ => None,
        })
}

/// One output's error spread of a target, where its cases carry estimates.
fn spread(b: &TargetReport, of: fn(&ErrorSummary) -> Option<Spread>) -> Option<Spread> {
    b.discretisation_error().and_then(of)
}

/// The discretisation error per target: median and worst relative error of the central film,
/// the minimum film and the plotted friction, with the case of the worst.
fn error_table(built: &[TargetReport]) -> String {
    let rows: Vec<String> = built
        .iter()
        .filter_map(|b| {
            let e = b.discretisation_error()?;
            let cell = |s: Option<Spread>| {
                s.map(|s| {
                    format!(
                        "{} % / {} % (case {})",
                        human(100.0 * s.median),
                        human(100.0 * s.worst),
                        s.worst_case
                    )
                })
                .unwrap_or_default()
            };
            Some(format!(
                "<tr><td><a href=\"#{name}\">{name}</a></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                e.estimated,
                cell(e.h_central),
                cell(e.h_min),
                cell(e.mu_bar),
                name = b.name,
            ))
        })
        .collect();
    if rows.is_empty() {
        return String::new();
    }
    format!(
        "<h2>Discretisation error</h2>\n<p>Each case's error, estimated from its level and the \
         two below it (observed order, Richardson extrapolation, Roache's safety factor; \
         docs/ACCURACY_NOTES.md): median / worst relative error over the cases, and the case \
         of the worst (its row in the figure's CSV). The figures draw it as error bars where \
         it is larger than the marker.</p>\n<table>\n<tr><th>target</th><th>cases estimated</th>\
         <th>central film</th><th>minimum film</th><th>mu-bar</th></tr>\n{}</table>\n",
        rows.concat()
    )
}

/// `figures/summary.csv`, one row per target.
pub fn summary_csv(built: &[TargetReport]) -> String {
    rows(built.iter().map(|b| {
        let fit = b.eq13();
        SummaryRow {
            target: &b.name,
            cases: b.cases,
            solved: b.solved,
            cached: b.cached,
            level: b.level,
            rms_abs_dev: fit.map(|f| f.rms_abs_dev),
            max_abs_dev: fit.map(|f| f.max_abs_dev),
            rms_rel_dev: fit.map(|f| f.rms_rel_dev),
            max_rel_dev: fit.map(|f| f.max_rel_dev),
            fitted_c: fit.map(|f| f.c),
            fitted_c_low: fit.map(|f| f.c_low),
            fitted_c_high: fit.map(|f| f.c_high),
            fitted_c_all: b.eq13_c_all(),
            refined_rms_rel_dev: refined_rms(built, &b.name),
            hc_err_median: spread(b, |e| e.h_central).map(|s| s.median),
            hc_err_worst: spread(b, |e| e.h_central).map(|s| s.worst),
            hc_err_worst_case: spread(b, |e| e.h_central).map(|s| s.worst_case),
            hmin_err_median: spread(b, |e| e.h_min).map(|s| s.median),
            hmin_err_worst: spread(b, |e| e.h_min).map(|s| s.worst),
            hmin_err_worst_case: spread(b, |e| e.h_min).map(|s| s.worst_case),
            mu_err_median: spread(b, |e| e.mu_bar).map(|s| s.median),
            mu_err_worst: spread(b, |e| e.mu_bar).map(|s| s.worst),
            mu_err_worst_case: spread(b, |e| e.mu_bar).map(|s| s.worst_case),
            seconds: Decimals(b.seconds),
        }
    }))
}

/// Rows of a CSV small enough to show as a table beside a picture.
const SMALL_TABLE_ROWS: usize = 10;

/// The mastercurve claim measured, one row per target that has points on it: the absolute
/// deviation from Eq. (13) first (what the paper's plot shows), the relative one, the fitted
/// `c` with its bootstrap interval, and the refined formula's cross-validated RMS.
fn measures_table(built: &[TargetReport]) -> String {
    let rows: Vec<String> = built
        .iter()
        .filter_map(|b| {
            let f = b.eq13()?;
            let pct = |v: f64| format!("{} %", human(100.0 * v));
            let refined = refined_rms(built, &b.name).map(pct).unwrap_or_default();
            Some(format!(
                "<tr><td><a href=\"#{name}\">{name}</a></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{} ({} to {})</td><td>{refined}</td></tr>\n",
                f.points,
                human(f.rms_abs_dev),
                human(f.max_abs_dev),
                pct(f.rms_rel_dev),
                pct(f.max_rel_dev),
                human(f.c),
                human(f.c_low),
                human(f.c_high),
                name = escape(&b.name),
            ))
        })
        .collect();
    if rows.is_empty() {
        return String::new();
    }
    format!(
        "<h2>The mastercurve claim, measured</h2>\n<p>Computed sliding friction (total for fig2) \
against Eq. (13), &mu;&#772; = asinh(&tau;&#772;<sub>c</sub>/5), over the cases with \
&tau;&#772;<sub>c</sub> &ge; 100. The paper's figures show the absolute deviation (&mu;&#772; \
from 0 to 45 on a linear axis); the relative one and the least-squares c follow, c with the \
95 % interval of a bootstrap over the cases. The last column is the refined formula of the \
mastercurve section, fitted without the figure it is tested on.</p>\n\
<div class=\"scroll\"><table>\n<tr><th>target</th><th>cases</th><th>RMS |&Delta;&mu;&#772;|</th>\
<th>largest |&Delta;&mu;&#772;|</th><th>RMS relative</th><th>largest relative</th>\
<th>c (95 % interval)</th><th>refined formula, RMS relative</th></tr>\n{}</table></div>\n",
        rows.concat()
    )
}

/// One target's section: claim, result, counts, its SVG (if any) and its table (tables only).
fn section(b: &TargetReport, read: &dyn Fn(&str) -> Option<String>) -> String {
    let mut s = format!(
        "<section id=\"{name}\">\n<h2>{title}</h2>\n<dl>\n<dt>paper</dt><dd>{claim}</dd>\n<dt>ours</dt><dd>{ours}</dd>\n",
        name = escape(&b.name),
        title = escape(&b.title),
        claim = escape(&b.paper_claim),
        ours = escape(&b.ours),
    );
    let mut facts = vec![format!("{} cases", b.cases)];
    if let Some(n) = b.solved {
        facts.push(format!("{n} solved"));
    }
    if let Some(n) = b.cached {
        facts.push(format!("{n} from the cache"));
    }
    if let Some(l) = b.level {
        facts.push(format!("level {l}"));
    }
    if let Some(l) = find(&b.name).and_then(|a| a.default_level()) {
        facts.push(format!(
            "cheapest level with mu-bar within 1 % (repro accuracy): {l}"
        ));
    }
    facts.push(format!("{:.1} s", b.seconds));
    s.push_str(&format!(
        "<dt>run</dt><dd>{}</dd>\n",
        escape(&facts.join(", "))
    ));
    if let Some(f) = b.eq13() {
        s.push_str(&format!(
            "<dt>Eq. 13</dt><dd>{} points with tau_c &ge; 100: {}</dd>\n",
            f.points,
            escape(&f.describe())
        ));
    }
    for f in b.files.iter().filter(|f| f.ends_with(provenance::SUFFIX)) {
        if let Some(text) = read(f) {
            s.push_str(&format!(
                "<dt>made by</dt><dd>{} (<a href=\"{}\">cache keys and stamps</a>)</dd>\n",
                escape(&provenance::summary_of(&text)),
                escape(f)
            ));
        }
    }
    s.push_str("</dl>\n");
    for f in &b.files {
        if f.ends_with(".svg") {
            s.push_str(&format!(
                "<p><img src=\"{f}\" alt=\"{alt}\" width=\"800\"></p>\n",
                f = escape(f),
                alt = escape(&b.title)
            ));
        }
    }
    // A table is shown where there is no picture, and small ones beside a picture (the line
    // contacts of Fig. 7, the refined fit); the per-case CSVs of the sweeps are only linked.
    let has_svg = b.files.iter().any(|f| f.ends_with(".svg"));
    for f in b.files.iter().filter(|f| f.ends_with(".csv")) {
        if let Some(text) = read(f) {
            if !has_svg || text.lines().count() <= SMALL_TABLE_ROWS + 1 {
                s.push_str(&format!("<p class=\"note\">{}</p>\n", escape(f)));
                s.push_str(&csv_table(&text, 30));
            }
        }
    }
    let links: Vec<String> = b
        .files
        .iter()
        .map(|f| format!("<a href=\"{0}\">{0}</a>", escape(f)))
        .collect();
    s.push_str(&format!(
        "<p class=\"files\">files: {}</p>\n</section>\n",
        links.join(" ")
    ));
    s
}

/// The whole page. `read(name)` returns a file of the output folder (the tables' CSVs).
pub fn index_html(built: &[TargetReport], read: &dyn Fn(&str) -> Option<String>) -> String {
    let mut page = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
<title>repro: A Generalized Traction Curve for EHL Contacts</title>\n<style>\n\
body { font-family: sans-serif; max-width: 60em; margin: 2em auto; padding: 0 1em; }\n\
table { border-collapse: collapse; font-size: 0.85em; }\n\
.scroll { overflow-x: auto; max-width: 100%; }\n\
img { max-width: 100%; height: auto; }\n\
td, th { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: right; }\n\
dt { font-weight: bold; float: left; width: 4em; }\n\
dd { margin-left: 5em; }\n\
.note, .files { color: #555; font-size: 0.9em; }\n\
</style>\n</head>\n<body>\n\
<h1>A Generalized Traction Curve for EHL Contacts: the paper regenerated</h1>\n\
<p>Jacod, Venner and Lugt, ASME J. Tribology 2001, recomputed from first principles by \
<code>repro</code>. Each section sets the paper's claim beside what this run computed; \
the CSV files hold every case. Nothing on this page is copied from the paper except the \
claims quoted as &ldquo;paper&rdquo;.</p>\n<ul>\n",
    );
    for b in built {
        page.push_str(&format!(
            "<li><a href=\"#{0}\">{1}</a></li>\n",
            escape(&b.name),
            escape(&b.title)
        ));
    }
    page.push_str("</ul>\n");
    page.push_str(&measures_table(built));
    page.push_str(&error_table(built));
    page.push_str(&reading_c());
    for b in built {
        page.push_str(&section(b, read));
    }
    page.push_str("</body>\n</html>\n");
    page
}

/// How to read a fitted `c`: the `c` that the paper's own Table 4 friction implies at the
/// Appendix case's `tau_c` (our Eq. 12, no solve needed).
fn reading_c() -> String {
    let Some((tau_c, c)) = crate::paper::table4::paper_implied_c() else {
        return String::new();
    };
    format!(
        "<p class=\"note\">Reading the fitted c: at large tau_c, Eq. (13) is ln(2 tau_c / c), so a \
1 % change of mu-bar near 40 moves c by a factor 1.5. The paper's own level-7 friction of \
Table 4 (41.13) at the case's tau_c = {tau_c:.3e} lies on Eq. (13) only with c = {c:.2}. \
The RMS and largest deviations from Eq. (13) measure the collapse better than c does.</p>\n"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paper::mastercurve::fit::Fit;

    fn built(name: &str, files: &[&str], fit: Option<Fit>) -> TargetReport {
        TargetReport {
            name: name.to_string(),
            title: format!("{name} <title>"),
            cases: 3,
            solved: Some(2),
            cached: Some(1),
            level: Some(7),
            seconds: 1.25,
            files: files.iter().map(|s| s.to_string()).collect(),
            paper_claim: "c = 5".into(),
            ours: "c = 4.93 & more".into(),
            headline: None,
            measures: fit.map(Measure::Eq13).into_iter().collect(),
        }
    }

    #[test]
    fn page_links_every_target_and_escapes_text() {
        let fit = Fit {
            points: 2,
            c: 4.9312,
            c_low: 3.1,
            c_high: 7.4,
            rms_abs_dev: 0.41,
            max_abs_dev: 1.2,
            rms_rel_dev: 0.021,
            max_rel_dev: 0.05,
        };
        let b = [
            built("table1", &["table1.csv"], None),
            built(
                "fig3",
                &["fig3.csv", "fig3.svg", "fig3.provenance.json"],
                Some(fit),
            ),
        ];
        let mut sidecar = provenance::Provenance::new("fig3", &["fig3.csv".into()]);
        sidecar.level = Some(7);
        let sidecar = sidecar.to_json();
        let read = |f: &str| match f {
            "table1.csv" => Some("a,b\n1,2\n".to_string()),
            "fig3.provenance.json" => Some(sidecar.clone()),
            _ => None,
        };
        let page = index_html(&b, &read);
        assert!(page.contains("href=\"#table1\"") && page.contains("href=\"#fig3\""));
        assert!(page.contains("<img src=\"fig3.svg\""));
        assert!(
            page.contains("<td>1</td><td>2</td>"),
            "table1 shown as a table"
        );
        assert!(page.contains("2 points with tau_c &ge; 100: off Eq. (13) by 0.41 RMS"));
        assert!(
            page.contains(
                "<td>0.41</td><td>1.2</td><td>2.1 %</td><td>5 %</td><td>4.931 (3.1 to 7.4)</td>"
            ),
            "the measures lead with the absolute band"
        );
        assert!(page.contains("table1 &lt;title&gt;") && page.contains("4.93 &amp; more"));
        assert!(!page.contains("<title>table1"), "titles are escaped");
        assert!(
            page.contains("<dt>made by</dt><dd>repro ")
                && page.contains("level 7, no solves (<a href=\"fig3.provenance.json\">"),
            "the sidecar is shown: {page}"
        );
    }
}
