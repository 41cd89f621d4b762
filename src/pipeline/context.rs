//! What every target shares: where and how it is built ([`Context`]), what building it
//! returns ([`Built`]) and how it writes a file ([`write`]). The targets (`targets/`) build on
//! this module, the registry (`targets/mod.rs`) on the targets, the report on the registry.

use crate::paper::mastercurve::fit::Fit;
use crate::paper::mastercurve::refined::FigureCheck;
use crate::pipeline::cache::Cache;
use crate::pipeline::csv::write_atomic;
use crate::pipeline::run::{RunProgress, Store};
use std::path::{Path, PathBuf};

/// The paper's working level (256 x 256), the default of every computed figure.
pub const WORKING_LEVEL: u32 = 7;

/// Level of the line contacts of Fig. 7 (512 intervals): sliding `mu-bar` within 0.2 % of
/// level 11 on the heaviest Table 3 case (docs/LINE_NOTES.md), a few tenths of a second per case.
pub const LINE_LEVEL: u32 = 8;

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
    /// Assemble from the cache alone (`--offline`): a case without an entry is an error.
    pub offline: bool,
}

impl Context<'_> {
    /// Where the solves of a target come from and go.
    pub fn store(&self) -> Store<'_> {
        match (&self.cache, self.offline) {
            (None, _) => Store::Nothing,
            (Some(c), false) => Store::Cache(c),
            (Some(c), true) => Store::Offline(c),
        }
    }
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
    /// Mastercurve fit over `tau_c >= FIT_TAU_C_MIN` (Figs. 2-8).
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
    /// The refined formula's cross-validation, by figure (the `mastercurve` target).
    pub refined: Vec<FigureCheck>,
}

/// Writes `text` to the file `name` of the output folder (atomically); returns `name`.
pub fn write(ctx: &Context, name: &str, text: &str) -> Result<String, String> {
    let path = ctx.out.join(name);
    write_atomic(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(name.to_string())
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
