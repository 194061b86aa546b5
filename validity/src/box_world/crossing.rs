//! The exact fractions at which a segment's computed points lie in a box
//! ([`Segment::crossing`]).
//!
//! Along one coordinate the computed value `x + (y − x)·t` is monotone in `t` (both roundings
//! are monotone), so the fractions whose point lies within a box's `[lo, hi]` along it form an
//! interval of floats, and the box's fractions are the intersection over the coordinates: one
//! interval `[τ₀, τ₁]`. It is found exactly by searching the floats themselves (non-negative
//! floats are ordered like their bits), starting from the span's loose ends, so testing a
//! point against the box becomes `τ₀ ≤ t ≤ τ₁`, with the answer of testing the point.

use crate::Segment;

impl Segment {
    /// The exact interval `[τ₀, τ₁]` of fractions `t ∈ [0, 1]` whose computed point lies in the
    /// closed box `row` (`[lo, hi]` per coordinate), given a `span` that contains it
    /// ([`Segment::span`]); `None` if no fraction's point does.
    pub(crate) fn crossing(&self, row: &[f64], span: [f64; 2]) -> Option<[f64; 2]> {
        let mut fractions = [span[0], span[1].min(1.0)];
        for (d, bounds) in row.chunks_exact(2).enumerate() {
            let (lo, hi) = (bounds[0], bounds[1]);
            fractions = self.coordinate_crossing(d, fractions, |v| v >= lo, |v| v <= hi)?;
        }
        Some(fractions)
    }

    /// Within the fractions `within` (`[t₀, t₁] ⊆ [0, 1]`), the exact interval of floats `t`
    /// whose computed coordinate `d`, `v = a_d + (b_d − a_d)·t`, passes both `above(v)` (false
    /// for small values, then true) and `below(v)` (true, then false for large values);
    /// `None` if no float there does. The computed coordinate is monotone in `t`, so those
    /// floats form one interval, found by searching the floats themselves.
    #[inline]
    pub(crate) fn coordinate_crossing(
        &self,
        d: usize,
        within: [f64; 2],
        above: impl Fn(f64) -> bool,
        below: impl Fn(f64) -> bool,
    ) -> Option<[f64; 2]> {
        // Non-negative, so that bits order like values (no −0.0).
        let t0 = if within[0] > 0.0 { within[0] } else { 0.0 };
        let t1 = within[1];
        // Empty, or a NaN end: nothing to search.
        if t0.partial_cmp(&t1).is_none_or(|order| order.is_gt()) {
            return None;
        }
        let (start, delta) = (self.start[d], self.delta[d]);
        let x = |t: f64| start + delta * t;
        if delta == 0.0 {
            let value = x(0.0);
            return (above(value) && below(value)).then_some([t0, t1]);
        }
        // Rising values enter at `above` and leave at `below`; falling ones the other way round.
        if delta > 0.0 {
            let t0 = first_where(t0, t1, |t| above(x(t)))?;
            Some([t0, last_where(t0, t1, |t| below(x(t)))?])
        } else {
            let t0 = first_where(t0, t1, |t| below(x(t)))?;
            Some([t0, last_where(t0, t1, |t| above(x(t)))?])
        }
    }
}

/// The smallest float `t ∈ [t0, t1]` (both ≥ 0) where `holds` does, for a `holds` that is
/// false then true as `t` grows; `None` if it does not hold at `t1`.
fn first_where(t0: f64, t1: f64, holds: impl Fn(f64) -> bool) -> Option<f64> {
    if holds(t0) {
        return Some(t0);
    }
    holds(t1).then(|| boundary(t0, t1, holds))
}

/// The largest float `t ∈ [t0, t1]` (both ≥ 0) where `holds` does, for a `holds` that is true
/// then false as `t` grows; `None` if it does not hold at `t0`.
fn last_where(t0: f64, t1: f64, holds: impl Fn(f64) -> bool) -> Option<f64> {
    if holds(t1) {
        return Some(t1);
    }
    holds(t0).then(|| boundary(t1, t0, holds))
}

/// Between a non-negative float `no` where `holds` fails and one, `yes`, where it holds (in
/// either order), the float nearest `no` where it holds, for a `holds` that changes once
/// between them. Gallops from `no` in float steps of 1, 2, 4, … towards `yes`, then bisects:
/// a change `k` floats from `no` costs `O(log k)` tests.
fn boundary(no: f64, yes: f64, holds: impl Fn(f64) -> bool) -> f64 {
    let (mut no, end) = (no.to_bits(), yes.to_bits());
    let towards = |from: u64, by: u64| {
        if end > from {
            from.saturating_add(by).min(end)
        } else {
            from.saturating_sub(by).max(end)
        }
    };
    let mut step = 1;
    let mut yes = loop {
        let probe = towards(no, step);
        if holds(f64::from_bits(probe)) {
            break probe;
        }
        no = probe;
        step = step.saturating_mul(2);
    };
    while no.abs_diff(yes) > 1 {
        let mid = no.min(yes) + no.abs_diff(yes) / 2;
        if holds(f64::from_bits(mid)) {
            yes = mid;
        } else {
            no = mid;
        }
    }
    f64::from_bits(yes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The neighbouring float of a positive `x` (MSRV 1.85 has no `next_up`).
    fn up(x: f64) -> f64 {
        f64::from_bits(x.to_bits() + 1)
    }

    fn down(x: f64) -> f64 {
        f64::from_bits(x.to_bits() - 1)
    }

    #[test]
    fn searches_find_the_exact_float() {
        let edge = 0.3_f64;
        assert_eq!(first_where(0.0, 1.0, |t| t >= edge), Some(edge));
        assert_eq!(last_where(0.0, 1.0, |t| t <= edge), Some(edge));
        assert_eq!(first_where(0.0, 1.0, |t| t > edge), Some(up(edge)));
        assert_eq!(last_where(0.0, 1.0, |t| t < edge), Some(down(edge)));
        assert_eq!(first_where(0.0, 0.2, |t| t >= edge), None);
        assert_eq!(last_where(0.4, 1.0, |t| t <= edge), None);
        assert_eq!(first_where(0.0, 1.0, |_| true), Some(0.0));
    }

    #[test]
    fn a_crossing_holds_exactly_the_fractions_whose_points_are_inside() {
        let mut segment = Segment::default();
        segment.set(&[0.1, -0.3], &[0.7, 0.45]);
        let row = [0.2, 0.4, -0.1, 0.3];
        let span = segment.span(&row).unwrap();
        let [t0, t1] = segment.crossing(&row, span).unwrap();
        let mut p = [0.0; 2];
        let inside =
            |p: &[f64; 2]| p[0] >= row[0] && p[0] <= row[1] && p[1] >= row[2] && p[1] <= row[3];
        for t in [t0, t1] {
            segment.point(t, &mut p);
            assert!(inside(&p));
        }
        for t in [down(t0), up(t1)] {
            segment.point(t, &mut p);
            assert!(!inside(&p));
        }
    }
}
