//! The line contact (Fig. 7, "using a separate approach based on the equations presented in
//! Ref. [11]", Conry, Wang and Cusano 1987): Hertz scales of a cylinder on a plane, the Moes
//! line-contact groups, the exact one-dimensional Eyring flow, line-contact film formulas and
//! the dimensionless problem the 1-D solver consumes. The line-contact groups are computed
//! here and nowhere else.
//!
//! Units. `w'` is the load per unit length (N/m), `E'` the reduced modulus of the paper's
//! Nomenclature (`2/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`), `u_s = u1 + u2 = 2 u_m` the sum
//! velocity as everywhere in the paper. Dimensionless variables: `X = x/a`, `P = p/p_H`,
//! `H = h Rx / a^2` (the 1-D analogue of the paper's `H = h/c`), so that the film equation is
//! `H = Delta + X^2/2 - (1/pi) int P(X') ln|X - X'| dX'` and the force balance `int P dX = pi/2`.

use super::case::{eyring_n_s, physical_scales, shear_law, LubricantSpec, PhysicalCase, Physics};
use super::checks::{field, hertzian_pressure, positive, slip_in_range, CaseError, MoesInputs};
use super::density::Density;
use super::lubricant::LubricantTable;
use super::rheology::{Rheology, ShearLaw};
use super::viscosity::{Viscosity, ViscosityLaw};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Hertzian scales of a line contact, SI units (or units of `Rx`, `E'` for a dimensionless
/// case).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LineHertz {
    /// Reduced radius of curvature in the rolling direction, m.
    pub rx: f64,
    /// Reduced modulus `E'`, Pa.
    pub e_prime: f64,
    /// Maximum Hertzian pressure, Pa.
    pub ph: f64,
    /// Hertzian half-width `a`, m.
    pub a: f64,
    /// Load per unit length `w'`, N/m.
    pub load_per_length: f64,
}

impl LineHertz {
    /// From the maximum Hertzian pressure: `a = 4 Rx p_H / E'` and `w' = pi a p_H / 2`.
    pub fn from_ph(ph: f64, rx: f64, e_prime: f64) -> Self {
        let a = 4.0 * rx * ph / e_prime;
        LineHertz {
            rx,
            e_prime,
            ph,
            a,
            load_per_length: PI * a * ph / 2.0,
        }
    }

    /// From the load per unit length: `p_H = sqrt(w' E' / (2 pi Rx))`.
    pub fn from_load(load_per_length: f64, rx: f64, e_prime: f64) -> Self {
        Self::from_ph(
            (load_per_length * e_prime / (2.0 * PI * rx)).sqrt(),
            rx,
            e_prime,
        )
    }

    /// The unit of the dimensionless film `H = h / (a^2 / Rx)`, m.
    pub fn film_unit(&self) -> f64 {
        self.a * self.a / self.rx
    }

    /// The dry Hertzian pressure `P = sqrt(1 - X^2)` inside the contact.
    pub fn pressure(x: f64) -> f64 {
        if x.abs() < 1.0 {
            (1.0 - x * x).sqrt()
        } else {
            0.0
        }
    }
}

/// The dimensionless groups of a line contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LineGroups {
    /// Moes load parameter `M = W' U^{-1/2}`, `W' = w' / (E' Rx)`, `U = eta0 u_s / (E' Rx)`.
    pub m: f64,
    /// Moes lubricant parameter `L = alpha E' U^{1/4}`.
    pub l: f64,
    /// Dimensionless slip, Eq. (9): `S-bar = S (u_s eta0 E' / (tau0^2 Rx))^{1/2}`.
    pub s_bar: f64,
    /// `alpha-bar = alpha p_H` (`= L sqrt(M / (2 pi))`).
    pub alpha_bar: f64,
    /// Speed parameter `lambda = 6 eta0 u_s Rx^2 / (a^3 p_H)` (`= 3 pi^2 / (8 M^2)`).
    pub lambda: f64,
    /// Eyring parameter `N = eta0 u_s Rx / (2 a^2 tau0)`: the Newtonian Couette stress over
    /// `tau0` is `N S eta_bar / H`.
    pub n: f64,
    /// Slide-to-roll ratio `S`.
    pub slip: f64,
    /// `(a/Rx)^2 U^{-1/2}` (`= 8 M / pi`): converts `H = h Rx / a^2` to Moes units
    /// `(h/Rx) U^{-1/2}`.
    pub moes_film_scale: f64,
    /// `a p_H / (2 Rx tau0)` (`= 6 N / lambda`): the Poiseuille stress on the surface over
    /// `tau0`, `G = (h/2)(dp/dx)/tau0`, is this times `H dP/dX`. Zero for `tau0 = inf`.
    pub poiseuille_stress_scale: f64,
}

impl LineGroups {
    /// Every group from the Hertz scales, `eta0 u_s` (Pa m), `alpha` (1/Pa), `1/tau0` (1/Pa,
    /// zero for an infinite Eyring stress) and `S`.
    pub fn new(hz: &LineHertz, eta0_us: f64, alpha: f64, tau0_inv: f64, slip: f64) -> Self {
        let u = eta0_us / (hz.e_prime * hz.rx);
        let w = hz.load_per_length / (hz.e_prime * hz.rx);
        let a_rx = hz.a / hz.rx;
        LineGroups {
            m: w / u.sqrt(),
            l: alpha * hz.e_prime * u.powf(0.25),
            s_bar: slip * (eta0_us * hz.e_prime / hz.rx).sqrt() * tau0_inv,
            alpha_bar: alpha * hz.ph,
            lambda: 6.0 * eta0_us * hz.rx * hz.rx / (hz.a.powi(3) * hz.ph),
            n: eta0_us * hz.rx / (2.0 * hz.a * hz.a) * tau0_inv,
            slip,
            moes_film_scale: a_rx * a_rx / u.sqrt(),
            poiseuille_stress_scale: hz.a * hz.ph / (2.0 * hz.rx) * tau0_inv,
        }
    }
}

/// Published central film-thickness formulas of the line contact, in Moes units
/// `Hc = (h_c / Rx) U^{-1/2}`, `U = eta0 u_s / (E' Rx)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum LineFilmFormula {
    /// Moes' line-contact formula (Moes 1992, "Optimum similarity analysis with applications
    /// to elastohydrodynamic lubrication", Wear 159; as quoted by Venner and Lubrecht,
    /// "Multilevel Methods in Lubrication", 2000), a fit of full numerical Newtonian, Barus,
    /// incompressible solutions between its four asymptotes:
    /// `H_RI = 3 M^{-1}`, `H_EI = 2.621 M^{-1/5}`, `H_RP = 1.287 L^{2/3}`,
    /// `H_EP = 1.311 M^{-1/8} L^{3/4}`, `s = (7 + 8 exp(-2 H_EI / H_RI)) / 5`,
    /// `Hc = [(H_RI^{7/3} + H_EI^{7/3})^{3s/7} + (H_RP^{-7/2} + H_EP^{-7/2})^{-2s/7}]^{1/s}`.
    /// The constants were checked against a public implementation of the same formula
    /// (GitHub `Konglingyu1997/Mixed-lubrication-Helical-gear`, README.md, whose load-sharing
    /// factor `gamma = 1` gives the smooth full-film case). This is the formula that defines
    /// `tau_c` for the line contact here: like Eq. (10) for the circular contact it is a fit to
    /// numerical solutions in the Moes groups, and its `H_EP` asymptote has the same `L^{3/4}`.
    #[default]
    Moes,
    /// Dowson and Toyoda (1979) central film, `h_c/Rx = 3.06 U_m^{0.69} G^{0.56} W'^{-0.10}` with
    /// `U_m = eta0 u_m / (E' Rx)` (mean velocity), `G = alpha E'`; exactly Moes-similar:
    /// `Hc = 3.06 2^{-0.69} L^{0.56} M^{-0.10}`.
    DowsonToyoda,
    /// Dowson and Higginson (1966) minimum film, `h_min/Rx = 2.65 U_m^{0.70} G^{0.54} W'^{-0.13}`
    /// (the formula Sec. IV of the paper uses for the line-contact measurements), taken as the
    /// film of `tau_c`: `Hc = 2.65 2^{-0.70} L^{0.54} M^{-0.13}`.
    DowsonHigginson,
}

impl LineFilmFormula {
    /// All formulas, for comparisons.
    pub const ALL: [LineFilmFormula; 3] = [
        LineFilmFormula::Moes,
        LineFilmFormula::DowsonToyoda,
        LineFilmFormula::DowsonHigginson,
    ];

    /// Central film thickness in Moes units at `(M, L)`.
    pub fn hc(self, m: f64, l: f64) -> f64 {
        match self {
            LineFilmFormula::Moes => {
                let h_ri = 3.0 / m;
                let h_ei = 2.621 * m.powf(-0.2);
                let h_rp = 1.287 * l.powf(2.0 / 3.0);
                let h_ep = 1.311 * m.powf(-0.125) * l.powf(0.75);
                let s = (7.0 + 8.0 * (-2.0 * h_ei / h_ri).exp()) / 5.0;
                let rigid = (h_ri.powf(7.0 / 3.0) + h_ei.powf(7.0 / 3.0)).powf(3.0 * s / 7.0);
                let piezo = (h_rp.powf(-3.5) + h_ep.powf(-3.5)).powf(-2.0 * s / 7.0);
                (rigid + piezo).powf(1.0 / s)
            }
            LineFilmFormula::DowsonToyoda => 3.06 * 2f64.powf(-0.69) * l.powf(0.56) * m.powf(-0.10),
            LineFilmFormula::DowsonHigginson => {
                2.65 * 2f64.powf(-0.70) * l.powf(0.54) * m.powf(-0.13)
            }
        }
    }

    /// A short name for tables.
    pub fn name(self) -> &'static str {
        match self {
            LineFilmFormula::Moes => "Moes",
            LineFilmFormula::DowsonToyoda => "Dowson-Toyoda",
            LineFilmFormula::DowsonHigginson => "Dowson-Higginson (h_min)",
        }
    }
}

/// Which Eyring flow the line contact uses (only read when the rheology is Eyring).
///
/// Across the film the shear stress is `tau(z) = tau_m + z dp/dx`, `-h/2 <= z <= h/2`, and the
/// Eyring fluid shears at `gamma_dot = (tau0/eta) sinh(tau/tau0)`. Integrating once and twice
/// across the film (Conry, Wang and Cusano 1987) gives, with `G = h (dp/dx) / (2 tau0)` and the
/// sliding speed `du = u2 - u1 = S u_m`:
///
/// - the mean stress: `sinh(tau_m/tau0) = (eta du / (h tau0)) G / sinh(G)`;
/// - the flow `q = u_m h - (h^3 / (12 eta)) cosh(tau_m/tau0) F(G) dp/dx`,
///   `F(G) = 3 (G cosh G - sinh G) / G^3`, i.e. Poiseuille flow with the effective viscosity
///   `eta / (cosh(tau_m/tau0) F(G))`.
///
/// Dropping `G` (`G / sinh G -> 1`, `F -> 1`) gives the perturbation form of Eqs. (2) and (4),
/// which is what the point contact uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum LineEyringFlow {
    /// The closed form above (SPEC.md section 2): the default for the line contact.
    #[default]
    Exact,
    /// Eqs. (2) and (4): `tau_m = asinh(eta du / (h tau0))`, `eta_x = eta / cosh(tau_m)`.
    Perturbation,
}

/// Largest `|G|` used in the flow factors: `cosh` overflows near 710; beyond 300 the Eyring
/// Poiseuille flux is saturated (`q -> u_m h -+ h du/2`) for any finite Couette stress.
const G_MAX: f64 = 300.0;

/// `F(G) = 3 (G cosh G - sinh G) / G^3`, even, `F(0) = 1`. Below `|G| = 0.1`, where the
/// difference loses `3e-16 / G^2` relative, the series `1 + G^2/10 + G^4/280 + G^6/15120`
/// (truncation `7.5e-7 G^8`) is used.
pub fn eyring_f(g: f64) -> f64 {
    let g = g.abs().min(G_MAX);
    if g < 0.1 {
        let g2 = g * g;
        1.0 + g2 * (1.0 / 10.0 + g2 * (1.0 / 280.0 + g2 / 15120.0))
    } else {
        3.0 * (g * g.cosh() - g.sinh()) / (g * g * g)
    }
}

/// `G / sinh(G)`, even, 1 at 0.
pub fn g_over_sinh(g: f64) -> f64 {
    let g = g.abs().min(G_MAX);
    if g < 1e-3 {
        let g2 = g * g;
        1.0 - g2 / 6.0 + 7.0 * g2 * g2 / 360.0
    } else {
        g / g.sinh()
    }
}

/// `F(G) G / sinh(G) = 3 (G coth G - 1) / G^2`, even, 1 at 0, `-> 3/|G|` for large `|G|`.
/// Below `|G| = 0.1` the series `1 - G^2/15 + 2 G^4/315 - G^6/1575` (truncation
/// `6.4e-5 G^8`) replaces the cancelling difference.
fn f_g_over_sinh(g: f64) -> f64 {
    let g = g.abs().min(G_MAX);
    if g < 0.1 {
        let g2 = g * g;
        1.0 - g2 * (1.0 / 15.0 - g2 * (2.0 / 315.0 - g2 / 1575.0))
    } else {
        3.0 * (g / g.tanh() - 1.0) / (g * g)
    }
}

impl LineEyringFlow {
    /// Dimensionless mean shear stress `tau_m / tau0` for the Couette argument
    /// `x = eta du / (h tau0)`, `G` and pressure `P`: `asinh(x G / sinh G)` (exact),
    /// `asinh(x)` (perturbation), `x` (Newtonian, where Couette and Poiseuille superpose
    /// exactly). The limiting-stress law has no closed form across a film whose stress varies
    /// by `2 G`; it is taken in the perturbation form, as the point contact takes it.
    pub fn mean_shear_stress(self, law: ShearLaw, x: f64, g: f64, p: f64) -> f64 {
        match (law, self) {
            (ShearLaw::Eyring, LineEyringFlow::Exact) => (x * g_over_sinh(g)).asinh(),
            _ => law.mean_shear_stress(x, p),
        }
    }

    /// Poiseuille conductance `H^3 / eta_eff` for film `h`, viscosity `eta`, `n_s = N S`,
    /// `G` and pressure `P`, written without overflow however large `eta` is:
    /// exact `H^2 hypot(F H / eta, N S F G / sinh G)`; perturbation `H^2 hypot(H / eta, N S)`;
    /// Newtonian `H^3 / eta`; the limiting-stress law in the perturbation form. Zero where
    /// `h <= 0`.
    pub fn conductance(self, law: ShearLaw, h: f64, eta: f64, n_s: f64, g: f64, p: f64) -> f64 {
        if h <= 0.0 {
            return 0.0;
        }
        match (law, self) {
            (ShearLaw::Eyring, LineEyringFlow::Exact) => {
                h * h * (eyring_f(g) * h / eta).hypot(n_s * f_g_over_sinh(g))
            }
            (ShearLaw::Eyring, LineEyringFlow::Perturbation) => h * h * (h / eta).hypot(n_s),
            _ => law.conductance_x(h, eta, n_s, p),
        }
    }
}

/// A line contact given by its physical operating conditions (SI units).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LinePhysicalCase {
    /// Pressure-viscosity coefficient at the case's temperature, 1/Pa.
    pub alpha_per_pa: f64,
    /// Ambient viscosity at the case's temperature, Pa s.
    pub eta0_pa_s: f64,
    /// Maximum Hertzian pressure, Pa (the load is given through it).
    pub ph_pa: f64,
    /// Mean velocity `u_m = (u1 + u2)/2`, m/s.
    pub um_m_s: f64,
    /// Slide-to-roll ratio `S = 2 (u2 - u1) / (u2 + u1)`.
    pub slip: f64,
    /// Eyring stress, Pa.
    pub tau0_pa: f64,
    /// Reduced radius in the rolling direction, m.
    pub rx_m: f64,
    /// Reduced modulus `E'`, Pa.
    pub e_prime_pa: f64,
}

impl LinePhysicalCase {
    /// The line contact of a point-contact case's operating conditions (its `Ry` dropped):
    /// how the Table 3 rows of `cases/fig7.toml` become the line contacts of Fig. 7.
    pub fn from_point_case(
        c: &PhysicalCase,
        lubricants: &LubricantTable,
    ) -> Result<Self, CaseError> {
        let (alpha_per_pa, eta0_pa_s) = match &c.lubricant {
            LubricantSpec::Named {
                lubricant,
                temperature_c,
            } => {
                let s = lubricants
                    .state(lubricant, *temperature_c)
                    .map_err(|e| field("lubricant", e.to_string()))?;
                (s.alpha_per_pa, s.eta0_pa_s)
            }
            LubricantSpec::Given {
                alpha_per_pa,
                eta0_pa_s,
            } => (*alpha_per_pa, *eta0_pa_s),
            LubricantSpec::Datasheet { .. } => {
                let s = c.lubricant.resolve(lubricants)?;
                (s.alpha_per_pa, s.eta0_pa_s)
            }
        };
        Ok(LinePhysicalCase {
            alpha_per_pa,
            eta0_pa_s,
            ph_pa: c.ph_pa,
            um_m_s: c.um_m_s,
            slip: c.slip,
            tau0_pa: c.tau0_pa,
            rx_m: c.rx_m,
            e_prime_pa: c.e_prime_pa,
        })
    }
}

/// A line contact given by its Moes groups.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LineDimensionlessCase {
    /// Moes line-contact load parameter `M`.
    pub m: f64,
    /// Moes lubricant parameter `L`.
    pub l: f64,
    /// Dimensionless slip, Eq. (9).
    pub s_bar: f64,
    /// Slide-to-roll ratio: with `S-bar` it fixes `tau0` (the scale of the rolling friction).
    pub slip: f64,
    /// Ambient viscosity, Pa s: needed only by Roelands.
    pub eta0_pa_s: Option<f64>,
    /// Maximum Hertzian pressure, Pa: needed only by Roelands and Dowson-Higginson.
    pub ph_pa: Option<f64>,
}

/// The dimensionless line-contact problem: what the 1-D solver consumes.
#[derive(Debug, Clone, PartialEq)]
pub struct LineProblem {
    /// Dimensionless groups.
    pub groups: LineGroups,
    /// Viscosity law.
    pub viscosity: Viscosity,
    /// Density law.
    pub density: Density,
    /// Rheology, as the case states it.
    pub rheology: Rheology,
    /// The rheology's dimensionless law, what the solver evaluates.
    pub shear: ShearLaw,
    /// Which Eyring flow (exact by default).
    pub eyring_flow: LineEyringFlow,
    /// Hertz scales (physical for a physical case; units `Rx = E' = 1`, `U = 1` for a
    /// dimensionless one).
    pub hertz: LineHertz,
}

impl LineProblem {
    /// From physical operating conditions; every field is checked and named on error.
    pub fn from_physical(c: &LinePhysicalCase, physics: Physics) -> Result<Self, CaseError> {
        let alpha = positive("alpha", c.alpha_per_pa)?;
        let eta0 = positive("eta0", c.eta0_pa_s)?;
        let ph = hertzian_pressure("ph", c.ph_pa)?;
        let um = positive("um", c.um_m_s)?;
        let slip = slip_in_range("slip", c.slip)?;
        let tau0 = positive("tau0", c.tau0_pa)?;
        let rx = positive("rx", c.rx_m)?;
        let e_prime = positive("e-prime", c.e_prime_pa)?;
        if ph >= e_prime {
            return Err(field(
                "ph",
                format!("p_H = {ph} Pa must be far below E' = {e_prime} Pa (small strains)"),
            ));
        }
        let hertz = LineHertz::from_ph(ph, rx, e_prime);
        let groups = LineGroups::new(&hertz, eta0 * 2.0 * um, alpha, 1.0 / tau0, slip);
        let shear = shear_law(physics.rheology, tau0 / ph, ph)?;
        Ok(Self::assemble(
            groups, hertz, physics, shear, eta0, alpha, ph,
        ))
    }

    /// From the Moes groups. In units `Rx = E' = 1` and `U = eta0 u_s / (E' Rx) = 1` the load
    /// per unit length is `M`, `alpha` is `L` and `1/tau0 = S-bar / S`.
    pub fn from_dimensionless(
        c: &LineDimensionlessCase,
        physics: Physics,
    ) -> Result<Self, CaseError> {
        let MoesInputs {
            m,
            l,
            slip,
            tau0_inv,
        } = MoesInputs::check(c.m, c.l, c.s_bar, c.slip)?;
        let hertz = LineHertz::from_load(m, 1.0, 1.0);
        let groups = LineGroups::new(&hertz, 1.0, l, tau0_inv, slip);
        let (ph_pa, eta0) = physical_scales(physics, c.ph_pa, c.eta0_pa_s)?;
        let shear = shear_law(physics.rheology, 1.0 / (tau0_inv * hertz.ph), ph_pa)?;
        let mut problem = Self::assemble(
            groups,
            hertz,
            physics,
            shear,
            eta0,
            groups.alpha_bar / ph_pa,
            ph_pa,
        );
        if physics.viscosity == ViscosityLaw::Barus {
            problem.viscosity = Viscosity::barus(groups.alpha_bar);
        }
        Ok(problem)
    }

    fn assemble(
        groups: LineGroups,
        hertz: LineHertz,
        physics: Physics,
        shear: ShearLaw,
        eta0: f64,
        alpha: f64,
        ph: f64,
    ) -> Self {
        LineProblem {
            groups,
            viscosity: Viscosity::new(physics.viscosity, eta0, alpha, ph),
            density: Density::new(physics.density, ph),
            rheology: physics.rheology,
            shear,
            eyring_flow: LineEyringFlow::default(),
            hertz,
        }
    }

    /// The same problem with another Eyring flow.
    pub fn with_eyring_flow(mut self, flow: LineEyringFlow) -> Self {
        self.eyring_flow = flow;
        self
    }

    /// The physics this problem composes.
    pub fn physics(&self) -> Physics {
        Physics::of(&self.viscosity, &self.density, self.rheology)
    }

    /// `N S`: the Couette stress argument is `N S eta_bar / H`.
    pub fn eyring_n_s(&self) -> f64 {
        eyring_n_s(self.groups.n, self.groups.slip)
    }

    /// Characteristic shear stress, Eq. (12), of the line contact: `tau_c = eta_bar(p_H)
    /// S-bar / Hc` with `Hc` from Moes' line-contact formula ([`LineFilmFormula::Moes`]).
    pub fn tau_c(&self) -> f64 {
        self.tau_c_with(LineFilmFormula::Moes)
    }

    /// `tau_c` with the central film of another formula.
    pub fn tau_c_with(&self, formula: LineFilmFormula) -> f64 {
        self.viscosity.eta_bar(1.0) * self.groups.s_bar / formula.hc(self.groups.m, self.groups.l)
    }
}

#[cfg(test)]
pub(crate) mod tests;
