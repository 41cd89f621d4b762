//! The paper's case definitions, shipped in `cases/` and compiled in, so the binary runs
//! anywhere: the sweeps of Figs. 1-7 (`cases/*.toml`, the format of
//! [`crate::pipeline::sweep`]), each compiled in by the figure that draws it (`sweep_file!` in
//! its entry, `paper/figures/spec.rs`). Table 1 (`cases/lubricants.toml`) is read
//! by [`crate::physics::lubricant::LubricantTable::table1`], the Appendix case
//! (`cases/table4.toml`) by [`crate::paper::table4::Table4Case::shipped`].

use crate::paper::target::ShippedSweep;
use crate::paper::REGISTRY;
use crate::pipeline::sweep::{Sweep, SweepError};

/// The sweep files shipped in `cases/`: those the registry's targets draw
/// ([`crate::paper::Target::sweep_file`]), each once, in the registry's order.
pub fn shipped() -> Vec<ShippedSweep> {
    let mut files: Vec<ShippedSweep> = Vec::new();
    for file in REGISTRY.iter().filter_map(|a| a.sweep_file()) {
        if !files.iter().any(|f| f.name == file.name) {
            files.push(file);
        }
    }
    files
}

/// A shipped sweep by name (the stem of its file in `cases/`).
pub fn shipped_sweep(name: &str) -> Result<Sweep, SweepError> {
    shipped()
        .into_iter()
        .find(|f| f.name == name)
        .ok_or_else(|| SweepError::Field {
            file: format!("cases/{name}.toml"),
            field: "name".into(),
            message: "no such shipped sweep".into(),
        })?
        .parse()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::Problem;
    use crate::physics::lubricant::LubricantTable;

    #[test]
    fn shipped_sweeps_parse_and_are_physical() {
        let lubs = LubricantTable::table1();
        // Every sweep file the paper draws, with the case count the README's table of targets
        // promises: a file dropped from the registry, or one that lost cases, shows here.
        let expected = [
            ("fig1-3", 125),
            ("fig4", 243),
            ("fig5", 243),
            ("fig6", 243),
            ("fig7", 10),
        ];
        let names: Vec<&str> = shipped().iter().map(|f| f.name).collect();
        assert_eq!(names, expected.map(|e| e.0));
        for (name, expect) in expected {
            let s = shipped_sweep(name).unwrap();
            assert_eq!(s.cases.len(), expect, "{name}");
            for c in &s.cases {
                Problem::from_case(c, &lubs).unwrap_or_else(|e| panic!("{name}: {e}"));
            }
        }
    }

    #[test]
    fn an_unknown_sweep_is_an_error_naming_its_file() {
        let e = shipped_sweep("fig99").unwrap_err();
        assert!(e.to_string().contains("cases/fig99.toml"), "{e}");
    }
}
