//! The report page's content as data: what `templates/index.html` renders (askama escapes
//! every string; only [`Num`] is marked safe). Each fact is stated once: the Eq. (13)
//! measures in one row per figure, the discretisation error in one row per set of cases,
//! Table 4 in its section, each target's other facts in its own section.

use super::convergence::Convergence;
use super::html::{percent, Cell, Num, Table};
use crate::paper::eq13::Fit;
use crate::paper::find;
use crate::paper::target::{ErrorSummary, Measure, Spread, TargetReport};
use crate::pipeline::cache::GIT_REVISION;
use crate::pipeline::provenance::{self, Provenance};
use askama::Template;

/// Rows of a CSV small enough to show as a table beside a picture.
const SMALL_TABLE_ROWS: usize = 10;

/// Rows of a table shown where there is no picture.
const TABLE_ROWS: usize = 30;

/// Why Fig. 6's two setups differ, in one line (docs/RESULTS.md, docs/DOMAIN_NOTES.md).
const SETUPS_DIFFER: &str = "The two setups differ at light loads: the paper's domain and its \
P = 0 edge starve the light contacts' inlet, whose shear the flooded contact (the rule's wide \
domain with the far field) carries, so the paper's light points sit nearer Eq. (13) \
(docs/RESULTS.md, docs/DOMAIN_NOTES.md).";

/// The page.
#[derive(Template)]
#[template(path = "index.html")]
pub struct Page {
    /// The git revision of the build that assembled the page.
    pub revision: String,
    /// Every build with uncommitted changes behind the page: shown as a warning at the top.
    pub dirty: Vec<String>,
    /// `(id, title)` of every target.
    pub toc: Vec<(String, String)>,
    /// Eq. (13) against the fitted `c`, one row per figure (two for Fig. 6's setups).
    pub eq13: Vec<Eq13Row>,
    /// Why Fig. 6's setups differ, where both are in the table.
    pub setups_differ: Option<&'static str>,
    /// The discretisation error, one row per set of cases.
    pub errors: Vec<ErrorRow>,
    /// `(tau_c, c)`: the `c` the paper's own level-7 friction implies at the Appendix case.
    pub reading_c: Option<(Num, Num)>,
    /// One section per target.
    pub sections: Vec<Section>,
}

/// A row of the Eq. (13) table.
pub struct Eq13Row {
    /// The target (its section's id).
    pub target: String,
    /// The first row of its target (carries the row's anchor).
    pub first: bool,
    /// What the row measures, where a target has more than one row.
    pub setup: &'static str,
    /// Points with `tau_c >= 100`.
    pub points: usize,
    /// RMS and largest `|mu-bar - Eq. (13)|`, mu-bar units.
    pub rms_abs: Num,
    /// Largest absolute deviation.
    pub max_abs: Num,
    /// RMS and largest relative deviation, per cent.
    pub rms_rel: Num,
    /// Largest relative deviation, per cent.
    pub max_rel: Num,
    /// Least-squares `c` and its 95 % bootstrap interval.
    pub c: Num,
    /// Low end of the interval.
    pub c_low: Num,
    /// High end of the interval.
    pub c_high: Num,
    /// Least-squares `c` over every point of the target.
    pub c_all: Option<Num>,
    /// The refined formula's cross-validated RMS relative deviation, per cent.
    pub refined: Option<Num>,
}

impl Eq13Row {
    fn of(target: &str, setup: &'static str, f: &Fit) -> Eq13Row {
        Eq13Row {
            target: target.to_string(),
            first: true,
            setup,
            points: f.points,
            rms_abs: Num(f.rms_abs_dev),
            max_abs: Num(f.max_abs_dev),
            rms_rel: percent(f.rms_rel_dev),
            max_rel: percent(f.max_rel_dev),
            c: Num(f.c),
            c_low: Num(f.c_low),
            c_high: Num(f.c_high),
            c_all: None,
            refined: None,
        }
    }
}

/// One output's error spread: median and worst, per cent, and the case of the worst.
pub struct SpreadCell {
    /// Median relative error, per cent.
    pub median: Num,
    /// Worst relative error, per cent.
    pub worst: Num,
    /// The case of the worst (its row in the CSV).
    pub case: usize,
}

impl SpreadCell {
    fn of(s: Option<Spread>) -> Option<SpreadCell> {
        s.map(|s| SpreadCell {
            median: percent(s.median),
            worst: percent(s.worst),
            case: s.worst_case,
        })
    }
}

/// A row of the discretisation-error table: the targets that share these cases and outputs.
pub struct ErrorRow {
    /// The targets.
    pub targets: Vec<String>,
    /// Cases with an estimate.
    pub estimated: usize,
    /// Central film.
    pub film: Option<SpreadCell>,
    /// Minimum film.
    pub min_film: Option<SpreadCell>,
    /// The plotted friction.
    pub friction: Option<SpreadCell>,
}

impl ErrorRow {
    /// Central film, minimum film and friction, in the table's order.
    pub fn spreads(&self) -> [Option<&SpreadCell>; 3] {
        [
            self.film.as_ref(),
            self.min_film.as_ref(),
            self.friction.as_ref(),
        ]
    }
}

/// A target's section.
pub struct Section {
    /// Target name, the section's id.
    pub id: String,
    /// Title.
    pub title: String,
    /// The paper's claim (empty where a table states it).
    pub paper: String,
    /// Our result, where no table of the page states it.
    pub ours: String,
    /// It has a row in the Eq. (13) table.
    pub eq13_row: bool,
    /// Cases, solves, levels, time.
    pub run: String,
    /// The provenance sidecar's summary and its file.
    pub made_by: Option<(String, String)>,
    /// Pictures.
    pub images: Vec<String>,
    /// Table 4's levels and claims.
    pub convergence: Option<Convergence>,
    /// CSVs shown as tables: `(file, table)`.
    pub tables: Vec<(String, Table)>,
    /// Every file it wrote.
    pub files: Vec<String>,
}

/// The levels a target's cases were solved on: the level asked, and the levels they ended
/// on where some ended finer.
fn levels(b: &TargetReport) -> Option<String> {
    if let Some(levels) = b.grid_convergence() {
        let (first, last) = (levels.first()?.level, levels.last()?.level);
        return Some(format!("levels {first} to {last}, one solve each"));
    }
    let asked = b.level?;
    let ended = b.levels_ended().unwrap_or_default();
    if ended.iter().all(|&(l, _)| l == asked) {
        return Some(format!("level {asked}"));
    }
    let counts: Vec<String> = ended
        .iter()
        .map(|(l, n)| format!("{n} on level {l}"))
        .collect();
    Some(format!(
        "level {asked} asked; the cases ended {} (finer where the accuracy rule refines a case, or where its solver has a level of its own: the line contacts)",
        counts.join(", ")
    ))
}

/// The section's run line.
fn run_line(b: &TargetReport) -> String {
    let mut facts = vec![format!("{} cases", b.cases)];
    if let Some(n) = b.solved {
        facts.push(format!("{n} solved"));
    }
    if let Some(n) = b.cached {
        facts.push(format!("{n} from the cache"));
    }
    facts.extend(levels(b));
    if let Some(l) = find(&b.name).and_then(|a| a.default_level()) {
        facts.push(format!(
            "cheapest level with mu-bar within 1 % (repro accuracy): {l}"
        ));
    }
    facts.push(format!("{:.1} s", b.seconds));
    facts.join("; ")
}

fn section(b: &TargetReport, read: &dyn Fn(&str) -> Option<String>) -> Section {
    let has_svg = b.files.iter().any(|f| f.ends_with(".svg"));
    let convergence = b.grid_convergence().map(Convergence::of);
    // A table is shown where there is no picture, and small ones beside a picture (the line
    // contacts of Fig. 7, the refined fit); the per-case CSVs of the sweeps are only linked,
    // and Table 4's CSV is the convergence table.
    let tables = b
        .files
        .iter()
        .filter(|f| f.ends_with(".csv") && convergence.is_none())
        .filter_map(|f| {
            let text = read(f)?;
            let rows = text.lines().count().saturating_sub(1);
            (!has_svg || rows <= SMALL_TABLE_ROWS)
                .then(|| Table::of_csv(&text, TABLE_ROWS))
                .flatten()
                .map(|t| (f.clone(), t))
        })
        .collect();
    let made_by = b
        .files
        .iter()
        .find(|f| f.ends_with(provenance::SUFFIX))
        .and_then(|f| Some((provenance::summary_of(&read(f)?), f.clone())));
    Section {
        id: b.name.clone(),
        title: b.title.clone(),
        paper: b.paper_claim.clone(),
        ours: b.ours.clone(),
        eq13_row: b.eq13().is_some(),
        run: run_line(b),
        made_by,
        images: b
            .files
            .iter()
            .filter(|f| f.ends_with(".svg"))
            .cloned()
            .collect(),
        convergence,
        tables,
        files: b.files.clone(),
    }
}

/// The refined formula's cross-validated RMS for target `name`, from whichever target
/// measured it.
pub fn refined_rms(built: &[TargetReport], name: &str) -> Option<f64> {
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

fn eq13_rows(built: &[TargetReport]) -> Vec<Eq13Row> {
    let mut rows = Vec::new();
    for b in built {
        let Some(f) = b.eq13() else { continue };
        let paper_setup = b.paper_setup_eq13();
        let setup = if paper_setup.is_some() {
            "flooded contact (drawn, fitted)"
        } else {
            ""
        };
        rows.push(Eq13Row {
            c_all: b.eq13_c_all().map(Num),
            refined: refined_rms(built, &b.name).map(percent),
            ..Eq13Row::of(&b.name, setup, f)
        });
        if let Some(p) = paper_setup {
            rows.push(Eq13Row {
                first: false,
                ..Eq13Row::of(&b.name, "the paper's setup (P = 0 on its domain)", p)
            });
        }
    }
    rows
}

/// The discretisation errors, targets with the same estimates (Figs. 1 and 2: the same
/// cases and friction) sharing a row.
fn error_rows(built: &[TargetReport]) -> Vec<ErrorRow> {
    let mut groups: Vec<(ErrorSummary, Vec<String>)> = Vec::new();
    for b in built {
        let Some(e) = b.discretisation_error() else {
            continue;
        };
        match groups.iter_mut().find(|g| g.0 == *e) {
            Some(g) => g.1.push(b.name.clone()),
            None => groups.push((*e, vec![b.name.clone()])),
        }
    }
    groups
        .into_iter()
        .map(|(e, targets)| ErrorRow {
            targets,
            estimated: e.estimated,
            film: SpreadCell::of(e.h_central),
            min_film: SpreadCell::of(e.h_min),
            friction: SpreadCell::of(e.mu_bar),
        })
        .collect()
}

/// The builds behind the page that had uncommitted changes: the assembling one, and every
/// one that solved cases the page shows.
fn dirty_builds(built: &[TargetReport], read: &dyn Fn(&str) -> Option<String>) -> Vec<String> {
    let mut dirty = Vec::new();
    if GIT_REVISION.ends_with("-dirty") {
        dirty.push(format!(
            "this page was assembled by a build of {GIT_REVISION}"
        ));
    }
    for b in built {
        let sidecars = b.files.iter().filter(|f| f.ends_with(provenance::SUFFIX));
        for text in sidecars.filter_map(|f| read(f)) {
            let Ok(p) = serde_json::from_str::<Provenance>(&text) else {
                continue;
            };
            for c in p
                .computed_by
                .iter()
                .filter(|c| c.git_revision.ends_with("-dirty"))
            {
                dirty.push(format!(
                    "{}: {} cases were solved by a build of {}",
                    b.name, c.cases, c.git_revision
                ));
            }
        }
    }
    dirty
}

impl Page {
    /// The page of `built`; `read(name)` returns a file of the output folder.
    pub fn of(built: &[TargetReport], read: &dyn Fn(&str) -> Option<String>) -> Page {
        let eq13 = eq13_rows(built);
        let has_setups = eq13.iter().any(|r| !r.first);
        Page {
            revision: GIT_REVISION.to_string(),
            dirty: dirty_builds(built, read),
            toc: built
                .iter()
                .map(|b| (b.name.clone(), b.title.clone()))
                .collect(),
            eq13,
            setups_differ: has_setups.then_some(SETUPS_DIFFER),
            errors: error_rows(built),
            reading_c: crate::paper::table4::paper_implied_c().map(|(t, c)| (Num(t), Num(c))),
            sections: built.iter().map(|b| section(b, read)).collect(),
        }
    }
}
