//! The sweep figures of the paper, Figs. 1-7, as data: each one [`SweepFigure`], its sweep
//! file, what it plots, how its series split, its level and the paper's claim. Adding a sweep
//! figure is its `cases/<sweep>.toml`, its entry here and its line in the registry
//! (`paper/mod.rs`); nothing else reads its name.

use super::plot::{Abscissa, FrictionAxis, Plot, SeriesBy};
use crate::paper::target::{sweep_file, ShippedSweep};
use crate::plot::Scale;

/// The claim of the figures of sliding friction (Figs. 3-7 and a user's study).
pub const SLIDING_CLAIM: &str = "sliding mu-bar follows Eq. (13): mu-bar = asinh(tau_c / 5)";

/// A figure of a shipped sweep: Figs. 1-7.
#[derive(Debug, Clone, Copy)]
pub struct SweepFigure {
    /// Target name, `fig1` ...
    pub name: &'static str,
    /// Its name in titles and the report, `Fig. 1` ...
    pub heading: &'static str,
    /// One line for `repro list`.
    pub description: &'static str,
    /// The shipped sweep it draws (`cases/<name>.toml`).
    pub sweep: ShippedSweep,
    /// What it plots.
    pub plot: Plot,
    /// How its cases split into series.
    pub series: SeriesBy,
    /// Level without `--level` ([`crate::paper::Target::default_level`]).
    pub level: u32,
    /// The paper's claim, for the report.
    pub claim: &'static str,
    /// Adds the line contacts of Table 3 (Fig. 7).
    pub line_contacts: bool,
    /// Draws beside its cases the paper's setup ([`crate::pipeline::job::Setup::Paper`]),
    /// every case as the paper computed it, a series of its own with its own Eq. (13)
    /// statistics (Fig. 6).
    pub paper_setup: bool,
    /// The friction axis's scale: the paper's Figs. 1-3 are log-log, Figs. 4-7 log-linear
    /// (its text: Figs. 4-6 "now" use a log-linear scale).
    pub friction_scale: Scale,
}

/// Fig. 1: total friction against the paper's severity group.
pub const FIG1: SweepFigure = SweepFigure {
    name: "fig1",
    heading: "Fig. 1",
    description:
        "Total mu-bar vs S-bar^(1/4) M L^3, Barus-incompressible circular contact (125 cases)",
    sweep: sweep_file!("fig1-3"),
    plot: Plot {
        x: Abscissa::Severity,
        y: FrictionAxis::Total,
    },
    series: SeriesBy::MoesL,
    level: 6,
    claim: "friction collapses on one curve for S-bar^(1/4) M L^3 >= 1e4, scattered below",
    line_contacts: false,
    paper_setup: false,
    friction_scale: Scale::Log,
};

/// Fig. 2: total friction against `tau_c`.
pub const FIG2: SweepFigure = SweepFigure {
    name: "fig2",
    heading: "Fig. 2",
    description: "Total mu-bar vs tau_c, same sweep, Eq. (13) dashed",
    plot: Plot {
        x: Abscissa::TauC,
        y: FrictionAxis::Total,
    },
    claim: "total mu-bar follows Eq. (13), c = 5, except a cluster at low tau_c where rolling friction dominates",
    ..FIG1
};

/// Fig. 3: sliding friction against `tau_c`, Figs. 1-2's sweep.
pub const FIG3: SweepFigure = SweepFigure {
    name: "fig3",
    heading: "Fig. 3",
    description: "Sliding mu-bar vs tau_c, same sweep, Eq. (13) dashed",
    plot: Plot::SLIDING,
    claim: SLIDING_CLAIM,
    ..FIG1
};

/// Fig. 4: mineral oil A over Table 2. Level 7 for Figs. 4-6: the level study's light end
/// (Fig. 6 case 23, on its nested domains) is 1.1 % off in friction at level 6, 0.44 % at 7.
pub const FIG4: SweepFigure = SweepFigure {
    name: "fig4",
    heading: "Fig. 4",
    description: "Sliding mu-bar vs tau_c, mineral oil A, Roelands + Dowson-Higginson, Table 2 grid (243 cases)",
    sweep: sweep_file!("fig4"),
    series: SeriesBy::Temperature,
    level: 7,
    friction_scale: Scale::Linear,
    ..FIG3
};

/// Fig. 5: the traction fluid over Table 2.
pub const FIG5: SweepFigure = SweepFigure {
    name: "fig5",
    heading: "Fig. 5",
    description: "Sliding mu-bar vs tau_c, traction fluid, Table 2 grid (243 cases)",
    sweep: sweep_file!("fig5"),
    ..FIG4
};

/// Fig. 6: 5P4E over Table 2.
pub const FIG6: SweepFigure = SweepFigure {
    name: "fig6",
    heading: "Fig. 6",
    description: "Sliding mu-bar vs tau_c, 5P4E, Table 2 grid (243 cases)",
    sweep: sweep_file!("fig6"),
    paper_setup: true,
    ..FIG4
};

/// Fig. 7: the ellipses and line contacts of Table 3.
pub const FIG7: SweepFigure = SweepFigure {
    name: "fig7",
    heading: "Fig. 7",
    description: "Sliding mu-bar vs tau_c, mineral oil A, Rx/Ry = 1/2, 1/5 and the line contact at the Table 3 cases",
    sweep: sweep_file!("fig7"),
    series: SeriesBy::RadiusRatio,
    level: 7,
    line_contacts: true,
    friction_scale: Scale::Linear,
    ..FIG3
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paper::{find, REGISTRY};
    use crate::physics::case::Problem;
    use crate::physics::lubricant::LubricantTable;
    use std::collections::BTreeSet;

    const FIGURES: [&SweepFigure; 7] = [&FIG1, &FIG2, &FIG3, &FIG4, &FIG5, &FIG6, &FIG7];

    /// The registry serves each entry of the table: its name, level, description and sweep
    /// file are the entry's, so `repro list`, `repro all` and the shipped sweeps
    /// ([`crate::paper::cases::shipped`]) read the one description. (A figure added later
    /// need not be listed here: the registry's line is all it needs.)
    #[test]
    fn the_registry_serves_the_figure_table() {
        for fig in FIGURES {
            let a = find(fig.name).unwrap_or_else(|| panic!("{} is not registered", fig.name));
            assert_eq!(a.describe(), fig.description);
            assert_eq!(a.default_level(), Some(fig.level));
            assert_eq!(a.sweep_file(), Some(fig.sweep), "{}", fig.name);
        }
    }

    /// Every registered target that draws a sweep has a sweep file that parses, in its own
    /// name's file (`cases/<name>.toml`, written once by `sweep_file!`), and a default level:
    /// what `repro list` shows and `make figures` runs for it.
    #[test]
    fn every_registered_sweep_parses_and_has_a_level() {
        for a in REGISTRY.iter().filter(|a| a.sweep_file().is_some()) {
            let file = a.sweep_file().unwrap();
            let sweep = file.parse().unwrap_or_else(|e| panic!("{}: {e}", a.name()));
            assert!(!sweep.cases.is_empty(), "{}", file.path());
            assert!(a.default_level().is_some(), "{}", a.name());
        }
    }

    /// Figures may share a sweep file (Figs. 1-3 draw `cases/fig1-3.toml`), but two entries
    /// that draw the same sweep the same way are one picture twice: a copied entry that kept
    /// its template's plot shows here. Names and headings are each figure's own.
    #[test]
    fn no_two_figures_draw_the_same_sweep_the_same_way() {
        let drawn: BTreeSet<_> = FIGURES
            .iter()
            .map(|f| (f.sweep.name, format!("{:?} {:?}", f.plot, f.series)))
            .collect();
        assert_eq!(drawn.len(), FIGURES.len());
        let names: BTreeSet<_> = FIGURES.iter().map(|f| f.name).collect();
        let headings: BTreeSet<_> = FIGURES.iter().map(|f| f.heading).collect();
        assert_eq!((names.len(), headings.len()), (7, 7));
        // Eq. (13) is a curve of tau_c: only a figure against tau_c is measured on it.
        assert!(!FIG1.plot.on_eq13() && FIGURES[1..].iter().all(|f| f.plot.on_eq13()));
    }

    /// Each figure's series key splits its sweep into at least two series (one series would
    /// hide the parameter the sweep varies) and at most five, the markers the picture has
    /// before it repeats one; and the keys are the labels the paper's figures carry.
    #[test]
    fn every_figure_splits_its_sweep_into_labelled_series() {
        let lubs = LubricantTable::table1();
        for fig in FIGURES {
            let sweep = fig.sweep.parse().unwrap();
            let keys: BTreeSet<String> = sweep
                .cases
                .iter()
                .map(|c| fig.series.key(c, &Problem::from_case(c, &lubs).unwrap()))
                .collect();
            assert!((2..=5).contains(&keys.len()), "{}: {keys:?}", fig.name);
            let expected: &[&str] = match fig.series {
                SeriesBy::MoesL => &["L = 1", "L = 10", "L = 15", "L = 2", "L = 5"],
                SeriesBy::RadiusRatio => &["Rx/Ry = 1/2", "Rx/Ry = 1/5"],
                SeriesBy::Temperature => &["100 °C", "40 °C", "60 °C"],
            };
            assert_eq!(keys.iter().collect::<Vec<_>>(), expected, "{}", fig.name);
        }
    }
}
