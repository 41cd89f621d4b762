//! Every flag of `repro`, as clap parses it: the only folder that knows clap (the flags of a
//! contact, `repro solve` and `repro predict`, in `contact.rs`). `config.rs` turns
//! these into cases, solver parameters and the pipeline's context once; nothing else reads a
//! raw flag.

mod contact;

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
pub use contact::{
    BaseOilArg, DatasheetArgs, DensityArg, DomainArg, EdgeArg, PatchArg, PredictArgs, RheologyArg,
    SolveArgs, ThermalArgs, ViscosityArg,
};
use repro::paper::{find, Target, REGISTRY};
use std::path::PathBuf;

/// Regenerates "A Generalized Traction Curve for EHL Contacts" (Jacod, Venner and Lugt,
/// ASME J. Tribology 2001) from first principles: EHL solves of elliptical contacts with an
/// Eyring lubricant by multigrid, their friction, and the mastercurve mu-bar = asinh(tau_c/5).
#[derive(Debug, Parser)]
#[command(name = "repro", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve one elliptical contact and print film thickness and reduced friction.
    ///
    /// Either in Moes groups (--m, --l, --s-bar, with --eta0 and --ph where Roelands or
    /// Dowson-Higginson need them; Barus, incompressible, Eyring by default) or physically
    /// (--lubricant or --alpha/--eta0 or a datasheet, --ph, --um, --slip, --tau0; Roelands,
    /// Dowson-Higginson, Eyring by default, the physics of Figs. 4-6).
    Solve(Box<SolveArgs>),
    /// Table 4 measured: the Appendix case at levels 5-8, each solved afresh and timed,
    /// beside the paper's values.
    ///
    /// The levels are solved one after the other, so the wall times compare; `repro all`
    /// builds the same table through the cache instead.
    Table4(Table4Args),
    /// Friction of your contact from the mastercurve, Eq. (14), in microseconds; with --solve
    /// also the full EHL solve beside it.
    ///
    /// The lubricant is one of Table 1 (--lubricant, --temperature), given (--alpha, --eta0),
    /// or a datasheet (--iso-vg or --nu40, --vi or --nu100, --rho15, --base-oil) at any
    /// --temperature: eta0 = nu rho by ASTM D341 and D1250, alpha from AGMA 925 unless
    /// --alpha is given. A correlated alpha is said so, with its band, and every output it
    /// moves is printed with its range over that band.
    Predict(Box<PredictArgs>),
    /// Every target, then figures/summary.csv (what `make figures` runs).
    All(TargetArgs),
    /// Run your own sweep file (the format of cases/*.toml) and put it on the mastercurve.
    Run(RunArgs),
    /// Recompute targets at the CI profile and compare them with the committed snapshots.
    ///
    /// Every target (or those named) is built at level 5 with every 4th case of the large
    /// sweeps, into a temporary folder, and each CSV cell is compared with snapshots/: numbers
    /// within a relative 2e-3 (four times the solver's stopping bound), text exactly. Exits 1
    /// naming the target, case, column, baseline and new value of every difference. With
    /// --accept the differences are shown and the new results become the baselines (what
    /// `make snapshots` runs).
    Check(CheckArgs),
    /// What accuracy costs: representative cases at levels 4-8, error against a Richardson
    /// extrapolation of the grids' own values and wall time (figures/accuracy.csv,
    /// accuracy.svg for the friction, accuracy_film.svg for the central film as reported and
    /// the grid's own, accuracy_hmin.svg for the minimum film of the designs, with the rule's
    /// top refined across the rolling direction, accuracy_levels.csv).
    Accuracy(AccuracyArgs),
    /// List the targets.
    List,
    /// The result cache: what it holds per solver revision, pruning what the present
    /// revisions cannot reach, merging caches of shards or of other machines.
    Cache(CacheArgs),
    /// Write sbatch scripts that run targets as a Slurm job array (one shard per task), then
    /// merge the shards' caches and assemble the figures in a dependent job.
    ///
    /// Writes <dir>/<name>.array.sbatch (the array: task i solves shard i of --tasks into its
    /// own cache, log per task), <dir>/<name>.assemble.sbatch (after every task succeeded:
    /// `repro cache merge` of the shards' caches into --cache, then each target with
    /// --offline into --out) and <dir>/<name>.submit.sh (submits both), and prints how to
    /// submit them. Nothing is submitted.
    Slurm(SlurmArgs),
}

/// `repro cache ...`.
#[derive(Debug, Args)]
pub struct CacheArgs {
    /// What to do (default: `list` of .repro-cache).
    #[command(subcommand)]
    pub command: Option<CacheCommand>,
}

#[derive(Debug, Subcommand)]
pub enum CacheCommand {
    /// What the cache holds: entries and size per solver revision, and whether the present
    /// revisions reach them (what `repro cache` alone prints).
    ///
    /// A cache key holds the revisions of the numerics that made its result, so an entry of
    /// an older revision is never answered again; entries written before entries recorded
    /// their revisions are listed as unrecorded (older than the present point revision).
    List(CacheDirArgs),
    /// Remove what the present revisions cannot reach: entries of other revisions,
    /// unrecorded ones, corrupt ones and temporary files of writes that never finished
    /// (older than an hour). What they reach stays.
    Prune(PruneArgs),
    /// Copy the verified entries of SRC caches into DST, by content hash.
    ///
    /// An entry DST lacks is copied as it is; one DST has with the same result is counted
    /// (the stamp of DST's is kept: who solved it and how long it took may differ); one DST
    /// has with a different result is refused and named by its key, as is a source entry that
    /// fails verification. Exits 1 when any entry was refused, 2 when a folder cannot be read
    /// or written.
    Merge(MergeArgs),
}

#[derive(Debug, Args)]
pub struct CacheDirArgs {
    /// Result cache folder.
    #[arg(long, default_value = ".repro-cache")]
    pub cache: PathBuf,
}

#[derive(Debug, Args)]
pub struct PruneArgs {
    #[command(flatten)]
    pub dir: CacheDirArgs,
    /// Say what would be removed, removing nothing.
    #[arg(long)]
    pub dry_run: bool,
}

#[derive(Debug, Args)]
pub struct MergeArgs {
    /// Source cache folders (e.g. the caches of the shards of a job array).
    #[arg(required = true, value_name = "SRC")]
    pub sources: Vec<PathBuf>,
    /// The cache to merge into (created if absent).
    #[arg(long, value_name = "DST")]
    pub into: PathBuf,
}

#[derive(Debug, Args)]
pub struct SlurmArgs {
    /// Targets to run (names of `repro list`, or `all`).
    #[arg(required = true, value_name = "TARGET")]
    pub targets: Vec<String>,
    /// Array tasks: the solves are split into this many shards, one per task, each a batch
    /// of cases (aim for minutes per task; the estimate printed helps). Lowered to the number
    /// of solves when above it.
    #[arg(long)]
    pub tasks: usize,
    /// Grid level of the computed targets (default: each target's level, as `repro <target>`).
    #[arg(long)]
    pub level: Option<u32>,
    /// Slurm partition (default: the cluster's default partition).
    #[arg(long)]
    pub partition: Option<String>,
    /// Wall-time limit of each array task, as Slurm takes it (e.g. 30, 2:00:00, 1-00:00:00).
    #[arg(long, default_value = "1:00:00")]
    pub time: String,
    /// CPUs per array task (the solves of a task run in parallel on them).
    #[arg(long, default_value_t = 2)]
    pub cpus: usize,
    /// Folder of the scripts, the shards' caches (caches/) and the logs (logs/); must be on
    /// a file system the compute nodes share.
    #[arg(long, default_value = "slurm")]
    pub dir: PathBuf,
    /// The cache the assembly merges the shards into.
    #[arg(long, default_value = ".repro-cache")]
    pub cache: PathBuf,
    /// Output folder of the assembled figures.
    #[arg(long, default_value = "figures")]
    pub out: PathBuf,
    /// The repro binary the jobs run (default: this one).
    #[arg(long)]
    pub repro: Option<PathBuf>,
    /// Name of the job and of the scripts (default: repro-<first target>).
    #[arg(long)]
    pub name: Option<String>,
}

#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Targets to check (default: all, and the summary).
    pub targets: Vec<String>,
    /// Show the differences, then make the new results the baselines.
    #[arg(long)]
    pub accept: bool,
    /// Folder of the baselines.
    #[arg(long, default_value = "snapshots")]
    pub snapshots: PathBuf,
    /// No progress on stderr.
    #[arg(long, short)]
    pub quiet: bool,
}

#[derive(Debug, Args)]
pub struct TargetArgs {
    /// Grid level of the computed targets (default: each target's level from the accuracy
    /// study, shown by `repro list`; `make figures` passes the paper's working level 7).
    #[arg(long)]
    pub level: Option<u32>,
    /// Output folder.
    #[arg(long, default_value = "figures")]
    pub out: PathBuf,
    /// Result cache folder.
    #[arg(long, default_value = ".repro-cache")]
    pub cache: PathBuf,
    /// Recompute every case, ignoring and not filling the cache.
    #[arg(long = "no-cache")]
    pub no_cache: bool,
    /// Solve only shard I of N (1-based) of the cases, split by cache key, into the cache;
    /// write no figures. Without it, a Slurm array task (SLURM_ARRAY_TASK_ID and
    /// SLURM_ARRAY_TASK_COUNT set) takes its shard from them. Other launchers hand the index
    /// over: GNU parallel `--shard {#}/N`, HyperQueue (array 1-N) `--shard $HQ_TASK_ID/N`.
    #[arg(long, value_name = "I/N", conflicts_with_all = ["offline", "no_cache"])]
    pub shard: Option<String>,
    /// Assemble from the cache alone, never solving: a case without an entry is an error
    /// that lists every missing case (after `repro cache merge` of a sharded run). Ignores
    /// the Slurm array variables.
    #[arg(long, conflicts_with = "no_cache")]
    pub offline: bool,
    /// No progress on stderr.
    #[arg(long, short)]
    pub quiet: bool,
}

#[derive(Debug, Args)]
pub struct RunArgs {
    /// The sweep file (TOML, the format of cases/*.toml; see docs/my-study.toml).
    pub file: PathBuf,
    #[command(flatten)]
    pub target: TargetArgs,
}

#[derive(Debug, Args)]
pub struct Table4Args {
    /// Levels to solve (default: those of cases/table4.toml, 5 to 8).
    #[arg(long, value_delimiter = ',')]
    pub levels: Option<Vec<u32>>,
    /// Output folder.
    #[arg(long, default_value = "figures")]
    pub out: PathBuf,
    /// No per-cycle progress on stderr.
    #[arg(long, short)]
    pub quiet: bool,
}

/// Flags of `repro accuracy`.
#[derive(Debug, Args)]
pub struct AccuracyArgs {
    /// Point-contact levels, `A..B` (inclusive) or a comma list (the line contact runs 2
    /// levels finer).
    #[arg(long, default_value = "4..8", value_parser = parse_levels)]
    pub levels: Levels,
    /// Solves per level; the median wall time is kept.
    #[arg(long, default_value_t = 1)]
    pub repeats: usize,
    /// Leave out the line contact of Fig. 7 (studied 2 levels finer than the point
    /// contacts; its level 10 takes about 1.5 s, its dense Newton solve is O(n^3)).
    #[arg(long = "no-line")]
    pub no_line: bool,
    /// Output folder.
    #[arg(long, default_value = "figures")]
    pub out: PathBuf,
    /// No per-level progress on stderr.
    #[arg(long, short)]
    pub quiet: bool,
}

/// A list of grid levels.
#[derive(Debug, Clone)]
pub struct Levels(pub Vec<u32>);

fn parse_levels(s: &str) -> std::result::Result<Levels, String> {
    let levels: Vec<u32> = if let Some((a, b)) = s.split_once("..") {
        let a: u32 = a.trim().parse().map_err(|e| format!("'{a}': {e}"))?;
        let b: u32 = b.trim().parse().map_err(|e| format!("'{b}': {e}"))?;
        (a..=b).collect()
    } else {
        s.split(',')
            .map(|v| v.trim().parse().map_err(|e| format!("'{v}': {e}")))
            .collect::<std::result::Result<_, _>>()?
    };
    if levels.is_empty() || levels.windows(2).any(|w| w[0] >= w[1]) {
        return Err(format!("'{s}': give increasing levels, e.g. 4..8 or 5,6,7"));
    }
    Ok(Levels(levels))
}

/// What the command line asks for: a target of the registry, or one of the other commands.
pub enum Invocation {
    /// `repro <target>`.
    Target(&'static dyn Target, TargetArgs),
    /// Any other command.
    Command(Command),
}

/// The commands, the registry's targets among them: each target of [`REGISTRY`] is a
/// subcommand with [`TargetArgs`] (unless a command of its name exists, as `table4`), listed
/// after `solve` in the registry's order.
pub fn command() -> clap::Command {
    let mut cmd = Cli::command();
    let targets: Vec<&str> = REGISTRY
        .iter()
        .map(|a| a.name())
        .filter(|n| !Command::has_subcommand(n))
        .collect();
    for a in REGISTRY {
        if targets.contains(&a.name()) {
            let sub = clap::Command::new(a.name()).about(a.describe());
            cmd = cmd.subcommand(TargetArgs::augment_args(sub));
        }
    }
    let order = std::iter::once("solve")
        .chain(REGISTRY.iter().map(|a| a.name()))
        .chain([
            "predict", "all", "run", "check", "accuracy", "list", "cache", "slurm",
        ]);
    for (i, name) in order.enumerate() {
        cmd = cmd.mut_subcommand(name, |s| s.display_order(i));
    }
    cmd
}

/// Parses the command line (exits with status 2 and one line naming the flag on error).
pub fn parse() -> Invocation {
    let matches = command().get_matches();
    let parsed = match matches.subcommand() {
        Some((name, sub)) if !Command::has_subcommand(name) => find(name)
            .ok_or_else(|| clap::Error::new(clap::error::ErrorKind::InvalidSubcommand))
            .and_then(|a| Ok(Invocation::Target(a, TargetArgs::from_arg_matches(sub)?))),
        _ => Cli::from_arg_matches(&matches).map(|c| Invocation::Command(c.command)),
    };
    parsed.unwrap_or_else(|e| e.exit())
}
