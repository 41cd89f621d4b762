//! `import repro`: the solver, the predictor, lubricants and studies of the `repro` crate as a
//! Python extension module (`repro._repro`; `repro/__init__.py` wraps it). Every function
//! calls the library as the command line does (`repro solve` and this module share
//! [`repro::report::solve::solve`]), so a result here has the bits of the command's.

mod args;
mod errors;
mod predict;
mod solve;
mod study;

use pyo3::prelude::*;
use repro::solver::point;

/// The extension module `repro._repro`.
#[pymodule]
fn _repro(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(solve::_solve, m)?)?;
    m.add_function(wrap_pyfunction!(predict::_predict, m)?)?;
    m.add_function(wrap_pyfunction!(predict::_lubricant, m)?)?;
    m.add_function(wrap_pyfunction!(study::_study, m)?)?;
    m.add_function(wrap_pyfunction!(study::_toml_of_json, m)?)?;
    m.add("LEVELS", (point::MIN_LEVEL, point::MAX_LEVEL))?;
    Ok(())
}
