//! A Newton step's preconditioner factor kept for the next steps, and mapped onto their
//! systems where the active set has moved at a few nodes.
//!
//! Near the solution a step moves the cavitation boundary by a few nodes (the Fig. 6 family
//! of 5P4E at 40 C, 2 GPa, 7 m/s at level 7: 2-90 of 57 000 unknowns), and the system's
//! unknowns with it. The factor made for the last step's unknowns still preconditions the
//! rest: each unknown both systems share, with the same kind of row (Reynolds or identity),
//! goes through the factor; an unknown only the new system has, or whose row changed kind,
//! is passed through unchanged, its row's diagonal being about 1 (the rows are scaled by
//! their own diagonal's magnitude, [`super::row_scales`], and a cavitating node's row is the
//! identity); an unknown only the factor has gets a zero right-hand side. GMRES is the
//! flexible form and corrects what the factor misses; a factor that no longer
//! preconditions within [`super::LAG_ITERATIONS`] gives way to a new one.

use crate::solver::bordered_lu::{BorderedLu, LuStorage};

/// Largest share of a system's unknowns that may differ from the factor's (be new, gone,
/// or of the other kind of row) for the factor to precondition it. 1 %: the steps near the
/// solution move a few tenths of a percent of the nodes; a step far from it moves more, and
/// its Jacobian has moved too far for a lagged factor anyway.
const CHANGED_SHARE: f64 = 0.01;

/// A factor and the unknowns it was made for.
#[derive(Clone)]
pub(crate) struct KeptFactor {
    lu: BorderedLu,
    /// Its unknowns' nodes, in its order.
    active: Vec<usize>,
    /// Per unknown: whether its row is the identity.
    cavitating: Vec<bool>,
}

impl std::fmt::Debug for KeptFactor {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "KeptFactor({} unknowns)", self.active.len())
    }
}

/// A factor as the preconditioner of one system: its own, or a kept one mapped onto it.
pub(super) struct Preconditioner {
    factor: KeptFactor,
    /// `None` where the system's unknowns are the factor's.
    map: Option<Map>,
}

/// A system's unknowns mapped onto a factor's.
struct Map {
    /// Per unknown of the system (less `Delta`): the factor's unknown, `usize::MAX` for one
    /// passed through.
    to_factor: Vec<usize>,
    /// The right-hand side and solution in the factor's unknowns.
    x: Vec<f64>,
    y: Vec<f64>,
}

impl KeptFactor {
    /// The storage of its factorisation, for a new one.
    pub(super) fn into_storage(self) -> LuStorage {
        self.lu.into_storage()
    }

    /// This factor as the preconditioner of the system of `active` nodes (`cavitating` its
    /// identity rows): as it is where they are its own; mapped where `moved` allows it and
    /// at most [`CHANGED_SHARE`] of the unknowns differ; else its storage back (boxed: it
    /// holds the factor's buffers by value).
    pub(super) fn remap(
        self,
        active: &[usize],
        cavitating: &[bool],
        moved: bool,
    ) -> Result<Preconditioner, Box<LuStorage>> {
        if active == self.active.as_slice() && cavitating == self.cavitating.as_slice() {
            return Ok(Preconditioner {
                factor: self,
                map: None,
            });
        }
        if !moved {
            return Err(Box::new(self.into_storage()));
        }
        let size = active.iter().chain(&self.active).max().map_or(0, |m| m + 1);
        let mut own = vec![usize::MAX; size];
        for (c, &k) in self.active.iter().enumerate() {
            own[k] = c;
        }
        let to_factor: Vec<usize> = active
            .iter()
            .zip(cavitating)
            .map(|(&k, &cav)| match own[k] {
                c if c != usize::MAX && self.cavitating[c] == cav => c,
                _ => usize::MAX,
            })
            .collect();
        let shared = to_factor.iter().filter(|&&c| c != usize::MAX).count();
        let changed = (active.len() - shared) + (self.active.len() - shared);
        if changed as f64 > CHANGED_SHARE * active.len() as f64 {
            return Err(Box::new(self.into_storage()));
        }
        let n = self.active.len() + 1;
        Ok(Preconditioner {
            factor: self,
            map: Some(Map {
                to_factor,
                x: vec![0.0; n],
                y: vec![0.0; n],
            }),
        })
    }
}

impl Preconditioner {
    /// A factor made for the system of `active` nodes (`cavitating` its identity rows).
    pub fn fresh(lu: BorderedLu, active: &[usize], cavitating: &[bool]) -> Self {
        let factor = KeptFactor {
            lu,
            active: active.to_vec(),
            cavitating: cavitating.to_vec(),
        };
        Preconditioner { factor, map: None }
    }

    /// `out = M^-1 v` for the system's `v` (its unknowns, then `Delta`'s row).
    pub fn solve(&mut self, v: &[f64], out: &mut [f64]) {
        let Some(map) = &mut self.map else {
            self.factor.lu.solve(v, out);
            return;
        };
        let (n, nf) = (map.to_factor.len(), self.factor.active.len());
        map.x.fill(0.0);
        for (b, &c) in map.to_factor.iter().enumerate() {
            if c != usize::MAX {
                map.x[c] = v[b];
            }
        }
        map.x[nf] = v[n];
        self.factor.lu.solve(&map.x, &mut map.y);
        for (b, &c) in map.to_factor.iter().enumerate() {
            out[b] = if c != usize::MAX { map.y[c] } else { v[b] };
        }
        out[n] = map.y[nf];
    }

    /// The factor, to be kept for the next step.
    pub fn into_kept(self) -> KeptFactor {
        self.factor
    }

    /// The storage of its factorisation, for a new one.
    pub(super) fn into_storage(self) -> LuStorage {
        self.factor.into_storage()
    }
}
