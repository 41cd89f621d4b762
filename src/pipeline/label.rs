//! Cases in words, for listings of missing cases, shard logs and progress.

use crate::physics::case::{Case, CaseForm, LubricantSpec};

/// A readable description of a case at `level`, e.g. `mineral-oil-a at 40 C, p_H 3 GPa, u_m
/// 12 m/s, S 0.005, tau0 4 MPa, Rx/Ry 1, level 7`.
pub fn case_label(case: &Case, level: u32) -> String {
    let body = match &case.spec {
        CaseForm::Physical(p) => {
            let lub = match &p.lubricant {
                LubricantSpec::Named {
                    lubricant,
                    temperature_c,
                } => format!("{lubricant} at {} C", short(*temperature_c)),
                LubricantSpec::Given {
                    alpha_per_pa,
                    eta0_pa_s,
                } => format!(
                    "alpha {} 1/GPa, eta0 {} mPa s",
                    short(alpha_per_pa * 1e9),
                    short(eta0_pa_s * 1e3)
                ),
                LubricantSpec::Datasheet {
                    datasheet,
                    temperature_c,
                    alpha_per_gpa,
                } => format!(
                    "{} at {} C{}",
                    datasheet.label(),
                    short(*temperature_c),
                    alpha_per_gpa
                        .map_or_else(String::new, |a| format!(", alpha {} 1/GPa", short(a)))
                ),
            };
            format!(
                "{lub}, p_H {} GPa, u_m {} m/s, S {}, tau0 {} MPa, Rx/Ry {}",
                short(p.ph_pa / 1e9),
                short(p.um_m_s),
                short(p.slip),
                short(p.tau0_pa / 1e6),
                short(p.rx_m / p.ry_m)
            )
        }
        CaseForm::Dimensionless(d) => format!(
            "M {}, L {}, S-bar {}, Rx/Ry {}, S {}",
            short(d.m),
            short(d.l),
            short(d.s_bar),
            short(d.d),
            short(d.slip)
        ),
    };
    format!("{body}, level {level}")
}

/// Seven significant digits, printed shortest: 0.30000000000000004 reads 0.3.
fn short(x: f64) -> String {
    format!("{:.6e}", x)
        .parse::<f64>()
        .map_or_else(|_| x.to_string(), |r| r.to_string())
}
