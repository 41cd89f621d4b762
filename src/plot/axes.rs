//! Axes: a value and its plotted coordinate (itself, or its log10), the range and the ticks.

use super::{PlotError, Scale};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};

/// Plotted coordinate of a value: itself (linear) or its log10 (log); `None` if unplottable.
pub(super) fn to_plot(scale: Scale, v: f64) -> Option<f64> {
    match scale {
        Scale::Linear if v.is_finite() => Some(v),
        Scale::Log if v.is_finite() && v > 0.0 => Some(v.log10()),
        _ => None,
    }
}

/// The vertical error bar of a plottable value `y` with half-width `e`, as the plotted
/// coordinates (low, high) of y - e and y + e; `None` (no bar) unless `e` is finite and
/// positive. On a log axis a low end y - e <= 0 has no plotted coordinate: it is -inf, to be
/// cut at the axis, as is an end that overflows to an infinity.
pub(super) fn error_bar(scale: Scale, y: f64, e: f64) -> Option<(f64, f64)> {
    if !(e.is_finite() && e > 0.0) {
        return None;
    }
    let (low, high) = (y - e, y + e);
    match scale {
        Scale::Linear => Some((low, high)),
        Scale::Log => {
            let low = if low > 0.0 {
                low.log10()
            } else {
                f64::NEG_INFINITY
            };
            Some((low, high.log10()))
        }
    }
}

/// One axis in plotted coordinates: range, labelled ticks and unlabelled grid lines.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct AxisPlan {
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) majors: Vec<(f64, String)>,
    pub(super) minors: Vec<f64>,
}

impl AxisPlan {
    pub(super) fn label_at(&self, u: f64) -> String {
        self.majors
            .iter()
            .find(|(t, _)| (t - u).abs() <= 1e-9 * t.abs().max(1.0))
            .map(|(_, s)| s.clone())
            .unwrap_or_default()
    }

    pub(super) fn contains(&self, u: f64) -> bool {
        u >= self.lo && u <= self.hi
    }
}

/// The axis as a plotters coordinate: linear in plotted units, grid lines and labels at our
/// ticks. (plotters' `WithKeyPoints` over `f64` lacks the value formatter its mesh needs.)
impl Ranged for AxisPlan {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        // `as` saturates (NaN gives 0): no panic on a degenerate value.
        limit.0 + (t * f64::from(limit.1 - limit.0)).round() as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minors.clone()
        } else {
            self.majors.iter().map(|m| m.0).collect()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

pub(super) fn plan_axis(
    axis: &'static str,
    scale: Scale,
    explicit: Option<(f64, f64)>,
    data: &[f64],
) -> Result<AxisPlan, PlotError> {
    let (lo, hi) = match explicit {
        Some((min, max)) => {
            let invalid = |reason| PlotError::InvalidRange {
                axis,
                min,
                max,
                reason,
            };
            if !(min.is_finite() && max.is_finite()) {
                return Err(invalid("bounds must be finite"));
            }
            if min >= max {
                return Err(invalid("minimum must be below maximum"));
            }
            if scale == Scale::Log && min <= 0.0 {
                return Err(invalid("a log axis needs a positive minimum"));
            }
            match scale {
                Scale::Linear => (min, max),
                Scale::Log => (min.log10(), max.log10()),
            }
        }
        None => auto_range(scale, data),
    };
    let (majors, minors) = match scale {
        Scale::Linear => linear_ticks(lo, hi),
        Scale::Log => log_ticks(lo, hi),
    };
    Ok(AxisPlan {
        lo,
        hi,
        majors,
        minors,
    })
}

/// Data range in plotted coordinates with a 4 % margin each side.
pub(super) fn auto_range(scale: Scale, data: &[f64]) -> (f64, f64) {
    let (min, max) = data
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    if min > max {
        // No data at all: a unit range (0..1, or 1..10 on a log axis).
        return (0.0, 1.0);
    }
    let span = max - min;
    let pad = if span > 0.0 {
        match scale {
            Scale::Linear => 0.04 * span,
            Scale::Log => (0.04 * span).max(0.05),
        }
    } else {
        match scale {
            Scale::Linear if min != 0.0 => 0.1 * min.abs(),
            Scale::Linear => 1.0,
            Scale::Log => 0.5,
        }
    };
    let mut lo = min - pad;
    let hi = max + pad;
    if scale == Scale::Linear && min >= 0.0 && lo < 0.0 {
        lo = 0.0;
    }
    (lo, hi)
}

/// Ticks at 1, 2 or 5 times a power of ten, five to ten of them.
pub(super) fn linear_ticks(lo: f64, hi: f64) -> (Vec<(f64, String)>, Vec<f64>) {
    let raw = (hi - lo) / 7.0;
    let mut exp = raw.log10().floor() as i32;
    let f = raw / 10f64.powi(exp);
    let m = if f <= 1.0 {
        1.0
    } else if f <= 2.0 {
        2.0
    } else if f <= 5.0 {
        5.0
    } else {
        exp += 1;
        1.0
    };
    let step = m * 10f64.powi(exp);
    let decimals = (-exp).max(0) as usize;
    let scientific = step < 1e-4 || hi.abs().max(lo.abs()) >= 1e6;
    let k0 = (lo / step - 1e-9).ceil() as i64;
    let k1 = (hi / step + 1e-9).floor() as i64;
    let majors = (k0..=k1)
        .take(100)
        .map(|k| {
            let v = k as f64 * step;
            let label = if k == 0 {
                "0".to_string()
            } else if scientific {
                let s = format!("{v:.1e}");
                s.replace("e-", "e−").replace('-', "−")
            } else {
                format!("{v:.decimals$}").replace('-', "−")
            };
            (v, label)
        })
        .collect();
    (majors, Vec::new())
}

/// Ticks on a log axis, in log10 units: decades (every `stride`-th decade when there are more
/// than eight), or 1-2-5 and then 1..9 multiples when fewer than three decades are in range.
pub(super) fn log_ticks(lo: f64, hi: f64) -> (Vec<(f64, String)>, Vec<f64>) {
    let d0 = (lo - 1e-9).ceil() as i64;
    let d1 = (hi + 1e-9).floor() as i64;
    let inside = |u: f64| u >= lo - 1e-9 && u <= hi + 1e-9;
    let mut majors: Vec<(i64, f64)> = Vec::new(); // (decade, mantissa)
    let mut minors = Vec::new();
    if d1 - d0 + 1 >= 3 {
        let n = d1 - d0 + 1;
        let stride = (n + 7) / 8;
        for d in d0..=d1 {
            if d.rem_euclid(stride) == 0 {
                majors.push((d, 1.0));
            } else {
                minors.push(d as f64);
            }
        }
        if stride == 1 && n <= 7 {
            for d in (d0 - 1)..=d1 {
                for m in 2..=9 {
                    let u = d as f64 + f64::from(m).log10();
                    if inside(u) {
                        minors.push(u);
                    }
                }
            }
        }
    } else {
        let (e0, e1) = ((lo - 1e-9).floor() as i64, (hi + 1e-9).ceil() as i64);
        for mantissas in [&[1, 2, 5][..], &[1, 2, 3, 4, 5, 6, 7, 8, 9][..]] {
            majors.clear();
            for d in e0..=e1 {
                for &m in mantissas {
                    if inside(d as f64 + f64::from(m).log10()) {
                        majors.push((d, f64::from(m)));
                    }
                }
            }
            if majors.len() >= 3 {
                break;
            }
        }
        for d in e0..=e1 {
            for m in 1..=9 {
                let u = d as f64 + f64::from(m).log10();
                let is_major = majors
                    .iter()
                    .any(|&(md, mm)| md == d && (mm - f64::from(m)).abs() < 0.5);
                if inside(u) && !is_major {
                    minors.push(u);
                }
            }
        }
    }
    let plain = majors.iter().all(|&(d, _)| (-3..=4).contains(&d));
    let majors = majors
        .into_iter()
        .map(|(d, m)| {
            let u = d as f64 + m.log10();
            let label = if plain {
                let v = m * 10f64.powi(d as i32);
                format!("{v:.*}", (-d).max(0) as usize)
            } else {
                let exp = if d < 0 {
                    format!("−{}", -d)
                } else {
                    d.to_string()
                };
                if m == 1.0 {
                    format!("10^{{{exp}}}")
                } else {
                    format!("{m}×10^{{{exp}}}")
                }
            };
            (u, label)
        })
        .collect();
    (majors, minors)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_ticks_cover_wide_and_narrow_ranges() {
        // Many decades: at most about eight labels, powers of ten outside 1e-3..1e4.
        let (majors, _) = log_ticks(-4.2, 9.3);
        assert!(majors.len() <= 8 && majors.len() >= 4, "{majors:?}");
        assert!(majors.iter().any(|(_, l)| l == "10^{−4}" || l == "10^{8}"));
        // Less than a decade: 1-2-5 ticks, plain.
        let (majors, _) = log_ticks(0.1, 0.9);
        let labels: Vec<&str> = majors.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["2", "3", "4", "5", "6", "7"]);
        let (majors, _) = log_ticks(-0.5, 1.2);
        let labels: Vec<&str> = majors.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["0.5", "1", "2", "5", "10"]);
    }

    #[test]
    fn linear_ticks_are_round() {
        let (majors, _) = linear_ticks(0.0, 7.3);
        let labels: Vec<&str> = majors.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["0", "2", "4", "6"]);
        let (majors, _) = linear_ticks(-0.013, 0.021);
        assert!(majors.iter().any(|m| m.1 == "−0.010"), "{majors:?}");
    }
}
