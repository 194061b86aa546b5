//! Closed-form optimal costs, for the families where the shortest path is known exactly.
//!
//! Two shapes of argument cover them (obstacles are closed, so optimal paths graze obstacle
//! boundaries and the optimum is an infimum that planners approach from above):
//!
//! - **Slab crossing.** Every obstacle lies in the slab `x ∈ [x_lo, x_hi]`, the start is left
//!   of it and the goal right of it, both with the same coordinates `r₀` besides `x`, and the
//!   free cross-section `C` (the coordinates besides `x` at which the slab can be crossed) is the
//!   same at every `x` of the slab. A path crosses the plane `x = x_lo` at some `p` and
//!   `x = x_hi` at some `q`, both with cross-section in `C`, so its length is at least
//!   `√(a² + m²) + (x_hi − x_lo) + √(b² + m²)` with `a`, `b` the distances of start and goal to
//!   the slab and `m` the distance from `r₀` to `C`; the path through the nearest point of `C`
//!   attains it.
//! - **Enclosure.** A hollow cube of outer half-side `h` with an opening of half-width `g` in
//!   one face, everything centred on the x-axis with equal widths in every coordinate besides
//!   `x`. Validity then depends only on `x` and the max-norm of the other coordinates, and
//!   mapping a path to `(x, ‖rest‖∞)` keeps it valid and does not lengthen it, so the optimum is
//!   the 2-D one. In 2-D the path leaves through the opening at height `y ≤ g`, climbs the outer
//!   face to the corner at `h`, and runs along the top of the cube; its length decreases in `y`,
//!   so `y = g`: from the enclosed centre to the far top corner costs
//!   `√(h² + g²) + (h − g) + 2h`.

/// Distance from `y` to the closed interval `[lo, hi]` (0 inside it).
pub(crate) fn interval_distance(y: f64, lo: f64, hi: f64) -> f64 {
    if y < lo {
        lo - y
    } else if y > hi {
        y - hi
    } else {
        0.0
    }
}

/// Distance from `y` to the union of the intervals, each first clipped to `[lower, upper]`;
/// infinite if none is left.
pub(crate) fn distance_to_union(y: f64, intervals: &[(f64, f64)], lower: f64, upper: f64) -> f64 {
    intervals
        .iter()
        .map(|&(lo, hi)| (lo.max(lower), hi.min(upper)))
        .filter(|(lo, hi)| lo <= hi)
        .map(|(lo, hi)| interval_distance(y, lo, hi))
        .fold(f64::INFINITY, f64::min)
}

/// The slab-crossing optimum (module docs), or `None` when its conditions fail: start not left
/// of the slab, goal not right of it, start and goal differing besides `x`, or no crossing
/// (`m` infinite).
pub(crate) fn slab_crossing(
    start: &[f64],
    goal: &[f64],
    x_lo: f64,
    x_hi: f64,
    m: f64,
) -> Option<f64> {
    let (&sx, &gx) = (start.first()?, goal.first()?);
    let same_rest = start.len() == goal.len() && start[1..] == goal[1..];
    if !(same_rest && sx < x_lo && gx > x_hi && x_lo <= x_hi && m.is_finite()) {
        return None;
    }
    Some((x_lo - sx).hypot(m) + (x_hi - x_lo) + (gx - x_hi).hypot(m))
}

/// Cost from the centre of an enclosure of outer side `outside` with an opening of width `gap`
/// to the outer corner on the far side of the opening (module docs).
pub(crate) fn enclosure_escape(outside: f64, gap: f64) -> f64 {
    let (h, g) = (0.5 * outside, 0.5 * gap);
    h.hypot(g) + (h - g) + outside
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interval_distances() {
        assert_eq!(interval_distance(0.0, 0.1, 0.2), 0.1);
        assert_eq!(interval_distance(0.3, 0.1, 0.2), 0.3 - 0.2);
        assert_eq!(interval_distance(0.15, 0.1, 0.2), 0.0);
        let union = [(0.1, 0.2), (-0.3, -0.05), (0.6, 0.9)];
        assert_eq!(distance_to_union(0.0, &union, -0.5, 0.5), 0.05);
        // (0.6, 0.9) is clipped away entirely.
        assert_eq!(distance_to_union(0.5, &union, -0.5, 0.5), 0.5 - 0.2);
        assert_eq!(distance_to_union(0.0, &[], -0.5, 0.5), f64::INFINITY);
    }

    #[test]
    fn slab_crossing_needs_its_conditions() {
        let s = [-0.3, 0.0];
        let g = [0.3, 0.0];
        // A slab [-0.1, 0.1] crossed at height 0: the straight line.
        assert!((slab_crossing(&s, &g, -0.1, 0.1, 0.0).unwrap() - 0.6).abs() < 1e-15);
        // Crossed at height 0.2: legs of √(0.2² + 0.2²) each side of the slab.
        let c = slab_crossing(&s, &g, -0.1, 0.1, 0.2).unwrap();
        assert!((c - (2.0 * 0.08f64.sqrt() + 0.2)).abs() < 1e-15);
        assert_eq!(slab_crossing(&s, &[0.3, 0.1], -0.1, 0.1, 0.2), None);
        assert_eq!(slab_crossing(&s, &g, -0.4, 0.1, 0.2), None);
        assert_eq!(slab_crossing(&s, &g, -0.1, 0.1, f64::INFINITY), None);
    }

    #[test]
    fn escape_of_the_default_enclosure() {
        // Outer half-side 0.125, opening half-width 0.1.
        let expected = (0.125f64 * 0.125 + 0.01).sqrt() + 0.025 + 0.25;
        assert!((enclosure_escape(0.25, 0.2) - expected).abs() < 1e-15);
    }
}
