//! The library's errors as Python exceptions: bad input as `ValueError` with the command
//! line's message (its flags written as this module's keywords), a failed solve as
//! `repro.SolveError` with its kind and residual history.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use repro::report::inputs::InputError;
use repro::solver::output::SolveError;

/// The command line's message with its flags as this module's keywords
/// (`--s-bar: required` -> `s_bar: required`).
pub fn keywords(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(at) = rest.find("--") {
        out.push_str(&rest[..at]);
        let flag = &rest[at + 2..];
        let end = flag
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
            .unwrap_or(flag.len());
        out.push_str(&flag[..end].replace('-', "_"));
        rest = &flag[end..];
    }
    out.push_str(rest);
    out
}

/// Bad input: `ValueError` with the command line's message, naming the keyword (the
/// error's own flag and any other it mentions).
pub fn value_error(e: InputError) -> PyErr {
    PyValueError::new_err(keywords(&e.to_string()))
}

/// A failed solve as `repro.SolveError` (defined in `repro/__init__.py`): the message, the
/// failure's kind and the residual history.
pub fn solve_error(py: Python<'_>, e: &SolveError) -> PyErr {
    let kind = match e {
        SolveError::NotConverged { .. } => "not_converged",
        SolveError::NonFinite { .. } => "non_finite",
        SolveError::FilmCollapse { .. } => "film_collapse",
        SolveError::InvalidParams(_) => "invalid_params",
        _ => "other",
    };
    let made = py.import("repro").and_then(|m| {
        m.getattr("SolveError")?
            .call1((e.to_string(), kind, e.residual_history().to_vec()))
    });
    match made {
        Ok(v) => PyErr::from_value(v),
        Err(err) => err,
    }
}
