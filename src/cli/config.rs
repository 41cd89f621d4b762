//! Flags turned once into what the library takes: a [`Case`], solver parameters, a line
//! problem, the pipeline's [`Context`]. Every error names the flag.

use super::args::{
    BaseOilArg, DatasheetArgs, DensityArg, DomainArg, EdgeArg, RheologyArg, SolveArgs, TargetArgs,
    ViscosityArg,
};
use anyhow::{anyhow, bail, Context as _, Result};
use repro::paper::artefact::WORKING_LEVEL;
use repro::physics::case::{
    Case, CaseError, CaseForm, DimensionlessCase, LubricantSpec, PhysicalCase, Physics, Problem,
};
use repro::physics::datasheet::Datasheet;
use repro::physics::density::DensityLaw;
use repro::physics::line_contact::{LineDimensionlessCase, LinePhysicalCase, LineProblem};
use repro::physics::lubricant::{LubricantError, LubricantTable};
use repro::physics::pressure_viscosity::BaseOil;
use repro::physics::rheology::{LimitingShearStress, Rheology};
use repro::physics::viscosity::ViscosityLaw;
use repro::pipeline::cache::Cache;
use repro::pipeline::context::{check_writable, Context};
use repro::pipeline::executor::RunProgress;
use repro::solver::grid::Domain;
use repro::solver::{line, point};

/// Checks a grid level flag.
pub fn check_level(flag: &str, level: u32) -> Result<u32> {
    if (point::MIN_LEVEL..=point::MAX_LEVEL).contains(&level) {
        Ok(level)
    } else {
        bail!(
            "{flag}: level {level} outside the supported range {}..={}",
            point::MIN_LEVEL,
            point::MAX_LEVEL
        )
    }
}

/// A case error as the flag it names.
pub fn flag_error(e: CaseError) -> anyhow::Error {
    match e {
        CaseError::Field { field, message } => anyhow!("--{field}: {message}"),
        CaseError::Lubricant(l @ LubricantError::Unknown { .. }) => anyhow!("--lubricant: {l}"),
        CaseError::Lubricant(l @ LubricantError::Temperature { .. }) => {
            anyhow!("--temperature: {l}")
        }
        CaseError::Datasheet(d) => anyhow!("--{}: {d}", datasheet_flag(d.field())),
        other => anyhow!("{other}"),
    }
}

/// The flag of a datasheet key ([`repro::physics::datasheet::DatasheetError::field`]).
fn datasheet_flag(key: &str) -> &str {
    match key {
        "nu40_mm2_s" => "nu40",
        "iso_vg" => "iso-vg",
        "nu100_mm2_s" => "nu100",
        "viscosity_index" => "vi",
        "rho15_kg_m3" => "rho15",
        "expansion15_per_k" => "expansion15",
        "base_oil" => "base-oil",
        "alpha_per_gpa" => "alpha",
        "temperature_c" => "temperature",
        other => other,
    }
}

/// The lubricant of the physical form (`repro solve`, `repro predict`): a lubricant of
/// Table 1 at `--temperature`, `--alpha` and `--eta0` given directly, or a datasheet at
/// `--temperature` (with `--alpha` when the user knows it). Which flags go together is
/// checked here; the datasheet's values are checked when the case is resolved.
pub fn lubricant_spec(
    lubricant: Option<&str>,
    temperature: Option<f64>,
    alpha: Option<f64>,
    eta0: Option<f64>,
    sheet: &DatasheetArgs,
) -> Result<LubricantSpec> {
    if sheet.any() {
        if lubricant.is_some() {
            bail!("--lubricant: a lubricant of Table 1 and datasheet flags (--nu40, --iso-vg, --nu100, --vi, --rho15, --expansion15, --base-oil) cannot be mixed");
        }
        if eta0.is_some() {
            bail!("--eta0: a datasheet gives eta0 (nu rho at --temperature); drop --eta0");
        }
        let one_of = |a: bool, b: bool, fa: &str, fb: &str| -> Result<()> {
            match (a, b) {
                (true, true) => bail!("{fb}: give {fa} or {fb}, not both"),
                (false, false) => bail!("{fa}: required with a datasheet (or {fb})"),
                _ => Ok(()),
            }
        };
        one_of(
            sheet.nu40.is_some(),
            sheet.iso_vg.is_some(),
            "--nu40",
            "--iso-vg",
        )?;
        one_of(sheet.nu100.is_some(), sheet.vi.is_some(), "--nu100", "--vi")?;
        let datasheet = Datasheet {
            nu40_mm2_s: sheet.nu40,
            iso_vg: sheet.iso_vg,
            nu100_mm2_s: sheet.nu100,
            viscosity_index: sheet.vi,
            rho15_kg_m3: need(sheet.rho15, "--rho15 (with a datasheet)")?,
            expansion15_per_k: sheet.expansion15,
            base_oil: match sheet.base_oil {
                Some(BaseOilArg::Mineral) => BaseOil::Mineral,
                Some(BaseOilArg::Pao) => BaseOil::Polyalphaolefin,
                Some(BaseOilArg::Pag) => BaseOil::Polyglycol,
                None => bail!("--base-oil: required with a datasheet (mineral, pao or pag)"),
            },
        };
        return Ok(LubricantSpec::Datasheet {
            datasheet,
            temperature_c: need(temperature, "--temperature (with a datasheet)")?,
            alpha_per_gpa: alpha.map(|a| a * 1e9),
        });
    }
    Ok(match (lubricant, alpha) {
        (Some(name), None) => LubricantSpec::Named {
            lubricant: name.to_string(),
            temperature_c: need(temperature, "--temperature")?,
        },
        (None, Some(alpha)) => LubricantSpec::Given {
            alpha_per_pa: alpha,
            eta0_pa_s: need(eta0, "--eta0")?,
        },
        (Some(_), Some(_)) => bail!("--lubricant and --alpha cannot be mixed"),
        (None, None) => bail!("--lubricant: required (or --alpha and --eta0)"),
    })
}

fn need(v: Option<f64>, flag: &str) -> Result<f64> {
    v.ok_or_else(|| anyhow!("{flag}: required"))
}

/// The rheology flags: `--rheology eyring-lss` needs `--lambda-lss` and `--tau-l0`, which
/// mean nothing with another rheology.
fn rheology(
    rheology: Option<RheologyArg>,
    lambda_lss: Option<f64>,
    tau_l0: Option<f64>,
) -> Result<Option<Rheology>> {
    Ok(match rheology {
        Some(RheologyArg::EyringLss) => Some(Rheology::EyringLss(LimitingShearStress {
            lambda: need(lambda_lss, "--lambda-lss (with --rheology eyring-lss)")?,
            tau_l0_pa: need(tau_l0, "--tau-l0 (with --rheology eyring-lss)")?,
        })),
        _ if lambda_lss.is_some() || tau_l0.is_some() => {
            bail!("--lambda-lss and --tau-l0 need --rheology eyring-lss")
        }
        Some(RheologyArg::Eyring) => Some(Rheology::Eyring),
        Some(RheologyArg::Newtonian) => Some(Rheology::Newtonian),
        None => None,
    })
}

/// The physics flags over `defaults`.
pub fn physics(
    viscosity: Option<ViscosityArg>,
    density: Option<DensityArg>,
    rheology: Option<Rheology>,
    defaults: Physics,
) -> Physics {
    Physics {
        viscosity: match viscosity {
            Some(ViscosityArg::Barus) => ViscosityLaw::Barus,
            Some(ViscosityArg::Roelands) => ViscosityLaw::Roelands,
            None => defaults.viscosity,
        },
        density: match density {
            Some(DensityArg::Incompressible) => DensityLaw::Incompressible,
            Some(DensityArg::DowsonHigginson) => DensityLaw::DowsonHigginson,
            None => defaults.density,
        },
        rheology: rheology.unwrap_or(defaults.rheology),
    }
}

impl SolveArgs {
    /// The case the flags describe (which form, and its physics).
    pub fn case(&self) -> Result<Case> {
        let dimensionless = self.m.is_some() || self.l.is_some() || self.s_bar.is_some();
        // --ph and --eta0 belong to both forms (the dimensionless form takes them for
        // Roelands and Dowson-Higginson), so they decide nothing when --m/--l/--s-bar are
        // given; alone they ask for the physical form.
        let physical_only = self.lubricant.is_some()
            || self.temperature.is_some()
            || self.um.is_some()
            || self.tau0.is_some()
            || self.alpha.is_some()
            || self.datasheet.any();
        let physical =
            physical_only || (!dimensionless && (self.ph.is_some() || self.eta0.is_some()));
        let spec = match (dimensionless, physical) {
            (true, true) => bail!("--m/--l/--s-bar (dimensionless form) and --lubricant/--temperature/--alpha/--um/--tau0 or a datasheet (physical form) cannot be mixed"),
            (false, false) => bail!("give a case: --m, --l, --s-bar (dimensionless) or --lubricant, --temperature, --ph, --um, --slip, --tau0 (physical); see --help"),
            (true, false) => CaseForm::Dimensionless(DimensionlessCase {
                m: need(self.m, "--m")?,
                l: need(self.l, "--l")?,
                s_bar: need(self.s_bar, "--s-bar")?,
                d: self.d.unwrap_or(1.0),
                slip: self.slip.unwrap_or(0.01),
                eta0_pa_s: self.eta0,
                ph_pa: self.ph,
            }),
            (false, true) => CaseForm::Physical(PhysicalCase {
                lubricant: lubricant_spec(self.lubricant.as_deref(), self.temperature, self.alpha, self.eta0, &self.datasheet)?,
                ph_pa: need(self.ph, "--ph")?,
                um_m_s: need(self.um, "--um")?,
                slip: need(self.slip, "--slip")?,
                tau0_pa: need(self.tau0, "--tau0")?,
                rx_m: self.rx,
                ry_m: self.ry.unwrap_or(self.rx),
                e_prime_pa: self.e_prime,
            }),
        };
        let defaults = if dimensionless {
            Physics::default()
        } else {
            Physics::figs_4_to_7()
        };
        let rheology = rheology(self.rheology, self.lambda_lss, self.tau_l0)?;
        let physics = physics(self.viscosity, self.density, rheology, defaults);
        Ok(Case { spec, physics })
    }

    /// Point-solver parameters for `problem`: the rule every command uses
    /// ([`point::Params::for_problem`]) at `--level`, with the numerics flags on top
    /// (`--domain auto` and `--edge auto` keep the rule's domain and edge; the others are
    /// expert overrides).
    pub fn params(&self, problem: &Problem) -> Result<point::Params> {
        let rule = point::Params::for_problem(
            problem,
            check_level("--level", self.level.unwrap_or(WORKING_LEVEL))?,
        );
        Ok(point::Params {
            domain: match self.domain {
                DomainArg::Auto => rule.domain,
                DomainArg::Paper => Domain::default(),
                DomainArg::Wide => Domain::wide(),
                DomainArg::Heavy => Domain::heavy(),
            },
            edge: match self.edge {
                EdgeArg::Auto => rule.edge,
                EdgeArg::Zero => point::Edge::Zero,
                EdgeArg::FarField => point::Edge::FarField,
            },
            max_cycles: self.max_cycles,
            newton_steps: self.newton_steps,
            rolling_friction: !self.no_rolling,
            ..rule
        })
    }

    /// The line-contact problem the flags describe (`--line`).
    pub fn line_problem(&self) -> Result<LineProblem> {
        self.reject_point_flags()?;
        let case = self.case()?;
        match &case.spec {
            CaseForm::Physical(ph) => {
                let line = LinePhysicalCase::from_point_case(ph, &LubricantTable::table1())
                    .map_err(flag_error)?;
                LineProblem::from_physical(&line, case.physics).map_err(flag_error)
            }
            CaseForm::Dimensionless(d) => {
                let line = LineDimensionlessCase {
                    m: d.m,
                    l: d.l,
                    s_bar: d.s_bar,
                    slip: d.slip,
                    eta0_pa_s: d.eta0_pa_s,
                    ph_pa: d.ph_pa,
                };
                LineProblem::from_dimensionless(&line, case.physics).map_err(flag_error)
            }
        }
    }

    /// Line-solver parameters for `problem`: the rule every command uses
    /// ([`line::Params::for_problem`]) at `--level` (default 8), with the numerics flags on
    /// top.
    pub fn line_params(&self, problem: &LineProblem) -> Result<line::Params> {
        let level = self.level.unwrap_or(line::Params::default().level);
        if !(line::MIN_LEVEL..=line::MAX_LEVEL).contains(&level) {
            bail!(
                "--level: level {level} outside the line-contact range {}..={}",
                line::MIN_LEVEL,
                line::MAX_LEVEL
            );
        }
        Ok(line::Params {
            max_iterations: self.max_cycles,
            rolling_friction: !self.no_rolling,
            ..line::Params::for_problem(problem, level)
        })
    }

    /// Flags of the elliptical contact that a line contact cannot take.
    fn reject_point_flags(&self) -> Result<()> {
        if self.ry.is_some() {
            bail!("--ry: a line contact has no Ry (it is infinite); drop --ry with --line");
        }
        if self.d.is_some() {
            bail!("--d: a line contact has D = Rx/Ry = 0; drop --d with --line");
        }
        if !matches!(self.domain, DomainArg::Auto) {
            bail!("--domain: the line contact has its own domain (-4.5 <= X <= 1.5); drop --domain with --line");
        }
        if !matches!(self.edge, EdgeArg::Auto) {
            bail!("--edge: the line contact has its own edge (P = 0); drop --edge with --line");
        }
        Ok(())
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
        check_level("--level", l)?;
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
    })
}
