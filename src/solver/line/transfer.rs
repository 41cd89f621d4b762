//! Transfer of a converged solution from a grid to the next finer one (ratio 2): the start of
//! the nested iteration.

use super::level::LineLevelFields;

/// The converged coarse pressure interpolated (four-point cubic, one
/// sided next to the ends) to the fine grid, projected on `P >= 0`.
pub(crate) fn interpolate_solution(coarse: &LineLevelFields, fine: &mut LineLevelFields) {
    let n = fine.n;
    let c = |k: usize| coarse.p[k / 2];
    for i in 0..=n {
        fine.p[i] = if i % 2 == 0 {
            c(i)
        } else if i == 1 {
            (5.0 * c(0) + 15.0 * c(2) - 5.0 * c(4) + c(6)) / 16.0
        } else if i == n - 1 {
            (5.0 * c(n) + 15.0 * c(n - 2) - 5.0 * c(n - 4) + c(n - 6)) / 16.0
        } else {
            (-c(i - 3) + 9.0 * c(i - 1) + 9.0 * c(i + 1) - c(i + 3)) / 16.0
        };
    }
    fine.p[0] = 0.0;
    fine.p[n] = 0.0;
    fine.p.iter_mut().for_each(|v| *v = v.max(0.0));
}
