//! Tables 1-3: emitted from `cases/` with their derived groups (nothing is solved).

use crate::paper::figures::{FIG4, FIG5, FIG6, FIG7};
use crate::paper::target::{Target, TargetReport};
use crate::physics::case::{CaseForm, LubricantSpec, Problem};
use crate::physics::lubricant::LubricantTable;
use crate::pipeline::context::Context;
use crate::pipeline::csv::rows;
use crate::pipeline::error::PipelineError;
use crate::pipeline::job::Job;
use serde::{Serialize, Serializer};

/// An emitted table's report.
fn emitted(
    name: &'static str,
    title: &str,
    cases: usize,
    file: String,
    claim: &str,
) -> TargetReport {
    TargetReport {
        paper_claim: claim.to_string(),
        ..TargetReport::emitted(name, title, cases, vec![file])
    }
}

/// Table 1: the lubricants of `cases/lubricants.toml`.
pub struct Table1;

impl Target for Table1 {
    fn name(&self) -> &'static str {
        "table1"
    }
    fn describe(&self) -> &'static str {
        "Lubricant properties alpha, eta0 at 40/60/100 C (from cases/lubricants.toml)"
    }
    fn jobs(&self, _: &Context) -> Result<Vec<Job>, PipelineError> {
        Ok(Vec::new())
    }
    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        table1(ctx)
    }
}

/// Table 2: the operating parameters of Figs. 4-6 (`cases/fig4.toml` ...).
pub struct Table2;

impl Target for Table2 {
    fn name(&self) -> &'static str {
        "table2"
    }
    fn describe(&self) -> &'static str {
        "Ranges of the operating parameters, with the derived M, L, S-bar ranges per lubricant"
    }
    fn jobs(&self, _: &Context) -> Result<Vec<Job>, PipelineError> {
        Ok(Vec::new())
    }
    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        table2(ctx)
    }
}

/// Table 3: the contact configurations of Fig. 7 (`cases/fig7.toml`).
pub struct Table3;

impl Target for Table3 {
    fn name(&self) -> &'static str {
        "table3"
    }
    fn describe(&self) -> &'static str {
        "The five contact-configuration cases, with M, L, S-bar, tau_c per geometry"
    }
    fn jobs(&self, _: &Context) -> Result<Vec<Job>, PipelineError> {
        Ok(Vec::new())
    }
    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        table3(ctx)
    }
}

/// A row of `table1.csv`.
#[derive(Debug, Default, Serialize)]
struct Table1Row<'a> {
    lubricant: &'a str,
    description: &'a str,
    temperature_c: f64,
    alpha_per_gpa: f64,
    eta0_mpa_s: f64,
}

fn table1(ctx: &Context) -> Result<TargetReport, PipelineError> {
    let lubs = LubricantTable::table1();
    let mut table = Vec::new();
    for (name, lub) in &lubs.0 {
        for (i, t) in lub.temperature_c.iter().enumerate() {
            table.push(Table1Row {
                lubricant: name,
                description: &lub.description,
                temperature_c: *t,
                alpha_per_gpa: lub.alpha_per_gpa[i],
                eta0_mpa_s: lub.eta0_mpa_s[i],
            });
        }
    }
    let n = table.len();
    let f = ctx.write("table1.csv", &rows(table))?;
    Ok(emitted(
        "table1",
        "Table 1: lubricant properties",
        n,
        f,
        "Table 1 of the paper, eta0 in mPa s",
    ))
}

/// The range of a parameter over a sweep, written `min to max` with four significant digits
/// (plain between 0.001 and 1e5, else in exponent form: `1 to 3`, `64.4 to 1.921e4`); `to`
/// rather than a hyphen, which would read as a minus sign or run into an exponent.
#[derive(Debug, Default, Clone, Copy)]
struct Span(f64, f64);

impl Span {
    /// The range of `v`.
    fn of(v: impl Iterator<Item = f64>) -> Self {
        let (a, b) = v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
        Span(a, b)
    }
}

impl Serialize for Span {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let text = |v: f64| {
            if v == 0.0 || (1e-3..1e5).contains(&v.abs()) {
                crate::plot::significant(v, 4)
            } else {
                format!("{v:.3e}")
            }
        };
        s.serialize_str(&format!("{} to {}", text(self.0), text(self.1)))
    }
}

/// A row of `table2.csv`: one lubricant's sweep.
#[derive(Debug, Default, Serialize)]
struct Table2Row {
    lubricant: String,
    ph_gpa: Span,
    temperature_c: &'static str,
    um_m_s: Span,
    slip: Span,
    tau0_mpa: Span,
    m_min: f64,
    m_max: f64,
    l_min: f64,
    l_max: f64,
    s_bar_min: f64,
    s_bar_max: f64,
    tau_c_min: f64,
    tau_c_max: f64,
}

fn table2(ctx: &Context) -> Result<TargetReport, PipelineError> {
    let lubs = LubricantTable::table1();
    let mut table = Vec::new();
    for fig in [&FIG4, &FIG5, &FIG6] {
        let sweep = fig.sweep()?;
        let problems: Vec<Problem> = sweep
            .cases
            .iter()
            .map(|c| {
                Problem::from_case(c, &lubs).map_err(|e| PipelineError::case(fig.sweep.path(), e))
            })
            .collect::<Result<_, _>>()?;
        let lubricant = match &sweep.cases[0].spec {
            CaseForm::Physical(p) => match &p.lubricant {
                LubricantSpec::Named { lubricant, .. } => lubricant.clone(),
                LubricantSpec::Given { .. } => "given".into(),
                LubricantSpec::Datasheet { datasheet, .. } => datasheet.label(),
            },
            CaseForm::Dimensionless(_) => "dimensionless".into(),
        };
        let phys: Vec<_> = sweep
            .cases
            .iter()
            .filter_map(|c| match &c.spec {
                CaseForm::Physical(p) => Some(p.clone()),
                CaseForm::Dimensionless(_) => None,
            })
            .collect();
        let m = Span::of(problems.iter().map(|p| p.groups.m));
        let l = Span::of(problems.iter().map(|p| p.groups.l));
        let s_bar = Span::of(problems.iter().map(|p| p.groups.s_bar));
        let tau_c = Span::of(problems.iter().map(|p| p.tau_c()));
        table.push(Table2Row {
            lubricant,
            ph_gpa: Span::of(phys.iter().map(|p| p.ph_pa / 1e9)),
            temperature_c: "40/60/100",
            um_m_s: Span::of(phys.iter().map(|p| p.um_m_s)),
            slip: Span::of(phys.iter().map(|p| p.slip)),
            tau0_mpa: Span::of(phys.iter().map(|p| p.tau0_pa / 1e6)),
            m_min: m.0,
            m_max: m.1,
            l_min: l.0,
            l_max: l.1,
            s_bar_min: s_bar.0,
            s_bar_max: s_bar.1,
            tau_c_min: tau_c.0,
            tau_c_max: tau_c.1,
        });
    }
    let n = table.len();
    let f = ctx.write("table2.csv", &rows(table))?;
    Ok(emitted(
        "table2",
        "Table 2: ranges of the operating parameters",
        n,
        f,
        "Table 2 of the paper",
    ))
}

/// A row of `table3.csv`: one case of Fig. 7.
#[derive(Debug, Default, Serialize)]
struct Table3Row {
    d: f64,
    ph_gpa: f64,
    temperature_c: Option<f64>,
    um_m_s: f64,
    slip: f64,
    tau0_mpa: f64,
    m: f64,
    l: f64,
    s_bar: f64,
    kappa: f64,
    tau_c: f64,
}

fn table3(ctx: &Context) -> Result<TargetReport, PipelineError> {
    let sweep = FIG7.sweep()?;
    let lubs = LubricantTable::table1();
    let mut table = Vec::new();
    for c in &sweep.cases {
        let p =
            Problem::from_case(c, &lubs).map_err(|e| PipelineError::case("cases/fig7.toml", e))?;
        if let CaseForm::Physical(ph) = &c.spec {
            table.push(Table3Row {
                d: ph.rx_m / ph.ry_m,
                ph_gpa: ph.ph_pa / 1e9,
                temperature_c: ph.lubricant.temperature_c(),
                um_m_s: ph.um_m_s,
                slip: ph.slip,
                tau0_mpa: ph.tau0_pa / 1e6,
                m: p.groups.m,
                l: p.groups.l,
                s_bar: p.groups.s_bar,
                kappa: p.groups.kappa,
                tau_c: p.tau_c(),
            });
        }
    }
    let n = table.len();
    let f = ctx.write("table3.csv", &rows(table))?;
    Ok(emitted(
        "table3",
        "Table 3: contact-configuration cases",
        n,
        f,
        "Table 3 of the paper (five load cases)",
    ))
}
