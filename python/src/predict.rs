//! `repro.predict` and `repro.lubricant`: the mastercurve predictor of `repro predict` and
//! the lubricant's resolution, over arrays.

use crate::args::{at, columns, contact, viscosity, Keywords, Lubricant};
use crate::errors::value_error;
use numpy::PyReadonlyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use repro::paper::eq13::{eq13_mu_bar, PAPER_C};
use repro::paper::prediction::contact::EngineeringContact;
use repro::paper::prediction::{operating_point, Band, Prediction};
use repro::physics::case::{LubricantSpec, Physics};
use repro::physics::lubricant::LubricantTable;
use repro::physics::traction::{characteristic, Characteristic, Load};
use repro::report::inputs::{flag_error, physics};

/// A lubricant resolved at one temperature: `alpha` and `eta0`, and `alpha`'s band when a
/// correlation estimated it ([`LubricantSpec::resolve`], the datasheet's laws).
#[derive(Clone, Copy)]
struct Resolved {
    alpha_per_pa: f64,
    eta0_pa_s: f64,
    band: Option<[f64; 2]>,
}

fn resolve(spec: &LubricantSpec, lubs: &LubricantTable) -> PyResult<Resolved> {
    let state = spec.resolve(lubs).map_err(|e| value_error(flag_error(e)))?;
    let band = match spec {
        LubricantSpec::Datasheet {
            datasheet,
            temperature_c,
            alpha_per_gpa,
        } => datasheet
            .resolve()
            .and_then(|d| d.at(*temperature_c, *alpha_per_gpa))
            .map_err(|e| value_error(flag_error(e.into())))?
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
/// [`repro::paper::prediction::Estimate::of`] computes it (its operating point): the
/// predictor's `alpha` band is evaluated the same way, with the band's ends given.
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
    let case = given.case(lubs).map_err(|e| value_error(flag_error(e)))?;
    let point = operating_point(&case).map_err(|e| value_error(flag_error(e)))?;
    characteristic(&point, lubs).map_err(|e| value_error(flag_error(e)))
}

/// The predictor of `repro predict` over arrays of equal length `n` (or length 1,
/// broadcast): `ph` (Pa) or `load` (N), `um`, `slip`, `tau0`, `temperature`. Eq. (12) ->
/// Eq. (14) -> `mu`, with Eq. (14) over a correlated `alpha`'s band; with `refined` also the
/// refined formula (whose flat-film integral costs tens of microseconds a contact). The
/// lubricant ([`Lubricant`]) is resolved once per distinct temperature; the geometry is
/// [`crate::args::Geometry`]'s keywords. Returns a dict of arrays.
#[pyfunction]
#[pyo3(signature = (*, n, ph, load, um, slip, tau0, temperature, viscosity=None,
    refined=false, **keywords))]
#[allow(clippy::too_many_arguments)]
pub fn _predict<'py>(
    py: Python<'py>,
    n: usize,
    ph: Option<PyReadonlyArray1<'py, f64>>,
    load: Option<PyReadonlyArray1<'py, f64>>,
    um: PyReadonlyArray1<'py, f64>,
    slip: PyReadonlyArray1<'py, f64>,
    tau0: PyReadonlyArray1<'py, f64>,
    temperature: Option<PyReadonlyArray1<'py, f64>>,
    viscosity: Option<&str>,
    refined: bool,
    keywords: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (lubricant, geometry) = contact(py, "predict", keywords)?;
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
        let spec = lubricant.spec(t)?;
        let key = t.map(f64::to_bits);
        let r = match state {
            Some((k, r)) if k == key => r,
            _ => {
                let r = resolve(&spec, &lubs)?;
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
            lubricant: spec,
            physics,
            load,
            rx_m: geometry.rx,
            ry_m: geometry.ry.unwrap_or(geometry.rx),
            e_prime_pa: geometry.e_prime,
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
                .map_err(|e| value_error(flag_error(e)))?;
            let p = Prediction::of(&case, &lubs).map_err(|e| value_error(flag_error(e)))?;
            row.extend([p.central.mu_bar_refined, p.central.mu_refined]);
        }
        for (col, v) in cols.iter_mut().zip(row) {
            col.push(v);
        }
    }
    columns(py, &keys, cols)
}

/// A lubricant's eta0 and alpha at each temperature (the keywords of [`Lubricant`]: Table 1,
/// given, or a datasheet: then alpha's band when it is correlated; NaN otherwise).
#[pyfunction]
#[pyo3(signature = (*, temperature, **keywords))]
pub fn _lubricant<'py>(
    py: Python<'py>,
    temperature: Option<PyReadonlyArray1<'py, f64>>,
    keywords: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let mut kw = Keywords::new(py, "lubricant", keywords)?;
    let lubricant = Lubricant::take(&mut kw)?;
    kw.finish()?;
    let temperature = temperature.as_ref().map(|a| a.as_slice()).transpose()?;
    let n = temperature.map_or(1, |t| t.len());
    let lubs = LubricantTable::table1();
    let mut cols: Vec<Vec<f64>> = (0..4).map(|_| Vec::with_capacity(n)).collect();
    for i in 0..n {
        let t = temperature.map(|t| t[i]);
        let r = resolve(&lubricant.spec(t)?, &lubs)?;
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
