//! The thermal post-process as a solve reports it: the shear-heating correction of the
//! sliding friction ([`crate::paper::prediction::heat`]) as a line of text and a JSON object,
//! with its warning.

use crate::paper::prediction::heat::{HeatCorrection, MaybeHeat};
use serde_json::{json, Value};

/// A heat correction as printed.
trait Printed {
    fn text(&self) -> String;
    fn json(&self) -> Value;
}

impl Printed for HeatCorrection {
    /// One line of the text summary.
    fn text(&self) -> String {
        let t = &self.thermal;
        format!(
            "thermal     mu-bar = {:.4} ({:+.2} %; mid-plane closure {:.4}, {:+.2} %), film +{:.1} K, surfaces +{:.1} K at most ({}; solids {} W/mK, beta0 = {:.4} /K, Peclet {:.0}, film Peclet {:.2e}; {:.1} ms)\n",
            t.mu_bar_sliding,
            100.0 * self.correction(),
            t.mu_bar_sliding_midplane,
            100.0 * (t.mu_bar_sliding_midplane / self.isothermal - 1.0),
            t.dt_film_max_k,
            t.dt_flash_max_k,
            self.source,
            t.k_solid_w_mk,
            t.beta0_per_k,
            t.peclet,
            t.film_peclet,
            self.seconds * 1e3,
        )
    }

    /// The JSON object.
    fn json(&self) -> Value {
        let mut v = serde_json::to_value(self.thermal).unwrap_or(Value::Null);
        v["correction"] = json!(self.correction());
        v["source"] = json!(self.source);
        v["seconds"] = json!(self.seconds);
        v["warning"] = json!(self.warning());
        v
    }
}

/// The text line and warning of an optional post-process, or why it is missing.
pub fn describe(report: &MaybeHeat) -> (String, Option<String>) {
    match report {
        Some(Ok(r)) => (r.text(), r.warning()),
        Some(Err(e)) => (format!("thermal     not computed: {e}\n"), None),
        None => (
            "thermal     not computed: needs a physical case with a Table 1 lubricant (--lubricant, --temperature) for the temperature coefficient\n".into(),
            None,
        ),
    }
}

/// The JSON value of an optional post-process (`null` where not computed).
pub fn json_of(report: &MaybeHeat) -> Value {
    match report {
        Some(Ok(r)) => r.json(),
        Some(Err(e)) => json!({ "error": e.to_string() }),
        None => Value::Null,
    }
}
