use super::*;

/// Labels `base..base + n`.
fn labels(base: usize, n: usize) -> Vec<usize> {
    (base..base + n).collect()
}

#[test]
fn solves_a_bordered_system_like_its_dense_form() {
    // A 1-D convection-diffusion block, a column and a row like Delta's and the load's.
    let n = 40;
    let mut entries = Vec::new();
    for i in 0..n {
        entries.push(Triplet::new(i, i, 2.4));
        if i > 0 {
            entries.push(Triplet::new(i, i - 1, -1.5));
        }
        if i + 1 < n {
            entries.push(Triplet::new(i, i + 1, -0.8));
            // A repeated position: summed.
            entries.push(Triplet::new(i, i + 1, 0.1));
        }
    }
    let u: Vec<f64> = (0..n).map(|i| 0.3 + 0.01 * i as f64).collect();
    let w = vec![0.05; n];
    let d = 0.0;
    let mut lu = BorderedLu::factorize(&entries, &labels(0, n), &u, &w, d, LuStorage::default())
        .expect("regular");
    // The dense form of the same matrix, solved by the dense LU.
    let m = n + 1;
    let mut dense = vec![0.0; m * m];
    for e in &entries {
        dense[e.row * m + e.col] += e.val;
    }
    for i in 0..n {
        dense[i * m + n] = u[i];
        dense[n * m + i] = w[i];
    }
    dense[n * m + n] = d;
    let rhs: Vec<f64> = (0..m).map(|i| (0.37 * i as f64).cos()).collect();
    let mut expect = rhs.clone();
    assert!(crate::solver::dense::solve(&dense, &mut expect, m));
    let mut got = vec![0.0; m];
    lu.solve(&rhs, &mut got);
    let err = got
        .iter()
        .zip(&expect)
        .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    let scale = expect.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    // A single-precision factor (unit roundoff 6e-8) of a matrix with condition number
    // ~1e2 against a double-precision dense LU: they agree to ~1e-6 relative (6.5e-7
    // measured); 1e-5 catches a wrong Schur complement or border, an O(1) error.
    assert!(
        err < 1e-5 * scale,
        "max difference {err:.3e} of {scale:.3e}"
    );
}

/// A 2-D convection-diffusion block on an `m x m` grid with the 5 x 5 box of entries
/// the Newton preconditioner has, or a 1-D one of order `m` (a system faer's own driver
/// would have factorised in its simplicial form), with a Delta-like column and load row.
fn system(m: usize, two_d: bool) -> (usize, Vec<Entry>, Vec<f64>, Vec<f64>) {
    let mut entries = Vec::new();
    let n = if two_d { m * m } else { m };
    for r in 0..n {
        entries.push(Triplet::new(r, r, 30.0 + (r % 7) as f64));
        if two_d {
            let (i, j) = ((r % m) as isize, (r / m) as isize);
            for dj in -2isize..=2 {
                for di in -2isize..=2 {
                    let (a, b) = (i + di, j + dj);
                    if (di, dj) != (0, 0)
                        && (0..m as isize).contains(&a)
                        && (0..m as isize).contains(&b)
                    {
                        let c = (b * m as isize + a) as usize;
                        entries.push(Triplet::new(
                            r,
                            c,
                            -0.5 / (1.0 + (di * di + dj * dj) as f64) - 0.1 * di as f64,
                        ));
                    }
                }
            }
        } else {
            if r > 0 {
                entries.push(Triplet::new(r, r - 1, -1.5));
            }
            if r + 1 < n {
                entries.push(Triplet::new(r, r + 1, -0.8));
            }
        }
    }
    let u = (0..n).map(|i| 0.3 + 0.01 * (i % 11) as f64).collect();
    let w = vec![1.0 / n as f64; n];
    (n, entries, u, w)
}

#[test]
fn storage_handed_on_gives_the_bits_of_a_fresh_factorisation() {
    // Orders that shrink and grow, 1-D and 2-D, as a Newton
    // iteration's active sets do: each solve must be the fresh factorisation's, bit for bit.
    let mut storage = LuStorage::default();
    let mut base = 0;
    for (m, two_d) in [
        (40, false),
        (30, false),
        (50, false),
        (50, false),
        (24, true),
        (20, true),
        (26, true),
        (35, false),
    ] {
        let (n, entries, u, w) = system(m, two_d);
        let rhs: Vec<f64> = (0..=n).map(|i| (0.37 * i as f64).cos()).collect();
        // Labels no earlier system had: COLAMD orders each, as it does a fresh one.
        base += 10_000;
        let labels = labels(base, n);
        let mut fresh = BorderedLu::factorize(&entries, &labels, &u, &w, 0.0, LuStorage::default())
            .expect("regular");
        let mut reused =
            BorderedLu::factorize(&entries, &labels, &u, &w, 0.0, storage).expect("regular");
        assert!(reused.reordered);
        let (mut a, mut b) = (vec![0.0; n + 1], vec![0.0; n + 1]);
        fresh.solve(&rhs, &mut a);
        reused.solve(&rhs, &mut b);
        assert_eq!(a, b, "order {n}");
        storage = reused.into_storage();
    }
}

#[test]
fn the_kept_order_ranks_the_known_labels_and_puts_new_ones_last() {
    // Labels 7, 3, 9 ranked 2, 0, 1 by the last COLAMD order.
    let mut ranks = vec![u32::MAX; 10];
    (ranks[7], ranks[3], ranks[9]) = (2, 0, 1);
    assert_eq!(kept_order(&ranks, &[7, 3, 9]), Some(vec![1, 2, 0]));
    // An unranked label (5, and 12 beyond the ranks) is one too many in a system of
    // three or four (more than 2 %) ...
    assert_eq!(kept_order(&ranks, &[7, 5, 3, 9]), None);
    assert_eq!(kept_order(&ranks, &[12, 7, 3, 9]), None);
    // ... but not in one of 60: it goes last.
    let mut ranks = vec![u32::MAX; 100];
    for (r, label) in (0..59).rev().enumerate() {
        ranks[label] = r as u32;
    }
    let labels: Vec<usize> = (0..59).chain([99]).collect();
    let order = kept_order(&ranks, &labels).expect("one new label of 60");
    assert_eq!(order[0], 58);
    assert_eq!(order[58], 0);
    assert_eq!(order[59], 59);
    // No ranks yet: COLAMD.
    assert_eq!(kept_order(&[], &[0, 1]), None);
}

#[test]
fn a_kept_order_solves_a_changed_system_like_a_fresh_factorisation() {
    // A 2-D system, then the same grid with two nodes gone and one node new (as a Newton
    // step's active set changes at the cavitation boundary): the second is factorised in
    // the first's order and must solve like a fresh (COLAMD) factorisation of it.
    let (n, entries, u, w) = system(30, true);
    let first = BorderedLu::factorize(&entries, &labels(0, n), &u, &w, 0.0, LuStorage::default())
        .expect("regular");
    assert!(first.reordered);
    // Drop unknowns 100 and 500; relabel the last one as a node the first system lacked.
    let keep: Vec<usize> = (0..n).filter(|&c| c != 100 && c != 500).collect();
    let new_index = |c: usize| keep.iter().position(|&k| k == c);
    let entries2: Vec<Entry> = entries
        .iter()
        .filter_map(|e| Some(Triplet::new(new_index(e.row)?, new_index(e.col)?, e.val)))
        .collect();
    let mut labels2: Vec<usize> = keep.clone();
    *labels2.last_mut().unwrap() = 5000;
    let u2: Vec<f64> = keep.iter().map(|&c| u[c]).collect();
    let w2: Vec<f64> = keep.iter().map(|&c| w[c]).collect();
    let mut kept = BorderedLu::factorize(&entries2, &labels2, &u2, &w2, 0.0, first.into_storage())
        .expect("regular");
    assert!(!kept.reordered);
    let mut fresh = BorderedLu::factorize(&entries2, &labels2, &u2, &w2, 0.0, LuStorage::default())
        .expect("regular");
    let rhs: Vec<f64> = (0..=keep.len()).map(|i| (0.37 * i as f64).cos()).collect();
    let (mut a, mut b) = (vec![0.0; rhs.len()], vec![0.0; rhs.len()]);
    kept.solve(&rhs, &mut a);
    fresh.solve(&rhs, &mut b);
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let err = a
        .iter()
        .zip(&b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    // Two single-precision LU solves (unit roundoff 6e-8) of a diagonally dominant
    // system (condition ~10) in different orders agree to ~1e-7 relative (7e-9
    // measured); 1e-5 catches a wrong permutation, which gives an O(1) difference.
    assert!(err < 1e-5 * scale, "difference {err:.3e} of {scale:.3e}");
}

#[test]
fn a_singular_block_is_refused() {
    let entries = vec![Triplet::new(0, 0, 1.0), Triplet::new(1, 0, 1.0)];
    assert!(BorderedLu::factorize(
        &entries,
        &[0, 1],
        &[1.0, 1.0],
        &[1.0, 1.0],
        0.0,
        LuStorage::default()
    )
    .is_none());
}
