//! Axis ranges and ticks of the experiment figures: 1-2-5 ticks on log-scale time axes with
//! labels in s, ms and µs, and ranges fitted to the data rather than to its outliers.

/// The ticks of a log-scale axis: the values labelled (and drawn as grid lines) and the
/// values drawn as light grid lines only.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LogTicks {
    /// Labelled ticks, ascending.
    pub(crate) labelled: Vec<f64>,
    /// Unlabelled ticks, ascending.
    pub(crate) light: Vec<f64>,
}

/// The 1-2-5 values `m · 10^k` (`m` ∈ {1, 2, 5}) within `[lo, hi]`, ascending, each the
/// double nearest its decimal value (`0.002`, not `2 · 0.001`).
pub(crate) fn one_two_five(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo > 0.0 && hi >= lo && hi.is_finite()) {
        return Vec::new();
    }
    let tolerance = 1e-9;
    let first = lo.log10().floor() as i32 - 1;
    let last = hi.log10().ceil() as i32 + 1;
    let mut values = Vec::new();
    for k in first..=last {
        for m in [1, 2, 5] {
            let v: f64 = format!("{m}e{k}").parse().unwrap_or(f64::NAN);
            if v >= lo * (1.0 - tolerance) && v <= hi * (1.0 + tolerance) {
                values.push(v);
            }
        }
    }
    values
}

/// Ticks for a log-scale axis over `[lo, hi]` with at most `max_labels` labels: every
/// 1-2-5 value if they are few enough, else the decades labelled (every second or more
/// decade on a very wide axis) and the other 1-2-5 values as light lines. An axis holding
/// fewer than two 1-2-5 values is labelled at its ends.
pub(crate) fn log_ticks(lo: f64, hi: f64, max_labels: usize) -> LogTicks {
    let all = one_two_five(lo, hi);
    let max_labels = max_labels.max(2);
    if all.len() < 2 {
        let mut labelled = vec![lo, hi];
        labelled.dedup();
        return LogTicks {
            labelled,
            light: all,
        };
    }
    if all.len() <= max_labels {
        return LogTicks {
            labelled: all,
            light: Vec::new(),
        };
    }
    let decades: Vec<f64> = all
        .iter()
        .copied()
        .filter(|v| leading_digit(*v) == 1)
        .collect();
    let step = decades.len().div_ceil(max_labels).max(1);
    let labelled: Vec<f64> = decades.iter().copied().step_by(step).collect();
    let light = all.into_iter().filter(|v| !labelled.contains(v)).collect();
    LogTicks { labelled, light }
}

/// The leading decimal digit of a positive value.
fn leading_digit(v: f64) -> u32 {
    let scaled = v / 10f64.powi(v.log10().floor() as i32);
    (scaled + 1e-9).floor() as u32
}

/// A duration for an axis label, in the unit that keeps it short (`500 µs`, `2 ms`,
/// `500 ms`, `2 s`); three significant digits at most.
pub(crate) fn time_label(seconds: f64) -> String {
    if !seconds.is_finite() || seconds <= 0.0 {
        return format!("{seconds}");
    }
    let (value, unit) = if seconds >= 1.0 - 1e-9 {
        (seconds, "s")
    } else if seconds >= 1e-3 * (1.0 - 1e-9) {
        (seconds * 1e3, "ms")
    } else {
        (seconds * 1e6, "µs")
    };
    format!("{} {unit}", significant(value))
}

/// `v` with three significant digits, trailing zeros dropped.
pub(crate) fn significant(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor() as i32;
    let decimals = (2 - magnitude).clamp(0, 8) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// How far beyond the medians' span a confidence bound may widen a fitted log axis: a factor
/// of 10 (one decade) on each side.
pub(crate) const BOUND_REACH: f64 = 10.0;

/// The log-scale range of the first-solution panel's time axis. It spans every finite
/// median, widened by the finite confidence bounds — each at most [`BOUND_REACH`] times
/// beyond the medians' span, so an outlying bound or an unsolved run (`∞`) does not stretch
/// it — then by a tenth of a decade, rounded out to 1-2-5 values, and kept within
/// `limits` (the figure's time span). `limits` itself without a finite median.
pub(crate) fn fitted_log_range(medians: &[f64], bounds: &[f64], limits: (f64, f64)) -> (f64, f64) {
    let usable = |v: &f64| v.is_finite() && *v > 0.0;
    let (m_lo, m_hi) = min_max(medians.iter().copied().filter(usable));
    if !(m_lo.is_finite() && m_hi.is_finite()) {
        return limits;
    }
    let (reach_lo, reach_hi) = (m_lo / BOUND_REACH, m_hi * BOUND_REACH);
    let clipped = bounds
        .iter()
        .copied()
        .filter(usable)
        .map(|b| b.clamp(reach_lo, reach_hi));
    let (b_lo, b_hi) = min_max(clipped);
    let pad = 10f64.powf(0.1);
    let lo = m_lo.min(b_lo) / pad;
    let hi = m_hi.max(b_hi) * pad;
    let lo = round_down_125(lo).max(limits.0);
    let hi = round_up_125(hi).min(limits.1);
    if hi > lo { (lo, hi) } else { limits }
}

/// The largest 1-2-5 value at most `v` (`v` > 0).
pub(crate) fn round_down_125(v: f64) -> f64 {
    one_two_five(v / 10.0, v).last().copied().unwrap_or(v)
}

/// The smallest 1-2-5 value at least `v` (`v` > 0).
pub(crate) fn round_up_125(v: f64) -> f64 {
    one_two_five(v, v * 10.0).first().copied().unwrap_or(v)
}

/// The linear range of a cost axis: it spans the finite `core` values (medians, lower
/// confidence bounds), widened by the finite `upper` bounds by at most half the core's span,
/// and by `optimum` only if it lies within a quarter of the span below (a distant optimum
/// would squash the curves; the legend names it instead); padded by 5 %. Returns the range
/// and whether the optimum lies within it.
pub(crate) fn cost_range(core: &[f64], upper: &[f64], optimum: Option<f64>) -> ((f64, f64), bool) {
    let (lo, hi) = min_max(core.iter().copied().filter(|v| v.is_finite()));
    let (lo, hi) = match (lo.is_finite(), hi.is_finite(), optimum) {
        (true, true, _) => (lo, hi),
        (_, _, Some(o)) if o.is_finite() => (o, o),
        _ => return ((0.0, 1.0), false),
    };
    let span = if hi > lo {
        hi - lo
    } else {
        0.1 * lo.abs().max(1.0)
    };
    let (_, u_hi) = min_max(upper.iter().copied().filter(|v| v.is_finite()));
    let mut top = if u_hi.is_finite() {
        hi.max(u_hi.min(hi + 0.5 * span))
    } else {
        hi
    };
    let mut bottom = lo;
    let shown =
        optimum.filter(|o| o.is_finite() && *o >= lo - 0.25 * span && *o <= top + 0.25 * span);
    if let Some(o) = shown {
        bottom = bottom.min(o);
        top = top.max(o);
    }
    let pad = 0.05 * (top - bottom).max(span);
    ((bottom - pad, top + pad), shown.is_some())
}

/// The smallest and largest of `values` (`(∞, −∞)` for none).
fn min_max(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_from_a_millisecond_to_ten_seconds_are_one_two_five() {
        let ticks = log_ticks(0.001, 10.0, 13);
        assert_eq!(
            ticks.labelled,
            [
                0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0
            ]
        );
        assert!(ticks.light.is_empty());
        // Fewer labels: the decades, the 2s and 5s as light lines.
        let ticks = log_ticks(0.001, 10.0, 6);
        assert_eq!(ticks.labelled, [0.001, 0.01, 0.1, 1.0, 10.0]);
        assert_eq!(ticks.light, [0.002, 0.005, 0.02, 0.05, 0.2, 0.5, 2.0, 5.0]);
        // Ten decades in at most four labels: every third decade.
        let ticks = log_ticks(1e-9, 10.0, 4);
        assert_eq!(ticks.labelled, [1e-9, 1e-6, 1e-3, 1.0]);
        // A narrow axis is labelled at its ends.
        assert_eq!(log_ticks(0.0021, 0.0049, 6).labelled, [0.0021, 0.0049]);
    }

    #[test]
    fn time_labels_use_a_unit_that_keeps_them_short() {
        let labels: Vec<String> = [2e-4, 0.001, 0.05, 0.5, 1.0, 20.0, 0.0125]
            .into_iter()
            .map(time_label)
            .collect();
        assert_eq!(
            labels,
            [
                "200 µs", "1 ms", "50 ms", "500 ms", "1 s", "20 s", "12.5 ms"
            ]
        );
        assert_eq!(significant(1234.5), "1234");
        assert_eq!(significant(0.001_234), "0.00123");
    }

    #[test]
    fn an_outlying_bound_does_not_stretch_the_first_solution_axis() {
        let limits = (1e-5, 1.0);
        // Medians 1 ms and 2 ms with tight bounds: a tenth of a decade of padding, rounded
        // out to 1-2-5 values.
        let tight = fitted_log_range(&[0.001, 0.002], &[0.0008, 0.003], limits);
        assert_eq!(tight, (0.0005, 0.005));
        // One planner's upper bound at 0.9 s, another's unsolved (∞): clipped a decade
        // beyond the largest median (20 ms), then padded and rounded: 0.05 s, not the budget.
        let wide = fitted_log_range(&[0.001, 0.002], &[0.0008, 0.9, f64::INFINITY], limits);
        assert_eq!(wide, (0.0005, 0.05));
        assert!(wide.1 <= 0.002 * BOUND_REACH * 10f64.powf(0.1) * 2.5);
        // Kept within the figure's span; without a median, the span itself.
        assert_eq!(fitted_log_range(&[0.5], &[0.9], limits).1, 1.0);
        assert_eq!(fitted_log_range(&[f64::INFINITY], &[], limits), limits);
        assert_eq!(round_down_125(0.0031), 0.002);
        assert_eq!(round_up_125(0.0031), 0.005);
        assert_eq!(round_up_125(0.002), 0.002);
    }

    #[test]
    fn a_distant_optimum_does_not_squash_the_cost_axis() {
        // Medians 10..12, the optimum at 1: left out of the range.
        let ((lo, hi), shown) = cost_range(&[10.0, 12.0, 10.5], &[30.0], Some(1.0));
        assert!(!shown);
        assert!(lo > 9.0 && lo < 10.0, "{lo}");
        // The upper bound at 30 is clipped at half the span above the medians: 13.
        assert!(hi > 13.0 && hi < 13.3, "{hi}");
        // An optimum just below the medians is drawn.
        let ((lo, _), shown) = cost_range(&[10.0, 12.0], &[], Some(9.8));
        assert!(shown && lo < 9.8);
        assert_eq!(cost_range(&[], &[], None), ((0.0, 1.0), false));
    }
}
