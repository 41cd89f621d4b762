//! Beyond the paper: a refined sliding-friction formula, fitted to every computed case of
//! Figs. 3-7 and the line contacts with `tau_c >= 100`, checked by cross-validation (fitted on
//! all figures but one, tested on that one).
//!
//! `mu-bar_refined = a G + b G H_n + c ln L + d`, linear in its four coefficients, where
//!
//! - `G` is the flat-film friction ([`crate::physics::flat_film`]) with the film of the
//!   formula `tau_c` is built on (Eq. 10; Moes' for the line contact), for an ellipse times
//!   Nijenbanning's ellipticity ratio ([`crate::physics::film::ellipticity_film_ratio`]):
//!   Eq. (10) is a circular-contact formula, and the solved films of Fig. 7's wide ellipses
//!   are 0.15 (`Rx/Ry = 1/2`) and 0.25 (`1/5`) thicker in `ln H` relative to it than the
//!   circles' (the ratio gives 0.09-0.13 and 0.18-0.22). `tau_c` and the whole
//!   viscosity-pressure profile, hence `alpha_e`, the second group the flat film shows
//!   friction depends on (`1.5 ln tau_c - 0.5 alpha_e` at large `tau_c`);
//! - `H_n` is that film over the Hertzian approach (`h/c`; `h Rx / a^2` for the line): where
//!   it approaches 1 the film is no longer flattened by the elastic deformation and the
//!   flat-film estimate runs high (Fig. 6's light 5P4E contacts, up to 21 %);
//! - `ln L` corrects Eq. (10)'s film, fitted to Barus incompressible solutions, for the
//!   Roelands and Dowson-Higginson lubricants.
//!
//! Everything is computable from the operating conditions, so `repro predict` can use it. It
//! is fitted by weighted least squares of the relative residual `mu-bar_refined / mu-bar - 1`.
//!
//! The fit runs inside the pipeline (the `mastercurve` target, on the computed cases); the
//! coefficients `repro predict` uses are [`REFINED`], copied from the level-7 fit, and a test
//! (tests/mastercurve.rs) refits them from `figures/mastercurve.csv` and checks they agree, so
//! they cannot drift from the data without a failing test. `predict` cannot run the fit itself:
//! it would need every level-7 solve.

use crate::physics::case::Problem;
use crate::physics::flat_film::{ln_couette_centre, mu_bar_flat, Geometry};
use crate::physics::line_contact::LineProblem;
use serde::Serialize;

use crate::paper::mastercurve::oracle::{line_nominal_film, point_refined_film};

/// The groups of the refined formula for one contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Features {
    /// `G`: flat-film friction with the nominal film.
    pub flat_nominal: f64,
    /// `H_n`: the nominal film over the Hertzian approach.
    pub film_nominal: f64,
    /// `ln L`.
    pub ln_l: f64,
}

impl Features {
    /// The groups of an elliptical contact.
    pub fn point(problem: &Problem) -> Self {
        let h = point_refined_film(problem);
        let ln_x = ln_couette_centre(problem.eyring_n_s(), &problem.viscosity, h);
        Features {
            flat_nominal: mu_bar_flat(
                Geometry::Elliptical,
                problem.shear,
                &problem.viscosity,
                ln_x,
            ),
            film_nominal: h,
            ln_l: problem.groups.l.ln(),
        }
    }

    /// The groups of a line contact.
    pub fn line(problem: &LineProblem) -> Self {
        let h = line_nominal_film(problem);
        let ln_x = ln_couette_centre(problem.eyring_n_s(), &problem.viscosity, h);
        Features {
            flat_nominal: mu_bar_flat(Geometry::Line, problem.shear, &problem.viscosity, ln_x),
            film_nominal: h,
            ln_l: problem.groups.l.ln(),
        }
    }

    /// The regressors `(G, G H_n, ln L, 1)`.
    fn row(&self) -> [f64; 4] {
        [
            self.flat_nominal,
            self.flat_nominal * self.film_nominal,
            self.ln_l,
            1.0,
        ]
    }
}

/// The refined formula's coefficients `(a, b, c, d)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Refined {
    /// `a`, `b`, `c`, `d` of `a G + b G H_n + c ln L + d`.
    pub coefficients: [f64; 4],
}

/// The coefficients of the level-7 fit (`repro mastercurve --level 7`, figures/mastercurve-fit.csv),
/// used by `repro predict`; tests/mastercurve.rs refits them.
pub const REFINED: Refined = Refined {
    coefficients: [1.000757e0, -7.451783e-2, 4.423268e-1, -4.523084e-1],
};

/// Half-width of `repro predict`'s band, relative: the 95th percentile of the cross-validated
/// relative residuals of the level-7 fit (figures/mastercurve-fit.csv; tests/mastercurve.rs).
pub const REFINED_BAND: f64 = 4.790182e-2;

impl Refined {
    /// `mu-bar_refined` of a contact.
    pub fn predict(&self, f: &Features) -> f64 {
        self.coefficients
            .iter()
            .zip(f.row())
            .map(|(c, x)| c * x)
            .sum()
    }
}

/// One computed case as the fit sees it.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    /// The figure it belongs to (the unit of cross-validation).
    pub figure: &'static str,
    /// Its groups.
    pub features: Features,
    /// The solver's sliding `mu-bar`.
    pub mu_bar: f64,
}

/// The cross-validation of one figure.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureCheck {
    /// Figure (or `mastercurve` for all cases together).
    pub figure: &'static str,
    /// Its cases in the fit.
    pub points: usize,
    /// RMS of `mu-bar_refined / mu-bar - 1` over its cases, the formula fitted without them.
    pub refined_rms_rel_dev: f64,
}

/// Solves the symmetric positive definite 4 x 4 system `a x = b` by Gaussian elimination with
/// partial pivoting; `None` if singular.
fn solve4(mut a: [[f64; 4]; 4], mut b: [f64; 4]) -> Option<[f64; 4]> {
    for i in 0..4 {
        let p = (i..4).max_by(|&r, &s| a[r][i].abs().total_cmp(&a[s][i].abs()))?;
        a.swap(i, p);
        b.swap(i, p);
        if a[i][i].abs() < 1e-300 {
            return None;
        }
        for r in i + 1..4 {
            let f = a[r][i] / a[i][i];
            for c in i..4 {
                a[r][c] -= f * a[i][c];
            }
            b[r] -= f * b[i];
        }
    }
    let mut x = [0.0; 4];
    for i in (0..4).rev() {
        let s: f64 = (i + 1..4).map(|c| a[i][c] * x[c]).sum();
        x[i] = (b[i] - s) / a[i][i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Least-squares fit of the relative residual over `samples` (weights `1/mu-bar^2`); `None`
/// with fewer than four usable samples or a singular system.
pub fn fit<'a>(samples: impl IntoIterator<Item = &'a Sample>) -> Option<Refined> {
    let mut a = [[0.0; 4]; 4];
    let mut b = [0.0; 4];
    let mut n = 0;
    for s in samples {
        let x = s.features.row();
        if !(s.mu_bar > 0.0 && x.iter().all(|v| v.is_finite())) {
            continue;
        }
        let w = 1.0 / (s.mu_bar * s.mu_bar);
        for i in 0..4 {
            for j in 0..4 {
                a[i][j] += w * x[i] * x[j];
            }
            b[i] += w * x[i] * s.mu_bar;
        }
        n += 1;
    }
    if n < 4 {
        return None;
    }
    solve4(a, b).map(|coefficients| Refined { coefficients })
}

/// The cross-validated prediction of every sample: from the formula fitted on the samples of
/// every other figure (`None` where that fit is impossible).
pub fn cross_validated(samples: &[Sample]) -> Vec<Option<f64>> {
    let mut figures: Vec<&str> = samples.iter().map(|s| s.figure).collect();
    figures.sort_unstable();
    figures.dedup();
    let fits: Vec<(&str, Option<Refined>)> = figures
        .iter()
        .map(|f| (*f, fit(samples.iter().filter(|s| s.figure != *f))))
        .collect();
    samples
        .iter()
        .map(|s| {
            fits.iter()
                .find(|(f, _)| *f == s.figure)
                .and_then(|(_, r)| r.as_ref())
                .map(|r| r.predict(&s.features))
        })
        .collect()
}

/// RMS of `predicted / actual - 1` over the pairs that have a prediction.
pub fn rms_rel(pairs: impl IntoIterator<Item = (Option<f64>, f64)>) -> Option<f64> {
    let devs: Vec<f64> = pairs
        .into_iter()
        .filter_map(|(p, m)| p.map(|p| p / m - 1.0))
        .collect();
    (!devs.is_empty()).then(|| (devs.iter().map(|d| d * d).sum::<f64>() / devs.len() as f64).sqrt())
}

/// The 95th percentile of `|predicted / actual - 1|` (the band of a prediction).
pub fn band95(pairs: impl IntoIterator<Item = (Option<f64>, f64)>) -> Option<f64> {
    let mut devs: Vec<f64> = pairs
        .into_iter()
        .filter_map(|(p, m)| p.map(|p| (p / m - 1.0).abs()))
        .collect();
    if devs.is_empty() {
        return None;
    }
    devs.sort_by(f64::total_cmp);
    let i = ((0.95 * devs.len() as f64).ceil() as usize).clamp(1, devs.len()) - 1;
    Some(devs[i])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(figure: &'static str, g: f64, h: f64, l: f64, coef: [f64; 4]) -> Sample {
        let features = Features {
            flat_nominal: g,
            film_nominal: h,
            ln_l: l.ln(),
        };
        let mu_bar = Refined { coefficients: coef }.predict(&features);
        Sample {
            figure,
            features,
            mu_bar,
        }
    }

    #[test]
    fn recovers_planted_coefficients_and_cross_validates_exactly() {
        let coef = [0.98, -0.03, 0.45, -0.4];
        let mut s = Vec::new();
        for (i, fig) in ["a", "b", "c"].into_iter().enumerate() {
            for k in 0..8 {
                let g = 5.0 + 4.0 * k as f64 + i as f64;
                s.push(sample(
                    fig,
                    g,
                    0.01 * (k * k) as f64 + 0.02,
                    2.0 + k as f64 + 3.0 * i as f64,
                    coef,
                ));
            }
        }
        let r = fit(&s).unwrap();
        for (u, v) in r.coefficients.iter().zip(coef) {
            // Exact data: the normal equations are solved to round-off (condition ~1e4).
            assert!((u - v).abs() < 1e-9, "{u} vs {v}");
        }
        let cv = cross_validated(&s);
        assert!(rms_rel(cv.iter().copied().zip(s.iter().map(|s| s.mu_bar))).unwrap() < 1e-9);
        // A figure that follows another law shows in its cross-validated residual.
        s.iter_mut()
            .filter(|s| s.figure == "c")
            .for_each(|s| s.mu_bar *= 1.1);
        let cv = cross_validated(&s);
        let c_rms = rms_rel(
            cv.iter()
                .zip(&s)
                .filter(|(_, s)| s.figure == "c")
                .map(|(p, s)| (*p, s.mu_bar)),
        )
        .unwrap();
        assert!(
            (c_rms - (1.0 / 1.1 - 1.0_f64).abs()).abs() < 1e-6,
            "{c_rms}"
        );
    }

    #[test]
    fn too_few_samples_give_no_fit() {
        let s: Vec<Sample> = (0..3)
            .map(|k| sample("a", 1.0 + k as f64, 0.1, 2.0, [1.0, 0.0, 0.0, 0.0]))
            .collect();
        assert!(fit(&s).is_none());
    }

    #[test]
    fn band_is_the_95th_percentile() {
        let pairs: Vec<(Option<f64>, f64)> = (1..=100)
            .map(|i| (Some(1.0 + i as f64 / 1000.0), 1.0))
            .collect();
        let b = band95(pairs).unwrap();
        // 95th of 0.001 .. 0.100: 0.095 (round-off of 1 + x - 1).
        assert!((b - 0.095).abs() < 1e-12, "{b}");
    }
}
