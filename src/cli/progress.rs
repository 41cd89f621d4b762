//! Progress of the sweeps on stderr, drawn by indicatif: a bar per target on a terminal; on
//! anything else (a batch job's log, a pipe) a plain line every tenth of a target's cases, so
//! the log stays readable; nothing with `-q`. Warnings go through it so that they do not tear
//! a bar.

use super::args::TargetArgs;
use super::config::context;
use anyhow::Result;
use indicatif::{ProgressBar, ProgressStyle};
use repro::pipeline::context::Context;
use repro::pipeline::executor::RunProgress;
use std::io::IsTerminal;
use std::sync::Mutex;

/// Runs `f` in the pipeline context of the target flags, the sweeps' progress shown while it
/// runs (and the bar finished before it returns); `warnings` false silences the warnings.
pub fn in_context<T>(
    args: &TargetArgs,
    warnings: bool,
    f: impl FnOnce(&mut Context) -> Result<T>,
) -> Result<T> {
    in_context_writing(args, true, warnings, f)
}

/// [`in_context`], the output folder checked only when the run `writes_outputs`.
pub fn in_context_writing<T>(
    args: &TargetArgs,
    writes_outputs: bool,
    warnings: bool,
    f: impl FnOnce(&mut Context) -> Result<T>,
) -> Result<T> {
    let shown = ProgressDisplay::new(args.quiet);
    let progress = |name: &str, p: RunProgress| shown.case_done(name, p);
    let warn = |w: String| {
        if warnings {
            shown.warn(&w)
        }
    };
    let mut ctx = context(args, writes_outputs, &progress, &warn)?;
    f(&mut ctx)
}

/// How progress is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Quiet,
    Bars,
    Lines,
}

/// The progress display of one command: the bar of the target being built, if any.
pub struct ProgressDisplay {
    mode: Mode,
    bar: Mutex<Option<(String, ProgressBar)>>,
}

impl ProgressDisplay {
    /// Bars when stderr is a terminal, plain lines otherwise, nothing when `quiet`.
    pub fn new(quiet: bool) -> Self {
        let mode = if quiet {
            Mode::Quiet
        } else if std::io::stderr().is_terminal() {
            Mode::Bars
        } else {
            Mode::Lines
        };
        ProgressDisplay {
            mode,
            bar: Mutex::new(None),
        }
    }

    /// Hears of a finished case of target `name` (from any thread).
    pub fn case_done(&self, name: &str, p: RunProgress) {
        match self.mode {
            Mode::Quiet => {}
            Mode::Lines => {
                let step = (p.total / 10).max(1);
                if p.done.is_multiple_of(step) || p.done == p.total {
                    eprintln!(
                        "  {name}: {}/{} cases ({} cached, {} bases)",
                        p.done, p.total, p.cached, p.bases
                    );
                }
            }
            Mode::Bars => {
                let mut slot = self.bar.lock().unwrap_or_else(|e| e.into_inner());
                if slot.as_ref().is_none_or(|(n, _)| n != name) {
                    if let Some((_, old)) = slot.take() {
                        close(&old);
                    }
                    *slot = Some((name.to_string(), new_bar(name, p.total)));
                }
                if let Some((_, bar)) = slot.as_ref() {
                    bar.set_position(p.done as u64);
                    bar.set_message(format!("{} cached, {} bases", p.cached, p.bases));
                    if p.done == p.total {
                        close(bar);
                    }
                }
            }
        }
    }

    /// Prints a warning (nothing when quiet), above the bar when one is drawn.
    pub fn warn(&self, w: &str) {
        if self.mode == Mode::Quiet {
            return;
        }
        let slot = self.bar.lock().unwrap_or_else(|e| e.into_inner());
        match slot.as_ref() {
            Some((_, bar)) if !bar.is_finished() => bar.suspend(|| eprintln!("warning: {w}")),
            _ => eprintln!("warning: {w}"),
        }
    }
}

/// Leaves a bar drawn in its final state, the cursor on the next line (indicatif leaves it
/// at the end of the bar, where the next output would continue the line).
fn close(bar: &ProgressBar) {
    if !bar.is_finished() {
        bar.finish();
        if !bar.is_hidden() {
            eprintln!();
        }
    }
}

fn new_bar(name: &str, total: usize) -> ProgressBar {
    let bar = ProgressBar::new(total as u64);
    // The template is a constant; should indicatif ever refuse it, the default style remains.
    if let Ok(style) = ProgressStyle::with_template(
        "  {prefix}: [{bar:30}] {pos}/{len} cases ({msg}), {elapsed}, eta {eta}",
    ) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_prefix(name.to_string());
    bar
}

impl Drop for ProgressDisplay {
    fn drop(&mut self) {
        if let Some((_, bar)) = self.bar.get_mut().ok().and_then(Option::take) {
            close(&bar);
        }
    }
}
