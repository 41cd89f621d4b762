//! Every artefact of the paper as a named target: its cases, its computation (cached solves)
//! and its files (CSV, SVG). `repro list`, `repro <target>`, `repro all` and `make figures`
//! all read [`TARGETS`].

use super::cache::Cache;
use super::csv::{num, opt, table, write_atomic};
use super::fit::{fit, mastercurve, Fit, PAPER_C};
use super::plot::{Marker, Series};
use super::run::{run_cases, CaseRun, Outcome, RunProgress};
use super::sweep::{shipped_sweep, Sweep};
use crate::physics::case::{LubricantSpec, Spec};
use crate::solver::point::Params;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The paper's working level (256 x 256), the default of every computed figure.
pub const WORKING_LEVEL: u32 = 7;

/// Level of the line contacts of Fig. 7 (512 intervals): sliding `mu-bar` within 0.2 % of
/// level 11 on the heaviest Table 3 case (LINE_NOTES.md), a few tenths of a second per case.
pub const LINE_LEVEL: u32 = 8;

/// `tau_c` above which the fit of Figs. 2-7 is taken: below it the centre of the contact is
/// not yet in the Eyring regime (`tau_m = asinh(tau_c/2) < 4`), friction is no longer
/// dominated by the shear of the central film, and the paper itself describes the points as
/// straying from the curve (Sec. III A).
pub const FIT_TAU_C_MIN: f64 = 100.0;

/// What a target is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Emitted from `cases/` data.
    Table,
    /// Computed.
    Computed,
}

/// A target of `repro list`.
#[derive(Debug, Clone, Copy)]
pub struct Target {
    /// Name on the command line.
    pub name: &'static str,
    /// One line for `repro list`.
    pub description: &'static str,
    /// Emitted or computed.
    pub kind: Kind,
    /// Level of `repro <target>` without `--level`: the cheapest level whose sliding `mu-bar`
    /// is within 1 % of the Richardson extrapolation for the case that stands for the target
    /// in `repro accuracy` (figures/accuracy_levels.csv). `make figures` builds every target
    /// at the paper's working level instead.
    pub default_level: Option<u32>,
}

/// Every target, in the paper's order.
pub const TARGETS: &[Target] = &[
    Target { name: "table1", description: "Lubricant properties alpha, eta0 at 40/60/100 C (from cases/lubricants.toml)", kind: Kind::Table, default_level: None },
    Target { name: "table2", description: "Ranges of the operating parameters, with the derived M, L, S-bar ranges per lubricant", kind: Kind::Table, default_level: None },
    Target { name: "table3", description: "The five contact-configuration cases, with M, L, S-bar, tau_c per geometry", kind: Kind::Table, default_level: None },
    Target { name: "table4", description: "Grid convergence of Hc and sliding mu-bar for the Appendix case, levels 5-8, with wall times", kind: Kind::Computed, default_level: None },
    Target { name: "fig1", description: "Total mu-bar vs S-bar^(1/4) M L^3, Barus-incompressible circular contact (125 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig2", description: "Total mu-bar vs tau_c, same sweep, Eq. (13) dashed", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig3", description: "Sliding mu-bar vs tau_c, same sweep, Eq. (13) dashed", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig4", description: "Sliding mu-bar vs tau_c, mineral oil A, Roelands + Dowson-Higginson, Table 2 grid (243 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig5", description: "Sliding mu-bar vs tau_c, traction fluid, Table 2 grid (243 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig6", description: "Sliding mu-bar vs tau_c, 5P4E, Table 2 grid (243 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig7", description: "Sliding mu-bar vs tau_c, mineral oil A, Rx/Ry = 1/2, 1/5 and the line contact at the Table 3 cases", kind: Kind::Computed, default_level: Some(7) },
    Target { name: "fig8", description: "Measured friction transformed to (tau_c, mu-bar) by Sec. IV, on Eq. (13) (datasets of cases/fig8/)", kind: Kind::Table, default_level: None },
];

/// Looks a target up.
pub fn target(name: &str) -> Option<&'static Target> {
    TARGETS.iter().find(|t| t.name == name)
}

/// Where and how targets are built.
pub struct Context<'a> {
    /// Output folder (`figures/`).
    pub out: PathBuf,
    /// Result cache (`None`: recompute everything).
    pub cache: Option<Cache>,
    /// Level override for computed targets.
    pub level: Option<u32>,
    /// Hears of every finished case: target name and progress.
    pub progress: &'a (dyn Fn(&str, RunProgress) + Sync),
    /// Hears of warnings (corrupt cache entries, failed cases).
    pub warn: &'a (dyn Fn(String) + Sync),
    /// Solve every `stride`-th case of sweeps larger than [`SAMPLED_ABOVE`] cases (the
    /// snapshot profile); 1 solves them all.
    pub stride: usize,
}

/// Sweeps with more cases than this are sampled when [`Context::stride`] is above 1.
pub const SAMPLED_ABOVE: usize = 200;

/// What building a target produced: the row of `figures/summary.csv` and the report's entry.
#[derive(Debug, Clone)]
pub struct Built {
    /// Target name.
    pub name: &'static str,
    /// Title.
    pub title: String,
    /// Cases computed or emitted.
    pub cases: usize,
    /// Cases solved (computed targets).
    pub solved: Option<usize>,
    /// Of those, taken from the cache.
    pub cached: Option<usize>,
    /// Grid level.
    pub level: Option<u32>,
    /// Mastercurve fit over `tau_c >= FIT_TAU_C_MIN` (Figs. 2-7).
    pub fit: Option<Fit>,
    /// Mastercurve fit over every point.
    pub fit_all: Option<Fit>,
    /// Wall time, s.
    pub seconds: f64,
    /// Files written, relative to the output folder.
    pub files: Vec<String>,
    /// The paper's claim, for the report.
    pub paper_claim: String,
    /// Ours, for the report.
    pub ours: String,
}

/// `figures/summary.csv`, one row per target.
pub fn summary_csv(built: &[Built]) -> String {
    let header = [
        "target",
        "cases",
        "solved",
        "cached",
        "level",
        "fitted_c",
        "rms_rel_dev",
        "max_rel_dev",
        "fitted_c_all",
        "seconds",
    ];
    let rows: Vec<Vec<String>> = built
        .iter()
        .map(|b| {
            vec![
                b.name.to_string(),
                b.cases.to_string(),
                b.solved.map(|v| v.to_string()).unwrap_or_default(),
                b.cached.map(|v| v.to_string()).unwrap_or_default(),
                b.level.map(|v| v.to_string()).unwrap_or_default(),
                opt(b.fit.map(|f| f.c)),
                opt(b.fit.map(|f| f.rms_rel_dev)),
                opt(b.fit.map(|f| f.max_rel_dev)),
                opt(b.fit_all.map(|f| f.c)),
                format!("{:.2}", b.seconds),
            ]
        })
        .collect();
    table(&header, &rows)
}

pub(crate) fn write(ctx: &Context, name: &str, text: &str) -> Result<String, String> {
    let path = ctx.out.join(name);
    write_atomic(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(name.to_string())
}

/// Builds one target.
pub fn build(name: &str, ctx: &Context) -> Result<Built, String> {
    let start = Instant::now();
    let Some(t) = target(name) else {
        let known: Vec<&str> = TARGETS.iter().map(|t| t.name).collect();
        return Err(format!(
            "unknown target '{name}' (known: {})",
            known.join(", ")
        ));
    };
    let mut built = match t.name {
        "table1" => super::tables::table1(ctx)?,
        "table2" => super::tables::table2(ctx)?,
        "table3" => super::tables::table3(ctx)?,
        "table4" => super::tables::table4(ctx)?,
        "fig8" => super::fig8::build(ctx)?,
        figure_name => figure(figure_name, ctx)?,
    };
    built.seconds = start.elapsed().as_secs_f64();
    Ok(built)
}

/// Which sweep a figure draws, and what it plots.
struct FigureSpec {
    sweep: &'static str,
    /// The quantity on the y axis: sliding or total reduced friction.
    total: bool,
    /// x is `S-bar^(1/4) M L^3` (Fig. 1) instead of `tau_c`.
    severity: bool,
}

fn figure_spec(name: &str) -> FigureSpec {
    match name {
        "fig1" => FigureSpec {
            sweep: "fig1-3",
            total: true,
            severity: true,
        },
        "fig2" => FigureSpec {
            sweep: "fig1-3",
            total: true,
            severity: false,
        },
        "fig3" => FigureSpec {
            sweep: "fig1-3",
            total: false,
            severity: false,
        },
        other => FigureSpec {
            sweep: other_sweep(other),
            total: false,
            severity: false,
        },
    }
}

fn other_sweep(name: &str) -> &'static str {
    match name {
        "fig4" => "fig4",
        "fig5" => "fig5",
        "fig6" => "fig6",
        _ => "fig7",
    }
}

/// Runs a sweep at the context's level (the sweep's own, else the working level).
pub fn run_sweep(label: &str, sweep: &Sweep, ctx: &Context) -> Result<(Vec<CaseRun>, u32), String> {
    let level = ctx
        .level
        .or(sweep.level)
        .or(target(label).and_then(|t| t.default_level))
        .unwrap_or(WORKING_LEVEL);
    let params = Params::at_level(level);
    let progress = |p: RunProgress| (ctx.progress)(label, p);
    let cases: Vec<_> = if ctx.stride > 1 && sweep.cases.len() > SAMPLED_ABOVE {
        sweep.cases.iter().step_by(ctx.stride).cloned().collect()
    } else {
        sweep.cases.clone()
    };
    let runs = run_cases(&cases, &params, ctx.cache.as_ref(), &progress, ctx.warn)?;
    Ok((runs, level))
}

/// The x and y of a case on a figure.
fn xy(run: &CaseRun, spec: &FigureSpec) -> Option<(f64, f64)> {
    let rec = run.record()?;
    let g = &run.problem.groups;
    let x = if spec.severity {
        g.s_bar.powf(0.25) * g.m * g.l.powi(3)
    } else {
        run.problem.tau_c()
    };
    let y = if spec.total {
        rec.mu_bar_total()
    } else {
        rec.mu_bar_sliding
    };
    Some((x, y))
}

/// The per-case CSV of a sweep's runs, with the figure's x and y.
pub fn runs_csv(
    runs: &[CaseRun],
    spec_x: &str,
    spec_y: &str,
    xy: impl Fn(&CaseRun) -> Option<(f64, f64)>,
) -> String {
    let header = [
        "case",
        "lubricant",
        "temperature_c",
        "ph_gpa",
        "um_m_s",
        "slip",
        "tau0_mpa",
        "d",
        "m",
        "l",
        "s_bar",
        "alpha_bar",
        "lambda",
        "kappa",
        "n",
        "tau_c",
        "mu_bar_eq13",
        "hc",
        "hc_moes",
        "hmin",
        "mu_bar_sliding",
        "mu_bar_rolling",
        "mu_bar_total",
        spec_x,
        spec_y,
        "rel_dev_eq13",
        "cycles",
        "residual",
        "seconds",
        "cached",
        "status",
    ];
    let rows: Vec<Vec<String>> = runs
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let g = &r.problem.groups;
            let tau_c = r.problem.tau_c();
            let (lub, temp, ph, um, tau0) = match &r.case.spec {
                Spec::Physical(p) => {
                    let (l, t) = match &p.lubricant {
                        LubricantSpec::Named {
                            lubricant,
                            temperature_c,
                        } => (lubricant.clone(), num(*temperature_c)),
                        LubricantSpec::Given { .. } => ("given".to_string(), String::new()),
                    };
                    (
                        l,
                        t,
                        num(p.ph_pa / 1e9),
                        num(p.um_m_s),
                        num(p.tau0_pa / 1e6),
                    )
                }
                Spec::Dimensionless(_) => (
                    String::new(),
                    String::new(),
                    String::new(),
                    String::new(),
                    String::new(),
                ),
            };
            let point = xy(r);
            let eq13 = mastercurve(tau_c, PAPER_C);
            let (rec_cells, status) = match &r.outcome {
                Outcome::Solved(rec) => (
                    vec![
                        num(rec.h_central),
                        num(rec.hc_moes),
                        num(rec.h_min),
                        num(rec.mu_bar_sliding),
                        opt(rec.mu_bar_rolling),
                        num(rec.mu_bar_total()),
                        opt(point.map(|p| p.0)),
                        opt(point.map(|p| p.1)),
                        opt(point.map(|p| p.1 / eq13 - 1.0)),
                        rec.cycles.to_string(),
                        num(rec.residual),
                        format!("{:.3}", rec.seconds),
                    ],
                    "solved".to_string(),
                ),
                Outcome::Failed {
                    residual_history, ..
                } => {
                    let mut cells = vec![String::new(); 12];
                    cells[9] = residual_history.len().to_string();
                    cells[10] = opt(residual_history.last().copied());
                    let kind = r.failure_kind().unwrap_or("failed");
                    (cells, format!("failed: {kind}"))
                }
            };
            let mut row = vec![
                (i + 1).to_string(),
                lub,
                temp,
                ph,
                um,
                num(g.slip),
                tau0,
                num(g.d),
                num(g.m),
                num(g.l),
                num(g.s_bar),
                num(g.alpha_bar),
                num(g.lambda),
                num(g.kappa),
                num(g.n),
                num(tau_c),
                num(eq13),
            ];
            row.extend(rec_cells);
            row.push(r.cached.to_string());
            row.push(status);
            row
        })
        .collect();
    table(&header, &rows)
}

fn figure(name: &'static str, ctx: &Context) -> Result<Built, String> {
    let spec = figure_spec(name);
    let sweep = shipped_sweep(spec.sweep).map_err(|e| e.to_string())?;
    let claim = match name {
        "fig1" => "friction collapses on one curve for S-bar^(1/4) M L^3 >= 1e4, scattered below",
        "fig2" => "total mu-bar follows Eq. (13), c = 5, except a cluster at low tau_c where rolling friction dominates",
        _ => "sliding mu-bar follows Eq. (13): mu-bar = asinh(tau_c / 5)",
    };
    // Fig. 7 adds the Table 3 line contacts, solved by the 1-D solver at its working level.
    let (line, extra) = if name == "fig7" {
        let runs = super::line_cases::solve_table3(LINE_LEVEL)?;
        let series = Series {
            label: "line contact".into(),
            points: super::line_cases::line_points(&runs),
            marker: Marker::Cross,
        };
        (Some(runs), vec![series])
    } else {
        (None, Vec::new())
    };
    let (mut built, runs) = sweep_figure(name, &sweep, &spec, ctx, &extra)?;
    if let Some(line) = &line {
        let csv = super::line_cases::line_csv(line, LINE_LEVEL);
        built.files.push(write(ctx, "fig7-line.csv", &csv)?);
        built.cases += line.len();
        let solved = line.iter().filter(|r| r.outcome.is_ok()).count();
        built.solved = built.solved.map(|s| s + solved);
    }
    built.name = name;
    built.paper_claim = claim.to_string();
    if spec.severity {
        built.ours.push_str(&severity_summary(&runs));
    }
    Ok(built)
}

/// Fig. 1's collapse: the scatter of total `mu-bar` ordered by the paper's `S-bar^(1/4) M L^3`
/// against the exponents of `S-bar^a M L^c` that collapse our points best.
fn severity_summary(runs: &[CaseRun]) -> String {
    let cases: Vec<(f64, f64, f64, f64)> = runs
        .iter()
        .filter_map(|r| {
            let g = &r.problem.groups;
            r.record()
                .map(|rec| (g.s_bar, g.m, g.l, rec.mu_bar_total()))
        })
        .collect();
    let mut paper: Vec<(f64, f64)> = cases
        .iter()
        .map(|&(s, m, l, mu)| (0.25 * s.ln() + m.ln() + 3.0 * l.ln(), mu))
        .collect();
    let paper_scatter = super::fit::scatter(&mut paper);
    match super::fit::severity_exponents(&cases) {
        Some((a, c, best)) => format!(
            "; scatter about one curve (0 = a curve, 2 = random) {paper_scatter:.3} with the paper's S-bar^(1/4) M L^3, {best:.3} with the best exponents S-bar^{a:.2} M L^{c:.1}"
        ),
        None => String::new(),
    }
}

/// A user's own sweep (`repro run`), drawn and fitted as Figs. 3-7: sliding `mu-bar` against
/// `tau_c`, files named after `stem`.
pub fn study(stem: &str, sweep: &Sweep, ctx: &Context) -> Result<Built, String> {
    let spec = FigureSpec {
        sweep: "",
        total: false,
        severity: false,
    };
    let (mut built, _) = sweep_figure(stem, sweep, &spec, ctx, &[])?;
    built.paper_claim = "sliding mu-bar follows Eq. (13): mu-bar = asinh(tau_c / 5)".into();
    Ok(built)
}

/// Runs `sweep`, writes `<stem>.csv` and `<stem>.svg`, fits the mastercurve.
fn sweep_figure(
    stem: &str,
    sweep: &Sweep,
    spec: &FigureSpec,
    ctx: &Context,
    extra: &[Series],
) -> Result<(Built, Vec<CaseRun>), String> {
    let (runs, level) = run_sweep(stem, sweep, ctx)?;
    for (i, r) in runs.iter().enumerate() {
        if let Outcome::Failed { error, .. } = &r.outcome {
            (ctx.warn)(format!(
                "{stem}: case {} (M {:.4}, L {:.4}, S-bar {:.3e}) failed: {error}",
                i + 1,
                r.problem.groups.m,
                r.problem.groups.l,
                r.problem.groups.s_bar
            ));
        }
    }
    let (xname, yname) = match (spec.severity, spec.total) {
        (true, _) => ("s_bar_quarter_m_l3", "mu_bar_total"),
        (false, true) => ("tau_c_x", "mu_bar_total_y"),
        (false, false) => ("tau_c_x", "mu_bar_sliding_y"),
    };
    let csv = write(
        ctx,
        &format!("{stem}.csv"),
        &runs_csv(&runs, xname, yname, |r| xy(r, spec)),
    )?;
    let points: Vec<(f64, f64)> = runs
        .iter()
        .filter_map(|r| xy(r, spec).map(|p| (r.problem.tau_c(), p.1)))
        .chain(extra.iter().flat_map(|e| e.points.iter().copied()))
        .collect();
    let (fit_range, fit_all) = if spec.severity {
        (None, None)
    } else {
        (
            fit(&points
                .iter()
                .copied()
                .filter(|p| p.0 >= FIT_TAU_C_MIN)
                .collect::<Vec<_>>()),
            fit(&points),
        )
    };
    let mut files = vec![csv];
    if let Some(svg) = super::figures::svg(
        stem,
        &sweep.title,
        &runs,
        &|r| xy(r, spec),
        spec.severity,
        spec.total,
        extra,
    )? {
        files.push(write(ctx, &format!("{stem}.svg"), &svg)?);
    }
    let solved = runs.iter().filter(|r| r.record().is_some()).count();
    let cached = runs.iter().filter(|r| r.cached).count();
    let ours = match fit_range {
        Some(f) => format!(
            "c = {:.2} over {} points with tau_c >= {} (RMS deviation from Eq. 13 {:.1} %, largest {:.1} %); c = {:.2} over all {} solved",
            f.c,
            f.points,
            FIT_TAU_C_MIN,
            100.0 * f.rms_rel_dev,
            100.0 * f.max_rel_dev,
            fit_all.map(|a| a.c).unwrap_or(f64::NAN),
            solved
        ),
        None => format!("{solved} of {} cases solved", runs.len()),
    };
    let built = Built {
        name: "study",
        title: sweep.title.clone(),
        cases: runs.len(),
        solved: Some(solved),
        cached: Some(cached),
        level: Some(level),
        fit: fit_range,
        fit_all,
        seconds: 0.0,
        files,
        paper_claim: String::new(),
        ours,
    };
    Ok((built, runs))
}

/// Builds every target in order and writes `summary.csv` and the report `index.html`; stops at the first target that
/// cannot be built (a solve that fails is a result, not a stop).
pub fn build_all(names: &[&str], ctx: &Context) -> Result<Vec<Built>, String> {
    let mut built = Vec::new();
    for n in names {
        built.push(build(n, ctx)?);
    }
    write(ctx, "summary.csv", &summary_csv(&built))?;
    let read = |f: &str| std::fs::read_to_string(ctx.out.join(f)).ok();
    write(ctx, "index.html", &super::html::index_html(&built, &read))?;
    Ok(built)
}

/// The output folder must be writable before hours of solves are spent.
pub fn check_writable(out: &Path) -> Result<(), String> {
    std::fs::create_dir_all(out)
        .map_err(|e| format!("cannot create output folder {}: {e}", out.display()))?;
    let probe = out.join(".repro-write-test");
    std::fs::write(&probe, b"ok")
        .map_err(|e| format!("output folder {} is not writable: {e}", out.display()))?;
    let _ = std::fs::remove_file(probe);
    Ok(())
}
