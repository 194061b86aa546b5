//! Piecewise-constant curves and the bands between two of them, as the experiment figure
//! draws medians, success rates and their confidence bands.

/// The piecewise-constant curve through `(times[i], values[i])`, split where values are not
/// finite.
pub(crate) fn steps(times: &[f64], values: &[f64]) -> Vec<Vec<(f64, f64)>> {
    let mut lines = Vec::new();
    let mut line: Vec<(f64, f64)> = Vec::new();
    for (i, (&t, &v)) in times.iter().zip(values).enumerate() {
        if !v.is_finite() {
            if line.len() > 1 {
                lines.push(std::mem::take(&mut line));
            }
            line.clear();
            continue;
        }
        if let Some(&(_, previous)) = line.last() {
            line.push((t, previous));
        }
        line.push((t, v));
        if i + 1 == times.len() && line.len() > 1 {
            lines.push(std::mem::take(&mut line));
        }
    }
    lines
}

/// Polygons between piecewise-constant lower and upper curves, over the stretches where the
/// lower curve is finite (an infinite upper bound is clamped by the caller).
pub(crate) fn bands(times: &[f64], lower: &[f64], upper: &[f64]) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < times.len() {
        if !(lower[i].is_finite() && upper[i].is_finite()) {
            i += 1;
            continue;
        }
        let start = i;
        while i < times.len() && lower[i].is_finite() && upper[i].is_finite() {
            i += 1;
        }
        let top = steps(&times[start..i], &upper[start..i]);
        let bottom = steps(&times[start..i], &lower[start..i]);
        if let (Some(top), Some(bottom)) = (top.into_iter().next(), bottom.into_iter().next()) {
            let mut polygon = top;
            polygon.extend(bottom.into_iter().rev());
            out.push(polygon);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_split_at_infinities() {
        let t = [1.0, 2.0, 3.0, 4.0];
        let v = [f64::INFINITY, 5.0, 4.0, 4.0];
        let lines = steps(&t, &v);
        assert_eq!(
            lines,
            vec![vec![
                (2.0, 5.0),
                (3.0, 5.0),
                (3.0, 4.0),
                (4.0, 4.0),
                (4.0, 4.0)
            ]]
        );
        let b = bands(&t, &[f64::INFINITY, 1.0, 1.0, 1.0], &[9.0, 9.0, 8.0, 8.0]);
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].first(), Some(&(2.0, 9.0)));
        assert_eq!(b[0].last(), Some(&(2.0, 1.0)));
    }
}
