//! Keyword arguments into the library's inputs: the named choices (`viscosity="roelands"`)
//! and the keyword groups several functions share, each group read by one piece of code
//! from the `**keywords` of every function that takes it.

use crate::errors::value_error;
use numpy::IntoPyArray;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use repro::physics::case::LubricantSpec;
use repro::physics::density::DensityLaw;
use repro::physics::pressure_viscosity::BaseOil;
use repro::physics::viscosity::ViscosityLaw;
use repro::report::inputs::{lubricant_spec, DatasheetInputs, RheologyChoice, SolveInputs};
use repro::solver::grid::Domain;
use repro::solver::point;
use repro::solver::point::composite::Patch;

/// The keywords a function takes beyond its signature (`**keywords`): each group takes its
/// own by name ([`Keywords::take`]) and [`Keywords::finish`] refuses what is left, as Python
/// refuses an unknown keyword.
pub struct Keywords<'py> {
    function: &'static str,
    left: Bound<'py, PyDict>,
}

impl<'py> Keywords<'py> {
    /// The keywords `given` to `function` (its Python name, for errors).
    pub fn new(
        py: Python<'py>,
        function: &'static str,
        given: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Self> {
        let left = match given {
            Some(d) => d.copy()?,
            None => PyDict::new(py),
        };
        Ok(Keywords { function, left })
    }

    /// The value of `name`, `None` where it is absent or `None`.
    pub fn take<T: FromPyObject<'py>>(&mut self, name: &str) -> PyResult<Option<T>> {
        let Some(v) = self.left.get_item(name)? else {
            return Ok(None);
        };
        self.left.del_item(name)?;
        if v.is_none() {
            return Ok(None);
        }
        v.extract()
            .map(Some)
            .map_err(|e| PyTypeError::new_err(format!("argument '{name}': {e}")))
    }

    /// Every keyword taken, or the `TypeError` of one that is not.
    pub fn finish(self) -> PyResult<()> {
        match self.left.keys().iter().next() {
            Some(k) => Err(PyTypeError::new_err(format!(
                "{}() got an unexpected keyword argument '{k}'",
                self.function
            ))),
            None => Ok(()),
        }
    }
}

/// The lubricant keywords of `solve`, `predict` and `lubricant`: one of Table 1
/// (`lubricant`), given (`alpha`, `eta0`), or a datasheet (`nu40` or `iso_vg`, `nu100` or
/// `vi`, `rho15`, `expansion15`, `base_oil`).
pub struct Lubricant {
    pub name: Option<String>,
    pub alpha: Option<f64>,
    pub eta0: Option<f64>,
    pub sheet: DatasheetInputs,
}

impl Lubricant {
    pub fn take(kw: &mut Keywords) -> PyResult<Self> {
        Ok(Lubricant {
            name: kw.take("lubricant")?,
            alpha: kw.take("alpha")?,
            eta0: kw.take("eta0")?,
            sheet: DatasheetInputs {
                nu40: kw.take("nu40")?,
                iso_vg: kw.take("iso_vg")?,
                nu100: kw.take("nu100")?,
                vi: kw.take("vi")?,
                rho15: kw.take("rho15")?,
                expansion15: kw.take("expansion15")?,
                base_oil: base_oil(kw.take::<String>("base_oil")?.as_deref())?,
            },
        })
    }

    /// The lubricant at `temperature` (C), as `repro predict` resolves its flags.
    pub fn spec(&self, temperature: Option<f64>) -> PyResult<LubricantSpec> {
        lubricant_spec(
            self.name.as_deref(),
            temperature,
            self.alpha,
            self.eta0,
            &self.sheet,
        )
        .map_err(value_error)
    }
}

/// The `**keywords` of `solve` and `predict` (`function`): a lubricant and a geometry,
/// nothing else.
pub fn contact(
    py: Python<'_>,
    function: &'static str,
    given: Option<&Bound<'_, PyDict>>,
) -> PyResult<(Lubricant, Geometry)> {
    let mut kw = Keywords::new(py, function, given)?;
    let lubricant = Lubricant::take(&mut kw)?;
    let geometry = Geometry::take(&mut kw)?;
    kw.finish()?;
    Ok((lubricant, geometry))
}

/// The contact's geometry and material keywords of `solve` and `predict`: `rx`, `ry` (m)
/// and `e_prime` (Pa), with `repro solve`'s defaults.
pub struct Geometry {
    pub rx: f64,
    pub ry: Option<f64>,
    pub e_prime: f64,
}

impl Geometry {
    pub fn take(kw: &mut Keywords) -> PyResult<Self> {
        let defaults = SolveInputs::default();
        Ok(Geometry {
            rx: kw.take("rx")?.unwrap_or(defaults.rx),
            ry: kw.take("ry")?,
            e_prime: kw.take("e_prime")?.unwrap_or(defaults.e_prime),
        })
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

pub fn viscosity(v: Option<&str>) -> PyResult<Option<ViscosityLaw>> {
    choice(
        "viscosity",
        v,
        &[
            ("barus", ViscosityLaw::Barus),
            ("roelands", ViscosityLaw::Roelands),
        ],
    )
}

pub fn density(v: Option<&str>) -> PyResult<Option<DensityLaw>> {
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

pub fn rheology(v: Option<&str>) -> PyResult<Option<RheologyChoice>> {
    choice(
        "rheology",
        v,
        &[
            ("eyring", RheologyChoice::Eyring),
            ("newtonian", RheologyChoice::Newtonian),
            ("eyring-lss", RheologyChoice::EyringLss),
        ],
    )
}

/// `"auto"` (`None`: the case's rule decides, as when not given) or one of `names`.
fn choice_or_auto<T: Copy>(
    flag: &str,
    value: Option<&str>,
    names: &[(&str, T)],
) -> PyResult<Option<T>> {
    let mut all = vec![("auto", None)];
    all.extend(names.iter().map(|&(n, t)| (n, Some(t))));
    Ok(choice(flag, value, &all)?.flatten())
}

pub fn domain(v: Option<&str>) -> PyResult<Option<Domain>> {
    choice_or_auto(
        "domain",
        v,
        &[
            ("paper", Domain::default()),
            ("wide", Domain::wide()),
            ("heavy", Domain::heavy()),
        ],
    )
}

pub fn edge(v: Option<&str>) -> PyResult<Option<point::Edge>> {
    choice_or_auto(
        "edge",
        v,
        &[
            ("zero", point::Edge::Zero),
            ("far-field", point::Edge::FarField),
        ],
    )
}

/// `patch`: the composite grid's patches, `"inlet"`, `"lobes"` or `"inlet-and-lobes"`, or
/// `None` / `"none"` for the rule's grid.
pub fn patch(v: Option<&str>) -> PyResult<Option<Patch>> {
    Ok(choice(
        "patch",
        v,
        &[
            ("none", None),
            ("inlet", Some(Patch::Inlet)),
            ("lobes", Some(Patch::Lobes)),
            ("inlet-and-lobes", Some(Patch::InletAndLobes)),
        ],
    )?
    .flatten())
}

/// The element `i` of a broadcast input (length 1 or n).
pub fn at(a: &[f64], i: usize) -> f64 {
    if a.len() == 1 {
        a[0]
    } else {
        a[i]
    }
}

/// Named columns as a dict of numpy arrays.
pub fn columns<'py>(
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
