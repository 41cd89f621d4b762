//! Every column of every CSV the targets write is described in `figures/README.md`: the
//! headers of the committed baselines (`snapshots/`, every target at the CI profile) and of
//! the accuracy study's files (`figures/accuracy*.csv`, not snapshotted), and the headers the
//! sweep figures' CSVs have now (a column added since the baselines were made included), each
//! column named there in backquotes.

use repro::paper::figures::line::line_csv;
use repro::paper::figures::{rows, FIG1, FIG2, FIG3, FIG4, FIG5, FIG6, FIG7};
use std::path::Path;

#[test]
fn every_csv_column_is_described_in_the_figures_readme() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("figures/README.md")).expect("README");
    let mut files: Vec<_> = std::fs::read_dir(root.join("snapshots"))
        .expect("snapshots/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    files.extend(
        ["figures/accuracy.csv", "figures/accuracy_levels.csv"]
            .iter()
            .map(|f| root.join(f))
            .filter(|p| p.exists()),
    );
    let mut texts: Vec<(String, String)> = files
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .map(|f| (f.display().to_string(), std::fs::read_to_string(f).unwrap()))
        .collect();
    // A CSV without rows is its header.
    for fig in [&FIG1, &FIG2, &FIG3, &FIG4, &FIG5, &FIG6, &FIG7] {
        texts.push((format!("{}.csv now", fig.name), rows::csv(&[], fig.plot)));
    }
    texts.push(("fig7-line.csv now".into(), line_csv(&[], 8)));
    let mut missing = Vec::new();
    let mut read = 0;
    for (file, text) in &texts {
        // The header: the first line that is not a comment.
        let Some(header) = text.lines().find(|l| !l.starts_with('#')) else {
            continue;
        };
        read += 1;
        for column in header.split(',') {
            if !readme.contains(&format!("`{column}`")) {
                missing.push(format!("{file}: {column}"));
            }
        }
    }
    // Every target's baseline at least (tables 1-4, figures 1-8, the rest).
    assert!(read >= 20, "read {read} CSV files");
    assert!(missing.is_empty(), "not described: {missing:?}");
}
