//! `repro predict`: the friction of a user's contact from the mastercurve, the "simple tool
//! for engineering use" of the Conclusions. The contact is given physically; Sec. IV's
//! transform ([`repro::physics::traction::characteristic`]) gives `tau_c` (Eq. 12), Eq. (14)
//! gives `mu-bar = asinh(tau_c / 5)` and Eq. (8) `mu = mu-bar tau0 / p_H`. With `--solve` the
//! full EHL solve of the same contact (the physics of Figs. 4-7) is printed beside it.

use super::args::PredictArgs;
use super::config::{check_level, flag_error, lubricant_spec, physics};
use super::print::{print_failure, rolling_text, solve_progress};
use super::solve::point_report;
use super::thermal::{self, ThermalReport};
use anyhow::{bail, Result};
use repro::artefacts::base::solve_case;
use repro::artefacts::fit::{mastercurve, FIT_TAU_C_MIN, PAPER_C};
use repro::artefacts::refined::{Features, REFINED, REFINED_BAND};
use repro::physics::case::{Case, PhysicalCase, Physics, Problem, Spec};
use repro::physics::lubricant::LubricantTable;
use repro::physics::thermal::ThermalError;
use repro::physics::traction::{
    characteristic, Characteristic, Contact, FilmFormula, Load, OperatingPoint, Sliding, Speed,
    ViscosityAtPh, ISOTHERMAL_SLIP_MAX,
};
use repro::solver::point::{Params, PointSolution};
use serde_json::json;
use std::time::Instant;

/// What the paper says about where Eq. (14) does not hold, for this case: low `tau_c`, and
/// shear heating beyond [`repro::physics::thermal::ISOTHERMAL_CORRECTION_MAX`] (where the
/// correction cannot be estimated, the paper's largest slip instead).
fn warnings(c: &Characteristic, heat: &Option<Result<ThermalReport, ThermalError>>) -> Vec<String> {
    let mut w = Vec::new();
    if c.tau_c < FIT_TAU_C_MIN {
        w.push(format!(
            "tau_c = {:.3e} is below {FIT_TAU_C_MIN}: at low tau_c the paper finds friction straying from the mastercurve because rolling friction dominates (Sec. III A, Figs. 2-3); Eq. (14) gives the sliding friction only",
            c.tau_c
        ));
    }
    if let (_, Some(warning)) = thermal::describe(heat) {
        w.push(warning);
    }
    if heat.is_none() && c.slip > ISOTHERMAL_SLIP_MAX {
        w.push(format!(
            "S = {} is above {ISOTHERMAL_SLIP_MAX}, the largest slip of the paper's isothermal runs (Table 2, Sec. III B): with significant sliding, shear heating makes Eq. (14) predict too large a friction (Conclusions)",
            c.slip
        ));
    }
    w
}

/// `repro predict`: false when the --solve did not converge (after printing why).
pub fn run(args: &PredictArgs) -> Result<bool> {
    let level = check_level("--level", args.level)?;
    let lubricant = lubricant_spec(
        args.lubricant.as_deref(),
        args.temperature,
        args.alpha,
        args.eta0,
    )?;
    let physics = physics(args.viscosity, args.density, None, Physics::figs_4_to_7());
    let load = match (args.ph, args.load) {
        (Some(ph), None) => Load::MaxPressure(ph),
        (None, Some(f)) => Load::Force(f),
        (Some(_), Some(_)) => bail!("--ph and --load cannot be mixed"),
        (None, None) => bail!("--ph: required (or --load)"),
    };
    let (um, slip, tau0) = (args.um, args.slip, args.tau0);
    let ry = args.ry.unwrap_or(args.rx);
    let point = OperatingPoint {
        contact: Contact::Elliptical {
            rx_m: args.rx,
            ry_m: ry,
        },
        e_prime_pa: args.e_prime,
        load,
        lubricant: lubricant.clone(),
        speed: Speed::Mean(um),
        sliding: Sliding::Slip(slip),
        tau0_pa: tau0,
        viscosity: ViscosityAtPh::Law(physics.viscosity),
        film: FilmFormula::Eq10,
    };
    let lubs = LubricantTable::table1();

    // The whole prediction: operating point -> tau_c -> mu-bar -> mu.
    let start = Instant::now();
    let c = characteristic(&point, &lubs).map_err(flag_error)?;
    let mu_bar = mastercurve(c.tau_c, PAPER_C);
    let mu = c.friction(mu_bar, tau0);
    let compute_seconds = start.elapsed().as_secs_f64();

    // The refined formula needs the contact's Hertz scales and viscosity law: its problem.
    let case = Case {
        spec: Spec::Physical(PhysicalCase {
            lubricant,
            ph_pa: c.ph_pa,
            um_m_s: um,
            slip,
            tau0_pa: tau0,
            rx_m: args.rx,
            ry_m: ry,
            e_prime_pa: args.e_prime,
        }),
        physics,
    };
    let problem = Problem::from_case(&case, &lubs).map_err(flag_error)?;
    let refined = Prediction::of(&problem, tau0, &c);

    let inputs = args.thermal.inputs()?;
    let solved = if args.solve {
        let params = Params::for_problem(&problem, level);
        let mut printer = solve_progress(args.quiet || args.json);
        // As `repro solve` and the sweeps: the case's base first ([`solve_case`]).
        let mut said = |_: &Case| {};
        match solve_case(
            &case,
            &problem,
            &params,
            &lubs,
            &mut said,
            Some(&mut printer),
        ) {
            Ok(s) => Some((problem.clone(), s)),
            Err(e) => {
                print_failure(&e);
                return Ok(false);
            }
        }
    } else {
        None
    };
    // The shear-heating correction: of the solve where there is one, else the flat-film
    // estimate; applied to Eq. (14) as a relative correction.
    let heat = match &solved {
        Some((p, s)) => thermal::of_solution(&case, p, s, &inputs),
        None => thermal::flat_estimate(&case, &problem, &inputs),
    };
    let mu_bar_thermal = match &heat {
        Some(Ok(r)) => Some(mu_bar * (1.0 + r.correction())),
        _ => None,
    };
    let warns = warnings(&c, &heat);

    if args.json {
        let solve = solved.as_ref().map(|(p, s)| {
            let mut v = point_report(p, s).json();
            v["mu_sliding"] = json!(c.friction(s.friction.sliding, tau0));
            v
        });
        let difference = solved.as_ref().map(|(_, s)| {
            json!({
                "mu_bar": mu_bar - s.friction.sliding,
                "relative": mu_bar / s.friction.sliding - 1.0,
                "mu_bar_refined": refined.mu_bar - s.friction.sliding,
                "relative_refined": refined.mu_bar / s.friction.sliding - 1.0,
            })
        });
        let out = json!({
            "ph_pa": c.ph_pa, "m": c.m, "l": c.l, "s_bar": c.s_bar, "slip": c.slip,
            "tau0_pa": tau0, "eta_bar_ph": c.eta_bar_ph, "hc_eq10": c.hc_moes, "hc_m": c.hc_m,
            "tau_c": c.tau_c, "mu_bar": mu_bar, "mu": mu,
            "mu_bar_source": "Eq. (14) of the paper, mu-bar = asinh(tau_c / 5)",
            "mu_bar_refined": refined.mu_bar, "mu_refined": refined.mu,
            "mu_bar_refined_band": [refined.low, refined.high],
            "mu_bar_refined_source": "refined formula (beyond the paper; repro mastercurve), band: 95 % of cross-validated residuals",
            "compute_seconds": compute_seconds,
            "thermal": thermal::json_of(&heat),
            "mu_bar_thermal": mu_bar_thermal,
            "warnings": warns,
            "solve": solve,
            "difference": difference,
        });
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        print!(
            "{}",
            text(
                &c,
                mu_bar,
                mu,
                &refined,
                compute_seconds,
                tau0,
                solved.as_ref().map(|(_, s)| s)
            )
        );
        print!("{}", thermal::describe(&heat).0);
        if let Some(m) = mu_bar_thermal {
            println!(
                "            Eq. (14) with the thermal correction: mu-bar = {m:.4}, mu = {:.5}",
                c.friction(m, tau0)
            );
        }
        for w in &warns {
            eprintln!("warning: {w}");
        }
    }
    Ok(true)
}

/// The refined formula's friction of a contact, with its band.
struct Prediction {
    mu_bar: f64,
    mu: f64,
    low: f64,
    high: f64,
}

impl Prediction {
    fn of(problem: &Problem, tau0: f64, c: &Characteristic) -> Self {
        let mu_bar = REFINED.predict(&Features::point(problem));
        Prediction {
            mu_bar,
            mu: c.friction(mu_bar, tau0),
            low: mu_bar * (1.0 - REFINED_BAND),
            high: mu_bar * (1.0 + REFINED_BAND),
        }
    }
}

fn text(
    c: &Characteristic,
    mu_bar: f64,
    mu: f64,
    refined: &Prediction,
    compute_seconds: f64,
    tau0: f64,
    solved: Option<&PointSolution>,
) -> String {
    let mut out = format!(
        "contact     p_H = {:.4e} Pa, M = {:.4}, L = {:.4}, S-bar = {:.4e}, S = {}\n\
         tau_c       {:.4e}  (Eq. 12: eta(p_H)/eta0 = {:.4e}, Hc of Eq. 10 = {:.4} = {:.4e} m)\n\
         mastercurve mu-bar = asinh(tau_c/5) = {:.4}  (the paper's Eq. 14, sliding friction)\n\
         friction    mu = mu-bar tau0 / p_H = {:.5}\n\
         refined     mu_bar_refined = {:.4} ({:.4} .. {:.4}), mu = {:.5}  (beyond the paper: flat-film formula fitted to Figs. 3-7, repro mastercurve; band holds 95 % of its cross-validated cases)\n\
         compute     {:.1} us\n",
        c.ph_pa,
        c.m,
        c.l,
        c.s_bar,
        c.slip,
        c.tau_c,
        c.eta_bar_ph,
        c.hc_moes,
        c.hc_m,
        mu_bar,
        mu,
        refined.mu_bar,
        refined.low,
        refined.high,
        refined.mu,
        compute_seconds * 1e6,
    );
    if let Some(s) = solved {
        let solve_mu = c.friction(s.friction.sliding, tau0);
        out.push_str(&format!(
            "solve       {} x {}: mu-bar sliding = {:.4} (mu = {:.5}), rolling = {}, Hc = {:.4} (Moes), {} cycles, {:.2} s\n\
             difference  mastercurve - solve: mu-bar {:+.4} ({:+.2} %), mu {:+.5}; refined - solve: mu-bar {:+.4} ({:+.2} %)\n",
            s.grid.nx,
            s.grid.ny,
            s.friction.sliding,
            solve_mu,
            rolling_text(s.friction.rolling),
            s.film.hc_moes,
            s.info.cycles,
            s.info.seconds,
            mu_bar - s.friction.sliding,
            100.0 * (mu_bar / s.friction.sliding - 1.0),
            mu - solve_mu,
            refined.mu_bar - s.friction.sliding,
            100.0 * (refined.mu_bar / s.friction.sliding - 1.0),
        ));
    }
    out
}
