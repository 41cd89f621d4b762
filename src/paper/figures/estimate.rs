//! What a case's discretisation-error estimate read and, where it read fewer levels than asked
//! or none, why: the `error_levels` and `error_status` columns of every figure CSV with error
//! columns (the point contacts' and Fig. 7's line contacts'), and the words the `solve`
//! report uses for a ladder that stopped.

use crate::pipeline::outcome::SolvedCase;
use crate::solver::output::{LadderStop, OutputErrors};
use serde::Serialize;

/// The estimate's columns of a row: the levels it read (`first-last`, blank where none) and
/// its status ([`status`]).
#[derive(Debug, Default, Serialize)]
pub struct EstimateCells {
    error_levels: String,
    error_status: String,
}

impl EstimateCells {
    /// The cells of a case: `solved`, or `None` where it failed.
    pub fn of(solved: Option<&SolvedCase>) -> Self {
        let Some(s) = solved else {
            return EstimateCells {
                error_levels: String::new(),
                error_status: "not estimated; the case failed".into(),
            };
        };
        let errors = s.errors.as_deref();
        let levels = errors.map_or(&[][..], |e| e.levels.as_slice());
        EstimateCells {
            error_levels: match (levels.first(), levels.last()) {
                (Some(a), Some(b)) => format!("{}-{}{}", a.level, b.level, across_words(errors)),
                _ => String::new(),
            },
            error_status: status(errors),
        }
    }
}

/// `+7y` (`+8y`) where the solve added a top refined across the rolling direction above level
/// 7 (8) ([`OutputErrors::across`]), else nothing.
fn across_words(errors: Option<&OutputErrors>) -> String {
    errors
        .and_then(|e| e.across)
        .map_or_else(String::new, |a| format!("+{}y", a.top.level))
}

/// The status of a solved case's estimate: `estimated` where it read two levels or more and
/// the ladder did not stop; `estimated; ...` where a coarser level stopped it after two or
/// more (two are read at the scheme's order where the level below was outside the asymptotic
/// range, else at first order: [`OutputErrors::estimate`]); `not estimated; ...` where it
/// read the finest level alone (its error cells are blank), with why.
pub fn status(errors: Option<&OutputErrors>) -> String {
    let read = errors.map_or(0, |e| e.levels.len());
    match (read >= 2, errors.and_then(|e| e.stopped)) {
        (true, None) => "estimated".into(),
        (true, Some(stop)) => format!("estimated; {}", ladder_stop_words(stop)),
        (false, Some(stop)) => format!("not estimated; {}", ladder_stop_words(stop)),
        (false, None) => "not estimated; no coarser level solved".into(),
    }
}

/// Why the ladder of coarser levels stopped, in a few words: `level 6 not read: it did not
/// converge`.
pub fn ladder_stop_words(stop: LadderStop) -> String {
    match stop {
        LadderStop::FilmClosed { level } => {
            format!("level {level} not read: its film closes at the centre")
        }
        LadderStop::NotConverged { level } => {
            format!("level {level} not read: it did not converge")
        }
        LadderStop::FilmUnresolved { level } => {
            format!("level {level} not read: its central film is under half the finest's")
        }
        LadderStop::OutsideAtBase { level } => {
            format!("level {level} not read: outside the asymptotic range at the case's base")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::output::LevelValues;

    fn errors(levels: &[u32], stopped: Option<LadderStop>) -> OutputErrors {
        let values = levels
            .iter()
            .map(|&level| LevelValues {
                level,
                h_central: 0.5,
                h_min: 0.4,
                mu_bar_sliding: 40.0,
                mu_bar_total: 41.0,
            })
            .collect();
        OutputErrors {
            stopped,
            ..OutputErrors::of(values, 1.0)
        }
    }

    #[test]
    fn the_status_says_why_an_estimate_is_missing_or_short() {
        assert_eq!(status(Some(&errors(&[5, 6, 7], None))), "estimated");
        let closed = Some(LadderStop::FilmClosed { level: 5 });
        assert_eq!(
            status(Some(&errors(&[6, 7], closed))),
            "estimated; level 5 not read: its film closes at the centre"
        );
        let diverged = Some(LadderStop::NotConverged { level: 6 });
        assert_eq!(
            status(Some(&errors(&[7], diverged))),
            "not estimated; level 6 not read: it did not converge"
        );
        assert_eq!(
            status(Some(&errors(&[7], None))),
            "not estimated; no coarser level solved"
        );
        assert_eq!(status(None), "not estimated; no coarser level solved");
    }
}
