//! The levels the line contact's discretisation error reads: the finest converged level and
//! up to [`ERROR_LEVELS`] below it from the nested iteration, each inside the asymptotic
//! range, coarse to fine ([`crate::solver::richardson`]).
//!
//! A coarser level is outside that range, and ends the ladder ([`LadderStop`]), where its
//! central film is closed (not positive: its friction is then negative, Fig. 7's line contact
//! 2 at level 6 gives -12.4 against 13.0 at level 8) or open but under
//! [`crate::solver::output::RESOLVED_FILM_SHARE`] of the finest level's (a film the mesh does not resolve: the same
//! contact at level 7 has 0.55e-3 against 2.2e-3 at level 8 and 2.8e-3 at level 10, and read,
//! it gives level 9 an error of 0.046 where level 10 is 0.053 away). The solve refines its
//! grid until three levels are read ([`super::Params::refinement_levels`]).

use crate::solver::output::{LadderStop, LevelValues, OutputErrors};
use crate::solver::richardson::ERROR_LEVELS;

/// The error record of `ladder` (every converged level of the nested iteration, coarse to
/// fine): its finest level and the coarser ones inside the asymptotic range next to it, with
/// the reason the ladder stopped where a level was left out. `None` where the nested
/// iteration converged fewer than `ERROR_LEVELS + 1` levels (it started too close to the
/// finest).
pub fn errors(ladder: &[LevelValues], seconds: f64) -> Option<OutputErrors> {
    let wanted = ERROR_LEVELS as usize + 1;
    if ladder.len() < wanted {
        return None;
    }
    let finest = ladder[ladder.len() - 1];
    let mut read = vec![finest];
    let mut stopped = None;
    for v in ladder.iter().rev().skip(1).take(wanted - 1) {
        if let Some(stop) = LadderStop::outside(v, &finest) {
            stopped = Some(stop);
            break;
        }
        read.insert(0, *v);
    }
    Some(OutputErrors {
        stopped,
        ..OutputErrors::of(read, seconds)
    })
}

/// Whether `errors` reads the three levels an observed order needs.
pub fn complete(errors: Option<&OutputErrors>) -> bool {
    errors.is_some_and(|e| e.levels.len() > ERROR_LEVELS as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn level(level: u32, h_central: f64, mu: f64) -> LevelValues {
        LevelValues {
            level,
            h_central,
            h_min: 0.9 * h_central,
            mu_bar_sliding: mu,
            mu_bar_total: mu,
        }
    }

    #[test]
    fn a_closed_or_unresolved_coarse_film_ends_the_ladder() {
        // Fig. 7's line contact 2 (levels 6-8 as the solver gives them).
        let line2 = [
            level(6, -3.84e-3, -12.37),
            level(7, 5.48e-4, 14.68),
            level(8, 2.22e-3, 13.02),
        ];
        let e = errors(&line2, 0.0).unwrap();
        assert_eq!(e.levels.len(), 1);
        assert_eq!(e.stopped, Some(LadderStop::FilmUnresolved { level: 7 }));
        assert!(!complete(Some(&e)));
        let e = errors(&[line2[0], line2[2], level(9, 2.7e-3, 12.79)], 0.0).unwrap();
        assert_eq!(e.levels.len(), 2);
        assert_eq!(e.stopped, Some(LadderStop::FilmClosed { level: 6 }));
        // Levels 8-10: all read.
        let e = errors(
            &[
                line2[1],
                line2[2],
                level(9, 2.70e-3, 12.79),
                level(10, 2.83e-3, 12.73),
            ],
            0.0,
        )
        .unwrap();
        assert_eq!(
            e.levels.iter().map(|v| v.level).collect::<Vec<_>>(),
            [8, 9, 10]
        );
        assert_eq!(e.stopped, None);
        assert!(complete(Some(&e)));
        // Fewer than three converged levels: no record.
        assert!(errors(&line2[1..], 0.0).is_none());
    }
}
