//! insta snapshots of what `repro` prints as text: the target list and the tables emitted
//! from cases/ (Tables 1-3). Review a change with `cargo insta review` (or accept it with
//! `INSTA_UPDATE=always`); the computed CSVs are guarded by `repro check` instead.

/// The stdout of `repro args`, which must succeed.
fn repro(args: &[&str]) -> String {
    let (code, out, err) = crate::support::repro(args);
    assert_eq!(code, 0, "{err}");
    out
}

#[test]
fn target_list() {
    insta::assert_snapshot!(repro(&["list"]));
}

#[test]
fn tables_1_to_3() {
    let dir = std::env::temp_dir().join(format!("repro-text-{}", std::process::id()));
    for t in ["table1", "table2", "table3"] {
        repro(&[t, "-q", "--out", dir.to_str().unwrap()]);
        let text = std::fs::read_to_string(dir.join(format!("{t}.csv"))).expect("csv written");
        insta::assert_snapshot!(t, text);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
