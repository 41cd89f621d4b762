//! The typed failure of a solve, with the residual history it carries.

/// A solve that did not produce a trustworthy answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SolveError {
    /// The residual did not fall below the tolerance within the cycle budget.
    #[error("not converged after {cycles} cycles: residual {last:.3e} > tolerance {tolerance:.1e} (history: {history})", last = residual_history.last().copied().unwrap_or(f64::NAN), history = format_history(residual_history))]
    NotConverged {
        /// Cycles run.
        cycles: usize,
        /// Requested tolerance.
        tolerance: f64,
        /// Residual after each cycle.
        residual_history: Vec<f64>,
    },
    /// A NaN or infinity appeared in the pressure, film or residual.
    #[error("non-finite {what} at cycle {cycle} (history: {history})", history = format_history(residual_history))]
    NonFinite {
        /// Which quantity.
        what: &'static str,
        /// Cycle in which it appeared.
        cycle: usize,
        /// Residual after each completed cycle.
        residual_history: Vec<f64>,
    },
    /// The film collapsed (`H <= 0` somewhere): the grid is too coarse for this load.
    #[error("film thickness became non-positive (min H = {h_min:.3e}) at level {level}, cycle {cycle}: {advice} (history: {history})", history = format_history(residual_history), advice = level_advice(*level_needed, *finest_level))]
    FilmCollapse {
        /// Minimum film.
        h_min: f64,
        /// The finest level solved on.
        level: u32,
        /// The level estimated to resolve the film, where the solver can estimate it
        /// ([`crate::solver::point::level_to_resolve`]).
        level_needed: Option<u32>,
        /// The finest level the solver accepts.
        finest_level: u32,
        /// Cycle.
        cycle: usize,
        /// Residual after each completed cycle.
        residual_history: Vec<f64>,
    },
    /// Parameters the solver cannot use.
    #[error("invalid solver parameter: {0}")]
    InvalidParams(String),
}

impl SolveError {
    /// `Ok` where `level` lies in `levels` (a solver's finest levels), else the
    /// [`SolveError::InvalidParams`] that names both.
    pub(crate) fn check_level(
        level: u32,
        levels: std::ops::RangeInclusive<u32>,
    ) -> Result<(), SolveError> {
        if levels.contains(&level) {
            Ok(())
        } else {
            Err(SolveError::InvalidParams(format!(
                "level {level} outside {}..={}",
                levels.start(),
                levels.end()
            )))
        }
    }

    /// The residual history carried by the error.
    pub fn residual_history(&self) -> &[f64] {
        match self {
            SolveError::NotConverged {
                residual_history, ..
            }
            | SolveError::NonFinite {
                residual_history, ..
            }
            | SolveError::FilmCollapse {
                residual_history, ..
            } => residual_history,
            SolveError::InvalidParams(_) => &[],
        }
    }
}

/// What a collapsed film asks of the grid.
fn level_advice(needed: Option<u32>, finest: u32) -> String {
    match needed {
        Some(n) if n < finest => {
            format!("the grid cannot resolve this film; level {n} is estimated to resolve it (--level {n})")
        }
        Some(n) if n == finest => format!(
            "the grid cannot resolve this film; level {n}, the solver's finest, is estimated to \
             resolve it (--level {below}, which refines a film closed there to {n}; level {n} \
             takes about 13 GB of memory and minutes on one core: docs/hard-cases.md)",
            below = n - 1
        ),
        Some(n) => format!(
            "the grid cannot resolve this film; level {n} is estimated to resolve it, beyond \
             the solver's finest level {finest}"
        ),
        None => "the grid cannot resolve this film; a finer level may resolve it".to_string(),
    }
}

fn format_history(h: &[f64]) -> String {
    h.iter()
        .map(|r| format!("{r:.2e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::level_advice;

    /// Below the finest level the advice names the level to ask for; at the finest it names
    /// the level below, whose closed film the rule refines to the finest (the path measured on
    /// the M 35 900 thin film, docs/hard-cases.md), and what that level costs; beyond it, that
    /// the solver has no such level.
    #[test]
    fn the_advice_names_the_level_to_ask_for_and_what_the_finest_costs() {
        assert!(level_advice(Some(8), 9).ends_with("(--level 8)"));
        let finest = level_advice(Some(9), 9);
        assert!(finest.contains("(--level 8, which refines") && finest.contains("13 GB"));
        assert!(level_advice(Some(10), 9).contains("beyond the solver's finest level 9"));
        assert!(level_advice(None, 9).contains("a finer level may resolve it"));
    }
}
