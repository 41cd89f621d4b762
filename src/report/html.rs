//! Pieces of the report page as data the template renders: numbers as a reader wants them
//! (four significant digits, `40` rather than `4.000000e1`, powers of ten as superscripts)
//! and a CSV as a table with units spelled out in its headings, while the CSVs keep full
//! precision.

use crate::pipeline::csv::reader;
use crate::plot::significant;
use std::fmt;

/// A number as the page shows it: four significant digits, plain between 0.001 and 100 000
/// (trailing zeros dropped: `40`, `0.005`, `41.13`), `3.075×10<sup>18</sup>` otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if v == 0.0 {
            return f.write_str("0");
        }
        if !v.is_finite() {
            return write!(f, "{v}");
        }
        if (1e-3..1e5).contains(&v.abs()) {
            return f.write_str(&significant(v, 4));
        }
        let s = format!("{v:.3e}");
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        write!(f, "{mantissa}×10<sup>{exp}</sup>")
    }
}

/// Its text is digits, a sign, a point, `×10` and a `<sup>` of its own: nothing to escape.
impl askama::filters::HtmlSafe for Num {}

/// `v` as a percentage, [`Num`]'s digits.
pub fn percent(v: f64) -> Num {
    Num(100.0 * v)
}

/// `v` in [`Num`] form, as its HTML text.
pub fn human(v: f64) -> String {
    Num(v).to_string()
}

/// A cell of a CSV: a number, a range `a-b` or a list `a/b/c` of numbers (Table 2), or text.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// Text, shown as it is (escaped by the template).
    Text(String),
    /// A number.
    Num(Num),
    /// A range of two numbers.
    Range(Num, Num),
    /// Numbers separated by `/`.
    List(Vec<Num>),
}

impl Cell {
    /// The cell of a CSV field.
    pub fn of(text: &str) -> Cell {
        // A '-' after a digit separates a range (after an 'e' it is an exponent's sign).
        let range_at = text
            .char_indices()
            .skip(1)
            .find(|&(i, c)| c == '-' && text[..i].ends_with(|p: char| p.is_ascii_digit()))
            .map(|(i, _)| i);
        if let Some(i) = range_at {
            if let (Some(a), Some(b)) = (number(&text[..i]), number(&text[i + 1..])) {
                return Cell::Range(a, b);
            }
        }
        if text.contains('/') {
            if let Some(list) = text.split('/').map(number).collect::<Option<Vec<_>>>() {
                return Cell::List(list);
            }
        }
        number(text).map_or_else(|| Cell::Text(text.to_string()), Cell::Num)
    }
}

/// A field that is a number written as a number (not `inf`, `NaN` or a word that parses).
fn number(text: &str) -> Option<Num> {
    let looks_numeric = !text.is_empty()
        && text
            .chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'));
    looks_numeric
        .then(|| text.parse::<f64>().ok().map(Num))
        .flatten()
}

/// Unit suffixes of our column names and how a reader writes them (longest first where one
/// ends another).
const UNITS: [(&str, &str); 6] = [
    ("_per_gpa", "1/GPa"),
    ("_mpa_s", "mPa s"),
    ("_mpa", "MPa"),
    ("_gpa", "GPa"),
    ("_m_s", "m/s"),
    ("_percent", "%"),
];

/// A column name as a heading: the unit suffix spelled out, underscores as spaces.
pub fn heading(name: &str) -> String {
    if name == "temperature_c" {
        return "temperature (°C)".into();
    }
    UNITS
        .iter()
        .find_map(|(suffix, unit)| {
            name.strip_suffix(suffix)
                .filter(|stem| !stem.is_empty())
                .map(|stem| format!("{} ({unit})", stem.replace('_', " ")))
        })
        .unwrap_or_else(|| name.replace('_', " "))
}

/// A CSV as the page shows it: its headings, at most `max_rows` rows, and how many more the
/// file has.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Column headings ([`heading`]).
    pub head: Vec<String>,
    /// Rows shown.
    pub rows: Vec<Vec<Cell>>,
    /// Rows of the file not shown.
    pub more: usize,
}

impl Table {
    /// The table of `csv`, cut after `max_rows` rows; `None` for a file without a header.
    pub fn of_csv(csv: &str, max_rows: usize) -> Option<Table> {
        let mut records = reader(csv).into_records().filter_map(Result::ok);
        let head = records.next()?.iter().map(heading).collect();
        let all: Vec<csv::StringRecord> = records.collect();
        Some(Table {
            head,
            rows: all
                .iter()
                .take(max_rows)
                .map(|r| r.iter().map(Cell::of).collect())
                .collect(),
            more: all.len().saturating_sub(max_rows),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_as_a_person_writes_them() {
        assert_eq!(human(4.0e1), "40");
        assert_eq!(human(3.0), "3");
        assert_eq!(human(1.2e1), "12");
        assert_eq!(human(5.0e-3), "0.005");
        assert_eq!(human(4.112994e1), "41.13");
        assert_eq!(human(1738.8318), "1739");
        assert_eq!(human(-0.0123456), "-0.01235");
        assert_eq!(human(3.074899e18), "3.075×10<sup>18</sup>");
        assert_eq!(human(2.1e-5), "2.100×10<sup>-5</sup>");
        assert_eq!(human(0.0), "0");
        assert_eq!(percent(0.0421).to_string(), "4.21");
    }

    #[test]
    fn headings_spell_units_and_cells_keep_text() {
        assert_eq!(heading("temperature_c"), "temperature (°C)");
        assert_eq!(heading("ph_gpa"), "ph (GPa)");
        assert_eq!(heading("um_m_s"), "um (m/s)");
        assert_eq!(heading("eta0_mpa_s"), "eta0 (mPa s)");
        assert_eq!(heading("alpha_per_gpa"), "alpha (1/GPa)");
        assert_eq!(heading("mu_bar_sliding"), "mu bar sliding");
        assert_eq!(heading("slip_percent"), "slip (%)");
        assert_eq!(heading("tau_c"), "tau c");
        let text = |s: &str| Cell::Text(s.to_string());
        assert_eq!(Cell::of("64x64"), text("64x64"));
        assert_eq!(Cell::of("ok-film-nonpositive"), text("ok-film-nonpositive"));
        assert_eq!(Cell::of("4.000000e1"), Cell::Num(Num(40.0)));
        assert_eq!(Cell::of("e"), text("e"));
        assert_eq!(Cell::of("inf"), text("inf"));
        assert_eq!(
            Cell::of("1.000000e0-3.000000e0"),
            Cell::Range(Num(1.0), Num(3.0))
        );
        assert_eq!(Cell::of("2.1e-5"), Cell::Num(Num(2.1e-5)));
        assert_eq!(
            Cell::of("40/60/100"),
            Cell::List(vec![Num(40.0), Num(60.0), Num(100.0)])
        );
        assert_eq!(Cell::of("mineral-oil-a"), text("mineral-oil-a"));
    }

    #[test]
    fn long_tables_are_cut_with_a_count() {
        let csv = std::iter::once("x".to_string())
            .chain((0..40).map(|i| i.to_string()))
            .collect::<Vec<_>>()
            .join("\n");
        let t = Table::of_csv(&csv, 30).unwrap();
        assert_eq!((t.rows.len(), t.more), (30, 10));
        assert_eq!(t.head, vec!["x".to_string()]);
    }
}
