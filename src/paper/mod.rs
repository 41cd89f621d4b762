//! The registry: every artefact of the paper as a named target, one module per kind of target
//! beneath it (the tables, the sweep figures, Fig. 8). `repro list`, `repro <target>`,
//! `repro all` and `make figures` all read [`TARGETS`].

pub mod accuracy;
pub mod fig8;
pub mod figures;
pub mod lss;
pub mod mastercurve;
pub mod picture;
pub mod prediction;
pub mod table4;
pub mod tables;
pub mod thermal;

use crate::pipeline::context::{write, Built, Context};
use crate::pipeline::provenance::{Provenance, SUFFIX};
use crate::pipeline::run::Job;
use figures as figure;
use std::time::Instant;

/// What a target is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Emitted from `cases/` data.
    Table,
    /// Computed.
    Computed,
}

/// A target of `repro list`.
#[derive(Debug, Clone, Copy)]
pub struct Target {
    /// Name on the command line.
    pub name: &'static str,
    /// One line for `repro list`.
    pub description: &'static str,
    /// Emitted or computed.
    pub kind: Kind,
    /// Level of `repro <target>` without `--level`: the cheapest level whose sliding `mu-bar`
    /// is within 1 % of the Richardson extrapolation for the case that stands for the target
    /// in `repro accuracy` (figures/accuracy_levels.csv). `make figures` builds every target
    /// at the paper's working level instead.
    pub default_level: Option<u32>,
}

/// Every target, in the paper's order.
pub const TARGETS: &[Target] = &[
    Target { name: "table1", description: "Lubricant properties alpha, eta0 at 40/60/100 C (from cases/lubricants.toml)", kind: Kind::Table, default_level: None },
    Target { name: "table2", description: "Ranges of the operating parameters, with the derived M, L, S-bar ranges per lubricant", kind: Kind::Table, default_level: None },
    Target { name: "table3", description: "The five contact-configuration cases, with M, L, S-bar, tau_c per geometry", kind: Kind::Table, default_level: None },
    Target { name: "table4", description: "Grid convergence of Hc and sliding mu-bar for the Appendix case, levels 5-8, with wall times", kind: Kind::Computed, default_level: None },
    Target { name: "fig1", description: "Total mu-bar vs S-bar^(1/4) M L^3, Barus-incompressible circular contact (125 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig2", description: "Total mu-bar vs tau_c, same sweep, Eq. (13) dashed", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig3", description: "Sliding mu-bar vs tau_c, same sweep, Eq. (13) dashed", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig4", description: "Sliding mu-bar vs tau_c, mineral oil A, Roelands + Dowson-Higginson, Table 2 grid (243 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig5", description: "Sliding mu-bar vs tau_c, traction fluid, Table 2 grid (243 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig6", description: "Sliding mu-bar vs tau_c, 5P4E, Table 2 grid (243 cases)", kind: Kind::Computed, default_level: Some(6) },
    Target { name: "fig7", description: "Sliding mu-bar vs tau_c, mineral oil A, Rx/Ry = 1/2, 1/5 and the line contact at the Table 3 cases", kind: Kind::Computed, default_level: Some(7) },
    Target { name: "fig8", description: "Measured friction transformed to (tau_c, mu-bar) by Sec. IV, on Eq. (13) (datasets of cases/fig8/)", kind: Kind::Table, default_level: None },
    Target { name: "mastercurve", description: "Beyond the paper: every case of Figs. 3-7 on Eq. (13) and on a refined formula fitted to them, cross-validated by figure", kind: Kind::Computed, default_level: None },
    Target { name: "thermal", description: "Beyond the paper: the shear-heating correction of Figs. 4-6 (isothermal vs thermal mu-bar, where the isothermal assumption holds)", kind: Kind::Computed, default_level: None },
    Target { name: "lss", description: "Beyond the paper: Fig. 4's cases with a limiting shear stress at Lambda-bar 5-40, and the form of their curve", kind: Kind::Computed, default_level: None },
];

/// Looks a target up.
pub fn target(name: &str) -> Option<&'static Target> {
    TARGETS.iter().find(|t| t.name == name)
}

/// Looks a target up, or says which targets there are.
fn known(name: &str) -> Result<&'static Target, String> {
    target(name).ok_or_else(|| {
        let known: Vec<&str> = TARGETS.iter().map(|t| t.name).collect();
        format!("unknown target '{name}' (known: {})", known.join(", "))
    })
}

/// Every solve target `name` needs in the context, as jobs (none for the emitted tables and
/// Fig. 8): what a shard divides and what `--offline` must find in the cache.
pub fn jobs(name: &str, ctx: &Context) -> Result<Vec<Job>, String> {
    let t = known(name)?;
    match t.name {
        "table1" | "table2" | "table3" | "fig8" => Ok(Vec::new()),
        "table4" => tables::table4_jobs(),
        "lss" => lss::jobs(ctx),
        "mastercurve" => {
            // The figures' own cases, each solve once.
            let mut seen = std::collections::HashSet::new();
            let mut all: Vec<Job> = Vec::new();
            for (figure, _) in mastercurve::FIGURES {
                for job in jobs(figure, ctx)? {
                    if seen.insert(job.key.clone()) {
                        all.push(job);
                    }
                }
            }
            Ok(all)
        }
        "thermal" => thermal::jobs(ctx),
        figure_name => figure::jobs(figure_name, t.default_level, ctx),
    }
}

/// Builds one target (and its provenance sidecar, for the targets that solve nothing).
pub fn build(name: &str, ctx: &Context) -> Result<Built, String> {
    let start = Instant::now();
    let t = known(name)?;
    let mut built = match t.name {
        "table1" => tables::table1(ctx)?,
        "table2" => tables::table2(ctx)?,
        "table3" => tables::table3(ctx)?,
        "table4" => tables::table4(ctx)?,
        "fig8" => fig8::build(ctx)?,
        "mastercurve" => mastercurve::build(ctx)?,
        "thermal" => thermal::build(ctx)?,
        "lss" => lss::build(ctx)?,
        figure_name => figure::build(figure_name, t.default_level, ctx)?,
    };
    if !built.files.iter().any(|f| f.ends_with(SUFFIX)) {
        let sidecar = Provenance::new(name, &built.files).to_json();
        built
            .files
            .push(write(ctx, &format!("{name}{SUFFIX}"), &sidecar)?);
    }
    built.seconds = start.elapsed().as_secs_f64();
    Ok(built)
}
