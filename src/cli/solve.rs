//! `repro solve`: one elliptical contact (multigrid) or, with `--line`, one line contact
//! (Newton), printed as a summary or as one JSON object with the same keys. The solve and its
//! report are the library's ([`repro::report::solve`]), shared with the Python package.

use super::args::SolveArgs;
use super::print::{print_failure, solve_progress};
use anyhow::{Context as _, Result};
use repro::physics::case::Case;
use repro::pipeline::csv::{rows, write_atomic};
use repro::pipeline::label::case_label;
use repro::report::solve::{self, SolveFailure, Solved};
use serde::Serialize;
use std::path::Path;

/// `repro solve`: false when the solve failed (after printing why).
pub fn run(args: &SolveArgs) -> Result<bool> {
    let mut printer = solve_progress(args.quiet);
    let quiet = args.quiet || args.json;
    let mut said = |b: &Case, level: u32| {
        if !quiet {
            eprintln!("solving its base first: {}", case_label(b, level));
        }
    };
    let solved = match solve::solve(&args.inputs(), &mut said, Some(&mut printer)) {
        Ok(s) => s,
        Err(SolveFailure::Solve(e)) => {
            print_failure(&e);
            return Ok(false);
        }
        Err(e) => return Err(e.into()),
    };
    if let Some(path) = &args.fields {
        write_fields(path, &fields_csv(&solved))?;
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&solved.json())?);
    } else {
        let (text, warning) = solved.text();
        print!("{text}");
        if let Some(w) = warning {
            eprintln!("warning: {w}");
        }
    }
    Ok(true)
}

/// A node of the point contact's fields (`--fields`).
#[derive(Default, Serialize)]
#[serde(rename_all = "UPPERCASE")]
struct PointNode {
    x: f64,
    y: f64,
    p: f64,
    h: f64,
}

/// A node of the line contact's fields (`--fields`).
#[derive(Default, Serialize)]
#[serde(rename_all = "UPPERCASE")]
struct LineNode {
    x: f64,
    p: f64,
    h: f64,
}

/// The pressure and film fields (`--fields`), one row per node.
fn fields_csv(solved: &Solved) -> String {
    match solved {
        Solved::Point(p) => {
            let s = &p.solution;
            let (g, p, h) = (&s.grid, &s.p, &s.h);
            let nodes = (0..g.py()).flat_map(|j| {
                (0..g.px()).map(move |i| {
                    let k = g.idx(i, j);
                    PointNode {
                        x: g.x(i),
                        y: g.y(j),
                        p: p[k],
                        h: h[k],
                    }
                })
            });
            rows(nodes)
        }
        Solved::Line(l) => {
            let s = &l.solution;
            let nodes = s.x.iter().zip(&s.p).zip(&s.h).map(|((x, p), h)| LineNode {
                x: *x,
                p: *p,
                h: *h,
            });
            rows(nodes)
        }
    }
}

/// Writes the pressure and film fields (`--fields`).
fn write_fields(path: &Path, text: &str) -> Result<()> {
    write_atomic(path, text).with_context(|| format!("--fields: cannot write {}", path.display()))
}
