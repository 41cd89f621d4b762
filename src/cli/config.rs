//! Flags turned once into what the library takes: the inputs of a solve
//! ([`SolveInputs`], which the library turns into a case, its parameters and its report), a
//! datasheet, the pipeline's [`Context`]. Every error names the flag.

use super::args::{
    BaseOilArg, DatasheetArgs, DensityArg, DomainArg, EdgeArg, PatchArg, RheologyArg, SolveArgs,
    TargetArgs, ViscosityArg,
};
use anyhow::{Context as _, Result};
use repro::physics::density::DensityLaw;
use repro::physics::pressure_viscosity::BaseOil;
use repro::physics::viscosity::ViscosityLaw;
use repro::pipeline::cache::Cache;
use repro::pipeline::context::{check_writable, Context};
use repro::pipeline::executor::RunProgress;
use repro::report::inputs::{self, DatasheetInputs, RheologyChoice, SolveInputs};
pub use repro::report::inputs::{flag_error, lubricant_spec, physics};
use repro::solver::grid::Domain;
use repro::solver::point;
use repro::solver::point::composite::Patch;

/// Checks a grid level flag.
pub fn check_level(flag: &'static str, level: u32) -> Result<u32> {
    Ok(inputs::check_level(flag, level)?)
}

impl DatasheetArgs {
    /// The datasheet flags as the library takes them.
    pub fn inputs(&self) -> DatasheetInputs {
        DatasheetInputs {
            nu40: self.nu40,
            iso_vg: self.iso_vg,
            nu100: self.nu100,
            vi: self.vi,
            rho15: self.rho15,
            expansion15: self.expansion15,
            base_oil: self.base_oil.map(|b| match b {
                BaseOilArg::Mineral => BaseOil::Mineral,
                BaseOilArg::Pao => BaseOil::Polyalphaolefin,
                BaseOilArg::Pag => BaseOil::Polyglycol,
            }),
        }
    }
}

impl ViscosityArg {
    /// The law the flag names.
    pub fn law(self) -> ViscosityLaw {
        match self {
            ViscosityArg::Barus => ViscosityLaw::Barus,
            ViscosityArg::Roelands => ViscosityLaw::Roelands,
        }
    }
}

impl DensityArg {
    /// The law the flag names.
    pub fn law(self) -> DensityLaw {
        match self {
            DensityArg::Incompressible => DensityLaw::Incompressible,
            DensityArg::DowsonHigginson => DensityLaw::DowsonHigginson,
        }
    }
}

impl SolveArgs {
    /// The flags as the library's inputs of one solve ([`SolveInputs`]), which turns them
    /// into the case, its parameters and its report for every caller alike.
    pub fn inputs(&self) -> SolveInputs {
        SolveInputs {
            m: self.m,
            l: self.l,
            s_bar: self.s_bar,
            d: self.d,
            lubricant: self.lubricant.clone(),
            temperature: self.temperature,
            alpha: self.alpha,
            ph: self.ph,
            um: self.um,
            tau0: self.tau0,
            rx: self.rx,
            ry: self.ry,
            e_prime: self.e_prime,
            datasheet: self.datasheet.inputs(),
            slip: self.slip,
            eta0: self.eta0,
            viscosity: self.viscosity.map(ViscosityArg::law),
            density: self.density.map(DensityArg::law),
            rheology: self.rheology.map(|r| match r {
                RheologyArg::Eyring => RheologyChoice::Eyring,
                RheologyArg::Newtonian => RheologyChoice::Newtonian,
                RheologyArg::EyringLss => RheologyChoice::EyringLss,
            }),
            lambda_lss: self.lambda_lss,
            tau_l0: self.tau_l0,
            line: self.line,
            level: self.level,
            exact_level: self.exact_level,
            domain: match self.domain {
                DomainArg::Auto => None,
                DomainArg::Paper => Some(Domain::default()),
                DomainArg::Wide => Some(Domain::wide()),
                DomainArg::Heavy => Some(Domain::heavy()),
            },
            edge: match self.edge {
                EdgeArg::Auto => None,
                EdgeArg::Zero => Some(point::Edge::Zero),
                EdgeArg::FarField => Some(point::Edge::FarField),
            },
            patch: match self.patch {
                PatchArg::None => None,
                PatchArg::Inlet => Some(Patch::Inlet),
                PatchArg::Lobes => Some(Patch::Lobes),
                PatchArg::InletAndLobes => Some(Patch::InletAndLobes),
            },
            max_cycles: self.max_cycles,
            newton_steps: self.newton_steps,
            rolling_friction: !self.no_rolling,
            cold: self.cold,
            k_solid: self.thermal.k_solid,
            k_lubricant: self.thermal.k_lubricant,
        }
    }
}

/// Where and how targets are built, from the target flags; `progress` and `warn` hear of the
/// run. The output folder is checked when the run `writes_outputs` (a shard writes none).
pub fn context<'a>(
    args: &TargetArgs,
    writes_outputs: bool,
    progress: &'a (dyn Fn(&str, RunProgress) + Sync),
    warn: &'a (dyn Fn(String) + Sync),
) -> Result<Context<'a>> {
    if let Some(l) = args.level {
        check_level("level", l)?;
    }
    if writes_outputs {
        check_writable(&args.out).context("--out")?;
    }
    Ok(Context {
        out: args.out.clone(),
        cache: (!args.no_cache).then(|| Cache::new(&args.cache)),
        level: args.level,
        progress,
        warn,
        stride: 1,
        offline: args.offline,
        stop: None,
    })
}
