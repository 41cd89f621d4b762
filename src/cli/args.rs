//! Every flag of `repro`, as clap parses it: the only file that knows clap. `config.rs` turns
//! these into cases, solver parameters and the pipeline's context once; nothing else reads a
//! raw flag.

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand, ValueEnum};
use repro::paper::{find, Artefact, REGISTRY};
use repro::solver::point::Params;
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
    /// within a relative 1e-4, text exactly. Exits 1 naming the target, case, column, baseline
    /// and new value of every difference. With --accept the differences are shown and the new
    /// results become the baselines (what `make snapshots` runs).
    Check(CheckArgs),
    /// What accuracy costs: representative cases at levels 4-8, error against a Richardson
    /// extrapolation and wall time (figures/accuracy.csv, accuracy.svg, accuracy_levels.csv).
    Accuracy(AccuracyArgs),
    /// List the targets.
    List,
    /// The result cache: merge caches of shards or of other machines.
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
    #[command(subcommand)]
    pub command: CacheCommand,
}

#[derive(Debug, Subcommand)]
pub enum CacheCommand {
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
    /// The sweep file (TOML, the format of cases/*.toml; see the README).
    pub file: PathBuf,
    #[command(flatten)]
    pub target: TargetArgs,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum ViscosityArg {
    Barus,
    Roelands,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum DensityArg {
    Incompressible,
    DowsonHigginson,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum RheologyArg {
    Eyring,
    Newtonian,
    /// Eyring with a limiting shear stress tau_L = tau_L0 + Lambda p (--lambda-lss, --tau-l0;
    /// beyond the paper).
    EyringLss,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum DomainArg {
    /// The case's domain by the rule every command and target uses: the paper's from
    /// M = 300 to 4000, the heavy-load one above, the wide one below, grown further where
    /// the light, viscous contacts' inlet pressure reaches out (with the flooded inlet's far
    /// field on its edge in every case). The others are expert overrides (with the same edge).
    Auto,
    /// -2.5 <= X <= 1.5, -2 <= Y <= 2: the paper's (reproduces Table 4).
    Paper,
    /// -4.5 <= X <= 1.5, -3 <= Y <= 3: a longer inlet for lightly loaded contacts (M < 100).
    Wide,
    /// -1.75 <= X <= 1.25, -1.5 <= Y <= 1.5: a finer mesh where heavily loaded contacts
    /// (M >= 4000) need it.
    Heavy,
}

#[derive(Debug, Args)]
#[command(allow_negative_numbers = true)]
pub struct SolveArgs {
    // Dimensionless form.
    /// Moes load parameter M (dimensionless form).
    #[arg(long, help_heading = "Dimensionless form")]
    pub m: Option<f64>,
    /// Moes lubricant parameter L.
    #[arg(long, help_heading = "Dimensionless form")]
    pub l: Option<f64>,
    /// Dimensionless slip S-bar, Eq. (9); 0 is pure rolling.
    #[arg(long = "s-bar", help_heading = "Dimensionless form")]
    pub s_bar: Option<f64>,
    /// Ellipticity ratio D = Rx/Ry in (0, 1] (default 1; not with --line).
    #[arg(long, help_heading = "Dimensionless form")]
    pub d: Option<f64>,

    // Physical form.
    /// Lubricant of Table 1 (cases/lubricants.toml): traction-fluid, mineral-oil-a, 5p4e.
    #[arg(long, help_heading = "Physical form")]
    pub lubricant: Option<String>,
    /// Temperature, C (with --lubricant: 40, 60 or 100 C, or between; with a datasheet: any
    /// temperature in -20..150 C).
    #[arg(long, help_heading = "Physical form")]
    pub temperature: Option<f64>,
    /// Pressure-viscosity coefficient, 1/Pa (instead of --lubricant; with a datasheet, instead
    /// of the AGMA 925 correlation).
    #[arg(long, help_heading = "Physical form")]
    pub alpha: Option<f64>,
    /// Maximum Hertzian pressure p_H, Pa.
    #[arg(long, help_heading = "Physical form")]
    pub ph: Option<f64>,
    /// Mean velocity u_m = (u1 + u2)/2, m/s.
    #[arg(long, help_heading = "Physical form")]
    pub um: Option<f64>,
    /// Eyring stress tau0, Pa.
    #[arg(long, help_heading = "Physical form")]
    pub tau0: Option<f64>,
    /// Reduced radius in the rolling direction Rx, m.
    #[arg(long, default_value_t = 1.03875e-2, help_heading = "Physical form")]
    pub rx: f64,
    /// Reduced radius across the rolling direction Ry, m (default: Rx, a circular contact).
    #[arg(long, help_heading = "Physical form")]
    pub ry: Option<f64>,
    /// Reduced modulus E', Pa.
    #[arg(
        long = "e-prime",
        default_value_t = 226e9,
        help_heading = "Physical form"
    )]
    pub e_prime: f64,
    #[command(flatten)]
    pub datasheet: DatasheetArgs,

    // Both forms.
    /// Slide-to-roll ratio S in [0, 2]. In the dimensionless form it fixes, with S-bar, the
    /// Eyring stress and so the size of the rolling friction in mu-bar (default 0.01 there).
    #[arg(long)]
    pub slip: Option<f64>,
    /// Ambient viscosity eta0, Pa s (physical form without --lubricant; dimensionless form with
    /// Roelands).
    #[arg(long)]
    pub eta0: Option<f64>,
    /// Viscosity-pressure law.
    #[arg(long, value_enum)]
    pub viscosity: Option<ViscosityArg>,
    /// Density-pressure law.
    #[arg(long, value_enum)]
    pub density: Option<DensityArg>,
    /// Rheology.
    #[arg(long, value_enum)]
    pub rheology: Option<RheologyArg>,
    /// Limiting shear stress's pressure slope Lambda = d tau_L / dp (with --rheology
    /// eyring-lss; e.g. 0.08).
    #[arg(long = "lambda-lss")]
    pub lambda_lss: Option<f64>,
    /// Limiting shear stress at ambient pressure tau_L0, Pa (with --rheology eyring-lss;
    /// must be > 0).
    #[arg(long = "tau-l0")]
    pub tau_l0: Option<f64>,

    /// Solve a line contact (1-D solver, Fig. 7) with the same flags; --ry and --d do not
    /// apply. The load is given by --ph (physical form) or by the line-contact M.
    #[arg(long)]
    pub line: bool,

    // Numerics and output.
    /// Grid level: 2^(level+1) points per direction (default 7, the paper's 256 x 256; with
    /// --line default 8, 512 intervals).
    #[arg(long, help_heading = "Numerics")]
    pub level: Option<u32>,
    /// Computational domain.
    #[arg(long, value_enum, default_value = "auto", help_heading = "Numerics")]
    pub domain: DomainArg,
    /// Most multigrid cycles on the finest level.
    #[arg(long = "max-cycles", default_value_t = Params::default().max_cycles, help_heading = "Numerics")]
    pub max_cycles: usize,
    /// Most Newton steps per level of the Newton-Krylov finish that takes over a
    /// point-contact solve when its cycles stall, diverge or run out (grid-sequenced from
    /// level 5 up to the finest); 0 turns the finish off.
    #[arg(long = "newton-steps", default_value_t = Params::default().newton_steps, help_heading = "Numerics")]
    pub newton_steps: usize,
    /// Skip the rolling (Poiseuille) part of the friction.
    #[arg(long = "no-rolling", help_heading = "Numerics")]
    pub no_rolling: bool,
    /// Solve from the Hertzian pressure alone, not from the case's base (the same contact
    /// at S 0.5 % and tau0 6 MPa, or S-bar 0.1 in Moes groups, solved first, as every sweep
    /// does): the path of Table 4 and the benchmarks. Without it the result is the bits of
    /// the case's figure row.
    #[arg(long, help_heading = "Numerics")]
    pub cold: bool,
    /// Print one JSON object instead of the summary.
    #[arg(long, help_heading = "Output")]
    pub json: bool,
    /// Write the pressure and film fields to this CSV file (columns X, Y, P, H).
    #[arg(long, help_heading = "Output")]
    pub fields: Option<PathBuf>,
    #[command(flatten)]
    pub thermal: ThermalArgs,
    /// No per-cycle progress on stderr.
    #[arg(long, short, help_heading = "Output")]
    pub quiet: bool,
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

/// Flags of `repro predict`.
#[derive(Debug, Args)]
#[command(allow_negative_numbers = true)]
pub struct PredictArgs {
    /// Lubricant of Table 1 (cases/lubricants.toml): traction-fluid, mineral-oil-a, 5p4e.
    #[arg(long, help_heading = "Lubricant")]
    pub lubricant: Option<String>,
    /// Temperature, C (with --lubricant: 40, 60 or 100 C, or between; with a datasheet: any
    /// temperature in -20..150 C).
    #[arg(long, help_heading = "Lubricant")]
    pub temperature: Option<f64>,
    /// Pressure-viscosity coefficient, 1/Pa (instead of --lubricant; with a datasheet, instead
    /// of the AGMA 925 correlation).
    #[arg(long, help_heading = "Lubricant")]
    pub alpha: Option<f64>,
    /// Ambient viscosity eta0, Pa s (with --alpha).
    #[arg(long, help_heading = "Lubricant")]
    pub eta0: Option<f64>,
    /// Viscosity-pressure law of eta(p_H) in tau_c (default roelands, as in Figs. 4-7).
    #[arg(long, value_enum, help_heading = "Lubricant")]
    pub viscosity: Option<ViscosityArg>,
    #[command(flatten)]
    pub datasheet: DatasheetArgs,

    /// Maximum Hertzian pressure p_H, Pa (or --load).
    #[arg(long, help_heading = "Contact")]
    pub ph: Option<f64>,
    /// Normal load f, N (or --ph).
    #[arg(long, help_heading = "Contact")]
    pub load: Option<f64>,
    /// Reduced radius in the rolling direction Rx, m.
    #[arg(long, default_value_t = 1.03875e-2, help_heading = "Contact")]
    pub rx: f64,
    /// Reduced radius across the rolling direction Ry, m (default: Rx, a circular contact).
    #[arg(long, help_heading = "Contact")]
    pub ry: Option<f64>,
    /// Reduced modulus E', Pa.
    #[arg(long = "e-prime", default_value_t = 226e9, help_heading = "Contact")]
    pub e_prime: f64,
    /// Mean velocity u_m = (u1 + u2)/2, m/s.
    #[arg(long, help_heading = "Contact")]
    pub um: f64,
    /// Slide-to-roll ratio S = 2 (u2 - u1)/(u2 + u1), in [0, 2].
    #[arg(long, help_heading = "Contact")]
    pub slip: f64,
    /// Eyring stress tau0, Pa.
    #[arg(long, help_heading = "Contact")]
    pub tau0: f64,

    /// Also run the full EHL solve (Roelands, Dowson-Higginson, Eyring) and print the
    /// difference.
    #[arg(long, help_heading = "Solve")]
    pub solve: bool,
    /// Grid level of --solve: 2^(level+1) points per direction (7 is the paper's 256 x 256).
    #[arg(long, default_value_t = 7, help_heading = "Solve")]
    pub level: u32,
    /// Density-pressure law of --solve (default dowson-higginson).
    #[arg(long, value_enum, help_heading = "Solve")]
    pub density: Option<DensityArg>,
    #[command(flatten)]
    pub thermal: ThermalArgs,

    /// Print one JSON object instead of the summary.
    ///
    /// Keys: `lubricant` {source (table1, given, datasheet), eta0_pa_s, alpha_per_pa,
    /// alpha_source, alpha_correlated, alpha_band_per_pa ([low, high] 1/Pa when correlated,
    /// else null); for a datasheet also datasheet, temperature_c, nu_mm2_s and rho_kg_m3 at
    /// it, nu40_mm2_s, nu100_mm2_s, viscosity_index, expansion15_per_k}; the contact's ph_pa,
    /// m, l, s_bar, slip, tau0_pa, eta_bar_ph, hc_eq10, hc_m, tau_c; Eq. (14)'s mu_bar, mu;
    /// the refined formula's mu_bar_refined, mu_refined and their bands
    /// mu_bar_refined_band, mu_refined_band (its own 95 % band, around its range over the
    /// alpha band when alpha is correlated); tau_c_band, hc_m_band, mu_bar_band, mu_band
    /// ([low, high] over the alpha band when alpha is correlated, else null); thermal,
    /// mu_bar_thermal, warnings, solve and difference (--solve), compute_seconds.
    #[arg(long, help_heading = "Output")]
    pub json: bool,
    /// No per-cycle progress of --solve on stderr.
    #[arg(long, short, help_heading = "Output")]
    pub quiet: bool,
}

/// A lubricant's datasheet (`repro solve`, `repro predict`): eta0 = nu rho at --temperature
/// by ASTM D341 and D1250, alpha from AGMA 925 for the base oil unless --alpha is given.
#[derive(Debug, Args)]
pub struct DatasheetArgs {
    /// Kinematic viscosity at 40 C, mm^2/s (or --iso-vg).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub nu40: Option<f64>,
    /// ISO 3448 viscosity grade (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, ..., 3200): nu40 is
    /// its midpoint (or --nu40).
    #[arg(long = "iso-vg", help_heading = "Lubricant datasheet")]
    pub iso_vg: Option<u32>,
    /// Kinematic viscosity at 100 C, mm^2/s (or --vi).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub nu100: Option<f64>,
    /// Viscosity index, ASTM D2270: nu100 follows from it and nu40 (or --nu100).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub vi: Option<f64>,
    /// Density at 15 C, kg/m^3.
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub rho15: Option<f64>,
    /// Thermal expansion coefficient at 15 C, 1/K (default: ASTM D1250 Table 54D's for
    /// rho15).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub expansion15: Option<f64>,
    /// Base-oil type, for the pressure-viscosity correlation.
    #[arg(long = "base-oil", value_enum, help_heading = "Lubricant datasheet")]
    pub base_oil: Option<BaseOilArg>,
}

impl DatasheetArgs {
    /// Whether any datasheet flag was given.
    pub fn any(&self) -> bool {
        self.nu40.is_some()
            || self.iso_vg.is_some()
            || self.nu100.is_some()
            || self.vi.is_some()
            || self.rho15.is_some()
            || self.expansion15.is_some()
            || self.base_oil.is_some()
    }
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum BaseOilArg {
    /// Mineral oil.
    Mineral,
    /// Polyalphaolefin without viscosity-index improver.
    Pao,
    /// Polyalkylene glycol.
    Pag,
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
    Target(&'static dyn Artefact, TargetArgs),
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

/// The thermal post-process's inputs (`repro solve`, `repro predict`).
#[derive(Debug, Args)]
pub struct ThermalArgs {
    /// Thermal conductivity of both solids, W/(m K): 46 for bearing steel, 21 for
    /// through-hardened steel (density 7850 kg/m^3, specific heat 470 J/(kg K)).
    #[arg(
        long = "k-solid",
        default_value_t = 46.0,
        help_heading = "Thermal post-process"
    )]
    pub k_solid: f64,
    /// Thermal conductivity of the lubricant film, W/(m K).
    #[arg(
        long = "k-lubricant",
        default_value_t = 0.13,
        help_heading = "Thermal post-process"
    )]
    pub k_lubricant: f64,
}
