//! The reference a case's errors are measured against: a Richardson extrapolation of its
//! finest converged levels (the module above says how), read from the grids' own values. A
//! central film the rule reports tau-extrapolated is of higher order than its level, so the
//! levels' sequence is the grids' films, and the reported one is measured against it. The
//! minimum film is extrapolated from the same levels (a case of the study solves square
//! levels, whose minimum film is the grid's own), where they give an estimate.

use super::{LevelOutputs, LevelRun, Reference};
use crate::solver::richardson::{estimate, FIRST_ORDER};

/// `f` extrapolated from the level below, `c`, at order `p`.
fn extrapolate(c: f64, f: f64, p: f64) -> f64 {
    f + (f - c) / (2f64.powf(p) - 1.0)
}

/// The reference of a case from its converged levels.
pub fn reference(levels: &[LevelRun]) -> Option<Reference> {
    let ok: Vec<(u32, LevelOutputs)> = levels
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok().map(|m| (r.level, *m)))
        .collect();
    let (&(lf, f), rest) = ok.split_last()?;
    let prev = rest.last().filter(|(l, _)| *l + 1 == lf).map(|p| p.1);
    let Some(c) = prev else {
        return Some(Reference {
            h_central: f.h_central_grid,
            mu_bar: f.mu_bar,
            h_min: Some(f.h_min),
            order_used_h_min: None,
            kind: "finest",
            order: None,
            order_used: None,
        });
    };
    let coarse =
        (rest.len() >= 2 && rest[rest.len() - 2].0 + 2 == lf).then(|| rest[rest.len() - 2].1);
    let Some(a) = coarse else {
        return Some(Reference {
            h_central: extrapolate(c.h_central_grid, f.h_central_grid, 2.0),
            mu_bar: extrapolate(c.mu_bar, f.mu_bar, 2.0),
            h_min: Some(extrapolate(c.h_min, f.h_min, 2.0)),
            order_used_h_min: Some(2.0),
            kind: "richardson",
            order: None,
            order_used: Some((2.0, 2.0)),
        });
    };
    // The solver's own estimate over the three levels (the same fit and acceptance).
    let film = estimate(
        &[a.h_central_grid, c.h_central_grid, f.h_central_grid],
        FIRST_ORDER,
    )?;
    let mu = estimate(&[a.mu_bar, c.mu_bar, f.mu_bar], FIRST_ORDER)?;
    let h_min = estimate(&[a.h_min, c.h_min, f.h_min], FIRST_ORDER);
    Some(Reference {
        h_central: film.extrapolated,
        mu_bar: mu.extrapolated,
        h_min: h_min.map(|e| e.extrapolated),
        order_used_h_min: h_min.map(|e| e.order_used),
        kind: "observed-order",
        order: film.order.zip(mu.order),
        order_used: Some((film.order_used, mu.order_used)),
    })
}
