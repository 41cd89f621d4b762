//! Cache keys: what makes two solves the same. A key is the SHA-256 of the canonical JSON of
//! everything a result depends on ([`key_of`]), so a result is reused exactly where it would
//! come out the same, and recomputed where anything it depends on changed.

use super::cache::key_of;
use crate::physics::case::{Case, Physics};
use crate::physics::thermal::{TARGET_INPUTS, THERMAL_REVISION};
use crate::solver::line;
use crate::solver::point::composite::PatchSpec;
use crate::solver::point::{Edge, FrictionRegion, Params, SOLVER_REVISION};
use serde::Serialize;

/// The revision of the line-contact numerics, part of every line-contact cache key.
pub use crate::solver::line::SOLVER_REVISION as LINE_SOLVER_REVISION;

/// The revisions a point case's key holds: the point numerics' and the thermal post-process's.
pub fn point_revisions() -> String {
    format!("{SOLVER_REVISION} {THERMAL_REVISION}")
}

/// The revision a line contact's key holds.
pub fn line_revisions() -> String {
    LINE_SOLVER_REVISION.to_string()
}

/// The revisions the present build's keys hold: an entry made under any other is never
/// answered again ([`super::prune`]).
pub fn present_revisions() -> [String; 2] {
    [point_revisions(), line_revisions()]
}

/// The cache key of a case at the given solver parameters: the case, the parameters a target
/// can set (level, domain, rolling friction, the film check, and the edge, friction region
/// and central film where they are not the rule's), the solver revision, which is
/// raised whenever a default parameter or the numerics change, the thermal post-process's
/// inputs and revision, and the key of the base it starts from
/// ([`super::base::base_of`]), whose solution is part of its arithmetic.
pub fn case_key(case: &Case, params: &Params, base_key: Option<&str>) -> String {
    let d = &params.domain;
    let key = (
        case,
        params.level,
        (d.x_start, d.x_end, d.y_half),
        params.friction.rolling,
        (
            params.accuracy.require_positive_film,
            params.accuracy.refinement_levels,
        ),
        SOLVER_REVISION,
        (THERMAL_REVISION, TARGET_INPUTS),
        base_key,
    );
    // The edge and the friction's region, where they are not the rule's (the paper's setup
    // beside Fig. 6), and the accuracy target, where one is set (the rule's, and an
    // expert's): a key without either is a solve to its level as given.
    let rule =
        params.edge == Edge::FarField && params.friction.region == FrictionRegion::LoadedFilm;
    let plain = match (rule, params.accuracy.target) {
        (true, None) => key_of(&key),
        (false, None) => key_of(&(key, setup(params))),
        (_, Some(target)) => key_of(&(key, setup(params), target)),
    };
    // A solve that reports its level's own central film, not the rule's tau-extrapolated one
    // (Table 4's levels): the rule's key, marked.
    let plain = if params.accuracy.tau_extrapolation {
        plain
    } else {
        key_of(&(plain, "the level's central film"))
    };
    // A composite grid's patch, where one is set: the key of the grid without it, and it.
    match &params.patch {
        None => plain,
        Some(set) => {
            let part = |p: &PatchSpec| (p.x_start, p.y_centre, p.cells_level, p.margin, p.band);
            let fixed: Vec<_> = set.fixed.iter().map(part).collect();
            key_of(&(plain, fixed, set.lobes.as_ref().map(part)))
        }
    }
}

/// The edge and friction region of `params`, as a key part.
fn setup(params: &Params) -> String {
    format!("{:?} {:?}", params.edge, params.friction.region)
}

/// The cache key of a line contact at the given solver parameters (the parameters a target
/// can set and the revision, as [`case_key`]).
pub fn line_key<C: Serialize>(case: &C, physics: &Physics, params: &line::Params) -> String {
    key_of(&(
        "line",
        case,
        physics,
        params.level,
        (params.domain.x_start, params.domain.x_end),
        params.rolling_friction,
        params.require_positive_film,
        params.refinement_levels,
        LINE_SOLVER_REVISION,
    ))
}
