//! Deterministic CSV text: fixed significant digits, `-0` written as `0`, empty cells for
//! missing values, written atomically (temporary file, then rename).

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

/// Joins cells into CSV lines (no cell of ours needs quoting; commas are refused).
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut out = header.join(",");
    out.push('\n');
    for r in rows {
        debug_assert!(r.iter().all(|c| !c.contains(',')));
        out.push_str(&r.join(","));
        out.push('\n');
    }
    out
}

/// A cell quoted as RFC 4180 wants when it holds a comma, a double quote or a line break
/// (free text such as a measured dataset's `source`); other cells unchanged.
pub fn quote(cell: &str) -> String {
    if cell.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", cell.replace('"', "\"\""))
    } else {
        cell.to_string()
    }
}

/// One record of a CSV text: its cells and the line it starts on (1-based).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Record {
    /// Line number of the record's first character.
    pub line: usize,
    /// Cells, unquoted, surrounding spaces of unquoted cells trimmed.
    pub cells: Vec<String>,
}

/// Splits CSV text into records (RFC 4180: cells in double quotes may hold commas, line
/// breaks and doubled quotes). Blank lines and lines starting with `#` are comments. An
/// unterminated quote is an error naming the line it opened on.
pub fn records(text: &str) -> Result<Vec<Record>, String> {
    let mut out = Vec::new();
    let mut chars = text.chars().peekable();
    let mut line = 1;
    let mut at_line_start = true;
    let mut cells: Vec<String> = Vec::new();
    let mut cell = String::new();
    let mut quoted = false;
    let mut start = 1;
    while let Some(c) = chars.next() {
        if at_line_start {
            at_line_start = false;
            start = line;
            if c == '#' || c == '\n' || (c == '\r' && chars.peek() == Some(&'\n')) {
                // A comment or blank line: skip to its end.
                let mut c = c;
                while c != '\n' {
                    match chars.next() {
                        Some(n) => c = n,
                        None => break,
                    }
                }
                line += 1;
                at_line_start = true;
                continue;
            }
        }
        match c {
            '"' if cell.trim().is_empty() && !quoted => {
                cell.clear();
                quoted = true;
                let open = line;
                loop {
                    match chars.next() {
                        Some('"') if chars.peek() == Some(&'"') => {
                            chars.next();
                            cell.push('"');
                        }
                        Some('"') => break,
                        Some(ch) => {
                            if ch == '\n' {
                                line += 1;
                            }
                            cell.push(ch);
                        }
                        None => return Err(format!("line {open}: unterminated quoted cell")),
                    }
                }
            }
            ',' => {
                cells.push(finish(&mut cell, &mut quoted));
            }
            '\n' => {
                cells.push(finish(&mut cell, &mut quoted));
                out.push(Record {
                    line: start,
                    cells: std::mem::take(&mut cells),
                });
                line += 1;
                at_line_start = true;
            }
            '\r' if chars.peek() == Some(&'\n') => {}
            other => cell.push(other),
        }
    }
    if !at_line_start {
        cells.push(finish(&mut cell, &mut quoted));
        out.push(Record { line: start, cells });
    }
    Ok(out)
}

fn finish(cell: &mut String, quoted: &mut bool) -> String {
    let c = std::mem::take(cell);
    let was_quoted = std::mem::replace(quoted, false);
    if was_quoted {
        c
    } else {
        c.trim().to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_unquote_and_skip_comments() {
        let text = "# comment\na,b , c\n\n\"x, \"\"y\"\"\",2,\"multi\nline\"\r\nlast,1,2";
        let r = records(text).unwrap();
        assert_eq!(r.len(), 3);
        assert_eq!(
            r[0],
            Record {
                line: 2,
                cells: vec!["a".into(), "b".into(), "c".into()]
            }
        );
        assert_eq!(r[1].line, 4);
        assert_eq!(r[1].cells, vec!["x, \"y\"", "2", "multi\nline"]);
        assert_eq!(r[2].line, 6);
        assert_eq!(r[2].cells, vec!["last", "1", "2"]);
        let e = records("a\n\"open,1\n").unwrap_err();
        assert!(e.contains("line 2"), "{e}");
        assert_eq!(quote("Fig. 2, read"), "\"Fig. 2, read\"");
        assert_eq!(
            records(&format!("{}\n", quote("say \"hi\", ok"))).unwrap()[0].cells,
            vec!["say \"hi\", ok"]
        );
    }

    #[test]
    fn numbers_are_fixed_width_and_negative_zero_is_zero() {
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(41.09), "4.109000e1");
        assert_eq!(opt(None), "");
    }
}
