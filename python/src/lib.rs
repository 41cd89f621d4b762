//! `import repro`: the solver, the predictor, lubricants and studies of the `repro` crate as a
//! Python extension module (`repro._repro`; `repro/__init__.py` wraps it). Every function
//! calls the library as the command line does (`repro solve` and this module share
//! [`repro::report::solve::solve`]), so a result here has the bits of the command's.

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::exceptions::{PyKeyboardInterrupt, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use repro::paper::mastercurve::fit::{eq13_mu_bar, PAPER_C};
use repro::paper::prediction::contact::EngineeringContact;
use repro::paper::prediction::{operating_point, Band, Prediction};
use repro::physics::case::{LubricantSpec, Physics};
use repro::physics::density::DensityLaw;
use repro::physics::lubricant::LubricantTable;
use repro::physics::pressure_viscosity::BaseOil;
use repro::physics::traction::{characteristic, Characteristic, Load};
use repro::physics::viscosity::ViscosityLaw;
use repro::pipeline::cache::Cache;
use repro::pipeline::context::{check_writable, Context};
use repro::pipeline::executor::RunProgress;
use repro::pipeline::sweep::Sweep;
use repro::report::solve::{
    self, check_level, lubricant_spec, physics, DatasheetInputs, InputError, RheologyChoice,
    SolveFailure, SolveInputs, Solved,
};
use repro::solver::grid::Domain;
use repro::solver::output::{Progress, SolveError};
use repro::solver::point;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The command line's message with its flags as this module's keywords
/// (`--s-bar: required` -> `s_bar: required`).
fn keywords(message: &str) -> String {
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

fn value_error(e: InputError) -> PyErr {
    PyValueError::new_err(keywords(&e.0))
}

/// A failed solve as `repro.SolveError` (defined in `repro/__init__.py`): the message, the
/// failure's kind and the residual history.
fn solve_error(py: Python<'_>, e: &SolveError) -> PyErr {
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

/// One of `names`' values for the keyword `flag`, or the error that lists them.
fn choice<T: Copy>(flag: &str, value: Option<&str>, names: &[(&str, T)]) -> PyResult<Option<T>> {
    let Some(v) = value else { return Ok(None) };
    let wanted = v.replace('_', "-");
    names
        .iter()
        .find(|(n, _)| *n == wanted)
        .map(|(_, t)| Some(*t))
        .ok_or_else(|| {
            let all: Vec<&str> = names.iter().map(|(n, _)| *n).collect();
            PyValueError::new_err(format!("{flag}: '{v}' is not one of {}", all.join(", ")))
        })
}

fn viscosity(v: Option<&str>) -> PyResult<Option<ViscosityLaw>> {
    choice(
        "viscosity",
        v,
        &[
            ("barus", ViscosityLaw::Barus),
            ("roelands", ViscosityLaw::Roelands),
        ],
    )
}

fn density(v: Option<&str>) -> PyResult<Option<DensityLaw>> {
    choice(
        "density",
        v,
        &[
            ("incompressible", DensityLaw::Incompressible),
            ("dowson-higginson", DensityLaw::DowsonHigginson),
        ],
    )
}

fn base_oil(v: Option<&str>) -> PyResult<Option<BaseOil>> {
    choice(
        "base_oil",
        v,
        &[
            ("mineral", BaseOil::Mineral),
            ("pao", BaseOil::Polyalphaolefin),
            ("pag", BaseOil::Polyglycol),
        ],
    )
}

/// The datasheet keywords.
#[allow(clippy::too_many_arguments)]
fn datasheet(
    nu40: Option<f64>,
    iso_vg: Option<u32>,
    nu100: Option<f64>,
    vi: Option<f64>,
    rho15: Option<f64>,
    expansion15: Option<f64>,
    oil: Option<&str>,
) -> PyResult<DatasheetInputs> {
    Ok(DatasheetInputs {
        nu40,
        iso_vg,
        nu100,
        vi,
        rho15,
        expansion15,
        base_oil: base_oil(oil)?,
    })
}

/// Solves one contact as `repro solve` does; returns the CLI's JSON text, its summary and
/// warning, and the fields (`X`, `Y`, `P`, `H`: 2-D `[j, i]` arrays for a point contact,
/// 1-D `X`, `P`, `H` for a line contact).
#[pyfunction]
#[pyo3(signature = (*, m=None, l=None, s_bar=None, d=None, lubricant=None, temperature=None,
    alpha=None, ph=None, um=None, tau0=None, rx=1.03875e-2, ry=None, e_prime=226e9,
    nu40=None, iso_vg=None, nu100=None, vi=None, rho15=None, expansion15=None, base_oil=None,
    slip=None, eta0=None, viscosity=None, density=None, rheology=None, lambda_lss=None,
    tau_l0=None, line=false, level=None, domain=None, edge=None, max_cycles=None,
    newton_steps=None, rolling=true, cold=false, k_solid=46.0, k_lubricant=0.13,
    progress=None))]
#[allow(clippy::too_many_arguments)]
fn _solve<'py>(
    py: Python<'py>,
    m: Option<f64>,
    l: Option<f64>,
    s_bar: Option<f64>,
    d: Option<f64>,
    lubricant: Option<String>,
    temperature: Option<f64>,
    alpha: Option<f64>,
    ph: Option<f64>,
    um: Option<f64>,
    tau0: Option<f64>,
    rx: f64,
    ry: Option<f64>,
    e_prime: f64,
    nu40: Option<f64>,
    iso_vg: Option<u32>,
    nu100: Option<f64>,
    vi: Option<f64>,
    rho15: Option<f64>,
    expansion15: Option<f64>,
    base_oil: Option<&str>,
    slip: Option<f64>,
    eta0: Option<f64>,
    viscosity: Option<&str>,
    density: Option<&str>,
    rheology: Option<&str>,
    lambda_lss: Option<f64>,
    tau_l0: Option<f64>,
    line: bool,
    level: Option<u32>,
    domain: Option<&str>,
    edge: Option<&str>,
    max_cycles: Option<usize>,
    newton_steps: Option<usize>,
    rolling: bool,
    cold: bool,
    k_solid: f64,
    k_lubricant: f64,
    progress: Option<PyObject>,
) -> PyResult<Bound<'py, PyDict>> {
    let defaults = SolveInputs::default();
    let inputs = SolveInputs {
        m,
        l,
        s_bar,
        d,
        lubricant,
        temperature,
        alpha,
        ph,
        um,
        tau0,
        rx,
        ry,
        e_prime,
        datasheet: datasheet(nu40, iso_vg, nu100, vi, rho15, expansion15, base_oil)?,
        slip,
        eta0,
        viscosity: self::viscosity(viscosity)?,
        density: self::density(density)?,
        rheology: choice(
            "rheology",
            rheology,
            &[
                ("eyring", RheologyChoice::Eyring),
                ("newtonian", RheologyChoice::Newtonian),
                ("eyring-lss", RheologyChoice::EyringLss),
            ],
        )?,
        lambda_lss,
        tau_l0,
        line,
        level,
        domain: choice(
            "domain",
            domain,
            &[
                ("auto", None),
                ("paper", Some(Domain::default())),
                ("wide", Some(Domain::wide())),
                ("heavy", Some(Domain::heavy())),
            ],
        )?
        .flatten(),
        edge: choice(
            "edge",
            edge,
            &[
                ("auto", None),
                ("zero", Some(point::Edge::Zero)),
                ("far-field", Some(point::Edge::FarField)),
            ],
        )?
        .flatten(),
        max_cycles: max_cycles.unwrap_or(defaults.max_cycles),
        newton_steps: newton_steps.unwrap_or(defaults.newton_steps),
        rolling_friction: rolling,
        cold,
        k_solid,
        k_lubricant,
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
    match &solved {
        Solved::Point(p) => {
            let s = &p.solution;
            let g = &s.grid;
            let (nx, ny) = (g.px(), g.py());
            let field =
                |f: &dyn Fn(usize, usize) -> f64| Array2::from_shape_fn((ny, nx), |(j, i)| f(i, j));
            out.set_item("kind", "point")?;
            out.set_item("X", field(&|i, _| g.x(i)).into_pyarray(py))?;
            out.set_item("Y", field(&|_, j| g.y(j)).into_pyarray(py))?;
            out.set_item("P", field(&|i, j| s.p[g.idx(i, j)]).into_pyarray(py))?;
            out.set_item("H", field(&|i, j| s.h[g.idx(i, j)]).into_pyarray(py))?;
            out.set_item("hx", g.hx)?;
            out.set_item("hy", g.hy)?;
        }
        Solved::Line(l) => {
            let s = &l.solution;
            out.set_item("kind", "line")?;
            out.set_item("X", s.x.clone().into_pyarray(py))?;
            out.set_item("P", s.p.clone().into_pyarray(py))?;
            out.set_item("H", s.h.clone().into_pyarray(py))?;
        }
    }
    Ok(out)
}

/// The lubricant spec of the predictor's and `lubricant()`'s keywords at one temperature.
#[allow(clippy::too_many_arguments)]
fn spec(
    lubricant: Option<&str>,
    temperature: Option<f64>,
    alpha: Option<f64>,
    eta0: Option<f64>,
    sheet: &DatasheetInputs,
) -> PyResult<LubricantSpec> {
    lubricant_spec(lubricant, temperature, alpha, eta0, sheet).map_err(value_error)
}

/// The element `i` of a broadcast input (length 1 or n).
fn at(a: &[f64], i: usize) -> f64 {
    if a.len() == 1 {
        a[0]
    } else {
        a[i]
    }
}

/// A lubricant resolved at one temperature: `alpha` and `eta0`, and `alpha`'s band when a
/// correlation estimated it ([`LubricantSpec::resolve`], the datasheet's laws).
#[derive(Clone, Copy)]
struct Resolved {
    alpha_per_pa: f64,
    eta0_pa_s: f64,
    band: Option<[f64; 2]>,
}

fn resolve(spec: &LubricantSpec, lubs: &LubricantTable) -> PyResult<Resolved> {
    let state = spec
        .resolve(lubs)
        .map_err(|e| value_error(solve::flag_error(e)))?;
    let band = match spec {
        LubricantSpec::Datasheet {
            datasheet,
            temperature_c,
            alpha_per_gpa,
        } => datasheet
            .resolve()
            .and_then(|d| d.at(*temperature_c, *alpha_per_gpa))
            .map_err(|e| value_error(solve::flag_error(e.into())))?
            .correlated
            .map(|e| [e.low_per_pa, e.high_per_pa]),
        _ => None,
    };
    Ok(Resolved {
        alpha_per_pa: state.alpha_per_pa,
        eta0_pa_s: state.eta0_pa_s,
        band,
    })
}

/// Eq. (12)'s `tau_c` of a contact whose lubricant is given by `alpha` and `eta0`, as
/// [`repro::paper::prediction::Estimate::of`] computes it (its operating point): the predictor's `alpha` band is evaluated the same way, with the
/// band's ends given.
fn characteristic_at(
    contact: &EngineeringContact,
    alpha_per_pa: f64,
    eta0_pa_s: f64,
    lubs: &LubricantTable,
) -> PyResult<Characteristic> {
    let given = EngineeringContact {
        lubricant: LubricantSpec::Given {
            alpha_per_pa,
            eta0_pa_s,
        },
        ..contact.clone()
    };
    let case = given
        .case(lubs)
        .map_err(|e| value_error(solve::flag_error(e)))?;
    let point = operating_point(&case).map_err(|e| value_error(solve::flag_error(e)))?;
    characteristic(&point, lubs).map_err(|e| value_error(solve::flag_error(e)))
}

/// The predictor of `repro predict` over arrays of equal length `n` (or length 1,
/// broadcast): `ph` (Pa) or `load` (N), `um`, `slip`, `tau0`, `temperature`. Eq. (12) ->
/// Eq. (14) -> `mu`, with Eq. (14) over a correlated `alpha`'s band; with `refined` also the
/// refined formula (whose flat-film integral costs tens of microseconds a contact). The
/// lubricant is resolved once per distinct temperature. Returns a dict of arrays.
#[pyfunction]
#[pyo3(signature = (*, n, ph, load, um, slip, tau0, temperature, lubricant=None, alpha=None,
    eta0=None, nu40=None, iso_vg=None, nu100=None, vi=None, rho15=None, expansion15=None,
    base_oil=None, viscosity=None, rx=1.03875e-2, ry=None, e_prime=226e9, refined=false))]
#[allow(clippy::too_many_arguments)]
fn _predict<'py>(
    py: Python<'py>,
    n: usize,
    ph: Option<PyReadonlyArray1<'py, f64>>,
    load: Option<PyReadonlyArray1<'py, f64>>,
    um: PyReadonlyArray1<'py, f64>,
    slip: PyReadonlyArray1<'py, f64>,
    tau0: PyReadonlyArray1<'py, f64>,
    temperature: Option<PyReadonlyArray1<'py, f64>>,
    lubricant: Option<&str>,
    alpha: Option<f64>,
    eta0: Option<f64>,
    nu40: Option<f64>,
    iso_vg: Option<u32>,
    nu100: Option<f64>,
    vi: Option<f64>,
    rho15: Option<f64>,
    expansion15: Option<f64>,
    base_oil: Option<&str>,
    viscosity: Option<&str>,
    rx: f64,
    ry: Option<f64>,
    e_prime: f64,
    refined: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let sheet = datasheet(nu40, iso_vg, nu100, vi, rho15, expansion15, base_oil)?;
    let physics = physics(
        self::viscosity(viscosity)?,
        None,
        None,
        Physics::figs_4_to_7(),
    );
    let (ph, load) = (
        ph.as_ref().map(|a| a.as_slice()).transpose()?,
        load.as_ref().map(|a| a.as_slice()).transpose()?,
    );
    let (um, slip, tau0) = (um.as_slice()?, slip.as_slice()?, tau0.as_slice()?);
    let temperature = temperature.as_ref().map(|a| a.as_slice()).transpose()?;
    let lubs = LubricantTable::table1();
    let mut keys = vec![
        "tau_c",
        "mu_bar",
        "mu",
        "m",
        "l",
        "s_bar",
        "ph_pa",
        "hc_m",
        "eta_bar_ph",
        "mu_bar_low",
        "mu_bar_high",
    ];
    if refined {
        keys.extend(["mu_bar_refined", "mu_refined"]);
    }
    let mut cols: Vec<Vec<f64>> = keys.iter().map(|_| Vec::with_capacity(n)).collect();
    // The lubricant at the temperature of the element before (a sweep of speed has one).
    let mut state: Option<(Option<u64>, Resolved)> = None;
    for i in 0..n {
        let t = temperature.map(|t| at(t, i));
        let lubricant = spec(lubricant, t, alpha, eta0, &sheet)?;
        let key = t.map(f64::to_bits);
        let r = match state {
            Some((k, r)) if k == key => r,
            _ => {
                let r = resolve(&lubricant, &lubs)?;
                state = Some((key, r));
                r
            }
        };
        let load = match (ph, load) {
            (Some(p), None) => Load::MaxPressure(at(p, i)),
            (None, Some(f)) => Load::Force(at(f, i)),
            (Some(_), Some(_)) => return Err(PyValueError::new_err("ph and load cannot be mixed")),
            (None, None) => return Err(PyValueError::new_err("ph: required (or load)")),
        };
        let tau0 = at(tau0, i);
        let contact = EngineeringContact {
            lubricant,
            physics,
            load,
            rx_m: rx,
            ry_m: ry.unwrap_or(rx),
            e_prime_pa: e_prime,
            um_m_s: at(um, i),
            slip: at(slip, i),
            tau0_pa: tau0,
        };
        let c = characteristic_at(&contact, r.alpha_per_pa, r.eta0_pa_s, &lubs)?;
        let mu_bar = eq13_mu_bar(c.tau_c, PAPER_C);
        let (low, high) = match r.band {
            Some(band) => {
                let mut ends = [mu_bar; 3];
                for (end, alpha) in ends.iter_mut().zip(band) {
                    let e = characteristic_at(&contact, alpha, r.eta0_pa_s, &lubs)?;
                    *end = eq13_mu_bar(e.tau_c, PAPER_C);
                }
                let b = Band::of(&ends);
                (b.low, b.high)
            }
            None => (f64::NAN, f64::NAN),
        };
        let mut row = vec![
            c.tau_c,
            mu_bar,
            c.friction(mu_bar, tau0),
            c.m,
            c.l,
            c.s_bar,
            c.ph_pa,
            c.hc_m,
            c.eta_bar_ph,
            low,
            high,
        ];
        if refined {
            let case = contact
                .case(&lubs)
                .map_err(|e| value_error(solve::flag_error(e)))?;
            let p = Prediction::of(&case, &lubs).map_err(|e| value_error(solve::flag_error(e)))?;
            row.extend([p.central.mu_bar_refined, p.central.mu_refined]);
        }
        for (col, v) in cols.iter_mut().zip(row) {
            col.push(v);
        }
    }
    columns(py, &keys, cols)
}

/// Named columns as a dict of numpy arrays.
fn columns<'py>(
    py: Python<'py>,
    keys: &[&str],
    cols: Vec<Vec<f64>>,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for (k, col) in keys.iter().zip(cols) {
        out.set_item(*k, col.into_pyarray(py))?;
    }
    Ok(out)
}

/// A lubricant's eta0 and alpha at each temperature (Table 1, given, or a datasheet: then
/// alpha's band when it is correlated; NaN otherwise).
#[pyfunction]
#[pyo3(signature = (*, temperature, lubricant=None, alpha=None, eta0=None, nu40=None,
    iso_vg=None, nu100=None, vi=None, rho15=None, expansion15=None, base_oil=None))]
#[allow(clippy::too_many_arguments)]
fn _lubricant<'py>(
    py: Python<'py>,
    temperature: Option<PyReadonlyArray1<'py, f64>>,
    lubricant: Option<&str>,
    alpha: Option<f64>,
    eta0: Option<f64>,
    nu40: Option<f64>,
    iso_vg: Option<u32>,
    nu100: Option<f64>,
    vi: Option<f64>,
    rho15: Option<f64>,
    expansion15: Option<f64>,
    base_oil: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let sheet = datasheet(nu40, iso_vg, nu100, vi, rho15, expansion15, base_oil)?;
    let temperature = temperature.as_ref().map(|a| a.as_slice()).transpose()?;
    let n = temperature.map_or(1, |t| t.len());
    let lubs = LubricantTable::table1();
    let mut cols: Vec<Vec<f64>> = (0..4).map(|_| Vec::with_capacity(n)).collect();
    for i in 0..n {
        let t = temperature.map(|t| t[i]);
        let r = resolve(&spec(lubricant, t, alpha, eta0, &sheet)?, &lubs)?;
        let [low, high] = r.band.unwrap_or([f64::NAN; 2]);
        for (col, v) in cols
            .iter_mut()
            .zip([r.eta0_pa_s, r.alpha_per_pa, low, high])
        {
            col.push(v);
        }
    }
    columns(
        py,
        &[
            "eta0_pa_s",
            "alpha_per_pa",
            "alpha_low_per_pa",
            "alpha_high_per_pa",
        ],
        cols,
    )
}

/// A sweep (TOML text; `file` names it in errors) through the pipeline and cache of
/// `repro run`, written to `out` as `<stem>.csv` and `<stem>.svg`. Returns the CSV's path,
/// the cases and the cases solved. The run goes on in its own thread; this one calls
/// `progress(done, total)` and checks for Ctrl-C between reports: on Ctrl-C the cases in
/// flight finish (into the cache), no new case starts, and KeyboardInterrupt is raised.
#[pyfunction]
#[pyo3(signature = (*, text, file, stem, out, level=None, cache=None, progress=None))]
#[allow(clippy::too_many_arguments)]
fn _study(
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
        check_level("--level", l).map_err(value_error)?;
    }
    check_writable(&out).map_err(|e| PyValueError::new_err(format!("out: {e}")))?;
    let stop = AtomicBool::new(false);
    let latest: Mutex<Option<(usize, usize)>> = Mutex::new(None);
    let done = AtomicBool::new(false);
    let report = |_: &str, p: RunProgress| {
        if let Ok(mut l) = latest.lock() {
            *l = Some((p.done, p.total));
        }
        if stop.load(Ordering::SeqCst) {
            // Unwinds out of the pool once the case that reports is in the cache: the
            // other workers stop at their next report, and no new case starts.
            std::panic::resume_unwind(Box::new("interrupted"));
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
    };
    let mut told = None;
    let mut interrupted = None;
    let result = std::thread::scope(|scope| {
        let run = scope.spawn(|| {
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                repro::paper::figures::study(stem, &sweep, &ctx)
            }));
            done.store(true, Ordering::SeqCst);
            r
        });
        while !done.load(Ordering::SeqCst) {
            py.allow_threads(|| std::thread::sleep(Duration::from_millis(20)));
            let now = latest.lock().ok().and_then(|l| *l);
            if now != told {
                told = now;
                if let (Some(cb), Some((d, t))) = (&progress, now) {
                    if let Err(e) = cb.call1(py, (d, t)) {
                        interrupted.get_or_insert(e);
                        stop.store(true, Ordering::SeqCst);
                    }
                }
            }
            if interrupted.is_none() {
                if let Err(e) = py.check_signals() {
                    interrupted = Some(e);
                    stop.store(true, Ordering::SeqCst);
                }
            }
        }
        run.join()
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let built = match result {
        Ok(Ok(r)) => r.map_err(|e| PyValueError::new_err(format!("{file}: {e}")))?,
        _ => return Err(PyKeyboardInterrupt::new_err("study interrupted")),
    };
    let csv = out.join(format!("{stem}.csv"));
    Ok((csv.display().to_string(), built.cases, built.solved))
}

/// A sweep given as JSON (a Python dict) as the TOML text a sweep file holds.
#[pyfunction]
fn _toml_of_json(text: &str) -> PyResult<String> {
    let v: toml::Value =
        serde_json::from_str(text).map_err(|e| PyValueError::new_err(format!("study: {e}")))?;
    toml::to_string(&v).map_err(|e| PyValueError::new_err(format!("study: {e}")))
}

/// The extension module `repro._repro`.
#[pymodule]
fn _repro(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_solve, m)?)?;
    m.add_function(wrap_pyfunction!(_predict, m)?)?;
    m.add_function(wrap_pyfunction!(_lubricant, m)?)?;
    m.add_function(wrap_pyfunction!(_study, m)?)?;
    m.add_function(wrap_pyfunction!(_toml_of_json, m)?)?;
    m.add("LEVELS", (point::MIN_LEVEL, point::MAX_LEVEL))?;
    Ok(())
}
