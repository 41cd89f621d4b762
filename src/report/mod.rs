//! The report of a run of every target: `figures/summary.csv` (one row per target) and
//! `figures/index.html`, every table and figure beside the paper's claim and our result, one
//! self-contained page that opens from disk (figures are linked by relative path, no scripts,
//! no fonts, no network).

pub mod convergence;
pub mod html;
pub mod inputs;
pub mod page;
pub mod solve;

use crate::paper::build;
use crate::paper::target::{ErrorSummary, Spread, Target, TargetReport};
use crate::pipeline::context::Context;
use crate::pipeline::csv::{rows, Decimals};
use crate::pipeline::error::PipelineError;
use askama::Template;
use page::{refined_rms, Page};
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

/// One output's error spread of a target, where its cases carry estimates.
fn spread(b: &TargetReport, of: fn(&ErrorSummary) -> Option<Spread>) -> Option<Spread> {
    b.discretisation_error().and_then(of)
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

/// The whole page. `read(name)` returns a file of the output folder (the tables' CSVs and
/// the provenance sidecars).
pub fn index_html(built: &[TargetReport], read: &dyn Fn(&str) -> Option<String>) -> String {
    // The page is plain data in a compiled template: rendering writes into a string and
    // cannot fail but for a formatting error of our own types, which would be a bug.
    Page::of(built, read)
        .render()
        .unwrap_or_else(|e| format!("<!DOCTYPE html>\n<p>the report failed to render: {e}</p>\n"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paper::eq13::Fit;
    use crate::paper::target::{LevelResult, Measure};
    use crate::pipeline::cache::Stamp;
    use crate::pipeline::provenance::Provenance;

    fn built(name: &str, files: &[&str], measures: Vec<Measure>) -> TargetReport {
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
            measures,
        }
    }

    const FIT: Fit = Fit {
        points: 2,
        c: 4.9312,
        c_low: 3.1,
        c_high: 7.4,
        rms_abs_dev: 0.41,
        max_abs_dev: 1.2,
        rms_rel_dev: 0.021,
        max_rel_dev: 0.05,
    };

    #[test]
    fn page_links_every_target_and_escapes_text() {
        let b = [
            built("table1", &["table1.csv"], Vec::new()),
            built(
                "fig3",
                &["fig3.csv", "fig3.svg", "fig3.provenance.json"],
                vec![Measure::Eq13(FIT)],
            ),
        ];
        let mut sidecar = Provenance::new("fig3", &["fig3.csv".into()]);
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
        assert!(
            page.contains(
                "<td>2</td><td>0.41</td><td>1.2</td><td>2.1 %</td><td>5 %</td>\n<td>4.931 (3.1 to 7.4)</td>"
            ),
            "one row per figure, the absolute deviation first: {page}"
        );
        assert_eq!(page.matches("0.41").count(), 1, "each fact once");
        assert!(page.contains("<a href=\"#eq13-fig3\">its row</a>"));
        assert!(page.contains("table1 &#60;title&#62;") || page.contains("table1 &lt;title&gt;"));
        assert!(page.contains("4.93 &#38; more") || page.contains("4.93 &amp; more"));
        assert!(!page.contains("<title>table1"), "titles are escaped");
        assert!(
            page.contains("<dt>made by</dt><dd>repro ")
                && page.contains("level 7, no solves (<a href=\"fig3.provenance.json\">"),
            "the sidecar is shown: {page}"
        );
    }

    #[test]
    fn the_run_line_gives_the_levels_the_cases_ended_on() {
        let one = built("fig1", &[], vec![Measure::levels_ended([7, 7])]);
        let two = built("fig4", &[], vec![Measure::levels_ended([8, 7, 8])]);
        let page = index_html(&[one, two], &|_| None);
        assert!(page.contains("2 from the cache") || page.contains("1 from the cache"));
        assert!(page.contains("1 from the cache; level 7; "), "{page}");
        assert!(
            page.contains("level 7 asked; the cases ended 1 on level 7, 2 on level 8"),
            "{page}"
        );
    }

    #[test]
    fn fig6_shows_both_setups_and_why_they_differ() {
        let paper = Fit {
            rms_abs_dev: 0.77,
            ..FIT
        };
        let fig6 = built(
            "fig6",
            &[],
            vec![Measure::Eq13(FIT), Measure::PaperSetupEq13(paper)],
        );
        let page = index_html(&[fig6], &|_| None);
        assert!(page.contains("fig6</a>, flooded contact"), "{page}");
        assert!(
            page.contains("fig6</a>, the paper&#39;s setup")
                || page.contains("fig6</a>, the paper&#x27;s setup"),
            "{page}"
        );
        assert!(page.contains("<td>0.77</td>") && page.contains("<td>0.41</td>"));
        assert!(page.contains("starve the light contacts"));
    }

    #[test]
    fn table4_sets_ours_beside_the_paper_and_its_claims() {
        let levels = (5..=8)
            .map(|level| LevelResult {
                level,
                h_central: Some(0.02 * (1.0 - 0.25f64.powi(level as i32 - 4))),
                mu_bar: Some(41.0 + 0.25f64.powi(level as i32 - 4)),
                status: if level == 5 {
                    "ok-film-nonpositive"
                } else {
                    "ok"
                },
                seconds: Some(0.5),
            })
            .collect();
        let t4 = built(
            "table4",
            &["table4.csv"],
            vec![Measure::GridConvergence(levels)],
        );
        let read = |_: &str| Some("level,hc\n5,1\n".to_string());
        let page = index_html(&[t4], &read);
        assert!(page.contains("levels 5 to 8, one solve each"), "{page}");
        assert!(page.contains("<code>ok-film-nonpositive</code>: the solve converged"));
        assert!(page.contains("order of convergence, central film"));
        assert!(!page.contains("<th>hc</th>"), "the CSV is not shown twice");
    }

    #[test]
    fn a_dirty_build_is_marked_loudly() {
        let mut sidecar = Provenance::new("fig3", &["fig3.csv".into()]);
        let stamp = Stamp {
            repro_version: "0.1.0".into(),
            git_revision: "abc-dirty".into(),
            host: "vm".into(),
            seconds: 1.0,
            revisions: None,
        };
        sidecar.add_rows("fig3.csv", [("key", Some(&stamp))]);
        let text = sidecar.to_json();
        let b = built("fig3", &["fig3.provenance.json"], Vec::new());
        let page = index_html(&[b], &|_| Some(text.clone()));
        assert!(page.contains("Not reproducible from a commit"));
        assert!(page.contains("fig3: 1 cases were solved by a build of abc-dirty"));
    }
}
