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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_fixed_width_and_negative_zero_is_zero() {
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(41.09), "4.109000e1");
        assert_eq!(opt(None), "");
    }
}
