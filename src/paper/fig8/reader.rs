//! Measured traction data files (`cases/fig8/*.csv`, format in `docs/measured-data.md`): one
//! row per measured point, parsed into [`OperatingPoint`]s and transformed by Sec. IV
//! ([`crate::physics::traction`]) to `(tau_c, mu-bar)`. Every error names the file, the row
//! and the column.

use crate::physics::case::{CaseError, LubricantSpec};
use crate::physics::lubricant::{LubricantError, LubricantTable};
use crate::physics::traction::{
    reduce, Contact, FilmFormula, Load, OperatingPoint, Reduced, Sliding, Speed, ViscosityAtPh,
};
use crate::physics::viscosity::ViscosityLaw;
use crate::pipeline::csv::{line_of, reader};
use std::path::Path;

/// Every column of the format, in the order of `docs/measured-data.md`.
pub const COLUMNS: &[&str] = &[
    "series",
    "source",
    "contact",
    "rx_m",
    "ry_m",
    "e_prime_pa",
    "ph_pa",
    "load_n",
    "load_per_length_n_m",
    "temperature_c",
    "um_m_s",
    "us_m_s",
    "slip",
    "shear_rate_per_s",
    "shear_rate_film_m",
    "mu",
    "tau0_pa",
    "lubricant",
    "alpha_per_pa",
    "eta0_pa_s",
    "viscosity_law",
    "eta_ph_pa_s",
    "film_formula",
];

/// A measured-data file that cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MeasuredError {
    /// The file or folder could not be read.
    #[error("{file}: cannot read: {message}")]
    Io {
        /// File or folder.
        file: String,
        /// OS message.
        message: String,
    },
    /// The header is unusable.
    #[error("{file}: header (line {line}): {message}")]
    Header {
        /// File.
        file: String,
        /// Line of the header.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A cell is missing, malformed or out of range, or the row's transform failed on it.
    #[error("{file}: row {row} (line {line}): {column}: {message}")]
    Field {
        /// File.
        file: String,
        /// Data row, from 1.
        row: usize,
        /// Line the row starts on.
        line: usize,
        /// Column.
        column: String,
        /// What is expected.
        message: String,
    },
}

/// One measured point of a file.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredRow {
    /// Data row, from 1.
    pub row: usize,
    /// Line the row starts on.
    pub line: usize,
    /// Legend label (the file's stem when the `series` cell is empty or absent).
    pub series: String,
    /// Publication, figure and how the values were read.
    pub source: String,
    /// The test temperature, C (the lubricant's `alpha` and `eta0` are at this temperature).
    pub temperature_c: f64,
    /// Operating conditions.
    pub point: OperatingPoint,
    /// Measured friction coefficient.
    pub mu: f64,
}

/// A measured-data file.
#[derive(Debug, Clone, PartialEq)]
pub struct Dataset {
    /// File name as given (errors and output name it).
    pub file: String,
    /// Its rows.
    pub rows: Vec<MeasuredRow>,
}

/// A row transformed to the paper's parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedRow {
    /// The dataset's file name (without its folder).
    pub dataset: String,
    /// The row.
    pub row: MeasuredRow,
    /// `tau_c`, `mu-bar` and the groups.
    pub reduced: Reduced,
}

struct Cells<'a> {
    file: &'a str,
    row: usize,
    line: usize,
    header: &'a [String],
    cells: &'a [String],
}

impl Cells<'_> {
    fn err(&self, column: &str, message: impl Into<String>) -> MeasuredError {
        MeasuredError::Field {
            file: self.file.to_string(),
            row: self.row,
            line: self.line,
            column: column.to_string(),
            message: message.into(),
        }
    }

    fn text(&self, column: &str) -> Option<&str> {
        self.header
            .iter()
            .position(|h| h == column)
            .map(|i| self.cells[i].as_str())
            .filter(|s| !s.is_empty())
    }

    fn number(&self, column: &str) -> Result<Option<f64>, MeasuredError> {
        match self.text(column) {
            None => Ok(None),
            Some(s) => match s.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(Some(v)),
                _ => Err(self.err(column, format!("expected a finite number, found '{s}'"))),
            },
        }
    }

    fn required(&self, column: &str) -> Result<f64, MeasuredError> {
        self.number(column)?
            .ok_or_else(|| self.err(column, "required"))
    }

    /// Exactly one of two alternatives.
    fn one_of(&self, a: &str, b: &str) -> Result<(bool, f64), MeasuredError> {
        match (self.number(a)?, self.number(b)?) {
            (Some(v), None) => Ok((true, v)),
            (None, Some(v)) => Ok((false, v)),
            (Some(_), Some(_)) => Err(self.err(a, format!("give {a} or {b}, not both"))),
            (None, None) => Err(self.err(a, format!("required (or {b})"))),
        }
    }
}

/// Parses the text of a measured-data file; `file` names it in errors.
pub fn parse(file: &str, text: &str) -> Result<Dataset, MeasuredError> {
    let mut recs = reader(text).into_records();
    let unreadable = |e: csv::Error| MeasuredError::Header {
        file: file.into(),
        line: e.position().map_or(0, |p| p.line() as usize),
        message: e.to_string(),
    };
    let head = match recs.next() {
        Some(r) => r.map_err(unreadable)?,
        None => {
            return Err(MeasuredError::Header {
                file: file.into(),
                line: 1,
                message: "the file has no header row".into(),
            })
        }
    };
    let header: Vec<String> = head.iter().map(String::from).collect();
    let header_err = |message: String| MeasuredError::Header {
        file: file.into(),
        line: line_of(text, &head),
        message,
    };
    for (i, h) in header.iter().enumerate() {
        if !COLUMNS.contains(&h.as_str()) {
            return Err(header_err(format!(
                "unknown column '{h}' (known: {})",
                COLUMNS.join(", ")
            )));
        }
        if header[..i].contains(h) {
            return Err(header_err(format!("column '{h}' appears twice")));
        }
    }
    for must in [
        "source",
        "contact",
        "rx_m",
        "e_prime_pa",
        "temperature_c",
        "mu",
        "tau0_pa",
        "film_formula",
    ] {
        if !header.iter().any(|h| h == must) {
            return Err(header_err(format!("missing column '{must}'")));
        }
    }
    let stem = Path::new(file)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| file.to_string());
    let mut rows = Vec::new();
    for (k, rec) in recs.enumerate() {
        let rec = rec.map_err(unreadable)?;
        let cells: Vec<String> = rec.iter().map(String::from).collect();
        let c = Cells {
            file,
            row: k + 1,
            line: line_of(text, &rec),
            header: &header,
            cells: &cells,
        };
        if cells.len() != header.len() {
            return Err(c.err(
                "(row)",
                format!(
                    "expected {} cells as in the header, found {}",
                    header.len(),
                    cells.len()
                ),
            ));
        }
        rows.push(parse_row(&c, &stem)?);
    }
    Ok(Dataset {
        file: file.to_string(),
        rows,
    })
}

fn parse_row(c: &Cells, stem: &str) -> Result<MeasuredRow, MeasuredError> {
    let source = c
        .text("source")
        .ok_or_else(|| c.err("source", "required: the publication, figure and how the values were read (only measured data with a stated source may be used)"))?
        .to_string();
    let rx_m = c.required("rx_m")?;
    let contact = match c.text("contact") {
        Some("elliptical") => Contact::Elliptical {
            rx_m,
            ry_m: c.number("ry_m")?.unwrap_or(rx_m),
        },
        Some("line") => {
            if c.text("ry_m").is_some() {
                return Err(c.err("ry_m", "a line contact has no Ry; leave it empty"));
            }
            Contact::Line { rx_m }
        }
        other => {
            return Err(c.err(
                "contact",
                format!(
                    "expected 'elliptical' or 'line', found '{}'",
                    other.unwrap_or("")
                ),
            ))
        }
    };
    let loads = [
        ("ph_pa", c.number("ph_pa")?.map(Load::MaxPressure)),
        ("load_n", c.number("load_n")?.map(Load::Force)),
        (
            "load_per_length_n_m",
            c.number("load_per_length_n_m")?.map(Load::PerLength),
        ),
    ];
    let given: Vec<_> = loads
        .iter()
        .filter_map(|(n, l)| l.map(|l| (*n, l)))
        .collect();
    let load = match given.as_slice() {
        [(_, l)] => *l,
        [] => return Err(c.err("ph_pa", "required (or load_n, or load_per_length_n_m)")),
        _ => {
            return Err(c.err(
                given[1].0,
                format!(
                    "give one of ph_pa, load_n, load_per_length_n_m, not {} and {}",
                    given[0].0, given[1].0
                ),
            ))
        }
    };
    let speed = match c.one_of("um_m_s", "us_m_s")? {
        (true, v) => Speed::Mean(v),
        (false, v) => Speed::Sum(v),
    };
    let film_m = c.number("shear_rate_film_m")?;
    let sliding = match c.one_of("slip", "shear_rate_per_s")? {
        (true, v) => {
            if film_m.is_some() {
                return Err(c.err("shear_rate_film_m", "only with shear_rate_per_s"));
            }
            Sliding::Slip(v)
        }
        (false, v) => Sliding::ShearRate { per_s: v, film_m },
    };
    let temperature_c = c.required("temperature_c")?;
    let lubricant = match (
        c.text("lubricant"),
        c.number("alpha_per_pa")?,
        c.number("eta0_pa_s")?,
    ) {
        (Some(name), None, None) => LubricantSpec::Named {
            lubricant: name.to_string(),
            temperature_c,
        },
        (None, Some(alpha_per_pa), Some(eta0_pa_s)) => LubricantSpec::Given {
            alpha_per_pa,
            eta0_pa_s,
        },
        (Some(_), _, _) => {
            return Err(c.err(
                "lubricant",
                "give a lubricant name or alpha_per_pa and eta0_pa_s, not both",
            ))
        }
        (None, None, _) => return Err(c.err("alpha_per_pa", "required (or lubricant)")),
        (None, _, None) => return Err(c.err("eta0_pa_s", "required with alpha_per_pa")),
    };
    let viscosity = match (c.text("viscosity_law"), c.number("eta_ph_pa_s")?) {
        (Some("barus"), None) => ViscosityAtPh::Law(ViscosityLaw::Barus),
        (Some("roelands"), None) => ViscosityAtPh::Law(ViscosityLaw::Roelands),
        (None, Some(eta)) => ViscosityAtPh::Given(eta),
        (Some(law), None) => {
            return Err(c.err(
                "viscosity_law",
                format!("expected 'barus' or 'roelands', found '{law}'"),
            ))
        }
        (Some(_), Some(_)) => {
            return Err(c.err(
                "viscosity_law",
                "give viscosity_law or eta_ph_pa_s, not both",
            ))
        }
        (None, None) => return Err(c.err("viscosity_law", "required (or eta_ph_pa_s)")),
    };
    let film_name = c.text("film_formula").unwrap_or("");
    let film = FilmFormula::from_name(film_name).ok_or_else(|| {
        c.err(
            "film_formula",
            format!("expected eq10 (elliptical), dowson-higginson, moes or dowson-toyoda (line), found '{film_name}'"),
        )
    })?;
    let point = OperatingPoint {
        contact,
        e_prime_pa: c.required("e_prime_pa")?,
        load,
        lubricant,
        speed,
        sliding,
        tau0_pa: c.required("tau0_pa")?,
        viscosity,
        film,
    };
    Ok(MeasuredRow {
        row: c.row,
        line: c.line,
        series: c.text("series").unwrap_or(stem).to_string(),
        source,
        temperature_c,
        point,
        mu: c.required("mu")?,
    })
}

/// The column a transform error is about, in the row's own terms.
fn column_of(field: &str, p: &OperatingPoint) -> &'static str {
    let load = match p.load {
        Load::MaxPressure(_) => "ph_pa",
        Load::Force(_) => "load_n",
        Load::PerLength(_) => "load_per_length_n_m",
    };
    match field {
        "ph" | "load" => load,
        "um" => match p.speed {
            Speed::Mean(_) => "um_m_s",
            Speed::Sum(_) => "us_m_s",
        },
        "slip" => match p.sliding {
            Sliding::Slip(_) => "slip",
            Sliding::ShearRate { .. } => "shear_rate_per_s",
        },
        "shear-rate" => "shear_rate_per_s",
        "shear-rate-film" => "shear_rate_film_m",
        "tau0" => "tau0_pa",
        "rx" => "rx_m",
        "ry" => "ry_m",
        "e-prime" => "e_prime_pa",
        "eta-ph" => "eta_ph_pa_s",
        "film" => "film_formula",
        "alpha" => "alpha_per_pa",
        "eta0" => "eta0_pa_s",
        "mu" => "mu",
        _ => "(row)",
    }
}

/// Transforms every row of a dataset (Sec. IV); the first row that fails names itself.
pub fn transform(data: &Dataset, lubs: &LubricantTable) -> Result<Vec<ReducedRow>, MeasuredError> {
    data.rows
        .iter()
        .map(|r| {
            let err = |column: &str, message: String| MeasuredError::Field {
                file: data.file.clone(),
                row: r.row,
                line: r.line,
                column: column.to_string(),
                message,
            };
            reduce(&r.point, r.mu, lubs)
                .map(|reduced| ReducedRow {
                    dataset: Path::new(&data.file)
                        .file_name()
                        .map(|n| n.to_string_lossy().into_owned())
                        .unwrap_or_else(|| data.file.clone()),
                    row: r.clone(),
                    reduced,
                })
                .map_err(|e| match e {
                    CaseError::Field { field, message } => err(column_of(field, &r.point), message),
                    CaseError::Lubricant(l @ LubricantError::Temperature { .. }) => {
                        err("temperature_c", l.to_string())
                    }
                    CaseError::Lubricant(l) => err("lubricant", l.to_string()),
                    // The measured-data files give no datasheet; the column is the key.
                    CaseError::Datasheet(d) => err(d.field(), d.to_string()),
                })
        })
        .collect()
}

/// Reads and parses one file.
pub fn read(path: &Path) -> Result<Dataset, MeasuredError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| MeasuredError::Io {
        file: file.clone(),
        message: e.to_string(),
    })?;
    parse(&file, &text)
}

/// Every `*.csv` of a folder, by file name (so the order is the same on any machine). A
/// folder that does not exist holds no dataset.
pub fn read_folder(dir: &Path) -> Result<Vec<Dataset>, MeasuredError> {
    if !dir.is_dir() {
        return Ok(Vec::new());
    }
    let io = |e: std::io::Error| MeasuredError::Io {
        file: dir.display().to_string(),
        message: e.to_string(),
    };
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .map_err(io)?
        .collect::<Result<Vec<_>, _>>()
        .map_err(io)?
        .into_iter()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "csv"))
        .collect();
    paths.sort();
    paths.iter().map(|p| read(p)).collect()
}

#[cfg(test)]
#[path = "reader_tests.rs"]
mod tests;
