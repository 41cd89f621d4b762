//! What the commands print and write.

use crate::cli::{RunArgs, SolveArgs, Table4Args, TargetArgs};
use anyhow::{Context as _, Result};
use repro::artefacts::cache::Cache;
use repro::artefacts::run::RunProgress;
use repro::artefacts::targets::{self, Built, Context};
use repro::artefacts::{csv, table4};
use repro::physics::case::Problem;
use repro::physics::lubricant::LubricantTable;
use repro::solver::point::{solve as solve_point, PointSolution, Progress};
use serde_json::json;
use std::io::IsTerminal;

/// Prints one progress line per cycle to stderr.
pub(crate) fn progress_printer(quiet: bool) -> impl FnMut(&Progress) {
    move |p: &Progress| {
        if !quiet {
            let krylov = if p.newton {
                format!(", {} GMRES iterations", p.krylov_iterations)
            } else {
                String::new()
            };
            eprintln!(
                "  level {:>2} {} {:>3}: residual {:.3e} (largest at X {:+.3}, Y {:+.3}), dP {:.1e}, load error {:.1e}, Hc {:.5e}{krylov}",
                p.level, if p.newton { "newton" } else { "cycle " }, p.cycle, p.residual, p.worst_at.0, p.worst_at.1, p.pressure_change, p.load_error, p.h_central
            );
        }
    }
}

/// The rolling part of the friction as printed: four decimals, or "not computed" when the
/// solve was asked to skip it.
pub(crate) fn rolling_text(rolling: Option<f64>) -> String {
    rolling
        .map(|r| format!("{r:.4}"))
        .unwrap_or_else(|| "not computed".into())
}

/// Prefixes a case error with the flag it names.
pub(crate) fn flag_error(e: repro::physics::case::CaseError) -> anyhow::Error {
    use repro::physics::case::CaseError;
    use repro::physics::lubricant::LubricantError;
    match e {
        CaseError::Field { field, message } => anyhow::anyhow!("--{field}: {message}"),
        CaseError::Lubricant(l @ LubricantError::Unknown { .. }) => {
            anyhow::anyhow!("--lubricant: {l}")
        }
        CaseError::Lubricant(l @ LubricantError::Temperature { .. }) => {
            anyhow::anyhow!("--temperature: {l}")
        }
        other => anyhow::anyhow!("{other}"),
    }
}

/// Prints why a solve failed, with its residual history, on stderr (`repro solve`, `solve
/// --line`, `predict --solve`).
pub(crate) fn print_failure(e: &repro::solver::output::SolveError) {
    eprintln!("solve failed: {e}");
    eprintln!("residual history: {:?}", e.residual_history());
}

/// `repro solve`: returns false when the solve failed (after printing why).
pub fn solve(args: &SolveArgs) -> Result<bool> {
    if args.line {
        return crate::solve_line::solve_line(args);
    }
    let case = args.case()?;
    let problem = Problem::from_case(&case, &LubricantTable::table1()).map_err(flag_error)?;
    let params = args.params(problem.groups.m)?;
    let mut printer = progress_printer(args.quiet);
    let solution = match solve_point(&problem, &params, Some(&mut printer)) {
        Ok(s) => s,
        Err(e) => {
            print_failure(&e);
            return Ok(false);
        }
    };
    if let Some(path) = &args.fields {
        csv::write_atomic(path, &fields_csv(&solution))
            .with_context(|| format!("--fields: cannot write {}", path.display()))?;
    }
    let tau_c = problem.tau_c();
    if args.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&summary_json(&problem, &params.level, &solution, tau_c))?
        );
    } else {
        print!("{}", summary_text(&problem, &solution, tau_c));
    }
    Ok(true)
}

pub(crate) fn summary_json(
    problem: &Problem,
    level: &u32,
    s: &PointSolution,
    tau_c: f64,
) -> serde_json::Value {
    let g = &problem.groups;
    json!({
        "level": level,
        "m": g.m, "l": g.l, "s_bar": g.s_bar, "d": g.d, "slip": g.slip,
        "alpha_bar": g.alpha_bar, "lambda": g.lambda, "kappa": g.kappa, "n": g.n,
        "viscosity": problem.physics().viscosity, "density": problem.physics().density, "rheology": problem.physics().rheology,
        "h_central": s.film.h_central, "h_min": s.film.h_min,
        "hc_moes": s.film.hc_moes, "hmin_moes": s.film.hmin_moes,
        "mu_bar_sliding": s.friction.sliding, "mu_bar_rolling": s.friction.rolling, "mu_bar_total": s.friction.total(),
        "tau_c": tau_c, "mu_bar_eq13": (tau_c / 5.0).asinh(),
        "cycles": s.info.cycles, "newton_steps": s.info.newton_steps,
        "residual": s.info.residual(), "load_error": s.info.load_error,
        "residual_history": s.info.residual_history, "seconds": s.info.seconds,
    })
}

fn summary_text(problem: &Problem, s: &PointSolution, tau_c: f64) -> String {
    let g = &problem.groups;
    let ph = problem.physics();
    let rolling = rolling_text(s.friction.rolling);
    format!(
        "case        M = {:.4}, L = {:.4}, S-bar = {:.4e}, D = {:.4}, S = {}\n\
         groups      alpha-bar = {:.4}, lambda = {:.4e}, kappa = {:.4}, N = {:.4e}\n\
         physics     {:?}, {:?}, {:?}\n\
         grid        {} x {}, {} cycles{}, residual {:.2e}, load error {:.1e}, {:.2} s\n\
         film        Hc = {:.5e} (Moes {:.4}), Hmin = {:.5e} (Moes {:.4})  [H = h/c]\n\
         friction    mu-bar sliding = {:.4}, rolling = {}, total = {:.4}\n\
         mastercurve tau_c = {:.4e}, Eq. (13) asinh(tau_c/5) = {:.4}\n",
        g.m,
        g.l,
        g.s_bar,
        g.d,
        g.slip,
        g.alpha_bar,
        g.lambda,
        g.kappa,
        g.n,
        ph.viscosity,
        ph.density,
        ph.rheology,
        s.grid.nx,
        s.grid.ny,
        s.info.cycles,
        match s.info.newton_steps {
            0 => String::new(),
            n => format!(" + {n} Newton steps"),
        },
        s.info.residual(),
        s.info.load_error,
        s.info.seconds,
        s.film.h_central,
        s.film.hc_moes,
        s.film.h_min,
        s.film.hmin_moes,
        s.friction.sliding,
        rolling,
        s.friction.total(),
        tau_c,
        (tau_c / 5.0).asinh(),
    )
}

fn fields_csv(s: &PointSolution) -> String {
    let g = &s.grid;
    let mut out = String::from("X,Y,P,H\n");
    for j in 0..g.py() {
        for i in 0..g.px() {
            let k = g.idx(i, j);
            out.push_str(&format!(
                "{},{},{},{}\n",
                csv::num(g.x(i)),
                csv::num(g.y(j)),
                csv::num(s.p[k]),
                csv::num(s.h[k])
            ));
        }
    }
    out
}

/// `repro table4`: returns false when a level failed.
pub fn table4(args: &Table4Args) -> Result<bool> {
    let spec = table4::Table4Case::shipped().map_err(anyhow::Error::msg)?;
    let levels = match &args.levels {
        Some(l) => l
            .iter()
            .map(|&v| crate::cli::check_level("--levels", v))
            .collect::<Result<Vec<_>>>()?,
        None => spec.levels.clone(),
    };
    let mut printer = progress_printer(args.quiet);
    let rows = table4::compute(&spec, &levels, |p| printer(p)).map_err(anyhow::Error::msg)?;
    let path = args.out.join("table4.csv");
    csv::write_atomic(&path, &table4::to_csv(&rows))
        .with_context(|| format!("--out: cannot write {}", path.display()))?;
    print!("{}", table4::to_text(&rows));
    println!("wrote {}", path.display());
    Ok(rows.iter().all(|r| r.outcome.is_ok()))
}

/// A progress line per target on stderr: rewritten in place on a terminal, every tenth of the
/// cases otherwise.
pub(crate) fn run_progress(quiet: bool) -> impl Fn(&str, RunProgress) + Sync {
    let tty = std::io::stderr().is_terminal();
    move |name: &str, p: RunProgress| {
        if quiet {
            return;
        }
        let step = (p.total / 10).max(1);
        if tty {
            eprint!(
                "\r  {name}: {}/{} cases ({} cached)   ",
                p.done, p.total, p.cached
            );
            if p.done == p.total {
                eprintln!();
            }
        } else if p.done.is_multiple_of(step) || p.done == p.total {
            eprintln!(
                "  {name}: {}/{} cases ({} cached)",
                p.done, p.total, p.cached
            );
        }
    }
}

pub(crate) fn summary_line(b: &Built) -> String {
    let mut line = format!("{}: {} cases", b.name, b.cases);
    if let (Some(s), Some(c)) = (b.solved, b.cached) {
        line.push_str(&format!(", {s} solved, {c} cached"));
    }
    if let Some(l) = b.level {
        line.push_str(&format!(", level {l}"));
    }
    line.push_str(&format!(", {:.1} s", b.seconds));
    if let Some(f) = b.fit {
        line.push_str(&format!(
            ", fitted c = {:.2} (RMS deviation from Eq. 13 {:.1} %)",
            f.c,
            100.0 * f.rms_rel_dev
        ));
    }
    if b.name == "fig1" {
        line.push_str(&format!(" ({})", b.ours));
    }
    line.push_str(&format!(" -> {}", b.files.join(", ")));
    line
}

pub(crate) fn context<'a>(
    args: &TargetArgs,
    progress: &'a (dyn Fn(&str, RunProgress) + Sync),
    warn: &'a (dyn Fn(String) + Sync),
) -> Result<Context<'a>> {
    if let Some(l) = args.level {
        crate::cli::check_level("--level", l)?;
    }
    targets::check_writable(&args.out).map_err(|e| anyhow::anyhow!("--out: {e}"))?;
    Ok(Context {
        out: args.out.clone(),
        cache: (!args.no_cache).then(|| Cache::new(&args.cache)),
        level: args.level,
        progress,
        warn,
        stride: 1,
    })
}

pub(crate) fn warner(quiet: bool) -> impl Fn(String) + Sync {
    move |w: String| {
        if !quiet {
            eprintln!("warning: {w}");
        }
    }
}

/// `repro <target>`.
pub fn target(name: &str, args: &TargetArgs) -> Result<bool> {
    let progress = run_progress(args.quiet);
    let warn = warner(args.quiet);
    let ctx = context(args, &progress, &warn)?;
    let built = targets::build(name, &ctx).map_err(anyhow::Error::msg)?;
    println!("{}", summary_line(&built));
    Ok(true)
}

/// `repro all`.
pub fn all(args: &TargetArgs) -> Result<bool> {
    let progress = run_progress(args.quiet);
    let warn = warner(args.quiet);
    let ctx = context(args, &progress, &warn)?;
    let names: Vec<&str> = targets::TARGETS.iter().map(|t| t.name).collect();
    let built = targets::build_all(&names, &ctx).map_err(anyhow::Error::msg)?;
    for b in &built {
        println!("{}", summary_line(b));
    }
    println!("wrote {}", args.out.join("summary.csv").display());
    Ok(true)
}

/// `repro run my-study.toml`: the same pipeline as a figure target.
pub fn run_study(args: &RunArgs) -> Result<bool> {
    let sweep = repro::artefacts::sweep::Sweep::read(&args.file)?;
    let progress = run_progress(args.target.quiet);
    let warn = warner(args.target.quiet);
    let ctx = context(&args.target, &progress, &warn)?;
    let stem = args
        .file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "study".into());
    let t = std::time::Instant::now();
    let mut built = targets::study(&stem, &sweep, &ctx)
        .map_err(|e| anyhow::anyhow!("{}: {e}", args.file.display()))?;
    built.seconds = t.elapsed().as_secs_f64();
    println!("{}", summary_line(&built).replacen("study", &stem, 1));
    println!("mastercurve (paper: c = 5): {}", built.ours);
    Ok(built.solved == Some(built.cases))
}
