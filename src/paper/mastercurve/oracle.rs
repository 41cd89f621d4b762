//! The flat-film estimate of a computed case ([`crate::physics::flat_film`]): the friction a
//! parallel film of the solver's own central thickness would give under the Hertzian
//! pressure. Computed from the case and its cached record, never by solving again.

use crate::physics::case::Problem;
use crate::physics::film::{ellipticity_film_ratio, hc_eq10};
use crate::physics::flat_film::{ln_couette_centre, mu_bar_flat, Geometry};
use crate::physics::line_contact::{LineFilmFormula, LineProblem};

/// `mu-bar_flat` of an elliptical contact whose central film is `h_central` (`H = h/c`).
pub fn point_flat(problem: &Problem, h_central: f64) -> f64 {
    let ln_x = ln_couette_centre(problem.eyring_n_s(), &problem.viscosity, h_central);
    mu_bar_flat(
        Geometry::Elliptical,
        problem.shear,
        &problem.viscosity,
        ln_x,
    )
}

/// `mu-bar_flat` of a line contact whose central film is `h_central` (`H = h Rx / a^2`).
pub fn line_flat(problem: &LineProblem, h_central: f64) -> f64 {
    let ln_x = ln_couette_centre(problem.eyring_n_s(), &problem.viscosity, h_central);
    mu_bar_flat(Geometry::Line, problem.shear, &problem.viscosity, ln_x)
}

/// The central film `H` of the formula `tau_c` is built on, in the solver's units: Eq. (10)
/// for an elliptical contact.
pub fn point_nominal_film(problem: &Problem) -> f64 {
    let g = &problem.groups;
    hc_eq10(g.m, g.l) / g.moes_film_scale
}

/// The nominal film of the refined formula ([`crate::paper::mastercurve::refined`]) for an elliptical contact:
/// Eq. (10), a circular-contact formula, times Nijenbanning's ellipticity ratio, so that a
/// wide ellipse (Fig. 7's `Rx/Ry = 1/2, 1/5`) is not given the circle's thinner film.
pub fn point_refined_film(problem: &Problem) -> f64 {
    let g = &problem.groups;
    point_nominal_film(problem) * ellipticity_film_ratio(g.m, g.l, g.d)
}

/// The central film `H` of the line contact's `tau_c` formula (Moes), in the solver's units.
pub fn line_nominal_film(problem: &LineProblem) -> f64 {
    let g = &problem.groups;
    LineFilmFormula::Moes.hc(g.m, g.l) / g.moes_film_scale
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::tests::worked_case;
    use crate::physics::lubricant::LubricantTable;

    #[test]
    fn centre_argument_is_half_tau_c_for_the_eq10_film() {
        // SPEC.md: at the centre, N eta(p_H) S / H = (tau_c / 2) (Hc / H) with Hc of
        // Eq. (10); with H the Eq. (10) film itself the argument is tau_c / 2. Both sides are
        // the same groups multiplied in another order: round-off only.
        let p = Problem::from_case(&worked_case(), &LubricantTable::table1()).unwrap();
        let ln_x = ln_couette_centre(p.eyring_n_s(), &p.viscosity, point_nominal_film(&p));
        assert!((ln_x - (p.tau_c() / 2.0).ln()).abs() < 1e-9, "{ln_x}");
    }
}
