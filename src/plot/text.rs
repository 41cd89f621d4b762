//! Text without fonts: the `_{...}` and `^{...}` markup of figure strings turned into
//! `<tspan>`s, a width estimate that stands in for font metrics, and numbers with a few
//! significant digits.

use std::fmt::Write as _;

/// Formats `v` with `digits` significant digits, without trailing zeros ("4.93", "5", "0.012").
pub fn significant(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let mag = v.abs().log10().floor() as i32;
    let decimals = (digits - 1 - mag).max(0) as usize;
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".to_string()
    } else {
        s
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Baseline {
    Base,
    Sub,
    Sup,
}

/// Splits text into runs at `_{...}` and `^{...}` (an unclosed brace runs to the end).
pub(super) fn runs(text: &str) -> Vec<(Baseline, String)> {
    let mut out: Vec<(Baseline, String)> = vec![(Baseline::Base, String::new())];
    let mut chars = text.chars().peekable();
    let mut in_group = false;
    while let Some(c) = chars.next() {
        if !in_group && (c == '_' || c == '^') && chars.peek() == Some(&'{') {
            chars.next();
            let shift = if c == '_' {
                Baseline::Sub
            } else {
                Baseline::Sup
            };
            out.push((shift, String::new()));
            in_group = true;
        } else if in_group && c == '}' {
            out.push((Baseline::Base, String::new()));
            in_group = false;
        } else if let Some(last) = out.last_mut() {
            last.1.push(c);
        }
    }
    out.retain(|(_, s)| !s.is_empty());
    out
}

/// Estimated width in pixels of `text` (with markup) in a sans-serif font of `px` pixels.
///
/// Advance widths of DejaVu Sans rounded up a little (digits and most letters 0.6 em, spaces
/// 0.32 em, combining marks 0); sub- and superscripts at 72 %. Only the layout depends on it.
pub fn text_width(text: &str, px: f64) -> f64 {
    runs(text)
        .iter()
        .map(|(shift, s)| {
            let scale = if *shift == Baseline::Base { 1.0 } else { 0.72 };
            s.chars()
                .map(|c| match c {
                    '\u{300}'..='\u{36f}' => 0.0,
                    ' ' | '.' | ',' | ':' | ';' | 'i' | 'l' | 'j' | '|' | '\'' => 0.32,
                    '(' | ')' | '[' | ']' | 'f' | 't' | 'r' | '/' | '-' => 0.4,
                    'M' | 'W' | 'm' | 'w' | '×' | '=' | '+' | '−' => 0.84,
                    _ => 0.62,
                })
                .sum::<f64>()
                * px
                * scale
        })
        .sum()
}

/// Rewrites the markup of every `<text>` element of an SVG document into `<tspan>`s.
pub(super) fn apply_markup(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len() + svg.len() / 16);
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        out.push_str(&rest[..start]);
        rest = &rest[start..];
        let Some(open_end) = rest.find('>') else {
            break;
        };
        let Some(close) = rest[open_end..].find("</text>") else {
            break;
        };
        let tag = &rest[..=open_end];
        let content = &rest[open_end + 1..open_end + close];
        out.push_str(tag);
        out.push_str(&tspans(content, font_size(tag)));
        rest = &rest[open_end + close..];
    }
    out.push_str(rest);
    out
}

/// The `font-size` attribute of a tag, or 16.
pub(super) fn font_size(tag: &str) -> f64 {
    tag.split_once("font-size=\"")
        .and_then(|(_, after)| after.split('"').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or(16.0)
}

/// Text content (already XML-escaped) with markup turned into shifted, smaller `<tspan>`s.
pub(super) fn tspans(content: &str, px: f64) -> String {
    if !content.contains("_{") && !content.contains("^{") {
        return content.to_string();
    }
    // Baseline offsets in tenths of a pixel, so the output has one fixed decimal.
    let offset = |s: Baseline| match s {
        Baseline::Base => 0,
        Baseline::Sub => (px * 3.0).round() as i64,
        Baseline::Sup => -(px * 4.5).round() as i64,
    };
    let tenths = |t: i64| {
        let sign = if t < 0 { "-" } else { "" };
        format!("{sign}{}.{}", t.abs() / 10, t.abs() % 10)
    };
    let small = (px * 7.2).round() as i64;
    let mut out = String::new();
    let mut current = 0i64;
    for (shift, text) in runs(content) {
        let target = offset(shift);
        if shift == Baseline::Base && target == current {
            out.push_str(&text);
            continue;
        }
        out.push_str("<tspan");
        if target != current {
            let _ = write!(out, " dy=\"{}\"", tenths(target - current));
        }
        if shift != Baseline::Base {
            let _ = write!(out, " font-size=\"{}\"", tenths(small));
        }
        let _ = write!(out, ">{text}</tspan>");
        current = target;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_becomes_tspans() {
        let s = tspans("S\u{304}^{1/4} M L^{3}", 20.0);
        assert_eq!(
            s,
            "S\u{304}<tspan dy=\"-9.0\" font-size=\"14.4\">1/4</tspan>\
             <tspan dy=\"9.0\"> M L</tspan><tspan dy=\"-9.0\" font-size=\"14.4\">3</tspan>"
        );
        assert_eq!(tspans("plain_text", 20.0), "plain_text");
        // Unclosed group: runs to the end, no panic.
        assert!(tspans("a_{b", 10.0).contains(">b</tspan>"));
        assert!(text_width("τ\u{304}_{c}", 20.0) < text_width("tau_c", 20.0));
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(4.9312, 3), "4.93");
        assert_eq!(significant(5.0, 3), "5");
        assert_eq!(significant(0.012345, 3), "0.0123");
        assert_eq!(significant(123.4, 3), "123");
    }
}
