//! CSV files through the `csv` crate, in our deterministic form: floats with 7 significant
//! digits in scientific notation, `-0` written as `0`, empty cells for missing values, `\n`
//! line ends, cells quoted only where RFC 4180 needs it, files written atomically (temporary
//! file, then rename).

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

/// An optional float: empty when absent.
pub fn opt(v: Option<f64>) -> String {
    v.map(num).unwrap_or_default()
}

/// `#[serde(serialize_with = "sci")]`: a float field as [`num`] writes it.
pub fn sci<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&num(*v))
}

/// `#[serde(serialize_with = "sci_opt")]`: an optional float field as [`opt`] writes it.
pub fn sci_opt<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&opt(*v))
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

/// CSV text of `header` and `rows`, each row anything that serialises as a sequence of cells
/// (a `Vec<String>`, an array of them).
pub fn table<R: Serialize>(header: &[&str], rows: impl IntoIterator<Item = R>) -> String {
    let mut w = writer(false);
    let put = || -> Result<(), csv::Error> {
        w.write_record(header)?;
        for r in rows {
            w.serialize(r)?;
        }
        Ok(())
    };
    finish(put().map(|_| w))
}

/// CSV text of serde records (structs): the header from the field names, one row each.
pub fn records<R: Serialize>(rows: impl IntoIterator<Item = R>) -> String {
    let mut w = writer(true);
    let put = || -> Result<(), csv::Error> {
        for r in rows {
            w.serialize(r)?;
        }
        Ok(())
    };
    finish(put().map(|_| w))
}

fn writer(has_headers: bool) -> csv::Writer<Vec<u8>> {
    csv::WriterBuilder::new()
        .has_headers(has_headers)
        .terminator(csv::Terminator::Any(b'\n'))
        .from_writer(Vec::new())
}

/// The text a writer into memory holds. Writing strings and numbers into a `Vec` cannot fail
/// (no I/O; our rows are flat), so a failure is a bug of the row type, reported in the text.
fn finish(w: Result<csv::Writer<Vec<u8>>, csv::Error>) -> String {
    match w.and_then(|w| w.into_inner().map_err(|e| e.into_error().into())) {
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
        assert_eq!(opt(None), "");
        #[derive(Serialize)]
        struct Row {
            name: &'static str,
            #[serde(serialize_with = "sci")]
            x: f64,
            #[serde(serialize_with = "sci_opt")]
            y: Option<f64>,
        }
        let text = records([Row {
            name: "a",
            x: -0.0,
            y: None,
        }]);
        assert_eq!(text, "name,x,y\na,0,\n");
    }
}
