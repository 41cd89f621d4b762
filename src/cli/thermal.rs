//! The thermal post-process's flags of `repro solve` and `repro predict`, checked; its text
//! line and JSON object are the library's ([`repro::report::solve`]).

use super::args::ThermalArgs;
use anyhow::Result;
use repro::physics::thermal::ThermalInputs;
pub use repro::report::solve::{thermal_json as json_of, thermal_text as describe};

impl ThermalArgs {
    /// The inputs, checked.
    pub fn inputs(&self) -> Result<ThermalInputs> {
        Ok(repro::report::inputs::thermal_inputs(
            self.k_solid,
            self.k_lubricant,
        )?)
    }
}
