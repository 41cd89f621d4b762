//! `repro.study`: a sweep through the pipeline and cache of `repro run`, interruptible.

use crate::errors::value_error;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use repro::pipeline::cache::Cache;
use repro::pipeline::context::{check_writable, Context};
use repro::pipeline::executor::RunProgress;
use repro::pipeline::sweep::Sweep;
use repro::report::inputs::check_level;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::Duration;

/// How often the calling thread looks for Ctrl-C while the study runs.
const SIGNAL_POLL: Duration = Duration::from_millis(20);

/// A sweep (TOML text; `file` names it in errors) through the pipeline and cache of
/// `repro run`, written to `out` as `<stem>.csv` and `<stem>.svg`. Returns the CSV's path,
/// the cases and the cases solved.
///
/// The run goes on in a thread of its own (and rayon's pool) without the GIL; this thread
/// looks for Ctrl-C every [`SIGNAL_POLL`] (signals reach Python's handlers in the main thread
/// only). `progress(done, total)` is called after each case is in the cache, from the
/// thread that solved it, holding the GIL. On Ctrl-C, or an exception from `progress`, the
/// run's stop flag ([`Context::stop`]) is set: the solves in flight finish into the cache, no
/// new one starts, and the exception (KeyboardInterrupt for Ctrl-C) is raised.
#[pyfunction]
#[pyo3(signature = (*, text, file, stem, out, level=None, cache=None, progress=None))]
#[allow(clippy::too_many_arguments)]
pub fn _study(
    py: Python<'_>,
    text: &str,
    file: &str,
    stem: &str,
    out: PathBuf,
    level: Option<u32>,
    cache: Option<PathBuf>,
    progress: Option<PyObject>,
) -> PyResult<(String, usize, Option<usize>)> {
    let sweep = Sweep::parse(file, text).map_err(|e| PyValueError::new_err(e.to_string()))?;
    if let Some(l) = level {
        check_level("level", l).map_err(value_error)?;
    }
    check_writable(&out).map_err(|e| PyValueError::new_err(format!("out: {e}")))?;
    let stop = AtomicBool::new(false);
    let raised: Mutex<Option<PyErr>> = Mutex::new(None);
    let interrupt = |e: PyErr| {
        raised
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get_or_insert(e);
        stop.store(true, Ordering::SeqCst);
    };
    let report = |_: &str, p: RunProgress| {
        if let Some(cb) = &progress {
            Python::with_gil(|py| {
                // Once stopped, the cases still finishing are not reported.
                if !stop.load(Ordering::SeqCst) {
                    if let Err(e) = cb.call1(py, (p.done, p.total)) {
                        interrupt(e);
                    }
                }
            });
        }
    };
    let warn = |_: String| {};
    let ctx = Context {
        out: out.clone(),
        cache: cache.as_ref().map(Cache::new),
        level,
        progress: &report,
        warn: &warn,
        stride: 1,
        offline: false,
        stop: Some(&stop),
    };
    let done = AtomicBool::new(false);
    let result = std::thread::scope(|scope| {
        let run = scope.spawn(|| {
            let r = repro::paper::figures::study(stem, &sweep, &ctx);
            done.store(true, Ordering::SeqCst);
            r
        });
        while !done.load(Ordering::SeqCst) {
            py.allow_threads(|| std::thread::sleep(SIGNAL_POLL));
            if !stop.load(Ordering::SeqCst) {
                if let Err(e) = py.check_signals() {
                    interrupt(e);
                }
            }
        }
        py.allow_threads(|| run.join())
    });
    if let Some(e) = raised.into_inner().unwrap_or_else(|p| p.into_inner()) {
        return Err(e);
    }
    let built = match result {
        Ok(r) => r.map_err(|e| PyValueError::new_err(format!("{file}: {e}")))?,
        // A panic of the library's: pyo3 turns it into a PanicException at the boundary.
        Err(panic) => std::panic::resume_unwind(panic),
    };
    let csv = out.join(format!("{stem}.csv"));
    Ok((csv.display().to_string(), built.cases, built.solved))
}

/// A sweep given as JSON (a Python dict) as the TOML text a sweep file holds.
#[pyfunction]
pub fn _toml_of_json(text: &str) -> PyResult<String> {
    let v: toml::Value =
        serde_json::from_str(text).map_err(|e| PyValueError::new_err(format!("study: {e}")))?;
    toml::to_string(&v).map_err(|e| PyValueError::new_err(format!("study: {e}")))
}
