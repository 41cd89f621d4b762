//! The flags that describe a contact and its solve: `repro solve` and `repro predict`, the
//! lubricant's datasheet and the thermal post-process's inputs.

use clap::{Args, ValueEnum};
use repro::solver::point::Params;
use std::path::PathBuf;

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum ViscosityArg {
    Barus,
    Roelands,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum DensityArg {
    Incompressible,
    DowsonHigginson,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum RheologyArg {
    Eyring,
    Newtonian,
    /// Eyring with a limiting shear stress tau_L = tau_L0 + Lambda p (--lambda-lss, --tau-l0;
    /// beyond the paper).
    EyringLss,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum DomainArg {
    /// The case's domain by the rule every command and target uses: the paper's from
    /// M = 300 to 4000, the heavy-load one above, the wide one below, grown further where
    /// the light, viscous contacts' inlet pressure reaches out (with the flooded inlet's far
    /// field on its edge in every case). The others are expert overrides (with the same edge).
    Auto,
    /// -2.5 <= X <= 1.5, -2 <= Y <= 2: the paper's (reproduces Table 4).
    Paper,
    /// -4.5 <= X <= 1.5, -3 <= Y <= 3: a longer inlet for lightly loaded contacts (M < 100).
    Wide,
    /// -1.75 <= X <= 1.25, -1.5 <= Y <= 1.5: a finer mesh where heavily loaded contacts
    /// (M >= 4000) need it.
    Heavy,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum EdgeArg {
    /// The case's edge by the rule every command and target uses: the flooded inlet's far
    /// field.
    Auto,
    /// P = 0 on the domain's edge, the paper's (and most EHL codes'): compare like with like
    /// with such a code, on its domain (--domain).
    Zero,
    /// The flooded inlet's far field, its amplitude fixed a priori from lambda (the rule's).
    FarField,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum PatchArg {
    /// The rule's grid: uniform, or nested domains for the light contacts.
    None,
    /// A composite grid: the domain at the level and a patch over the inlet's pressure rise
    /// (X from -1.2, a quarter of the domain per direction) at half its mesh, coupled both
    /// ways. The central film of a contact from M of about 300 up comes out as the uniform
    /// grid one level finer gives it, at 40-80 % of that grid's time; the friction moves
    /// about half-way, the minimum film not (docs/ACCURACY_NOTES.md, "Composite grid").
    /// Solved cold, at the level given, with its own error estimate.
    Inlet,
    /// Two patches over the side lobes (a quarter of the domain per direction each), centred
    /// on the whole-domain level's minimum film and mirrored about the axis: the minimum film
    /// of a heavy contact comes out as the uniform grid one level finer gives it, at more than
    /// that grid's time (docs/ACCURACY_NOTES.md, "Patches over the side lobes").
    Lobes,
    /// The inlet's patch and the side lobes': the central and the minimum film of the uniform
    /// grid one level finer, the friction 60 % of the way there, at 1.7-1.8 times that grid's
    /// time.
    InletAndLobes,
}

#[derive(Debug, Args)]
#[command(allow_negative_numbers = true)]
pub struct SolveArgs {
    // Dimensionless form.
    /// Moes load parameter M (dimensionless form).
    #[arg(long, help_heading = "Dimensionless form")]
    pub m: Option<f64>,
    /// Moes lubricant parameter L.
    #[arg(long, help_heading = "Dimensionless form")]
    pub l: Option<f64>,
    /// Dimensionless slip S-bar, Eq. (9); 0 is pure rolling.
    #[arg(long = "s-bar", help_heading = "Dimensionless form")]
    pub s_bar: Option<f64>,
    /// Ellipticity ratio D = Rx/Ry in (0, 1] (default 1; not with --line).
    #[arg(long, help_heading = "Dimensionless form")]
    pub d: Option<f64>,

    // Physical form.
    /// Lubricant of Table 1 (cases/lubricants.toml): traction-fluid, mineral-oil-a, 5p4e.
    #[arg(long, help_heading = "Physical form")]
    pub lubricant: Option<String>,
    /// Temperature, C (with --lubricant: 40, 60 or 100 C, or between; with a datasheet: any
    /// temperature in -20..150 C).
    #[arg(long, help_heading = "Physical form")]
    pub temperature: Option<f64>,
    /// Pressure-viscosity coefficient, 1/Pa (instead of --lubricant; with a datasheet, instead
    /// of the AGMA 925 correlation).
    #[arg(long, help_heading = "Physical form")]
    pub alpha: Option<f64>,
    /// Maximum Hertzian pressure p_H, Pa.
    #[arg(long, help_heading = "Physical form")]
    pub ph: Option<f64>,
    /// Mean velocity u_m = (u1 + u2)/2, m/s.
    #[arg(long, help_heading = "Physical form")]
    pub um: Option<f64>,
    /// Eyring stress tau0, Pa.
    #[arg(long, help_heading = "Physical form")]
    pub tau0: Option<f64>,
    /// Reduced radius in the rolling direction Rx, m.
    #[arg(long, default_value_t = 1.03875e-2, help_heading = "Physical form")]
    pub rx: f64,
    /// Reduced radius across the rolling direction Ry, m (default: Rx, a circular contact).
    #[arg(long, help_heading = "Physical form")]
    pub ry: Option<f64>,
    /// Reduced modulus E', Pa.
    #[arg(
        long = "e-prime",
        default_value_t = 226e9,
        help_heading = "Physical form"
    )]
    pub e_prime: f64,
    #[command(flatten)]
    pub datasheet: DatasheetArgs,

    // Both forms.
    /// Slide-to-roll ratio S in [0, 2]. In the dimensionless form it fixes, with S-bar, the
    /// Eyring stress and so the size of the rolling friction in mu-bar (default 0.01 there).
    #[arg(long)]
    pub slip: Option<f64>,
    /// Ambient viscosity eta0, Pa s (physical form without --lubricant; dimensionless form with
    /// Roelands).
    #[arg(long)]
    pub eta0: Option<f64>,
    /// Viscosity-pressure law.
    #[arg(long, value_enum)]
    pub viscosity: Option<ViscosityArg>,
    /// Density-pressure law.
    #[arg(long, value_enum)]
    pub density: Option<DensityArg>,
    /// Rheology.
    #[arg(long, value_enum)]
    pub rheology: Option<RheologyArg>,
    /// Limiting shear stress's pressure slope Lambda = d tau_L / dp (with --rheology
    /// eyring-lss; e.g. 0.08).
    #[arg(long = "lambda-lss")]
    pub lambda_lss: Option<f64>,
    /// Limiting shear stress at ambient pressure tau_L0, Pa (with --rheology eyring-lss;
    /// must be > 0).
    #[arg(long = "tau-l0")]
    pub tau_l0: Option<f64>,

    /// Solve a line contact (1-D solver, Fig. 7) with the same flags; --ry and --d do not
    /// apply. The load is given by --ph (physical form) or by the line-contact M.
    #[arg(long)]
    pub line: bool,

    // Numerics and output.
    /// Grid level: 2^(level+1) points per direction (default 7, the paper's 256 x 256; with
    /// --line default 8, 512 intervals). A point contact whose sliding friction is estimated
    /// more than 1 % off there is solved one level finer; the output names the level.
    #[arg(long, help_heading = "Numerics")]
    pub level: Option<u32>,
    /// Solve exactly the level given: no finer level where the estimated error misses the
    /// accuracy target (or, for a line contact, where fewer than three levels are inside the
    /// asymptotic range), so the output shows what one level costs and buys. A film that
    /// closes at that level is an error naming the level it needs.
    #[arg(long = "exact-level", help_heading = "Numerics")]
    pub exact_level: bool,
    /// Computational domain.
    #[arg(long, value_enum, default_value = "auto", help_heading = "Numerics")]
    pub domain: DomainArg,
    /// The condition on the domain's edge (an expert override, like --domain).
    #[arg(long, value_enum, default_value = "auto", help_heading = "Numerics")]
    pub edge: EdgeArg,
    /// A composite grid's patches (an expert option; not the figures').
    #[arg(long, value_enum, default_value = "none", help_heading = "Numerics")]
    pub patch: PatchArg,
    /// Most multigrid cycles on the finest level.
    #[arg(long = "max-cycles", default_value_t = Params::default().multigrid.max_cycles, help_heading = "Numerics")]
    pub max_cycles: usize,
    /// Most Newton steps per level of the Newton-Krylov finish that takes over a
    /// point-contact solve when its cycles stall, diverge or run out (grid-sequenced from
    /// level 5 up to the finest); 0 turns the finish off.
    #[arg(long = "newton-steps", default_value_t = Params::default().newton.steps, help_heading = "Numerics")]
    pub newton_steps: usize,
    /// Skip the rolling (Poiseuille) part of the friction.
    #[arg(long = "no-rolling", help_heading = "Numerics")]
    pub no_rolling: bool,
    /// Solve from the Hertzian pressure alone, not from the case's base (the same contact
    /// at S 0.5 % and tau0 6 MPa, or S-bar 0.1 in Moes groups, solved first, as every sweep
    /// does): the path of Table 4 and the benchmarks. Without it the result is the bits of
    /// the case's figure row.
    #[arg(long, help_heading = "Numerics")]
    pub cold: bool,
    /// Print one JSON object instead of the summary.
    #[arg(long, help_heading = "Output")]
    pub json: bool,
    /// Write the pressure and film fields to this CSV file (columns X, Y, P, H).
    #[arg(long, help_heading = "Output")]
    pub fields: Option<PathBuf>,
    #[command(flatten)]
    pub thermal: ThermalArgs,
    /// No per-cycle progress on stderr.
    #[arg(long, short, help_heading = "Output")]
    pub quiet: bool,
}

/// Flags of `repro predict`.
#[derive(Debug, Args)]
#[command(allow_negative_numbers = true)]
pub struct PredictArgs {
    /// Lubricant of Table 1 (cases/lubricants.toml): traction-fluid, mineral-oil-a, 5p4e.
    #[arg(long, help_heading = "Lubricant")]
    pub lubricant: Option<String>,
    /// Temperature, C (with --lubricant: 40, 60 or 100 C, or between; with a datasheet: any
    /// temperature in -20..150 C).
    #[arg(long, help_heading = "Lubricant")]
    pub temperature: Option<f64>,
    /// Pressure-viscosity coefficient, 1/Pa (instead of --lubricant; with a datasheet, instead
    /// of the AGMA 925 correlation).
    #[arg(long, help_heading = "Lubricant")]
    pub alpha: Option<f64>,
    /// Ambient viscosity eta0, Pa s (with --alpha).
    #[arg(long, help_heading = "Lubricant")]
    pub eta0: Option<f64>,
    /// Viscosity-pressure law of eta(p_H) in tau_c (default roelands, as in Figs. 4-7).
    #[arg(long, value_enum, help_heading = "Lubricant")]
    pub viscosity: Option<ViscosityArg>,
    #[command(flatten)]
    pub datasheet: DatasheetArgs,

    /// Maximum Hertzian pressure p_H, Pa (or --load).
    #[arg(long, help_heading = "Contact")]
    pub ph: Option<f64>,
    /// Normal load f, N (or --ph).
    #[arg(long, help_heading = "Contact")]
    pub load: Option<f64>,
    /// Reduced radius in the rolling direction Rx, m.
    #[arg(long, default_value_t = 1.03875e-2, help_heading = "Contact")]
    pub rx: f64,
    /// Reduced radius across the rolling direction Ry, m (default: Rx, a circular contact).
    #[arg(long, help_heading = "Contact")]
    pub ry: Option<f64>,
    /// Reduced modulus E', Pa.
    #[arg(long = "e-prime", default_value_t = 226e9, help_heading = "Contact")]
    pub e_prime: f64,
    /// Mean velocity u_m = (u1 + u2)/2, m/s.
    #[arg(long, help_heading = "Contact")]
    pub um: f64,
    /// Slide-to-roll ratio S = 2 (u2 - u1)/(u2 + u1), in [0, 2].
    #[arg(long, help_heading = "Contact")]
    pub slip: f64,
    /// Eyring stress tau0, Pa.
    #[arg(long, help_heading = "Contact")]
    pub tau0: f64,

    /// Also run the full EHL solve (Roelands, Dowson-Higginson, Eyring) and print the
    /// difference.
    #[arg(long, help_heading = "Solve")]
    pub solve: bool,
    /// Grid level of --solve: 2^(level+1) points per direction (7 is the paper's 256 x 256).
    #[arg(long, default_value_t = 7, help_heading = "Solve")]
    pub level: u32,
    /// Density-pressure law of --solve (default dowson-higginson).
    #[arg(long, value_enum, help_heading = "Solve")]
    pub density: Option<DensityArg>,
    #[command(flatten)]
    pub thermal: ThermalArgs,

    /// Print one JSON object instead of the summary.
    ///
    /// Keys: `lubricant` {source (table1, given, datasheet), eta0_pa_s, alpha_per_pa,
    /// alpha_source, alpha_correlated, alpha_band_per_pa ([low, high] 1/Pa when correlated,
    /// else null); for a datasheet also datasheet, temperature_c, nu_mm2_s and rho_kg_m3 at
    /// it, nu40_mm2_s, nu100_mm2_s, viscosity_index, expansion15_per_k}; the contact's ph_pa,
    /// m, l, s_bar, slip, tau0_pa, eta_bar_ph, hc_eq10, hc_m, tau_c; Eq. (14)'s mu_bar, mu;
    /// the refined formula's mu_bar_refined, mu_refined and their bands
    /// mu_bar_refined_band, mu_refined_band (its own 95 % band, around its range over the
    /// alpha band when alpha is correlated); tau_c_band, hc_m_band, mu_bar_band, mu_band
    /// ([low, high] over the alpha band when alpha is correlated, else null); thermal,
    /// mu_bar_thermal, warnings, solve and difference (--solve), compute_seconds.
    #[arg(long, help_heading = "Output")]
    pub json: bool,
    /// No per-cycle progress of --solve on stderr.
    #[arg(long, short, help_heading = "Output")]
    pub quiet: bool,
}

/// A lubricant's datasheet (`repro solve`, `repro predict`): eta0 = nu rho at --temperature
/// by ASTM D341 and D1250, alpha from AGMA 925 for the base oil unless --alpha is given.
#[derive(Debug, Args)]
pub struct DatasheetArgs {
    /// Kinematic viscosity at 40 C, mm^2/s (or --iso-vg).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub nu40: Option<f64>,
    /// ISO 3448 viscosity grade (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, ..., 3200): nu40 is
    /// its midpoint (or --nu40).
    #[arg(long = "iso-vg", help_heading = "Lubricant datasheet")]
    pub iso_vg: Option<u32>,
    /// Kinematic viscosity at 100 C, mm^2/s (or --vi).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub nu100: Option<f64>,
    /// Viscosity index, ASTM D2270: nu100 follows from it and nu40 (or --nu100).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub vi: Option<f64>,
    /// Density at 15 C, kg/m^3.
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub rho15: Option<f64>,
    /// Thermal expansion coefficient at 15 C, 1/K (default: ASTM D1250 Table 54D's for
    /// rho15).
    #[arg(long, help_heading = "Lubricant datasheet")]
    pub expansion15: Option<f64>,
    /// Base-oil type, for the pressure-viscosity correlation.
    #[arg(long = "base-oil", value_enum, help_heading = "Lubricant datasheet")]
    pub base_oil: Option<BaseOilArg>,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum BaseOilArg {
    /// Mineral oil.
    Mineral,
    /// Polyalphaolefin without viscosity-index improver.
    Pao,
    /// Polyalkylene glycol.
    Pag,
}

/// The thermal post-process's inputs (`repro solve`, `repro predict`).
#[derive(Debug, Args)]
pub struct ThermalArgs {
    /// Thermal conductivity of both solids, W/(m K): 46 for bearing steel, 21 for
    /// through-hardened steel (density 7850 kg/m^3, specific heat 470 J/(kg K)).
    #[arg(
        long = "k-solid",
        default_value_t = 46.0,
        help_heading = "Thermal post-process"
    )]
    pub k_solid: f64,
    /// Thermal conductivity of the lubricant film, W/(m K).
    #[arg(
        long = "k-lubricant",
        default_value_t = 0.13,
        help_heading = "Thermal post-process"
    )]
    pub k_lubricant: f64,
}
