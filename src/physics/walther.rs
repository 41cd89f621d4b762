//! ASTM D341 (Walther, Ubbelohde-Walther): kinematic viscosity against temperature.
//!
//! D341 draws a petroleum oil's kinematic viscosity `nu` (mm^2/s) against the absolute
//! temperature `T` (K) as a straight line,
//!
//! ```text
//! log10 log10 Z = A - B log10 T,
//! Z = nu + 0.7 + exp(-1.47 - 1.84 nu - 0.51 nu^2)                         (D341-09, Eq. 2)
//! nu = (Z - 0.7) - exp(-0.7487 - 3.295 (Z - 0.7) + 0.6119 (Z - 0.7)^2
//!                                     - 0.3193 (Z - 0.7)^3)               (D341-09, Eq. 3)
//! ```
//!
//! For `nu >= 2.0 mm^2/s` the exponential terms are below 1e-3 and `Z = nu + 0.7`, the plain
//! Walther form D341 gives for that range (and the form every 40/100 C datasheet calculation
//! uses). Eqs. 2 and 3 are D341's extension for oils whose viscosity falls below 2 mm^2/s; they
//! are used everywhere here so the line has no seam at 2 mm^2/s. Eq. 3 is an approximate
//! inverse of Eq. 2: a round trip `nu -> Z -> nu` is exact to 3e-4 (relative) from 0.2 mm^2/s up,
//! checked by a test, which is why [`WALTHER_NU_MIN_MM2_S`] is 0.2 mm^2/s. (Eqs. 2 and 3 were
//! read from two secondary copies of D341-09, not from the standard itself; its own lower limit
//! for them could not be confirmed.)
//!
//! D341 holds only where the oil is a homogeneous liquid, between its cloud point and its
//! initial boiling point (D341 Sec. 3). A datasheet gives neither, so this module accepts
//! temperatures in [`WALTHER_TEMPERATURE_RANGE_C`], a window chosen here (not by D341) that
//! keeps an extrapolation from 40/100 C data within 60 K of the data.

/// Lowest kinematic viscosity the line is evaluated to, mm^2/s (see the module docs).
pub const WALTHER_NU_MIN_MM2_S: f64 = 0.2;

/// Lowest viscosity of D341's plain form `Z = nu + 0.7`, mm^2/s.
pub const PLAIN_FORM_NU_MIN_MM2_S: f64 = 2.0;

/// Temperatures at which a line is built or evaluated, C (a choice of this module; see the
/// module docs).
pub const WALTHER_TEMPERATURE_RANGE_C: (f64, f64) = (-20.0, 150.0);

/// Kelvin at 0 C.
const ZERO_C_IN_K: f64 = 273.15;

/// Errors of a Walther line.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum WaltherError {
    /// A viscosity that is zero, negative or not finite.
    #[error("{field} = {value}: a viscosity must be a positive finite number")]
    NotPositive {
        /// The input's name.
        field: &'static str,
        /// Its value.
        value: f64,
    },
    /// A temperature outside [`WALTHER_TEMPERATURE_RANGE_C`].
    #[error(
        "{field} = {temperature_c} C is outside the range of the D341 line here ({lo_c}..{hi_c} C)"
    )]
    TemperatureOutOfRange {
        /// The input's name.
        field: &'static str,
        /// Its value, C.
        temperature_c: f64,
        /// Lowest accepted temperature, C.
        lo_c: f64,
        /// Highest accepted temperature, C.
        hi_c: f64,
    },
    /// A viscosity below [`WALTHER_NU_MIN_MM2_S`], given or predicted.
    #[error(
        "{field} = {nu_mm2_s} mm^2/s is below {min_mm2_s} mm^2/s, the low end of the D341 line"
    )]
    ViscosityBelowRange {
        /// The input's name, or `nu_mm2_s` for a predicted value.
        field: &'static str,
        /// The viscosity, mm^2/s.
        nu_mm2_s: f64,
        /// The lowest accepted viscosity, mm^2/s.
        min_mm2_s: f64,
    },
    /// Two points that do not make a line falling with temperature (equal temperatures, or a
    /// viscosity that does not fall as the temperature rises).
    #[error(
        "the viscosity must fall as the temperature rises: {nu1_mm2_s} mm^2/s at \
         {t1_c} C and {nu2_mm2_s} mm^2/s at {t2_c} C do not"
    )]
    NotFalling {
        /// First temperature, C.
        t1_c: f64,
        /// Viscosity at the first temperature, mm^2/s.
        nu1_mm2_s: f64,
        /// Second temperature, C.
        t2_c: f64,
        /// Viscosity at the second temperature, mm^2/s.
        nu2_mm2_s: f64,
    },
}

/// D341 Eq. 2: the Walther variable `Z` of a kinematic viscosity in mm^2/s.
pub fn walther_z(nu_mm2_s: f64) -> f64 {
    let nu = nu_mm2_s;
    nu + 0.7 + (-1.47 - 1.84 * nu - 0.51 * nu * nu).exp()
}

/// D341 Eq. 3: the kinematic viscosity in mm^2/s of a Walther variable `Z` (the approximate
/// inverse of [`walther_z`]).
pub fn walther_nu_mm2_s(z: f64) -> f64 {
    let x = z - 0.7;
    x - (-0.7487 - 3.295 * x + 0.6119 * x * x - 0.3193 * x * x * x).exp()
}

/// A D341 line `log10 log10 Z = A - B log10 T`, `T` in K.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaltherLine {
    a: f64,
    b: f64,
}

impl WaltherLine {
    /// The line through two kinematic viscosities (mm^2/s) at two temperatures (C); the
    /// viscosity must fall as the temperature rises.
    pub fn through(
        t1_c: f64,
        nu1_mm2_s: f64,
        t2_c: f64,
        nu2_mm2_s: f64,
    ) -> Result<Self, WaltherError> {
        check_temperature("t1_c", t1_c)?;
        check_temperature("t2_c", t2_c)?;
        check_viscosity("nu1_mm2_s", nu1_mm2_s)?;
        check_viscosity("nu2_mm2_s", nu2_mm2_s)?;
        // The hotter point must have the lower viscosity; this also refuses t1 == t2.
        let falling =
            (t2_c > t1_c && nu2_mm2_s < nu1_mm2_s) || (t1_c > t2_c && nu1_mm2_s < nu2_mm2_s);
        if !falling {
            return Err(WaltherError::NotFalling {
                t1_c,
                nu1_mm2_s,
                t2_c,
                nu2_mm2_s,
            });
        }
        let (x1, x2) = (log_t(t1_c), log_t(t2_c));
        let (y1, y2) = (log_log_z(nu1_mm2_s), log_log_z(nu2_mm2_s));
        let b = (y1 - y2) / (x2 - x1);
        Ok(WaltherLine { a: y1 + b * x1, b })
    }

    /// The constant `A` (temperature in K, logarithms base 10).
    pub fn a(&self) -> f64 {
        self.a
    }

    /// The slope `B` (temperature in K, logarithms base 10), the "ASTM slope".
    pub fn b(&self) -> f64 {
        self.b
    }

    /// Kinematic viscosity at `temperature_c`, mm^2/s.
    pub fn nu_mm2_s(&self, temperature_c: f64) -> Result<f64, WaltherError> {
        check_temperature("temperature_c", temperature_c)?;
        let z = 10f64.powf(10f64.powf(self.a - self.b * log_t(temperature_c)));
        let nu = walther_nu_mm2_s(z);
        if nu < WALTHER_NU_MIN_MM2_S {
            return Err(WaltherError::ViscosityBelowRange {
                field: "nu_mm2_s",
                nu_mm2_s: nu,
                min_mm2_s: WALTHER_NU_MIN_MM2_S,
            });
        }
        Ok(nu)
    }
}

fn log_t(temperature_c: f64) -> f64 {
    (temperature_c + ZERO_C_IN_K).log10()
}

fn log_log_z(nu_mm2_s: f64) -> f64 {
    walther_z(nu_mm2_s).log10().log10()
}

fn check_temperature(field: &'static str, temperature_c: f64) -> Result<(), WaltherError> {
    let (lo_c, hi_c) = WALTHER_TEMPERATURE_RANGE_C;
    if !(lo_c..=hi_c).contains(&temperature_c) {
        return Err(WaltherError::TemperatureOutOfRange {
            field,
            temperature_c,
            lo_c,
            hi_c,
        });
    }
    Ok(())
}

fn check_viscosity(field: &'static str, nu_mm2_s: f64) -> Result<(), WaltherError> {
    if !(nu_mm2_s > 0.0 && nu_mm2_s.is_finite()) {
        return Err(WaltherError::NotPositive {
            field,
            value: nu_mm2_s,
        });
    }
    if nu_mm2_s < WALTHER_NU_MIN_MM2_S {
        return Err(WaltherError::ViscosityBelowRange {
            field,
            nu_mm2_s,
            min_mm2_s: WALTHER_NU_MIN_MM2_S,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::lubricant::LubricantTable;
    use crate::physics::pressure_viscosity::STACHOWIAK_TABLE_2_3;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    #[test]
    fn eq3_inverts_eq2_down_to_the_floor_and_is_the_plain_form_above_2() {
        // Eqs. 2 and 3 are separate fits; their round trip is what fixes the 0.2 mm^2/s floor.
        // 3e-4: the largest round-trip error found on this grid is 2.4e-4 (at 0.3 mm^2/s).
        for i in 0..=200 {
            let nu = 0.2 + 0.05 * f64::from(i);
            assert!(rel(walther_nu_mm2_s(walther_z(nu)), nu) < 3e-4, "nu = {nu}");
        }
        // Above 2 mm^2/s the correction is below 1e-3 in Z, so D341's plain form holds:
        // 7.6e-4 at 2 mm^2/s, 4.2e-8 at 4 mm^2/s.
        assert!((walther_z(2.0) - 2.7).abs() < 1e-3);
        assert!((walther_z(4.0) - 4.7).abs() < 1e-7);
    }

    #[test]
    fn reproduces_published_d341_calculations() {
        // A D341 spreadsheet (Scribd "Viscosity vs Temperature Calculator"): 32 mm^2/s at
        // 40 C and 5.4 mm^2/s at 100 C give A = 9.5259, B = 3.7449 and 8.5 mm^2/s at 80 C.
        // It takes T = t + 273 (not 273.15), which moves A and B in the third decimal; A and B
        // are therefore checked to 1e-3 relative, and the 80 C value to the 0.05 mm^2/s its
        // rounding to one decimal allows.
        let line = WaltherLine::through(40.0, 32.0, 100.0, 5.4).unwrap();
        assert!(rel(line.a(), 9.5259) < 1e-3, "A = {}", line.a());
        assert!(rel(line.b(), 3.7449) < 1e-3, "B = {}", line.b());
        assert!((line.nu_mm2_s(80.0).unwrap() - 8.5).abs() < 0.05);
        // olezol.com's D341 example: SAE 140 gear oil, 404 mm^2/s at 40 C and 28 mm^2/s at
        // 100 C, gives 132.126 mm^2/s at 60 C (printed to 3 decimals, so 5e-4 absolute).
        let line = WaltherLine::through(40.0, 404.0, 100.0, 28.0).unwrap();
        assert!((line.nu_mm2_s(60.0).unwrap() - 132.126).abs() < 5e-4);
    }

    #[test]
    fn passes_through_its_points() {
        // Eq. 3 inverts Eq. 2 to 3e-4 (test above); at these viscosities to far better.
        let line = WaltherLine::through(40.0, 46.0, 100.0, 6.8).unwrap();
        assert!(rel(line.nu_mm2_s(40.0).unwrap(), 46.0) < 1e-9);
        assert!(rel(line.nu_mm2_s(100.0).unwrap(), 6.8) < 1e-9);
        let n = line.nu_mm2_s(70.0).unwrap();
        assert!(6.8 < n && n < 46.0);
    }

    #[test]
    fn predicts_the_measured_60_c_viscosity_of_13_mineral_oils() {
        // Measured viscosity at a third temperature: Stachowiak & Batchelor, *Engineering
        // Tribology*, Table 2.3 (from the ASME Pressure-Viscosity Report, 1953), dynamic
        // viscosity of 13 mineral oils at 30, 60 and 100 C, 2-3 significant digits.
        // The line through 30 and 100 C, applied to the dynamic viscosity in mPa s (the table
        // gives no density); it predicts the 60 C value with errors from -7.5 % to +10.5 %
        // (median -2.7 %). 11 % is that worst case: the data's 2-3 significant digits alone
        // move a 30 C value such as 18.6 by up to 0.3 %, and the older mineral oils need not
        // follow a Walther line exactly.
        let mut worst: f64 = 0.0;
        for ([e30, e60, e100], _) in STACHOWIAK_TABLE_2_3 {
            let line = WaltherLine::through(30.0, e30, 100.0, e100).unwrap();
            let err = line.nu_mm2_s(60.0).unwrap() / e60 - 1.0;
            worst = worst.max(err.abs());
        }
        assert!(worst < 0.11, "worst error {worst}");
        assert!(worst > 0.10, "the documented worst case moved: {worst}");
    }

    #[test]
    fn table1_60_c_from_the_40_and_100_c_points() {
        // Table 1 gives DYNAMIC viscosity at 40, 60 and 100 C and no density, so the D341 line
        // is applied to eta in mPa s as if it were nu in mm^2/s (a kinematic line would need
        // an assumed density; rho changes by ~4 % from 40 to 100 C, which shifts a 60 C
        // prediction by well under 1 %). Predicted 60 C value against Table 1:
        //   traction fluid   13.160 vs 13.1 mPa s:  +0.46 %
        //   mineral oil A     4.553 vs 4.19 mPa s:  +8.67 %
        //   5P4E             76.877 vs 79 mPa s:    -2.69 %
        // The assertions pin these numbers to 0.05 percentage points (the table's 3 digits
        // are exact inputs here, so only round-off is left), so this comment stays true.
        // Mineral oil A's 8.7 % is far outside what D341 does for mineral oils with 3-digit
        // data (the worst of 13 oils above is 10.5 % with 2-digit data, median 2.7 %): Table 1's
        // 60 C value for it is not on the Walther line of its 40 and 100 C values.
        let table = LubricantTable::table1();
        for (name, expected) in [
            ("traction-fluid", 0.0046),
            ("mineral-oil-a", 0.0867),
            ("5p4e", -0.0269),
        ] {
            let lub = table.get(name).unwrap();
            let eta = &lub.eta0_mpa_s;
            let line = WaltherLine::through(40.0, eta[0], 100.0, eta[2]).unwrap();
            let err = line.nu_mm2_s(60.0).unwrap() / eta[1] - 1.0;
            assert!((err - expected).abs() < 5e-4, "{name}: {err}");
        }
    }

    #[test]
    fn every_error_is_reachable() {
        assert!(matches!(
            WaltherLine::through(40.0, -1.0, 100.0, 5.0),
            Err(WaltherError::NotPositive {
                field: "nu1_mm2_s",
                ..
            })
        ));
        assert!(matches!(
            WaltherLine::through(40.0, 30.0, 100.0, f64::NAN),
            Err(WaltherError::NotPositive {
                field: "nu2_mm2_s",
                ..
            })
        ));
        assert!(matches!(
            WaltherLine::through(40.0, 30.0, 200.0, 5.0),
            Err(WaltherError::TemperatureOutOfRange { field: "t2_c", .. })
        ));
        assert!(matches!(
            WaltherLine::through(40.0, 30.0, 100.0, 0.1),
            Err(WaltherError::ViscosityBelowRange {
                field: "nu2_mm2_s",
                ..
            })
        ));
        assert!(matches!(
            WaltherLine::through(40.0, 5.0, 100.0, 30.0),
            Err(WaltherError::NotFalling { .. })
        ));
        assert!(matches!(
            WaltherLine::through(40.0, 5.0, 40.0, 3.0),
            Err(WaltherError::NotFalling { .. })
        ));
        // 1.0 and 0.3 mm^2/s at 40 and 100 C extrapolate to 0.18 mm^2/s at 150 C.
        let line = WaltherLine::through(40.0, 1.0, 100.0, 0.3).unwrap();
        assert!(matches!(
            line.nu_mm2_s(-30.0),
            Err(WaltherError::TemperatureOutOfRange {
                field: "temperature_c",
                ..
            })
        ));
        let e = line.nu_mm2_s(150.0).unwrap_err();
        assert!(matches!(e, WaltherError::ViscosityBelowRange { .. }), "{e}");
        assert!(e.to_string().contains("nu_mm2_s"), "{e}");
    }
}
