//! The paper's case definitions, shipped in `cases/` and compiled in, so the binary runs
//! anywhere: the sweeps of Figs. 1-7 (`cases/*.toml`, the format of
//! [`crate::pipeline::sweep`]). Table 1 (`cases/lubricants.toml`) is read by
//! [`crate::physics::lubricant::LubricantTable::table1`], the Appendix case
//! (`cases/table4.toml`) by [`crate::paper::table4::Table4Case::shipped`].

use crate::pipeline::sweep::{Sweep, SweepError};
use std::collections::BTreeMap;

/// The sweep files shipped in `cases/`, by name (compiled in, so the binary runs anywhere).
pub fn shipped() -> BTreeMap<&'static str, &'static str> {
    BTreeMap::from([
        ("fig1-3", include_str!("../../cases/fig1-3.toml")),
        ("fig4", include_str!("../../cases/fig4.toml")),
        ("fig5", include_str!("../../cases/fig5.toml")),
        ("fig6", include_str!("../../cases/fig6.toml")),
        ("fig7", include_str!("../../cases/fig7.toml")),
    ])
}

/// A shipped sweep by name.
pub fn shipped_sweep(name: &str) -> Result<Sweep, SweepError> {
    let text = shipped()
        .get(name)
        .copied()
        .ok_or_else(|| SweepError::Field {
            file: format!("cases/{name}.toml"),
            field: "name".into(),
            message: "no such shipped sweep".into(),
        })?;
    Sweep::parse(&format!("cases/{name}.toml"), text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::Problem;
    use crate::physics::lubricant::LubricantTable;

    #[test]
    fn shipped_sweeps_parse_and_are_physical() {
        let lubs = LubricantTable::table1();
        for (name, expect) in [
            ("fig1-3", 125),
            ("fig4", 243),
            ("fig5", 243),
            ("fig6", 243),
            ("fig7", 10),
        ] {
            let s = shipped_sweep(name).unwrap();
            assert_eq!(s.cases.len(), expect, "{name}");
            for c in &s.cases {
                Problem::from_case(c, &lubs).unwrap_or_else(|e| panic!("{name}: {e}"));
            }
        }
    }
}
