//! The contact `repro predict` is asked about: given physically, its load as `p_H` or as a
//! force, turned into the case the mastercurve and the solver take.

use crate::physics::case::{Case, CaseError, CaseForm, LubricantSpec, PhysicalCase, Physics};
use crate::physics::lubricant::LubricantTable;
use crate::physics::traction::{
    characteristic, Contact, FilmFormula, Load, OperatingPoint, Sliding, Speed, ViscosityAtPh,
};

/// An elliptical contact as an engineer gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct EngineeringContact {
    /// The lubricant.
    pub lubricant: LubricantSpec,
    /// The physics of `eta(p_H)` in `tau_c` and of a full solve.
    pub physics: Physics,
    /// The load: `p_H` or the normal force.
    pub load: Load,
    /// Reduced radius along the rolling direction, m.
    pub rx_m: f64,
    /// Reduced radius across it, m.
    pub ry_m: f64,
    /// Reduced modulus, Pa.
    pub e_prime_pa: f64,
    /// Mean velocity `u_m`, m/s.
    pub um_m_s: f64,
    /// Slide-to-roll ratio `S`.
    pub slip: f64,
    /// Eyring stress, Pa.
    pub tau0_pa: f64,
}

impl EngineeringContact {
    /// The case: the load resolved to `p_H` (the Hertz scales of the ellipse, Sec. IV's
    /// transform), the rest as given.
    pub fn case(&self, lubs: &LubricantTable) -> Result<Case, CaseError> {
        let point = OperatingPoint {
            contact: Contact::Elliptical {
                rx_m: self.rx_m,
                ry_m: self.ry_m,
            },
            e_prime_pa: self.e_prime_pa,
            load: self.load,
            lubricant: self.lubricant.clone(),
            speed: Speed::Mean(self.um_m_s),
            sliding: Sliding::Slip(self.slip),
            tau0_pa: self.tau0_pa,
            viscosity: ViscosityAtPh::Law(self.physics.viscosity),
            film: FilmFormula::Eq10,
        };
        let ph_pa = characteristic(&point, lubs)?.ph_pa;
        Ok(Case {
            spec: CaseForm::Physical(PhysicalCase {
                lubricant: self.lubricant.clone(),
                ph_pa,
                um_m_s: self.um_m_s,
                slip: self.slip,
                tau0_pa: self.tau0_pa,
                rx_m: self.rx_m,
                ry_m: self.ry_m,
                e_prime_pa: self.e_prime_pa,
            }),
            physics: self.physics,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::tests::worked_case;
    use crate::physics::hertz::Hertz;

    /// The Appendix contact (mineral oil A at 40 C, 3 GPa, 12 m/s, S 0.5 %, tau0 4 MPa).
    fn appendix(load: Load) -> EngineeringContact {
        let CaseForm::Physical(p) = worked_case().spec else {
            panic!("the worked case is physical")
        };
        EngineeringContact {
            lubricant: p.lubricant,
            physics: worked_case().physics,
            load,
            rx_m: p.rx_m,
            ry_m: p.ry_m,
            e_prime_pa: p.e_prime_pa,
            um_m_s: p.um_m_s,
            slip: p.slip,
            tau0_pa: p.tau0_pa,
        }
    }

    #[test]
    fn a_given_p_h_is_the_case_itself() {
        let lubs = LubricantTable::table1();
        let case = appendix(Load::MaxPressure(3e9)).case(&lubs).unwrap();
        assert_eq!(case, worked_case());
    }

    /// A force resolves to the `p_H` of its Hertzian ellipse: the ellipse of that `p_H`
    /// (scaled from `p_H`, not from the force) carries the force back, `f = 2 pi a b p_H / 3`,
    /// to the elliptic integrals' round-off.
    #[test]
    fn a_force_resolves_to_its_hertzian_pressure() {
        let lubs = LubricantTable::table1();
        let case = appendix(Load::Force(250.0)).case(&lubs).unwrap();
        let CaseForm::Physical(p) = case.spec else {
            panic!("physical")
        };
        let h = Hertz::from_ph(p.ph_pa, p.rx_m, p.ry_m, p.e_prime_pa);
        let force = 2.0 * std::f64::consts::PI * h.a * h.b * p.ph_pa / 3.0;
        assert!((force / 250.0 - 1.0).abs() < 1e-10, "{force} N");
        let bad = appendix(Load::Force(-1.0)).case(&lubs);
        assert!(bad.is_err(), "a negative load is refused");
    }
}
