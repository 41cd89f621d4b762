//! `repro.solve`: one contact through [`repro::report::solve::solve`], the function behind
//! `repro solve`, with the GIL released; the report's JSON and text and the fields as numpy
//! arrays.

use crate::args::{contact, density, domain, edge, patch, rheology, viscosity};
use crate::errors::{solve_error, value_error};
use numpy::ndarray::Array2;
use numpy::IntoPyArray;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use repro::report::solve::{self, SolveFailure, SolveInputs, Solved};
use repro::solver::output::Progress;
use repro::solver::{line, point};
use std::time::Instant;

/// Solves one contact as `repro solve` does; returns the CLI's JSON text, its summary and
/// warning, and the fields (`X`, `Y`, `P`, `H` and the mean shear stress `tau_m`: 2-D
/// `[j, i]` arrays for a point contact, 1-D `X`, `P`, `H`, `tau_m` for a line contact). The
/// lubricant and geometry keywords are [`crate::args::Lubricant`]'s and
/// [`crate::args::Geometry`]'s; the defaults are the command line's
/// ([`SolveInputs::default`]).
#[pyfunction]
#[pyo3(signature = (*, m=None, l=None, s_bar=None, d=None, temperature=None, ph=None,
    um=None, tau0=None, slip=None, viscosity=None, density=None, rheology=None,
    lambda_lss=None, tau_l0=None, line=false, level=None, exact_level=false, domain=None, edge=None,
    patch=None, max_cycles=None, newton_steps=None, rolling=true, cold=false, k_solid=None,
    k_lubricant=None, progress=None, **keywords))]
#[allow(clippy::too_many_arguments)]
pub fn _solve<'py>(
    py: Python<'py>,
    m: Option<f64>,
    l: Option<f64>,
    s_bar: Option<f64>,
    d: Option<f64>,
    temperature: Option<f64>,
    ph: Option<f64>,
    um: Option<f64>,
    tau0: Option<f64>,
    slip: Option<f64>,
    viscosity: Option<&str>,
    density: Option<&str>,
    rheology: Option<&str>,
    lambda_lss: Option<f64>,
    tau_l0: Option<f64>,
    line: bool,
    level: Option<u32>,
    exact_level: bool,
    domain: Option<&str>,
    edge: Option<&str>,
    patch: Option<&str>,
    max_cycles: Option<usize>,
    newton_steps: Option<usize>,
    rolling: bool,
    cold: bool,
    k_solid: Option<f64>,
    k_lubricant: Option<f64>,
    progress: Option<PyObject>,
    keywords: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (lubricant, geometry) = contact(py, "solve", keywords)?;
    let defaults = SolveInputs::default();
    let inputs = SolveInputs {
        m,
        l,
        s_bar,
        d,
        lubricant: lubricant.name,
        temperature,
        alpha: lubricant.alpha,
        ph,
        um,
        tau0,
        rx: geometry.rx,
        ry: geometry.ry,
        e_prime: geometry.e_prime,
        datasheet: lubricant.sheet,
        slip,
        eta0: lubricant.eta0,
        viscosity: self::viscosity(viscosity)?,
        density: self::density(density)?,
        rheology: self::rheology(rheology)?,
        lambda_lss,
        tau_l0,
        line,
        level,
        exact_level,
        domain: self::domain(domain)?,
        edge: self::edge(edge)?,
        patch: self::patch(patch)?,
        max_cycles: max_cycles.unwrap_or(defaults.max_cycles),
        newton_steps: newton_steps.unwrap_or(defaults.newton_steps),
        rolling_friction: rolling,
        cold,
        k_solid: k_solid.unwrap_or(defaults.k_solid),
        k_lubricant: k_lubricant.unwrap_or(defaults.k_lubricant),
    };
    // The solve runs without the GIL; a progress callback takes it back for each step.
    let start = Instant::now();
    let solved = py.allow_threads(|| {
        let mut tell = |p: &Progress| {
            if let Some(cb) = &progress {
                Python::with_gil(|py| {
                    let _ = cb.call1(py, (p.level, p.count, p.residual, p.h_central));
                });
            }
        };
        solve::solve(&inputs, &mut |_, _| {}, Some(&mut tell))
    });
    let solved = match solved {
        Ok(s) => s,
        Err(SolveFailure::Input(e)) => return Err(value_error(e)),
        Err(SolveFailure::Solve(e)) => return Err(solve_error(py, &e)),
        Err(e @ SolveFailure::Pipeline(_)) => return Err(PyValueError::new_err(e.to_string())),
    };
    let out = PyDict::new(py);
    let json = serde_json::to_string_pretty(&solved.json())
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    let (text, warning) = solved.text();
    // The library's part of the call (solve and report), to measure the binding's overhead.
    out.set_item("library_seconds", start.elapsed().as_secs_f64())?;
    out.set_item("json", json)?;
    out.set_item("text", text)?;
    out.set_item("warning", warning)?;
    fields(&out, &solved)?;
    Ok(out)
}

/// The solution's fields into `out`: `kind`, `X`, `Y`, `P`, `H` and `tau_m` = tau_m / tau0
/// ([`point::mean_shear_stress`], [`line::LineSolution::tau_m`]; 0 where `P <= 0`), and a
/// point contact's mesh `hx`, `hy`.
fn fields(out: &Bound<'_, PyDict>, solved: &Solved) -> PyResult<()> {
    let py = out.py();
    match solved {
        Solved::Point(p) => {
            let s = &p.solution;
            let g = &s.grid;
            let (nx, ny) = (g.px(), g.py());
            let field =
                |f: &dyn Fn(usize, usize) -> f64| Array2::from_shape_fn((ny, nx), |(j, i)| f(i, j));
            let tau_m = point::mean_shear_stress(&p.problem, s);
            out.set_item("kind", "point")?;
            out.set_item("X", field(&|i, _| g.x(i)).into_pyarray(py))?;
            out.set_item("Y", field(&|_, j| g.y(j)).into_pyarray(py))?;
            out.set_item("P", field(&|i, j| s.p[g.idx(i, j)]).into_pyarray(py))?;
            out.set_item("H", field(&|i, j| s.h[g.idx(i, j)]).into_pyarray(py))?;
            out.set_item("tau_m", field(&|i, j| tau_m[g.idx(i, j)]).into_pyarray(py))?;
            out.set_item("hx", g.hx)?;
            out.set_item("hy", g.hy)?;
        }
        Solved::Line(l) => {
            let s: &line::LineSolution = &l.solution;
            out.set_item("kind", "line")?;
            out.set_item("X", s.x.clone().into_pyarray(py))?;
            out.set_item("P", s.p.clone().into_pyarray(py))?;
            out.set_item("H", s.h.clone().into_pyarray(py))?;
            out.set_item("tau_m", s.tau_m.clone().into_pyarray(py))?;
        }
    }
    Ok(())
}
