//! Table 4 as the report shows it: per level the paper's value, ours and their difference,
//! with the observed order of each; then the paper's convergence claims (its Appendix text)
//! beside what its own table shows and what ours shows.

use super::html::{percent, Num};
use crate::paper::table4::{paper_at, PaperClaims, PAPER_CLAIMS};
use crate::paper::target::LevelResult;

/// One output (central film or friction) at one level.
#[derive(Debug, Clone, PartialEq)]
pub struct Output {
    /// The paper's value.
    pub paper: Option<Num>,
    /// Ours.
    pub ours: Option<Num>,
    /// `ours / paper - 1`, per cent.
    pub difference: Option<Num>,
    /// Observed order of ours from this level and the two below it.
    pub order_ours: Option<Num>,
    /// Observed order of the paper's, likewise.
    pub order_paper: Option<Num>,
}

/// One level's row.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelRow {
    /// Grid level.
    pub level: u32,
    /// Grid points, `n x n`.
    pub points: String,
    /// Central film `H = h/c`.
    pub film: Output,
    /// Sliding `mu-bar`.
    pub friction: Output,
    /// As `table4.csv` writes it.
    pub status: &'static str,
    /// Wall time, s.
    pub seconds: Option<Num>,
}

impl LevelRow {
    /// Central film and friction, in the table's order.
    pub fn outputs(&self) -> [&Output; 2] {
        [&self.film, &self.friction]
    }
}

/// One claim of the paper's Appendix, beside what the paper's table and ours show.
#[derive(Debug, Clone, PartialEq)]
pub struct Claim {
    /// What is claimed.
    pub what: String,
    /// The paper's words, as a number.
    pub paper_says: String,
    /// What the paper's own Table 4 shows.
    pub paper_table: Option<Num>,
    /// What ours shows.
    pub ours: Option<Num>,
    /// The unit of the last two (`%` or empty).
    pub unit: &'static str,
}

/// The report's Table 4.
#[derive(Debug, Clone, PartialEq)]
pub struct Convergence {
    /// One row per level.
    pub rows: Vec<LevelRow>,
    /// The paper's claims.
    pub claims: Vec<Claim>,
    /// The levels the claims are measured on (the claim's level and its neighbours).
    pub claim_levels: String,
    /// A level ended `ok-film-nonpositive`.
    pub film_nonpositive: bool,
}

/// The observed order of a quantity at three consecutive levels, `(f0, f1, f2)` coarse to
/// fine: `log2(|f1 - f0| / |f2 - f1|)`; `None` where the differences do not shrink.
pub fn observed_order(f0: f64, f1: f64, f2: f64) -> Option<f64> {
    let p = ((f1 - f0).abs() / (f2 - f1).abs()).log2();
    (p.is_finite() && p > 0.0).then_some(p)
}

/// The relative error of the middle of three consecutive levels `(f0, f1, f2)` against
/// their Richardson extrapolation with the observed order.
pub fn middle_error(f0: f64, f1: f64, f2: f64) -> Option<f64> {
    let p = observed_order(f0, f1, f2)?;
    let limit = f2 + (f2 - f1) / (2f64.powf(p) - 1.0);
    Some(((f1 - limit) / limit).abs())
}

/// The three consecutive levels ending at `levels[i]`, by `value`, if all are there.
fn three(levels: &[LevelResult], i: usize, value: Value) -> Option<[f64; 3]> {
    let w = levels.get(i.checked_sub(2)?..=i)?;
    let consecutive = w[1].level == w[0].level + 1 && w[2].level == w[1].level + 1;
    consecutive.then_some([value(&w[0])?, value(&w[1])?, value(&w[2])?])
}

/// A level's output: ours from `levels`, the paper's from its Table 4.
fn output(levels: &[LevelResult], i: usize, (_, paper, ours): (&str, Value, Value)) -> Output {
    let r = &levels[i];
    let (o, p) = (ours(r), paper(r));
    let order = |value| three(levels, i, value).and_then(|[a, b, c]| observed_order(a, b, c));
    Output {
        paper: p.map(Num),
        ours: o.map(Num),
        difference: o.zip(p).map(|(o, p)| percent(o / p - 1.0)),
        order_ours: order(ours).map(Num),
        order_paper: order(paper).map(Num),
    }
}

/// Ours of one output at a level.
type Value = fn(&LevelResult) -> Option<f64>;

/// The paper's central film and friction at a level, ours at it, and their names.
const OUTPUTS: [(&str, Value, Value); 2] = [
    (
        "central film",
        |r| paper_at(r.level).map(|p| p.0),
        |r| r.h_central,
    ),
    ("friction", |r| paper_at(r.level).map(|p| p.1), |r| r.mu_bar),
];

/// The paper's claims beside its table and ours, measured on the claim's level and the
/// levels either side of it: the order of each output, then its error.
fn claims(levels: &[LevelResult], claims: PaperClaims) -> Vec<Claim> {
    let at = levels.iter().position(|r| r.level == claims.level + 1);
    let measure = |value: Value, how: fn(f64, f64, f64) -> Option<f64>, scale: f64| {
        at.and_then(|i| three(levels, i, value))
            .and_then(|[a, b, c]| how(a, b, c))
            .map(|v| Num(scale * v))
    };
    let claimed_errors = [claims.film_error, claims.friction_error];
    let orders = OUTPUTS.iter().map(|&(name, paper, ours)| Claim {
        what: format!("order of convergence, {name}"),
        paper_says: format!("{}", claims.order),
        paper_table: measure(paper, observed_order, 1.0),
        ours: measure(ours, observed_order, 1.0),
        unit: "",
    });
    let errors = OUTPUTS
        .iter()
        .zip(claimed_errors)
        .map(|(&(name, paper, ours), claimed)| Claim {
            what: format!("error at level {}, {name}", claims.level),
            paper_says: format!("about {} %", percent(claimed)),
            paper_table: measure(paper, middle_error, 100.0),
            ours: measure(ours, middle_error, 100.0),
            unit: " %",
        });
    orders.chain(errors).collect()
}

impl Convergence {
    /// The report's Table 4 of a grid-convergence study (levels in ascending order).
    pub fn of(levels: &[LevelResult]) -> Convergence {
        let rows = (0..levels.len())
            .map(|i| {
                let r = &levels[i];
                let n = 1u32 << (r.level + 1);
                LevelRow {
                    level: r.level,
                    points: format!("{n}×{n}"),
                    film: output(levels, i, OUTPUTS[0]),
                    friction: output(levels, i, OUTPUTS[1]),
                    status: r.status,
                    seconds: r.seconds.map(Num),
                }
            })
            .collect();
        let l = PAPER_CLAIMS.level;
        Convergence {
            rows,
            claims: claims(levels, PAPER_CLAIMS),
            claim_levels: format!("{}-{}", l - 1, l + 1),
            film_nonpositive: levels.iter().any(|r| r.status == "ok-film-nonpositive"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn second_order_data_show_order_two_and_the_extrapolated_error() {
        // f = 1 + h^2 with h halving: differences 3/16 then 3/64, order exactly 2; the
        // middle level's error against the limit 1 is 1/16 (floating point only).
        let f = |k: i32| 1.0 + 0.25f64.powi(k);
        let p = observed_order(f(1), f(2), f(3)).unwrap();
        assert!((p - 2.0).abs() < 1e-12, "{p}");
        let e = middle_error(f(1), f(2), f(3)).unwrap();
        assert!((e - 0.0625).abs() < 1e-12, "{e}");
        assert_eq!(observed_order(1.0, 2.0, 4.0), None, "growing differences");
    }

    #[test]
    fn table4_rows_set_ours_beside_the_paper() {
        let level = |level, h: f64, mu: f64| LevelResult {
            level,
            h_central: Some(h),
            mu_bar: Some(mu),
            status: if level == 5 {
                "ok-film-nonpositive"
            } else {
                "ok"
            },
            seconds: Some(1.0),
        };
        // The paper's own values as "ours": no difference, and its own orders on both sides.
        let levels: Vec<LevelResult> = (5..=8)
            .map(|l| {
                let (h, mu) = paper_at(l).unwrap();
                level(l, h, mu)
            })
            .collect();
        let c = Convergence::of(&levels);
        assert!(c.film_nonpositive);
        assert_eq!(c.rows[0].points, "64×64");
        assert_eq!(c.rows[3].friction.difference, Some(Num(0.0)));
        assert_eq!(
            c.rows[0].film.order_ours, None,
            "no two levels below level 5"
        );
        let order = c.rows[3].film.order_ours.unwrap().0;
        assert_eq!(Some(Num(order)), c.rows[3].film.order_paper);
        // The paper's films at levels 6-8 (1.603e-2, 1.978e-2, 2.076e-2): order
        // log2(0.375 / 0.098) = 1.94.
        assert!((order - 1.936).abs() < 1e-3, "{order}");
        assert_eq!(c.claims.len(), 4);
        assert_eq!(c.claims[0].paper_table, c.claims[0].ours);
        assert_eq!(c.claims[2].paper_says, "about 5 %");
        assert_eq!(c.claim_levels, "6-8");
    }
}
