//! The line contacts of Fig. 7: the five Table 3 load cases of `cases/fig7.toml` (mineral oil
//! A, Roelands, Dowson-Higginson, Eyring) without their `Ry`.

use super::sweep::shipped_sweep;
use crate::physics::case::{Physics, Spec};
use crate::physics::line_contact::LinePhysicalCase;
use crate::physics::lubricant::LubricantTable;

/// The five Table 3 cases as line contacts, in the order of the table, with the physics of
/// Figs. 4-7. The rows are read from the shipped `cases/fig7.toml` (its `D = 1/2` block), the
/// one source of truth for Table 3.
pub fn table3_line_cases() -> Result<(Vec<LinePhysicalCase>, Physics), String> {
    let sweep = shipped_sweep("fig7").map_err(|e| e.to_string())?;
    let lubs = LubricantTable::table1();
    let mut out: Vec<LinePhysicalCase> = Vec::new();
    for c in &sweep.cases {
        if let Spec::Physical(ph) = &c.spec {
            let line = LinePhysicalCase::from_point_case(ph, &lubs)
                .map_err(|e| format!("cases/fig7.toml: {e}"))?;
            if !out.contains(&line) {
                out.push(line);
            }
        }
    }
    if out.len() != 5 {
        return Err(format!(
            "cases/fig7.toml: expected the 5 load cases of Table 3, found {}",
            out.len()
        ));
    }
    Ok((out, Physics::figs_4_to_7()))
}

#[cfg(test)]
mod tests {
    #[test]
    fn table3_has_five_line_cases_in_order() {
        let (cases, _) = super::table3_line_cases().unwrap();
        // Table 3 of the paper: p_H (GPa) 1, 2, 2, 3, 3 and S 2 %, then 0.1 %.
        let ph: Vec<f64> = cases.iter().map(|c| c.ph_pa / 1e9).collect();
        assert_eq!(ph, vec![1.0, 2.0, 2.0, 3.0, 3.0]);
        assert!((cases[0].slip - 0.02).abs() < 1e-15);
        // Table 1 at 40 C for the last case: alpha 21.6 /GPa, eta0 8.24 mPa s.
        assert!((cases[4].alpha_per_pa - 21.6e-9).abs() < 1e-15);
        assert!((cases[4].eta0_pa_s - 8.24e-3).abs() < 1e-15);
    }
}
