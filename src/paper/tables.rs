//! The table targets: Tables 1-3 emitted from `cases/` with their derived groups, and
//! Table 4, the grid convergence of the Appendix case at its own levels.

use crate::physics::case::{LubricantSpec, Spec};
use crate::physics::lubricant::LubricantTable;
use crate::pipeline::context::{write, Built, Context};
use crate::pipeline::csv::{num, table};
use crate::pipeline::provenance::{Provenance, SUFFIX};
use crate::pipeline::sweep::shipped_sweep;
use crate::solver::point::SOLVER_REVISION;

fn emitted(
    name: &'static str,
    title: &str,
    cases: usize,
    files: Vec<String>,
    claim: &str,
) -> Built {
    Built {
        name,
        title: title.to_string(),
        cases,
        solved: None,
        cached: None,
        level: None,
        fit: None,
        fit_all: None,
        seconds: 0.0,
        files,
        paper_claim: claim.to_string(),
        ours: "emitted from cases/".to_string(),
        refined: Vec::new(),
    }
}

pub(super) fn table1(ctx: &Context) -> Result<Built, String> {
    let lubs = LubricantTable::table1();
    let mut rows = Vec::new();
    for (name, lub) in &lubs.0 {
        for (i, t) in lub.temperature_c.iter().enumerate() {
            rows.push(vec![
                name.clone(),
                lub.description.clone(),
                num(*t),
                num(lub.alpha_per_gpa[i]),
                num(lub.eta0_mpa_s[i]),
            ]);
        }
    }
    let n = rows.len();
    let csv = table(
        &[
            "lubricant",
            "description",
            "temperature_c",
            "alpha_per_gpa",
            "eta0_mpa_s",
        ],
        &rows,
    );
    let f = write(ctx, "table1.csv", &csv)?;
    Ok(emitted(
        "table1",
        "Table 1: lubricant properties",
        n,
        vec![f],
        "Table 1 of the paper, eta0 in mPa s",
    ))
}

/// `(min, max)` of an iterator of values.
fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    })
}

pub(super) fn table2(ctx: &Context) -> Result<Built, String> {
    let lubs = LubricantTable::table1();
    let mut rows = Vec::new();
    for fig in ["fig4", "fig5", "fig6"] {
        let sweep = shipped_sweep(fig).map_err(|e| e.to_string())?;
        let problems: Vec<_> = sweep
            .cases
            .iter()
            .map(|c| {
                crate::physics::case::Problem::from_case(c, &lubs)
                    .map_err(|e| format!("cases/{fig}.toml: {e}"))
            })
            .collect::<Result<_, _>>()?;
        let lub = match &sweep.cases[0].spec {
            Spec::Physical(p) => match &p.lubricant {
                LubricantSpec::Named { lubricant, .. } => lubricant.clone(),
                LubricantSpec::Given { .. } => "given".into(),
                LubricantSpec::Datasheet { datasheet, .. } => datasheet.label(),
            },
            Spec::Dimensionless(_) => "dimensionless".into(),
        };
        let phys: Vec<_> = sweep
            .cases
            .iter()
            .filter_map(|c| {
                if let Spec::Physical(p) = &c.spec {
                    Some(p.clone())
                } else {
                    None
                }
            })
            .collect();
        let (ph0, ph1) = range(phys.iter().map(|p| p.ph_pa / 1e9));
        let (u0, u1) = range(phys.iter().map(|p| p.um_m_s));
        let (s0, s1) = range(phys.iter().map(|p| p.slip * 100.0));
        let (t0, t1) = range(phys.iter().map(|p| p.tau0_pa / 1e6));
        let (m0, m1) = range(problems.iter().map(|p| p.groups.m));
        let (l0, l1) = range(problems.iter().map(|p| p.groups.l));
        let (b0, b1) = range(problems.iter().map(|p| p.groups.s_bar));
        let (c0, c1) = range(problems.iter().map(|p| p.tau_c()));
        rows.push(vec![
            lub,
            format!("{}-{}", num(ph0), num(ph1)),
            "40/60/100".into(),
            format!("{}-{}", num(u0), num(u1)),
            format!("{}-{}", num(s0), num(s1)),
            format!("{}-{}", num(t0), num(t1)),
            num(m0),
            num(m1),
            num(l0),
            num(l1),
            num(b0),
            num(b1),
            num(c0),
            num(c1),
        ]);
    }
    let header = [
        "lubricant",
        "ph_gpa",
        "temperature_c",
        "um_m_s",
        "slip_percent",
        "tau0_mpa",
        "m_min",
        "m_max",
        "l_min",
        "l_max",
        "s_bar_min",
        "s_bar_max",
        "tau_c_min",
        "tau_c_max",
    ];
    let f = write(ctx, "table2.csv", &table(&header, &rows))?;
    Ok(emitted(
        "table2",
        "Table 2: ranges of the operating parameters",
        rows.len(),
        vec![f],
        "Table 2 of the paper",
    ))
}

pub(super) fn table3(ctx: &Context) -> Result<Built, String> {
    let sweep = shipped_sweep("fig7").map_err(|e| e.to_string())?;
    let lubs = LubricantTable::table1();
    let mut rows = Vec::new();
    for c in &sweep.cases {
        let p = crate::physics::case::Problem::from_case(c, &lubs)
            .map_err(|e| format!("cases/fig7.toml: {e}"))?;
        if let Spec::Physical(ph) = &c.spec {
            let t = ph.lubricant.temperature_c().map(num).unwrap_or_default();
            rows.push(vec![
                num(ph.rx_m / ph.ry_m),
                num(ph.ph_pa / 1e9),
                t,
                num(ph.um_m_s),
                num(ph.slip * 100.0),
                num(ph.tau0_pa / 1e6),
                num(p.groups.m),
                num(p.groups.l),
                num(p.groups.s_bar),
                num(p.groups.kappa),
                num(p.tau_c()),
            ]);
        }
    }
    let header = [
        "d",
        "ph_gpa",
        "temperature_c",
        "um_m_s",
        "slip_percent",
        "tau0_mpa",
        "m",
        "l",
        "s_bar",
        "kappa",
        "tau_c",
    ];
    let f = write(ctx, "table3.csv", &table(&header, &rows))?;
    Ok(emitted(
        "table3",
        "Table 3: contact-configuration cases",
        rows.len(),
        vec![f],
        "Table 3 of the paper (five load cases)",
    ))
}

/// The solves of Table 4: the Appendix case at its own levels.
pub(super) fn table4_jobs() -> Result<Vec<crate::pipeline::run::Job>, String> {
    let spec = crate::paper::table4::Table4Case::shipped()?;
    crate::paper::table4::jobs(&spec, &spec.levels)
}

pub(super) fn table4(ctx: &Context) -> Result<Built, String> {
    use crate::paper::table4 as t4;
    let spec = t4::Table4Case::shipped()?;
    // A grid-convergence table: always its own levels (cases/table4.toml), whatever level
    // the other targets are built at.
    let levels = spec.levels.clone();
    let progress = |p| (ctx.progress)("table4", p);
    let stored = t4::compute_stored(&spec, &levels, ctx.store(), &progress, ctx.warn)?;
    let rows = &stored.rows;
    let csv = write(ctx, "table4.csv", &t4::to_csv(rows))?;
    let mut sidecar = Provenance::new("table4", std::slice::from_ref(&csv));
    sidecar.solver_revision = Some(SOLVER_REVISION.to_string());
    let problem = spec.problem()?;
    sidecar.params = levels
        .iter()
        .map(|&l| format!("{:?}", t4::params(&problem, l)))
        .collect();
    sidecar.add_rows(
        &csv,
        stored
            .keys
            .iter()
            .map(String::as_str)
            .zip(stored.stamps.iter().map(Option::as_ref)),
    );
    let sidecar = write(ctx, &format!("table4{SUFFIX}"), &sidecar.to_json())?;
    let solved = rows.iter().filter(|r| r.outcome.record().is_some()).count();
    let ours = rows
        .iter()
        .filter_map(|r| {
            r.outcome.record().map(|s| {
                format!(
                    "level {}: Hc {:.4e}, mu-bar {:.2}",
                    r.level, s.h_central, s.mu_bar_sliding
                )
            })
        })
        .collect::<Vec<_>>()
        .join("; ")
        + "; "
        + t4::mastercurve_note(rows).trim_end();
    let claim = t4::PAPER
        .iter()
        .map(|p| format!("level {}: Hc {:.4e}, mu-bar {:.2}", p.0, p.1, p.2))
        .collect::<Vec<_>>()
        .join("; ");
    Ok(Built {
        name: "table4",
        title: "Table 4: grid convergence of the Appendix case".into(),
        cases: rows.len(),
        solved: Some(solved),
        cached: Some(stored.cached),
        level: levels.iter().max().copied(),
        fit: None,
        fit_all: None,
        seconds: 0.0,
        files: vec![csv, sidecar],
        paper_claim: claim,
        ours,
        refined: Vec::new(),
    })
}
