//! A study's own lubricants: `[lubricants.NAME]` tables of datasheets, checked.

use super::error::{field, SweepError};
use crate::physics::datasheet::Datasheet;
use crate::physics::lubricant::LubricantTable;
use std::collections::BTreeMap;

/// A study's own lubricant: its datasheet and, when the user knows it, its `alpha`.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyLubricant {
    /// The datasheet.
    pub datasheet: Datasheet,
    /// Pressure-viscosity coefficient, 1/GPa, used instead of the correlation.
    pub alpha_per_gpa: Option<f64>,
}

/// The `[lubricants.NAME]` tables of a study, checked: a name of Table 1 is refused, and
/// each datasheet must be complete and consistent (its own errors name
/// `lubricants.NAME.KEY`).
pub fn study_lubricants(
    file: &str,
    tables: &BTreeMap<String, toml::Table>,
) -> Result<BTreeMap<String, StudyLubricant>, SweepError> {
    let table1 = LubricantTable::table1();
    let mut out = BTreeMap::new();
    for (name, table) in tables {
        let here = format!("lubricants.{name}");
        if table1.0.contains_key(name) {
            return Err(field(
                file,
                &here,
                format!("'{name}' is a lubricant of Table 1 (cases/lubricants.toml); give yours another name"),
            ));
        }
        let mut table = table.clone();
        let alpha_per_gpa = match table.remove("alpha_per_gpa") {
            None => None,
            Some(v) => Some(
                v.as_float()
                    .or(v.as_integer().map(|i| i as f64))
                    .ok_or_else(|| {
                        field(
                            file,
                            &format!("{here}.alpha_per_gpa"),
                            "must be a number (1/GPa)",
                        )
                    })?,
            ),
        };
        let datasheet: Datasheet = toml::Value::Table(table)
            .try_into()
            .map_err(|e| field(file, &here, e.to_string().trim_end()))?;
        datasheet
            .resolve()
            .map_err(|e| field(file, &format!("{here}.{}", e.field()), e.to_string()))?;
        out.insert(
            name.clone(),
            StudyLubricant {
                datasheet,
                alpha_per_gpa,
            },
        );
    }
    Ok(out)
}
