//! HTML pieces of the report: escaping, and tables that show numbers as a reader wants them
//! (four significant digits, `40` rather than `4.000000e1`, powers of ten as superscripts,
//! units from the column names) while the CSVs keep full precision.

use crate::pipeline::csv::reader;
use crate::plot::significant;

/// Escapes text for HTML element content and attribute values.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// A number with four significant digits, as HTML: plain between 0.001 and 100 000 (trailing
/// zeros dropped: `40`, `0.005`, `41.13`), `3.075×10<sup>18</sup>` otherwise.
pub fn human(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v == 0.0 { "0".into() } else { v.to_string() };
    }
    if (1e-3..1e5).contains(&v.abs()) {
        significant(v, 4)
    } else {
        let s = format!("{v:.3e}");
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        format!("{mantissa}×10<sup>{exp}</sup>")
    }
}

/// A cell of a CSV as HTML: a number in [`human`] form, a range `a-b` or a list `a/b/c` of
/// numbers likewise (Table 2), anything else escaped.
fn cell(text: &str) -> String {
    // A '-' after a digit separates a range (after an 'e' it is an exponent's sign).
    let range_at = text
        .char_indices()
        .skip(1)
        .find(|&(i, c)| c == '-' && text[..i].ends_with(|p: char| p.is_ascii_digit()))
        .map(|(i, _)| i);
    if let Some(i) = range_at {
        let (a, b) = (&text[..i], &text[i + 1..]);
        if a.parse::<f64>().is_ok() && b.parse::<f64>().is_ok() {
            return format!("{}&ndash;{}", number(a), number(b));
        }
    }
    if text.contains('/') && text.split('/').all(|p| p.parse::<f64>().is_ok()) {
        return text.split('/').map(number).collect::<Vec<_>>().join("/");
    }
    number(text)
}

/// A single number in [`human`] form, anything else escaped.
fn number(text: &str) -> String {
    let looks_numeric = text
        .chars()
        .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'));
    match text.parse::<f64>() {
        Ok(v) if looks_numeric && !text.is_empty() => human(v),
        _ => escape(text),
    }
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
fn heading(name: &str) -> String {
    if name == "temperature_c" {
        return "temperature (°C)".into();
    }
    let text = UNITS
        .iter()
        .find_map(|(suffix, unit)| {
            name.strip_suffix(suffix)
                .filter(|stem| !stem.is_empty())
                .map(|stem| format!("{} ({unit})", stem.replace('_', " ")))
        })
        .unwrap_or_else(|| name.replace('_', " "));
    escape(&text)
}

/// A CSV as an HTML table that scrolls sideways when wide, at most `max_rows` rows, the rest
/// counted below it.
pub fn csv_table(csv: &str, max_rows: usize) -> String {
    let mut rows = reader(csv).into_records().filter_map(Result::ok);
    let Some(header) = rows.next() else {
        return String::new();
    };
    let head: String = header
        .iter()
        .map(|c| format!("<th>{}</th>", heading(c)))
        .collect();
    let mut out = format!("<div class=\"scroll\"><table>\n<tr>{head}</tr>\n");
    let rows: Vec<csv::StringRecord> = rows.collect();
    for row in rows.iter().take(max_rows) {
        let cells: String = row
            .iter()
            .map(|c| format!("<td>{}</td>", cell(c)))
            .collect();
        out.push_str(&format!("<tr>{cells}</tr>\n"));
    }
    out.push_str("</table></div>\n");
    if rows.len() > max_rows {
        out.push_str(&format!(
            "<p class=\"note\">{} more rows in the CSV.</p>\n",
            rows.len() - max_rows
        ));
    }
    out
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
        assert_eq!(cell("64x64"), "64x64");
        assert_eq!(cell("ok-film-nonpositive"), "ok-film-nonpositive");
        assert_eq!(cell("4.000000e1"), "40");
        assert_eq!(cell("e"), "e");
        assert_eq!(cell("1.000000e0-3.000000e0"), "1&ndash;3");
        assert_eq!(cell("2.1e-5"), "2.100×10<sup>-5</sup>");
        assert_eq!(cell("40/60/100"), "40/60/100");
        assert_eq!(cell("mineral-oil-a"), "mineral-oil-a");
    }

    #[test]
    fn long_tables_are_cut_with_a_count_and_scroll() {
        let csv = std::iter::once("x".to_string())
            .chain((0..40).map(|i| i.to_string()))
            .collect::<Vec<_>>()
            .join("\n");
        let t = csv_table(&csv, 30);
        assert_eq!(t.matches("<tr>").count(), 31);
        assert!(t.contains("10 more rows") && t.starts_with("<div class=\"scroll\">"));
    }
}
