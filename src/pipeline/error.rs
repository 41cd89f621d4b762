//! Why a target could not be built: the one error of the pipeline and the paper's targets.
//!
//! One enum serves both layers: a target fails for the pipeline's reasons (a case, a
//! solve, a sweep file, a file, the cache, the offline mode) plus two of its own (a picture,
//! an unknown target), and a second enum that only wrapped this one would add a layer every
//! message passes through without saying more. It lives in `pipeline` because `paper` sits
//! above it (the architecture is one-way); a target's own typed input errors (the measured
//! data of Fig. 8) come in whole ([`PipelineError::Data`]). The CLI alone turns it
//! into a line and an exit code. Every message names the file and field where known, and
//! carries its cause's text: the wrapped errors are fields, not sources, so that a chain
//! printed with `{:#}` does not say them twice (the transparent variants pass their inner
//! error's own source on).

use crate::physics::case::CaseError;
use crate::plot::PlotError;
use crate::solver::output::SolveError;
use std::path::PathBuf;

pub use super::sweep::SweepError;

/// Why a target, a job list or a pipeline step failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PipelineError {
    /// A case that does not resolve into a problem; `what` names it (file, case number).
    #[error("{what}: {error}")]
    Case {
        /// Which case: its file and number, or its role (`the case's base`).
        what: String,
        /// The case's error (names the field).
        error: CaseError,
    },
    /// A solve whose answer the caller needed failed (a sweep's failures are results
    /// instead, [`super::outcome::CaseOutcome::Failed`]).
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// A sweep file that cannot be read (names the file and the field).
    #[error(transparent)]
    Sweep(#[from] SweepError),
    /// A file or folder that could not be read, written or created.
    #[error("{what}: {error}")]
    Io {
        /// What was tried, with the path (`cannot write figures/fig4.csv`).
        what: String,
        /// The file or folder.
        path: PathBuf,
        /// The OS error.
        error: std::io::Error,
    },
    /// A file that does not parse or holds a wrong field (TOML, a cache entry).
    #[error("{file}: {}{message}", field.map(|f| format!("field {f}: ")).unwrap_or_default())]
    Parse {
        /// The file.
        file: String,
        /// The field, where known.
        field: Option<&'static str>,
        /// What is wrong (a parser's message gives line and column).
        message: String,
    },
    /// A picture that could not be drawn.
    #[error("{file}: {error}")]
    Plot {
        /// The SVG file.
        file: String,
        /// The plot's error.
        error: PlotError,
    },
    /// Cases the offline mode needs that the cache lacks, or lost during the run; the
    /// message lists them with their targets and keys.
    #[error("{0}")]
    Offline(String),
    /// A run stopped before every job was done ([`super::executor::run_jobs_until`]): the
    /// solves it finished are in the cache.
    #[error("{target}: interrupted with {unsolved} cases not solved")]
    Interrupted {
        /// The run's target.
        target: String,
        /// Its jobs left unsolved.
        unsolved: usize,
    },
    /// A target name that is not in the registry.
    #[error("unknown target '{name}' (known: {known})")]
    UnknownTarget {
        /// The name asked for.
        name: String,
        /// The registered names, comma-separated.
        known: String,
    },
    /// A shard specification that cannot be used (`--shard I/N`, a Slurm array).
    #[error("{0}")]
    Shard(String),
    /// An input a target cannot use: a shipped case file without the case it needs.
    #[error("{0}")]
    Input(String),
    /// A target's own typed input error (the measured data of Fig. 8), as its source.
    #[error(transparent)]
    Data(Box<dyn std::error::Error + Send + Sync>),
}

impl PipelineError {
    /// The case error of `what`.
    pub fn case(what: impl Into<String>, error: CaseError) -> Self {
        PipelineError::Case {
            what: what.into(),
            error,
        }
    }

    /// The I/O error of `what` (a phrase with the path) on `path`.
    pub fn io(what: impl Into<String>, path: impl Into<PathBuf>, error: std::io::Error) -> Self {
        PipelineError::Io {
            what: what.into(),
            path: path.into(),
            error,
        }
    }

    /// The parse error of `file`, `field` where known.
    pub fn parse(
        file: impl Into<String>,
        field: Option<&'static str>,
        message: impl ToString,
    ) -> Self {
        PipelineError::Parse {
            file: file.into(),
            field,
            message: message.to_string(),
        }
    }

    /// The drawing error of the picture `file`.
    pub fn plot(file: impl Into<String>, error: PlotError) -> Self {
        PipelineError::Plot {
            file: file.into(),
            error,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each message keeps the text the strings had, and says its cause once when the CLI
    /// prints the chain (`{:#}`).
    #[test]
    fn messages_name_the_file_and_field_and_say_the_cause_once() {
        let cases = [
            (
                PipelineError::io(
                    "cannot write out/fig4.csv",
                    "out/fig4.csv",
                    std::io::Error::other("disk full"),
                ),
                "cannot write out/fig4.csv: disk full",
            ),
            (
                PipelineError::parse("ab/abcd.json", Some("sha256"), "hash mismatch"),
                "ab/abcd.json: field sha256: hash mismatch",
            ),
            (
                PipelineError::parse("cases/table4.toml", None, "expected `=`"),
                "cases/table4.toml: expected `=`",
            ),
            (
                PipelineError::case(
                    "case 3",
                    CaseError::Field {
                        field: "ph",
                        message: "must be positive".into(),
                    },
                ),
                "case 3: ph: must be positive",
            ),
        ];
        for (error, text) in cases {
            assert_eq!(error.to_string(), text);
            assert_eq!(format!("{:#}", anyhow::Error::from(error)), text);
        }
    }
}
