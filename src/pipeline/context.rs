//! Where and how targets are built ([`Context`]): the output folder, the cache and how it is
//! used, the level, the sample of the large sweeps, and who hears of progress and warnings.

use crate::pipeline::cache::Cache;
use crate::pipeline::csv::write_atomic;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::{CachePolicy, RunProgress};
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

/// Where and how targets are built.
#[derive(Clone)]
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
    /// Set (by a Ctrl-C handler): the sweeps start no new solve and end in
    /// [`PipelineError::Interrupted`] once the solves in flight are in the cache
    /// ([`crate::pipeline::executor::run_jobs_until`]). `None`: runs go to their end.
    pub stop: Option<&'a AtomicBool>,
}

/// Sweeps with more cases than this are sampled when [`Context::stride`] is above 1.
pub const SAMPLED_ABOVE: usize = 200;

impl Context<'_> {
    /// How the solves of a target use the cache.
    pub fn cache_policy(&self) -> CachePolicy<'_> {
        match (&self.cache, self.offline) {
            (None, _) => CachePolicy::Ignore,
            (Some(c), false) => CachePolicy::Use(c),
            (Some(c), true) => CachePolicy::Offline(c),
        }
    }

    /// The step through a sweep of `cases` cases: [`Context::stride`] for a large sweep, else
    /// 1 (every case).
    pub fn stride_for(&self, cases: usize) -> usize {
        if self.stride > 1 && cases > SAMPLED_ABOVE {
            self.stride
        } else {
            1
        }
    }

    /// Writes `text` to the file `name` of the output folder (atomically); returns `name`.
    pub fn write(&self, name: &str, text: &str) -> Result<String, PipelineError> {
        let path = self.out.join(name);
        write_atomic(&path, text)
            .map_err(|e| PipelineError::io(format!("cannot write {}", path.display()), &path, e))?;
        Ok(name.to_string())
    }
}

/// The output folder must be writable before hours of solves are spent.
pub fn check_writable(out: &Path) -> Result<(), PipelineError> {
    std::fs::create_dir_all(out).map_err(|e| {
        PipelineError::io(
            format!("cannot create output folder {}", out.display()),
            out,
            e,
        )
    })?;
    let probe = out.join(".repro-write-test");
    std::fs::write(&probe, b"ok").map_err(|e| {
        PipelineError::io(
            format!("output folder {} is not writable", out.display()),
            out,
            e,
        )
    })?;
    let _ = std::fs::remove_file(probe);
    Ok(())
}
