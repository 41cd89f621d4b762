//! CSV files through the `csv` crate, in our deterministic form: floats with 7 significant
//! digits in scientific notation, `-0` written as `0`, empty cells for missing values, `\n`
//! line ends, cells quoted only where RFC 4180 needs it, files written atomically (temporary
//! file, then rename).
//!
//! A CSV is written from rows that are structs (`#[derive(Serialize, Default)]`): the header
//! is the field names, and every cell goes through one serializer (`cell.rs`), which writes
//! each float as [`num`] does, `None` as an empty cell and text as it is. A row type says
//! what its columns are; no code counts cells.

mod cell;

use cell::{cells, CellError};
use serde::{Serialize, Serializer};
use std::io::Write;
use std::path::Path;

/// A float with 7 significant digits in scientific notation (`-0` as `0`).
pub fn num(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else {
        format!("{v:.6e}")
    }
}

/// A float written with `N` decimals, for wall times (`0.068`); the one cell type a row
/// uses instead of the scientific form.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Decimals<const N: usize>(pub f64);

impl<const N: usize> Serialize for Decimals<N> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&format!("{:.*}", N, self.0))
    }
}

/// Writes `text` to `path` atomically, creating the parent folder.
pub fn write_atomic(path: &Path, text: &str) -> std::io::Result<()> {
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            std::fs::create_dir_all(dir)?;
        }
    }
    let tmp = path.with_extension("tmp");
    {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.sync_all()?;
    }
    std::fs::rename(&tmp, path)
}

/// CSV text of `rows`: the header from the fields of `R` (of its default value, so that a
/// table without rows still has its header), one line per row.
pub fn rows<R: Serialize + Default>(rows: impl IntoIterator<Item = R>) -> String {
    rows_renamed(rows, &[])
}

/// [`rows`] with columns renamed in the header: `(field, column)` pairs (a figure names its
/// x and y columns after what it plots).
pub fn rows_renamed<R: Serialize + Default>(
    rows: impl IntoIterator<Item = R>,
    renamed: &[(&str, &str)],
) -> String {
    let put = || -> Result<csv::Writer<Vec<u8>>, CellError> {
        let mut w = writer();
        let (names, _) = cells(&R::default())?;
        let header = names.iter().map(|n| {
            renamed
                .iter()
                .find(|(field, _)| field == n)
                .map_or(n.as_str(), |(_, column)| column)
        });
        w.write_record(header)?;
        for r in rows {
            let (_, row) = cells(&r)?;
            w.write_record(&row)?;
        }
        Ok(w)
    };
    finish(put())
}

/// CSV text of `header` and rows of text cells (a CSV read and written again).
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let put = || -> Result<csv::Writer<Vec<u8>>, CellError> {
        let mut w = writer();
        w.write_record(header)?;
        for r in rows {
            w.write_record(r)?;
        }
        Ok(w)
    };
    finish(put())
}

fn writer() -> csv::Writer<Vec<u8>> {
    csv::WriterBuilder::new()
        .has_headers(false)
        .terminator(csv::Terminator::Any(b'\n'))
        .from_writer(Vec::new())
}

/// The text a writer into memory holds. Writing into a `Vec` cannot fail (no I/O), and a row
/// that is not a flat struct is a bug of its type, reported in the text.
fn finish(w: Result<csv::Writer<Vec<u8>>, CellError>) -> String {
    let bytes = w.and_then(|w| w.into_inner().map_err(|e| CellError(e.to_string())));
    match bytes {
        Ok(bytes) => String::from_utf8_lossy(&bytes).into_owned(),
        Err(e) => format!("# CSV error: {e}\n"),
    }
}

/// A reader of CSV text, the header row its first record (so that it has a position too):
/// lines starting with `#` are comments, cells are trimmed, rows may have any number of cells
/// (the caller names a short row).
pub fn reader(text: &str) -> csv::Reader<&[u8]> {
    csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .flexible(true)
        .from_reader(text.as_bytes())
}

/// The line of `text` a record of its [`reader`] starts on, from 1. The reader's position is
/// where it began to read the record, before the comment and blank lines it skipped (and its
/// line count leaves comments out), so those are skipped here too.
pub fn line_of(text: &str, record: &csv::StringRecord) -> usize {
    let mut at = record
        .position()
        .map_or(0, |p| p.byte() as usize)
        .min(text.len());
    while let Some(rest) = text.get(at..) {
        let skipped = rest.starts_with('#') || rest.starts_with('\n') || rest.starts_with("\r\n");
        match rest.find('\n') {
            Some(end) if skipped => at += end + 1,
            _ => break,
        }
    }
    text[..at].matches('\n').count() + 1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_are_quoted_only_where_needed_and_read_back() {
        let rows = vec![
            vec!["1".to_string(), "Fig. 2, read".to_string()],
            vec!["".to_string(), "say \"hi\"".to_string()],
        ];
        let text = table(&["a", "b"], &rows);
        assert_eq!(text, "a,b\n1,\"Fig. 2, read\"\n,\"say \"\"hi\"\"\"\n");
        let back: Vec<Vec<String>> = reader(&text)
            .records()
            .skip(1)
            .map(|rec| rec.unwrap().iter().map(String::from).collect())
            .collect();
        assert_eq!(back, rows);
    }

    #[test]
    fn comments_blank_lines_and_positions() {
        let text = "# comment\na,b , c\n\n\"x, \"\"y\"\"\",2,\"multi\nline\"\r\nlast,1,2";
        let recs: Vec<_> = reader(text).records().map(Result::unwrap).collect();
        assert_eq!(recs.len(), 3);
        assert_eq!(recs[0], vec!["a", "b", "c"]);
        assert_eq!(line_of(text, &recs[0]), 2);
        assert_eq!(recs[1], vec!["x, \"y\"", "2", "multi\nline"]);
        assert_eq!(line_of(text, &recs[1]), 4);
        assert_eq!(recs[2], vec!["last", "1", "2"]);
        assert_eq!(line_of(text, &recs[2]), 6);
    }

    #[test]
    fn numbers_are_fixed_width_and_negative_zero_is_zero() {
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(41.09), "4.109000e1");
    }

    /// A row struct: the header from its fields (also without rows), every float through the
    /// one cell serializer, `None` empty, integers and text as they are, renamed columns.
    #[test]
    fn rows_are_structs_with_one_number_format() {
        #[derive(Serialize, Default)]
        struct Row {
            name: &'static str,
            level: u32,
            x: f64,
            y: Option<f64>,
            seconds: Decimals<3>,
        }
        let text = rows([
            Row {
                name: "a, b",
                level: 7,
                x: -0.0,
                y: None,
                seconds: Decimals(0.0684),
            },
            Row {
                x: 41.09,
                y: Some(2.5e-7),
                ..Row::default()
            },
        ]);
        assert_eq!(
            text,
            "name,level,x,y,seconds\n\"a, b\",7,0,,0.068\n,0,4.109000e1,2.500000e-7,0.000\n"
        );
        assert_eq!(rows(Vec::<Row>::new()), "name,level,x,y,seconds\n");
        let renamed = rows_renamed(Vec::<Row>::new(), &[("x", "tau_c_x")]);
        assert_eq!(renamed, "name,level,tau_c_x,y,seconds\n");
    }

    #[test]
    fn a_row_that_is_not_a_flat_struct_is_reported() {
        #[derive(Serialize, Default)]
        struct Nested {
            v: Vec<f64>,
        }
        let text = rows([Nested { v: vec![1.0] }]);
        assert!(text.starts_with("# CSV error"), "{text}");
    }
}
