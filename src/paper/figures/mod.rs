//! The sweep figures (Figs. 1-7) and a user's own sweep (`repro run`): run the sweep's cases
//! (cached), write the per-case CSV and the picture, fit the mastercurve.

pub mod line;
pub mod picture;

use crate::paper::mastercurve::fit::{fit, mastercurve, FIT_TAU_C_MIN, PAPER_C};
use crate::paper::mastercurve::oracle::point_flat;
use crate::physics::case::{Case, LubricantSpec, Spec};
use crate::pipeline::context::{write, Built, Context, LINE_LEVEL, SAMPLED_ABOVE, WORKING_LEVEL};
use crate::pipeline::csv::{num, opt, table};
use crate::pipeline::provenance::{Provenance, SUFFIX};
use crate::pipeline::run::{
    point_jobs, run_cases, CaseRun, Job, Outcome, RunProgress, LINE_SOLVER_REVISION,
};
use crate::pipeline::sweep::{shipped_sweep, Sweep};
use crate::plot::{Marker, Series};
use crate::solver::point::{Params, SOLVER_REVISION};
use line::LineRun;

/// Which sweep a figure draws, and what it plots.
struct FigureSpec {
    /// What the picture's title starts with ("Fig. 4", or a study's file stem).
    heading: String,
    /// The shipped sweep (`cases/<sweep>.toml`).
    sweep: &'static str,
    /// The quantity on the y axis: sliding or total reduced friction.
    total: bool,
    /// x is `S-bar^(1/4) M L^3` (Fig. 1) instead of `tau_c`.
    severity: bool,
}

fn figure_spec(name: &str) -> FigureSpec {
    let (sweep, total, severity) = match name {
        "fig1" => ("fig1-3", true, true),
        "fig2" => ("fig1-3", true, false),
        "fig3" => ("fig1-3", false, false),
        "fig4" => ("fig4", false, false),
        "fig5" => ("fig5", false, false),
        "fig6" => ("fig6", false, false),
        _ => ("fig7", false, false),
    };
    FigureSpec {
        heading: name.replace("fig", "Fig. "),
        sweep,
        total,
        severity,
    }
}

/// The cases of a sweep that a context runs (a sample of the large sweeps at the snapshot
/// profile) and their level: the context's, else the sweep's own, else the target's
/// `default_level`, else the working level.
fn selection(sweep: &Sweep, default_level: Option<u32>, ctx: &Context) -> (Vec<Case>, u32) {
    let level = ctx
        .level
        .or(sweep.level)
        .or(default_level)
        .unwrap_or(WORKING_LEVEL);
    let cases: Vec<_> = if ctx.stride > 1 && sweep.cases.len() > SAMPLED_ABOVE {
        sweep.cases.iter().step_by(ctx.stride).cloned().collect()
    } else {
        sweep.cases.clone()
    };
    (cases, level)
}

/// Runs a sweep's cases of the context (see [`selection`]) through its store.
pub fn run_sweep(
    label: &str,
    sweep: &Sweep,
    default_level: Option<u32>,
    ctx: &Context,
) -> Result<(Vec<CaseRun>, u32), String> {
    let (cases, level) = selection(sweep, default_level, ctx);
    let progress = |p: RunProgress| (ctx.progress)(label, p);
    let runs = run_cases(label, &cases, level, ctx.store(), &progress, ctx.warn)?;
    Ok((runs, level))
}

/// Every solve figure `name` needs in the context (what a shard divides and `--offline`
/// looks up): its sweep's cases, and for Fig. 7 the line contacts.
pub fn jobs(name: &str, default_level: Option<u32>, ctx: &Context) -> Result<Vec<Job>, String> {
    let spec = figure_spec(name);
    let sweep = shipped_sweep(spec.sweep).map_err(|e| e.to_string())?;
    let mut jobs = study_jobs(&sweep, default_level, ctx)?;
    if name == "fig7" {
        jobs.extend(
            line::table3_jobs(LINE_LEVEL)?
                .into_iter()
                .map(|(j, _, _)| j),
        );
    }
    Ok(jobs)
}

/// Every solve of a sweep in the context (a study of `repro run`, or a figure's sweep).
pub fn study_jobs(
    sweep: &Sweep,
    default_level: Option<u32>,
    ctx: &Context,
) -> Result<Vec<Job>, String> {
    let (cases, level) = selection(sweep, default_level, ctx);
    Ok(point_jobs(&cases, level)?
        .into_iter()
        .map(|(j, _)| j)
        .collect())
}

/// The sidecar of a sweep figure: its point cases (and Fig. 7's line contacts).
fn provenance(stem: &str, built: &Built, runs: &[CaseRun], line: Option<&[LineRun]>) -> Provenance {
    let files: Vec<String> = built
        .files
        .iter()
        .filter(|f| !f.ends_with(SUFFIX))
        .cloned()
        .collect();
    let mut p = Provenance::new(stem, &files);
    p.solver_revision = Some(SOLVER_REVISION.to_string());
    p.level = built.level;
    if let Some(level) = built.level {
        // The rule's parameters differ from case to case (the domain): each distinct set once,
        // in the order of the rows that first use it.
        for run in runs {
            let params = format!("{:?}", Params::for_problem(&run.problem, level));
            if !p.params.contains(&params) {
                p.params.push(params);
            }
        }
    }
    p.add_rows(
        &format!("{stem}.csv"),
        runs.iter().map(|r| (r.key.as_str(), r.stamp.as_ref())),
    );
    if let Some(line) = line {
        p.line_solver_revision = Some(LINE_SOLVER_REVISION.to_string());
        p.params.push(format!(
            "{:?}",
            crate::solver::line::Params::at_level(LINE_LEVEL)
        ));
        p.add_rows(
            "fig7-line.csv",
            line.iter().map(|r| (r.key.as_str(), r.stamp.as_ref())),
        );
    }
    p
}

/// Writes the sidecar of a sweep figure and lists it among the built files.
fn write_provenance(
    stem: &str,
    built: &mut Built,
    runs: &[CaseRun],
    line: Option<&[LineRun]>,
    ctx: &Context,
) -> Result<(), String> {
    let text = provenance(stem, built, runs, line).to_json();
    built
        .files
        .push(write(ctx, &format!("{stem}{SUFFIX}"), &text)?);
    Ok(())
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
        "mu_bar_flat",
        spec_x,
        spec_y,
        "rel_dev_eq13",
        "rel_dev_flat",
        "level",
        "cycles",
        "newton_steps",
        "residual",
        "mu_bar_thermal",
        "rel_dev_thermal",
        "mu_bar_thermal_midplane",
        "dt_film_k",
        "dt_flash_k",
        "status",
    ];
    let rows: Vec<Vec<String>> = runs
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let g = &r.problem.groups;
            let tau_c = r.problem.tau_c();
            let [lub, temp, ph, um, tau0] = operating_cells(&r.case);
            let point = xy(r);
            let eq13 = mastercurve(tau_c, PAPER_C);
            let (rec_cells, status) = match &r.outcome {
                Outcome::Solved(rec) => {
                    let flat = point_flat(&r.problem, rec.h_central);
                    (
                        vec![
                            num(rec.h_central),
                            num(rec.hc_moes),
                            num(rec.h_min),
                            num(rec.mu_bar_sliding),
                            opt(rec.mu_bar_rolling),
                            num(rec.mu_bar_total()),
                            num(flat),
                            opt(point.map(|p| p.0)),
                            opt(point.map(|p| p.1)),
                            opt(point.map(|p| p.1 / eq13 - 1.0)),
                            num(rec.mu_bar_sliding / flat - 1.0),
                            rec.level.to_string(),
                            rec.cycles.to_string(),
                            rec.newton_steps.to_string(),
                            num(rec.residual),
                        ],
                        "solved".to_string(),
                    )
                }
                Outcome::Failed {
                    residual_history, ..
                } => {
                    // Cycles and Newton steps are not told apart in a failure's history.
                    let mut cells = vec![String::new(); 15];
                    cells[12] = residual_history.len().to_string();
                    cells[14] = opt(residual_history.last().copied());
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
            row.extend(thermal_cells(r.record()));
            row.push(status);
            row
        })
        .collect();
    table(&header, &rows)
}

/// The physical operating point of a case as CSV cells: lubricant, temperature (C), `p_H`
/// (GPa), `u_m` (m/s), `tau0` (MPa); blank for a dimensionless case.
pub fn operating_cells(case: &Case) -> [String; 5] {
    match &case.spec {
        Spec::Physical(p) => {
            let (l, t) = match &p.lubricant {
                LubricantSpec::Named {
                    lubricant,
                    temperature_c,
                } => (lubricant.clone(), num(*temperature_c)),
                LubricantSpec::Given { .. } => ("given".to_string(), String::new()),
                LubricantSpec::Datasheet {
                    datasheet,
                    temperature_c,
                    ..
                } => (datasheet.label(), num(*temperature_c)),
            };
            [
                l,
                t,
                num(p.ph_pa / 1e9),
                num(p.um_m_s),
                num(p.tau0_pa / 1e6),
            ]
        }
        Spec::Dimensionless(_) => Default::default(),
    }
}

/// The thermal columns of a case (steel, [`crate::physics::thermal::TARGET_INPUTS`]'s
/// first): thermal sliding `mu-bar` (mean-temperature closure), its relative correction, the
/// mid-plane closure's `mu-bar`, the largest film and surface temperature rises (K); blank
/// where not computed (dimensionless cases, failures).
pub fn thermal_cells(record: Option<&crate::pipeline::run::Record>) -> Vec<String> {
    match record.and_then(|r| r.thermal().map(|t| (r, t))) {
        Some((r, t)) => vec![
            num(t.mu_bar_sliding),
            num(t.correction(r.mu_bar_sliding)),
            num(t.mu_bar_sliding_midplane),
            num(t.dt_film_max_k),
            num(t.dt_flash_max_k),
        ],
        None => vec![String::new(); 5],
    }
}

/// Builds figure `name` (Figs. 1-7) at the context's level, else `default_level`.
pub fn build(
    name: &'static str,
    default_level: Option<u32>,
    ctx: &Context,
) -> Result<Built, String> {
    let spec = figure_spec(name);
    let sweep = shipped_sweep(spec.sweep).map_err(|e| e.to_string())?;
    let claim = match name {
        "fig1" => "friction collapses on one curve for S-bar^(1/4) M L^3 >= 1e4, scattered below",
        "fig2" => "total mu-bar follows Eq. (13), c = 5, except a cluster at low tau_c where rolling friction dominates",
        _ => "sliding mu-bar follows Eq. (13): mu-bar = asinh(tau_c / 5)",
    };
    // Fig. 7 adds the Table 3 line contacts, solved by the 1-D solver at its working level.
    let (line, extra) = if name == "fig7" {
        let progress = |p: RunProgress| (ctx.progress)("fig7-line", p);
        let runs = line::solve_table3(name, LINE_LEVEL, ctx.store(), &progress, ctx.warn)?;
        let series = Series {
            label: "line contact".into(),
            points: line::line_points(&runs),
            marker: Marker::Cross,
            ..Series::default()
        };
        (Some(runs), vec![series])
    } else {
        (None, Vec::new())
    };
    let (mut built, runs) = sweep_figure(name, &sweep, &spec, default_level, ctx, &extra)?;
    if let Some(line) = &line {
        let csv = line::line_csv(line, LINE_LEVEL);
        built.files.push(write(ctx, "fig7-line.csv", &csv)?);
        built.cases += line.len();
        let solved = line.iter().filter(|r| r.outcome.record().is_some()).count();
        built.solved = built.solved.map(|s| s + solved);
        let cached = line.iter().filter(|r| r.cached).count();
        built.cached = built.cached.map(|c| c + cached);
    }
    write_provenance(name, &mut built, &runs, line.as_deref(), ctx)?;
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
    let paper_scatter = crate::paper::mastercurve::fit::scatter(&mut paper);
    match crate::paper::mastercurve::fit::severity_exponents(&cases) {
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
        heading: stem.to_string(),
        sweep: "",
        total: false,
        severity: false,
    };
    let (mut built, runs) = sweep_figure(stem, sweep, &spec, None, ctx, &[])?;
    write_provenance(stem, &mut built, &runs, None, ctx)?;
    built.paper_claim = "sliding mu-bar follows Eq. (13): mu-bar = asinh(tau_c / 5)".into();
    Ok(built)
}

/// Runs `sweep`, writes `<stem>.csv` and `<stem>.svg`, fits the mastercurve.
fn sweep_figure(
    stem: &str,
    sweep: &Sweep,
    spec: &FigureSpec,
    default_level: Option<u32>,
    ctx: &Context,
    extra: &[Series],
) -> Result<(Built, Vec<CaseRun>), String> {
    let (runs, level) = run_sweep(stem, sweep, default_level, ctx)?;
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
    if let Some(svg) = picture::svg(
        stem,
        &format!("{} — {}", spec.heading, sweep.title),
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
            "{} points with tau_c >= {FIT_TAU_C_MIN}: {}; c = {:.2} over all {solved} solved",
            f.points,
            f.describe(),
            fit_all.map(|a| a.c).unwrap_or(f64::NAN),
        ),
        None => format!("{solved} of {} cases solved", runs.len()),
    };
    let built = Built {
        name: "study",
        title: format!("{}: {}", spec.heading, sweep.title),
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
        refined: Vec::new(),
    };
    Ok((built, runs))
}
