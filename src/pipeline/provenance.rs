//! Provenance sidecars: beside every target's CSV, `<target>.provenance.json` says what made
//! it: the crate version, the solver revisions, the level and solver parameters, and for each
//! row its case's cache key and the stamp of the entry (the git revision and host of the
//! build that solved it, and its wall time).
//!
//! The sidecar is a function of the cache entries it was assembled from, nothing else: the
//! same cache gives the same bytes, so rebuilding the figures at a new commit leaves it (and
//! the committed `figures/`) unchanged unless a case was solved again, and it is the same for
//! a one-machine run and an `--offline` assembly of merged shards up to the stamps, which say
//! truthfully that other processes solved the cases. The git revision of the assembling
//! build is deliberately left out: it would change the file at every commit while nothing it
//! describes changed (the CSV is a function of the results, and a change of its format shows
//! in the CSV itself). Sidecars are JSON, not CSV, so `repro check` never compares them.

use super::cache::Stamp;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// File name suffix of a sidecar: `fig7.provenance.json`.
pub const SUFFIX: &str = ".provenance.json";

/// The sidecar of a target.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// Target (or study) name.
    pub target: String,
    /// The files it describes.
    pub files: Vec<String>,
    /// `repro`'s crate version of the assembling build.
    pub repro_version: String,
    /// Point-contact solver revision (part of every point-contact cache key).
    pub solver_revision: Option<String>,
    /// Line-contact solver revision (part of every line-contact cache key).
    pub line_solver_revision: Option<String>,
    /// Grid level of the point contacts.
    pub level: Option<u32>,
    /// Solver parameters, as the solver's `Params` print: every distinct set the rule
    /// (`Params::for_problem`) gives the target's point contacts (their domains differ with
    /// the load), then the line contacts'.
    pub params: Vec<String>,
    /// Who solved the cases: one entry per build and host, with its count of cases.
    pub computed_by: Vec<Computation>,
    /// Every row with a case: its file, row, cache key and the stamp of the entry.
    pub cases: Vec<CaseSource>,
}

/// A build and host that solved some of a target's cases.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Computation {
    /// Crate version, or `unknown` for entries written before stamps.
    pub repro_version: String,
    /// Git revision, or `unknown`.
    pub git_revision: String,
    /// Host, or `unknown`.
    pub host: String,
    /// Cases.
    pub cases: usize,
}

/// One row's case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CaseSource {
    /// File of the row.
    pub file: String,
    /// 1-based row (the `case` column).
    pub row: usize,
    /// Cache key of the case.
    pub key: String,
    /// How its entry was made (`null` for entries written before stamps).
    pub stamp: Option<Stamp>,
}

impl Provenance {
    /// A sidecar of `target` describing `files`, with no cases (an emitted table).
    pub fn new(target: &str, files: &[String]) -> Self {
        Provenance {
            target: target.to_string(),
            files: files.to_vec(),
            repro_version: env!("CARGO_PKG_VERSION").to_string(),
            solver_revision: None,
            line_solver_revision: None,
            level: None,
            params: Vec::new(),
            computed_by: Vec::new(),
            cases: Vec::new(),
        }
    }

    /// Lists a set of solver parameters, as they print, unless it is listed already.
    pub fn add_params(&mut self, params: &impl std::fmt::Debug) {
        let params = format!("{params:?}");
        if !self.params.contains(&params) {
            self.params.push(params);
        }
    }

    /// Adds the rows of `file`: `(key, stamp)` of each, in row order.
    pub fn add_rows<'a>(
        &mut self,
        file: &str,
        rows: impl IntoIterator<Item = (&'a str, Option<&'a Stamp>)>,
    ) {
        for (i, (key, stamp)) in rows.into_iter().enumerate() {
            self.cases.push(CaseSource {
                file: file.to_string(),
                row: i + 1,
                key: key.to_string(),
                stamp: stamp.cloned(),
            });
        }
        self.computed_by = computations(&self.cases);
    }

    /// The sidecar as written: pretty JSON, one trailing newline.
    pub fn to_json(&self) -> String {
        // Plain data of strings and numbers: serialising cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_default() + "\n"
    }

    /// One line for the report: revisions, level, who solved the cases.
    pub fn summary(&self) -> String {
        let mut parts = vec![format!("repro {}", self.repro_version)];
        if let Some(r) = &self.solver_revision {
            parts.push(format!("point solver {r}"));
        }
        if let Some(r) = &self.line_solver_revision {
            parts.push(format!("line solver {r}"));
        }
        if let Some(l) = self.level {
            parts.push(format!("level {l}"));
        }
        if self.cases.is_empty() {
            parts.push("no solves".into());
        } else {
            let by: Vec<String> = self
                .computed_by
                .iter()
                .map(|c| {
                    format!(
                        "{} by repro {} at {} on {}",
                        c.cases,
                        c.repro_version,
                        short(&c.git_revision),
                        c.host
                    )
                })
                .collect();
            parts.push(format!(
                "{} cases by cache key, solved: {}",
                self.cases.len(),
                by.join("; ")
            ));
        }
        parts.join(", ")
    }
}

/// A git revision shortened to 12 digits (its `-dirty` mark kept).
fn short(rev: &str) -> String {
    match rev.split_once('-') {
        Some((hash, rest)) if hash.len() > 12 => format!("{}-{rest}", &hash[..12]),
        None if rev.len() > 12 => rev[..12].to_string(),
        _ => rev.to_string(),
    }
}

/// The cases grouped by build and host, in a stable order.
fn computations(cases: &[CaseSource]) -> Vec<Computation> {
    let mut by: BTreeMap<(String, String, String), usize> = BTreeMap::new();
    for c in cases {
        let unknown = || "unknown".to_string();
        let id = match &c.stamp {
            Some(s) => (
                s.repro_version.clone(),
                s.git_revision.clone(),
                s.host.clone(),
            ),
            None => (unknown(), unknown(), unknown()),
        };
        *by.entry(id).or_default() += 1;
    }
    by.into_iter()
        .map(|((repro_version, git_revision, host), cases)| Computation {
            repro_version,
            git_revision,
            host,
            cases,
        })
        .collect()
}

/// The report's line for a sidecar's text, or why it cannot be read.
pub fn summary_of(text: &str) -> String {
    match serde_json::from_str::<Provenance>(text) {
        Ok(p) => p.summary(),
        Err(e) => format!("unreadable provenance sidecar: {e}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stamp(rev: &str, host: &str) -> Stamp {
        Stamp {
            repro_version: "0.1.0".into(),
            git_revision: rev.into(),
            host: host.into(),
            seconds: 1.5,
            revisions: None,
        }
    }

    #[test]
    fn rows_are_grouped_by_build_and_the_summary_names_them() {
        let (a, b) = (stamp(&"a".repeat(40), "node1"), stamp("b-dirty", "node2"));
        let mut p = Provenance::new("fig7", &["fig7.csv".into()]);
        p.level = Some(5);
        p.add_rows(
            "fig7.csv",
            [
                ("k1", Some(&a)),
                ("k2", Some(&b)),
                ("k3", Some(&a)),
                ("k4", None),
            ],
        );
        assert_eq!(p.cases[2].row, 3);
        let counts: Vec<(String, usize)> = p
            .computed_by
            .iter()
            .map(|c| (c.host.clone(), c.cases))
            .collect();
        assert_eq!(
            counts,
            vec![
                ("node1".into(), 2),
                ("node2".into(), 1),
                ("unknown".into(), 1)
            ]
        );
        let s = summary_of(&p.to_json());
        assert!(
            s.contains("level 5") && s.contains("2 by repro 0.1.0 at aaaaaaaaaaaa on node1"),
            "{s}"
        );
        assert!(s.contains("at b-dirty on node2"), "{s}");
        // Same input, same bytes.
        assert_eq!(p.to_json(), p.clone().to_json());
        assert!(summary_of("{").starts_with("unreadable"));
    }
}
