//! `repro predict`: the friction of a user's contact from the mastercurve, the "simple tool
//! for engineering use" of the Conclusions. The contact is given physically; Sec. IV's
//! transform ([`repro::physics::traction::characteristic`]) gives `tau_c` (Eq. 12), Eq. (14)
//! gives `mu-bar = asinh(tau_c / 5)` and Eq. (8) `mu = mu-bar tau0 / p_H`. With `--solve` the
//! full EHL solve of the same contact (the physics of Figs. 4-7) is printed beside it.
//!
//! The lubricant is printed first, with where its `alpha` comes from. When that is a
//! correlation (a datasheet without `--alpha`), every output that depends on `alpha` is
//! printed with the range it takes over the correlation's band
//! ([`repro::paper::prediction`]), and the refined formula's band holds that range and the
//! formula's own.

use super::args::PredictArgs;
use super::config::{check_level, flag_error, lubricant_spec, physics};
use super::print::{print_failure, rolling_text, solve_progress};
use super::thermal;
use anyhow::{bail, Result};
use repro::paper::prediction::contact::EngineeringContact;
use repro::paper::prediction::heat::{warnings, HeatCorrection};
use repro::paper::prediction::{Band, Prediction};
use repro::physics::case::{Case, CaseForm, LubricantSpec, Physics};
use repro::physics::lubricant::LubricantTable;
use repro::physics::traction::Load;
use repro::pipeline::base::solve_case;
use repro::pipeline::error::PipelineError;
use repro::report::solve::point_report;
use repro::solver::point::{Params, PointSolution};
use serde_json::json;
use std::time::Instant;

/// `repro predict`: false when the --solve did not converge (after printing why).
pub fn run(args: &PredictArgs) -> Result<bool> {
    let level = check_level("level", args.level)?;
    let lubricant = lubricant_spec(
        args.lubricant.as_deref(),
        args.temperature,
        args.alpha,
        args.eta0,
        &args.datasheet.inputs(),
    )?;
    let physics = physics(
        args.viscosity.map(|v| v.law()),
        args.density.map(|d| d.law()),
        None,
        Physics::figs_4_to_7(),
    );
    let load = match (args.ph, args.load) {
        (Some(ph), None) => Load::MaxPressure(ph),
        (None, Some(f)) => Load::Force(f),
        (Some(_), Some(_)) => bail!("--ph and --load cannot be mixed"),
        (None, None) => bail!("--ph: required (or --load)"),
    };
    let tau0 = args.tau0;
    let contact = EngineeringContact {
        lubricant,
        physics,
        load,
        rx_m: args.rx,
        ry_m: args.ry.unwrap_or(args.rx),
        e_prime_pa: args.e_prime,
        um_m_s: args.um,
        slip: args.slip,
        tau0_pa: tau0,
    };
    let lubs = LubricantTable::table1();

    // The whole prediction: operating point -> p_H -> the case -> tau_c -> mu-bar -> mu, and
    // the refined formula (which needs the case's Hertz scales and viscosity law), at the
    // lubricant's alpha and at the ends of its band when it is estimated.
    let start = Instant::now();
    let case = contact.case(&lubs).map_err(flag_error)?;
    let prediction = Prediction::of(&case, &lubs).map_err(flag_error)?;
    let compute_seconds = start.elapsed().as_secs_f64();
    let c = prediction.central.characteristic;
    let (mu_bar, mu) = (prediction.central.mu_bar, prediction.central.mu);
    let refined = &prediction.central;
    let refined_band = prediction.mu_bar_refined_band();
    let problem = prediction.problem.clone();
    let lubricant = describe_lubricant(&case, &lubs)?;

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
            Err(PipelineError::Solve(e)) => {
                print_failure(&e);
                return Ok(false);
            }
            Err(e) => return Err(e.into()),
        }
    } else {
        None
    };
    // The shear-heating correction: of the solve where there is one, else the flat-film
    // estimate; applied to Eq. (14) as a relative correction.
    let heat = match &solved {
        Some((p, s)) => HeatCorrection::of_solution(&case, p, s, &inputs),
        None => HeatCorrection::flat_estimate(&case, &problem, &inputs),
    };
    let mu_bar_thermal = match &heat {
        Some(Ok(h)) => Some(h.corrected(mu_bar)),
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
                "mu_bar_refined": refined.mu_bar_refined - s.friction.sliding,
                "relative_refined": refined.mu_bar_refined / s.friction.sliding - 1.0,
            })
        });
        let pair = |b: Option<Band>| b.map(Band::pair);
        let out = json!({
            "lubricant": lubricant.json,
            "ph_pa": c.ph_pa, "m": c.m, "l": c.l, "s_bar": c.s_bar, "slip": c.slip,
            "tau0_pa": tau0, "eta_bar_ph": c.eta_bar_ph, "hc_eq10": c.hc_moes, "hc_m": c.hc_m,
            "hc_m_band": pair(prediction.hc_m_band()),
            "tau_c": c.tau_c, "tau_c_band": pair(prediction.tau_c_band()),
            "mu_bar": mu_bar, "mu_bar_band": pair(prediction.mu_bar_band()),
            "mu": mu, "mu_band": pair(prediction.mu_band()),
            "mu_bar_source": "Eq. (14) of the paper, mu-bar = asinh(tau_c / 5)",
            "mu_bar_refined": refined.mu_bar_refined, "mu_refined": refined.mu_refined,
            "mu_bar_refined_band": refined_band.pair(),
            "mu_refined_band": prediction.mu_refined_band().pair(),
            "mu_bar_refined_source": if prediction.alpha_band.is_some() {
                "refined formula (beyond the paper; repro mastercurve), band: 95 % of cross-validated residuals around its range over the alpha band"
            } else {
                "refined formula (beyond the paper; repro mastercurve), band: 95 % of cross-validated residuals"
            },
            "compute_seconds": compute_seconds,
            "thermal": thermal::json_of(&heat),
            "mu_bar_thermal": mu_bar_thermal,
            "warnings": warns,
            "solve": solve,
            "difference": difference,
        });
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        print!("{}", lubricant.text);
        print!(
            "{}",
            text(
                &prediction,
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

/// The lubricant as printed: a text block and a JSON object.
struct LubricantReport {
    text: String,
    json: serde_json::Value,
}

/// What the lubricant is, its `eta0` and `alpha`, and where `alpha` comes from: Table 1, the
/// user, or a correlation (then with its band and source, and said so).
fn describe_lubricant(case: &Case, lubs: &LubricantTable) -> Result<LubricantReport> {
    let CaseForm::Physical(p) = &case.spec else {
        bail!("repro predict takes a physical contact");
    };
    let state = p.lubricant.resolve(lubs).map_err(flag_error)?;
    let (eta0, alpha) = (state.eta0_pa_s, state.alpha_per_pa);
    let gpa = |a: f64| a * 1e9;
    Ok(match &p.lubricant {
        LubricantSpec::Named {
            lubricant,
            temperature_c,
        } => LubricantReport {
            text: format!(
                "lubricant   {lubricant} at {temperature_c} C (Table 1): eta0 = {eta0:.4e} Pa s, alpha = {:.2} 1/GPa\n",
                gpa(alpha)
            ),
            json: json!({
                "source": "table1", "name": lubricant, "temperature_c": temperature_c,
                "eta0_pa_s": eta0, "alpha_per_pa": alpha, "alpha_correlated": false,
                "alpha_source": "Table 1 (cases/lubricants.toml)", "alpha_band_per_pa": null,
            }),
        },
        LubricantSpec::Given { .. } => LubricantReport {
            text: format!(
                "lubricant   given: eta0 = {eta0:.4e} Pa s, alpha = {:.2} 1/GPa (--alpha)\n",
                gpa(alpha)
            ),
            json: json!({
                "source": "given", "eta0_pa_s": eta0, "alpha_per_pa": alpha,
                "alpha_correlated": false, "alpha_source": "given (--alpha)",
                "alpha_band_per_pa": null,
            }),
        },
        LubricantSpec::Datasheet {
            datasheet,
            temperature_c,
            alpha_per_gpa,
        } => {
            // The computation of `LubricantSpec::datasheet_state`, keeping the laws to print.
            let sheet = datasheet.resolve().map_err(|e| flag_error(e.into()))?;
            let d = sheet
                .at(*temperature_c, *alpha_per_gpa)
                .map_err(|e| flag_error(e.into()))?;
            let vi = sheet
                .viscosity_index()
                .map_or_else(|| "none (nu100 < 2 mm^2/s)".into(), |v| format!("{v:.1}"));
            let mut text = format!(
                "lubricant   {} (nu40 = {:.4} mm^2/s, nu100 = {:.4} mm^2/s, VI {vi}, rho15 = {} kg/m^3, expansion {:.4e} 1/K)\n\
                 \x20           at {temperature_c} C: nu = {:.4} mm^2/s (ASTM D341), rho = {:.2} kg/m^3 (ASTM D1250), eta0 = nu rho = {eta0:.4e} Pa s\n",
                datasheet.label(),
                sheet.nu40_mm2_s(),
                sheet.nu100_mm2_s(),
                datasheet.rho15_kg_m3,
                sheet.density().expansion15_per_k(),
                d.nu_mm2_s,
                d.rho_kg_m3,
            );
            let (source, band) = match &d.correlated {
                Some(e) => {
                    text.push_str(&format!(
                        "alpha       {:.2} 1/GPa, CORRELATED (no --alpha given): band {:.2} .. {:.2} 1/GPa; {}\n",
                        gpa(alpha),
                        gpa(e.low_per_pa),
                        gpa(e.high_per_pa),
                        e.source
                    ));
                    (e.source, Some([e.low_per_pa, e.high_per_pa]))
                }
                None => {
                    text.push_str(&format!(
                        "alpha       {:.2} 1/GPa, given (--alpha): no correlation, no band\n",
                        gpa(alpha)
                    ));
                    ("given (--alpha)", None)
                }
            };
            LubricantReport {
                text,
                json: json!({
                    "source": "datasheet", "datasheet": datasheet, "temperature_c": temperature_c,
                    "nu40_mm2_s": sheet.nu40_mm2_s(), "nu100_mm2_s": sheet.nu100_mm2_s(),
                    "viscosity_index": sheet.viscosity_index(),
                    "expansion15_per_k": sheet.density().expansion15_per_k(),
                    "nu_mm2_s": d.nu_mm2_s, "rho_kg_m3": d.rho_kg_m3, "eta0_pa_s": eta0,
                    "alpha_per_pa": alpha, "alpha_correlated": d.correlated.is_some(),
                    "alpha_source": source, "alpha_band_per_pa": band,
                }),
            }
        }
    })
}

/// ` (a .. b over the alpha band)` when there is one, formatted with `f`.
fn over_alpha(band: Option<Band>, f: impl Fn(f64) -> String) -> String {
    band.map_or_else(String::new, |b| {
        format!(" ({} .. {} over the alpha band)", f(b.low), f(b.high))
    })
}

fn text(
    prediction: &Prediction,
    compute_seconds: f64,
    tau0: f64,
    solved: Option<&PointSolution>,
) -> String {
    let e = &prediction.central;
    let c = &e.characteristic;
    let (mu_bar, mu) = (e.mu_bar, e.mu);
    let refined_band = prediction.mu_bar_refined_band();
    let mu_refined_band = prediction.mu_refined_band();
    let bands_say = if prediction.alpha_band.is_some() {
        "95 % of its cross-validated cases, around its range over the alpha band"
    } else {
        "band holds 95 % of its cross-validated cases"
    };
    let mut out = format!(
        "contact     p_H = {:.4e} Pa, M = {:.4}, L = {:.4}, S-bar = {:.4e}, S = {}\n\
         tau_c       {:.4e}{}  (Eq. 12: eta(p_H)/eta0 = {:.4e}, Hc of Eq. 10 = {:.4} = {:.4e} m{})\n\
         mastercurve mu-bar = asinh(tau_c/5) = {:.4}{}  (the paper's Eq. 14, sliding friction)\n\
         friction    mu = mu-bar tau0 / p_H = {:.5}{}\n\
         refined     mu_bar_refined = {:.4} ({:.4} .. {:.4}), mu = {:.5} ({:.5} .. {:.5})  (beyond the paper: flat-film formula fitted to Figs. 3-7, repro mastercurve; {bands_say})\n\
         compute     {:.1} us\n",
        c.ph_pa,
        c.m,
        c.l,
        c.s_bar,
        c.slip,
        c.tau_c,
        over_alpha(prediction.tau_c_band(), |v| format!("{v:.4e}")),
        c.eta_bar_ph,
        c.hc_moes,
        c.hc_m,
        prediction.hc_m_band().map_or_else(String::new, |b| format!(
            "; {:.4e} .. {:.4e} m over the alpha band",
            b.low, b.high
        )),
        mu_bar,
        over_alpha(prediction.mu_bar_band(), |v| format!("{v:.4}")),
        mu,
        over_alpha(prediction.mu_band(), |v| format!("{v:.5}")),
        e.mu_bar_refined,
        refined_band.low,
        refined_band.high,
        e.mu_refined,
        mu_refined_band.low,
        mu_refined_band.high,
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
            e.mu_bar_refined - s.friction.sliding,
            100.0 * (e.mu_bar_refined / s.friction.sliding - 1.0),
        ));
    }
    out
}
