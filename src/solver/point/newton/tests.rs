use super::lagged::Preconditioner;
use super::*;
use crate::physics::case::Problem;
use crate::physics::hertz::Hertz;
use crate::solver::dense;
use crate::solver::grid::{Domain, Grid};
use crate::solver::point::HalfPointMean;

/// A moderately loaded Eyring contact on a level-4 grid, at the Hertzian pressure and a
/// `Delta` that keeps the film positive.
fn setup() -> (LevelFields, Model, f64) {
    setup_with(HalfPointMean::Arithmetic)
}

/// [`setup`] with the half-point mean `mean`.
fn setup_with(mean: HalfPointMean) -> (LevelFields, Model, f64) {
    let problem = Problem::circular(100.0, 10.0, 0.5);
    let model = Model::new(&problem).with_half_point(mean);
    let grid = Grid::level(&Domain::default(), 4);
    let mut level = LevelFields::new(grid, &model);
    level.half_point = mean;
    level.p = grid.sample(Hertz::pressure);
    let delta = 0.3;
    level.update_film(delta);
    assert!(
        level.h.iter().all(|&h| h > 0.0),
        "the test needs a positive film"
    );
    (level, model, delta)
}

/// `r / c` at the given nodes and the relative load error, for pressure `p` and `delta`.
fn reynolds(
    level: &mut LevelFields,
    model: &Model,
    p: &[f64],
    delta: f64,
    scale: &[f64],
    at: &[usize],
) -> Vec<f64> {
    level.p.copy_from_slice(p);
    let ev = evaluate(level, model, delta, scale);
    let g = level.grid;
    let mut out: Vec<f64> = at
        .iter()
        .map(|&k| level.residual(k % g.px(), k / g.px()) / scale[k])
        .collect();
    out.push(ev.load);
    out
}

/// The Jacobian at the test state for its pressurised nodes.
fn linearise(level: &mut LevelFields, model: &Model) -> Jacobian {
    let g = level.grid;
    level.update_coefficients(model);
    let scale = row_scales(level);
    let active: Vec<usize> = (1..g.ny)
        .flat_map(|j| (1..g.nx).map(move |i| g.idx(i, j)))
        .filter(|&k| level.p[k] > 0.0)
        .collect();
    assert!(active.len() > 100, "{} pressurised nodes", active.len());
    let cavitating = vec![false; active.len()];
    Jacobian::new(level, model, active, cavitating, scale)
}

/// A direction with every node moving differently, and `Delta` moving too.
fn direction(n: usize) -> Vec<f64> {
    (0..n)
        .map(|r| ((r * 7919) % 101) as f64 / 101.0 - 0.3)
        .collect()
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

#[test]
fn jacobian_vector_product_matches_central_differences_of_the_residual() {
    for mean in [HalfPointMean::Arithmetic, HalfPointMean::ExponentialFit] {
        jacobian_vector_product_matches_central_differences_with(mean);
    }
}

fn jacobian_vector_product_matches_central_differences_with(mean: HalfPointMean) {
    let (mut level, model, delta) = setup_with(mean);
    let mut jac = linearise(&mut level, &model);
    let scale = row_scales(&level);
    let n = jac.len();
    let v = direction(n);
    let mut jv = vec![0.0; n];
    jac.apply(&mut level, &v, &mut jv);
    // The assembled dense Jacobian (the oracle of the other tests), at the same state.
    let dense = jac.dense(&level);
    let dv: Vec<f64> = (0..n)
        .map(|r| (0..n).map(|c| dense[r * n + c] * v[c]).sum())
        .collect();
    let p0 = level.p.clone();
    let eps = 1e-6;
    let moved = |sign: f64| {
        let mut p = p0.clone();
        for (r, &k) in jac.active.iter().enumerate() {
            p[k] += sign * eps * v[r];
        }
        (p, delta + sign * eps * v[n - 1])
    };
    let (pp, hp) = moved(1.0);
    let (pm, hm) = moved(-1.0);
    let plus = reynolds(&mut level, &model, &pp, hp, &scale, &jac.active);
    let minus = reynolds(&mut level, &model, &pm, hm, &scale, &jac.active);
    let fd: Vec<f64> = plus
        .iter()
        .zip(&minus)
        .map(|(a, b)| (a - b) / (2.0 * eps))
        .collect();
    // Central differences with step 1e-6 are exact to ~1e-10 relative (truncation
    // O(eps^2), round-off 1e-16 / eps), the Jacobian's local coefficient derivatives to
    // ~1e-9 (FD_REL = 1e-5): 1e-6 leaves room for both and catches any wrong term.
    let (worst, big) = (max_diff(&jv, &fd), max_abs(&fd));
    assert!(
        worst < 1e-6 * big,
        "{mean:?}: max |J v - FD| = {worst:.3e}, max |FD| = {big:.3e}"
    );
    // The dense Jacobian is the same operator: the kernel by direct summation instead
    // of the FFT, the same terms summed in another order; round-off only.
    assert!(
        max_diff(&dv, &jv) < 1e-10 * big,
        "{:.3e}",
        max_diff(&dv, &jv)
    );
}

/// Solves `J x = b` by the preconditioned GMRES of the Newton step.
fn krylov(
    level: &mut LevelFields,
    jac: &mut Jacobian,
    radius: usize,
    local_rows: bool,
    b: &[f64],
    tolerance: f64,
) -> (Vec<f64>, gmres::Convergence) {
    let mut pc = jac
        .preconditioner(level, radius, local_rows, LuStorage::default())
        .expect("regular");
    let mut x = vec![0.0; jac.len()];
    let out = gmres::solve(
        b,
        &mut x,
        &gmres::KrylovParams {
            restart: 50,
            max_iterations: 400,
        },
        tolerance,
        |v, o| jac.apply(level, v, o),
        |v, o| pc.solve(v, o),
    );
    (x, out)
}

#[test]
fn a_step_does_not_depend_on_the_coefficients_left_on_the_level() {
    // A level fresh from interpolation holds no current coefficients (here: none at
    // all); one whose coefficients are those of its state must take the same step.
    let (mut stale, model, delta) = setup();
    let (mut current, _, _) = setup();
    current.update_coefficients(&model);
    let newton = NewtonParams {
        steps: 1,
        box_radius: 2,
        finest_box_radius: 3,
        krylov: gmres::KrylovParams {
            restart: 30,
            max_iterations: 60,
        },
        ..NewtonParams::default()
    };
    let stopping = StoppingParams {
        tolerance: 0.0,
        load_tolerance: 0.0,
        ..StoppingParams::default()
    };
    let (mut a, mut b) = (delta, delta);
    iterate(
        &mut stale,
        &model,
        &mut a,
        (&newton, &stopping),
        FIRST_FORCING,
        None,
        &mut |_, _| {},
    );
    iterate(
        &mut current,
        &model,
        &mut b,
        (&newton, &stopping),
        FIRST_FORCING,
        None,
        &mut |_, _| {},
    );
    assert_eq!((stale.p, a), (current.p, b));
}

#[test]
fn preconditioned_krylov_solve_matches_the_dense_solve() {
    let (mut level, model, _) = setup();
    let mut jac = linearise(&mut level, &model);
    // Some rows of cavitating nodes (identity rows), as a Newton step has them.
    for r in (0..jac.active.len()).step_by(17) {
        jac.cavitating[r] = true;
    }
    let n = jac.len();
    let b = direction(n);
    let mut expect = b.clone();
    assert!(dense::solve(&jac.dense(&level), &mut expect, n));
    let (x, out) = krylov(&mut level, &mut jac, 2, true, &b, 1e-11);
    // A 1e-11 relative residual leaves a relative error of at most cond(J) times that;
    // the level-4 system is well conditioned (cond ~1e3): 1e-7 is ample and catches a
    // wrong product or preconditioner.
    let err = max_diff(&x, &expect) / max_abs(&expect);
    assert!(err < 1e-7, "relative error {err:.3e}, {out:?}");
    // The 5 x 5 box preconditioner leaves few iterations (the feasibility study: 4 to
    // 1e-2, 12 to 1e-6 at level 5); unpreconditioned GMRES needs hundreds.
    assert!(out.iterations <= 30, "{out:?}");
}

#[test]
fn a_box_over_the_whole_grid_is_the_exact_inverse() {
    for mean in [HalfPointMean::Arithmetic, HalfPointMean::ExponentialFit] {
        a_box_over_the_whole_grid_is_the_exact_inverse_with(mean);
    }
}

fn a_box_over_the_whole_grid_is_the_exact_inverse_with(mean: HalfPointMean) {
    let (mut level, model, _) = setup_with(mean);
    let mut jac = linearise(&mut level, &model);
    let radius = level.grid.nx.max(level.grid.ny);
    let b = direction(jac.len());
    let (_, out) = krylov(&mut level, &mut jac, radius, false, &b, 1e-5);
    // With no kernel entry dropped the preconditioner is J itself, factorised in single
    // precision: one iteration leaves only the factor's rounding (unit roundoff 6e-8
    // times this level-4 system's condition, 1.4e-6 measured), below 1e-5; the 5 x 5
    // box, which drops the kernel's far field, needs more (the feasibility study: 12
    // iterations to 1e-6 at level 5).
    assert_eq!(out.iterations, 1, "{out:?}");
}

/// The system of `jac` with its first unknown dropped and every 23rd row made the identity
/// (a step that moved the cavitation boundary), at the same state.
fn moved(level: &LevelFields, model: &Model, jac: &Jacobian) -> Jacobian {
    let active = jac.active[1..].to_vec();
    let cavitating = (0..active.len()).map(|r| r % 23 == 5).collect();
    Jacobian::new(level, model, active, cavitating, row_scales(level))
}

#[test]
fn a_factor_mapped_onto_moved_unknowns_preconditions_their_system() {
    let (mut level, model, _) = setup();
    let jac = linearise(&mut level, &model);
    let factor = || {
        let lu = jac
            .preconditioner(&level, 2, true, LuStorage::default())
            .expect("regular");
        Preconditioner::fresh(lu, &jac.active, &jac.cavitating).into_kept()
    };
    let mut next = moved(&level, &model, &jac);
    let changed = 1 + next.cavitating.iter().filter(|&&c| c).count();
    // Outside the quadratic regime only the factor's own unknowns are taken.
    assert!(
        factor()
            .remap(&next.active, &next.cavitating, false)
            .is_err(),
        "a moved system mapped outside the quadratic regime"
    );
    // `changed` is about 5 % of this level-4 system's unknowns, above the 1 % share a mapped
    // factor may miss: refused too. (At level 7 a step moves 0.01-0.2 %.)
    assert!(changed as f64 > 0.01 * next.active.len() as f64);
    assert!(
        factor()
            .remap(&next.active, &next.cavitating, true)
            .is_err(),
        "{changed} moved unknowns of {} mapped",
        next.active.len()
    );
    // One moved unknown (the dropped one) is within the share: mapped, and GMRES with it
    // reaches the dense solve of the moved system.
    next.cavitating.iter_mut().for_each(|c| *c = false);
    let Ok(mut pc) = factor().remap(&next.active, &next.cavitating, true) else {
        panic!("one moved unknown refused");
    };
    let n = next.len();
    let b = direction(n);
    let mut expect = b.clone();
    assert!(dense::solve(&next.dense(&level), &mut expect, n));
    let mut x = vec![0.0; n];
    let out = gmres::solve(
        &b,
        &mut x,
        &gmres::KrylovParams {
            restart: 50,
            max_iterations: 400,
        },
        1e-11,
        |v, o| next.apply(&mut level, v, o),
        |v, o| pc.solve(v, o),
    );
    // The tolerance as in the unmapped solve's test (cond ~1e3 at level 4).
    let err = max_diff(&x, &expect) / max_abs(&expect);
    assert!(err < 1e-7, "relative error {err:.3e}, {out:?}");
    // The unmapped factor takes at most 30 iterations to 1e-11 here; one unknown passed
    // through by the identity costs a few more, never the hundreds of no preconditioner.
    assert!(out.iterations <= 40, "{out:?}");
}

#[test]
fn a_handed_factor_preconditions_a_related_solve_to_the_same_solution() {
    // The test contact converged, its last factor kept; a related contact (S-bar 0.6 instead
    // of 0.5: other Eyring conductances, as a family's member has) solved from that solution
    // with the factor handed in and without, as a warm member's finish is.
    let (mut level, model, mut delta) = setup();
    let newton = NewtonParams::default();
    let stopping = StoppingParams {
        tolerance: 1e-10,
        load_tolerance: 1e-10,
        ..StoppingParams::default()
    };
    let (run, factor) = iterate(
        &mut level,
        &model,
        &mut delta,
        (&newton, &stopping),
        FIRST_FORCING,
        None,
        &mut |_, _| {},
    );
    assert!(run.converged, "the base converges");
    let factor = factor.expect("a converged solve keeps its last factor");
    let related = Model::new(&Problem::circular(100.0, 10.0, 0.6));
    let solve = |handed: Option<KeptFactor>| {
        let (mut member, _, _) = setup();
        member.p.copy_from_slice(&level.p);
        let mut d = delta;
        let (run, _) = iterate(
            &mut member,
            &related,
            &mut d,
            (&newton, &stopping),
            1e-4,
            handed,
            &mut |_, _| {},
        );
        assert!(run.converged);
        (member.p, d, run)
    };
    let (p_handed, d_handed, handed) = solve(Some(factor));
    let (p_fresh, d_fresh, fresh) = solve(None);
    // Both solve the same equations to a residual of 1e-10: the same solution within a
    // few times that (the pressures are of order 1).
    let apart = max_diff(&p_handed, &p_fresh);
    assert!(apart < 1e-8, "{apart}");
    assert!((d_handed - d_fresh).abs() < 1e-8);
    // The handed factor served the first step: one factorisation fewer.
    assert_eq!(
        handed.factorisations + 1,
        fresh.factorisations,
        "handed {} / fresh {} factorisations",
        handed.factorisations,
        fresh.factorisations
    );
}

/// Level 9's finishes take turns ([`FINEST_FINISH`]); the coarser levels' do not wait.
#[test]
fn level_nine_finishes_take_turns() {
    use crate::solver::point::MAX_LEVEL;
    assert!(finest_turn(MAX_LEVEL - 1).is_none(), "level 8 runs freely");
    let turn = finest_turn(MAX_LEVEL).expect("level 9 holds the turn");
    let other = std::thread::spawn(|| FINEST_FINISH.try_lock().is_ok())
        .join()
        .expect("the probe thread");
    assert!(
        !other,
        "a second level-9 finish waits while the first holds the turn"
    );
    drop(turn);
}
