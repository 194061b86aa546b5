//! [`Segment`]: a straight edge prepared for batched point checks, and what a validity checker
//! says about it once prepared ([`Preparation`]).

use wide::f64x4;

use crate::box_world::segment_certification::ExactCertification;

/// What a validity checker made of a straight segment it was asked to prepare
/// ([`StateValidity::prepare_segment`](crate::StateValidity::prepare_segment)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preparation {
    /// The checker prepares nothing (the default): test interpolated states one by one or in
    /// batches of [`StateValidity::batch_width`](crate::StateValidity::batch_width).
    Unprepared,
    /// The segment is prepared: test its points with
    /// [`StateValidity::first_invalid_on`](crate::StateValidity::first_invalid_on) (or
    /// [`any_invalid_on`](crate::StateValidity::any_invalid_on), as edge checks do).
    Prepared,
    /// Every point of the segment is valid, proven without testing any (nothing the checker
    /// knows of comes near the segment): there is nothing to test.
    AllValid,
}

/// A straight edge `a → b` whose points `a + (b − a)·t` are to be tested, with room for what
/// the validity checker keeps of its world for this edge (the per-edge broad phase).
///
/// The [`GridWalker`](crate::GridWalker) owns one and reuses it for every edge, so preparing an
/// edge allocates nothing once the buffers have grown to the world's size. It is prepared only
/// in spaces whose edges are straight lines
/// ([`StateSpace::is_euclidean`](mit_star_spaces::StateSpace::is_euclidean)); the points are computed
/// with exactly the floating-point operations of their `interpolate`,
/// `x + (y − x)·t` per coordinate, so a prepared check answers bit for bit what interpolating
/// and testing state by state would.
///
/// ```
/// use mit_star_validity::Segment;
/// let mut segment = Segment::default();
/// segment.set(&[0.0, 1.0], &[1.0, 3.0]);
/// let mut point = [0.0; 2];
/// segment.point(0.25, &mut point);
/// assert_eq!(point, [0.25, 1.5]);
/// ```
#[derive(Debug, Clone, Default)]
pub struct Segment {
    /// The start `a`.
    pub(crate) start: Vec<f64>,
    /// `b − a`, per coordinate.
    pub(crate) delta: Vec<f64>,
    /// Smallest and largest value each coordinate can take at any `t ∈ [0, 1]`, rounding
    /// included: `[lo₀, hi₀, lo₁, hi₁, …]`.
    pub(crate) reach: Vec<f64>,
    /// Per coordinate, the bound on the rounding error of a computed point (the reach's
    /// widening).
    pub(crate) slack: Vec<f64>,
    /// For a box world: the `[lo, hi]` rows of the boxes of one kind that meet `reach` (the
    /// broad phase's candidates, turned into crossings by [`cross`](Self::cross)).
    pub(crate) candidates: Vec<f64>,
    /// For a box world: per obstacle the segment crosses, exactly the fractions `[τ₀, τ₁]`
    /// whose computed point lies in it ([`Segment::crossing`]).
    pub(crate) obstacle_crossings: Vec<[f64; 2]>,
    /// For a box world: the crossings of the anti-obstacles, likewise.
    pub(crate) anti_crossings: Vec<[f64; 2]>,
    /// For a box world: the coordinates along which a point may leave the bounds.
    pub(crate) bound_coordinates: Vec<usize>,
    /// For a box world: `true` if lattices must be tested point by point.
    pub(crate) lattices: bool,
    /// One state, for checkers that test points one by one.
    pub(crate) state: Vec<f64>,
    /// For a box world: where an exact certification of a motion stands, so that a stopped
    /// one resumes (left alone by [`set`](Self::set)).
    pub(crate) exact: ExactCertification,
}

/// A relative bound on the rounding error of `x + (y − x)·t` for `t ∈ [0, 1]`: at most about
/// `5u · max(|x|, |y|)` with `u = 2⁻⁵³`; this is `16u`, with room to spare.
pub(crate) const ROUNDING: f64 = 8.0 * f64::EPSILON;

impl Segment {
    /// Sets the segment to `a → b` (equal lengths), keeping the buffers.
    ///
    /// Also records the coordinates' reach: an interval per coordinate that contains every
    /// computed point `x + (y − x)·t`, `t ∈ [0, 1]`, widened for rounding — what a broad phase
    /// may compare against.
    pub fn set(&mut self, a: &[f64], b: &[f64]) {
        let n = a.len().min(b.len());
        self.start.clear();
        self.start.extend_from_slice(&a[..n]);
        // Sized once, then written in place: no capacity check per coordinate.
        self.delta.resize(n, 0.0);
        self.slack.resize(n, 0.0);
        self.reach.resize(2 * n, 0.0);
        let rows = self.delta.iter_mut().zip(&mut self.slack);
        for (((delta, slack), reach), (&x, &y)) in rows
            .zip(self.reach.chunks_exact_mut(2))
            .zip(a.iter().zip(b))
        {
            *delta = y - x;
            *slack = ROUNDING * x.abs().max(y.abs()) + f64::MIN_POSITIVE;
            reach[0] = x.min(y) - *slack;
            reach[1] = x.max(y) + *slack;
        }
        self.candidates.clear();
        self.obstacle_crossings.clear();
        self.anti_crossings.clear();
        self.bound_coordinates.clear();
        self.lattices = false;
    }

    /// Number of coordinates.
    #[inline]
    pub fn dimension(&self) -> usize {
        self.start.len()
    }

    /// The start `a`.
    #[inline]
    pub fn start(&self) -> &[f64] {
        &self.start
    }

    /// `b − a`, per coordinate: the point at fraction `t` is `start + delta · t`.
    #[inline]
    pub fn delta(&self) -> &[f64] {
        &self.delta
    }

    /// `true` if every coordinate of `a` and `b − a` is finite (so is every point).
    pub fn is_finite(&self) -> bool {
        self.start
            .iter()
            .chain(&self.delta)
            .all(|value| value.is_finite())
    }

    /// The point at fraction `t`, as the space's `interpolate` computes it: `a + (b − a)·t`.
    #[inline]
    pub fn point(&self, t: f64, out: &mut [f64]) {
        for ((o, &x), &d) in out.iter_mut().zip(&self.start).zip(&self.delta) {
            *o = x + d * t;
        }
    }

    /// Coordinate `d` of the four points at fractions `t` (one per lane).
    #[inline]
    pub(crate) fn lanes(&self, d: usize, t: f64x4) -> f64x4 {
        f64x4::splat(self.start[d]) + f64x4::splat(self.delta[d]) * t
    }

    /// Coordinate `d`'s reach `(lo, hi)`.
    #[inline]
    pub(crate) fn reach(&self, d: usize) -> (f64, f64) {
        (self.reach[2 * d], self.reach[2 * d + 1])
    }

    /// The fractions `[t₀, t₁]` outside which no computed point `a + (b − a)·t`, `t ∈ [0, 1]`,
    /// lies in the closed box `row` (`[lo, hi]` per coordinate), or `None` if none does.
    ///
    /// The slab test of the exact line against the box widened by the points' rounding bound
    /// (a computed point in the box puts the exact point in the widened box), each end moved
    /// outwards by a bound on its own rounding error — so the span may be loose, never short.
    pub(crate) fn span(&self, row: &[f64]) -> Option<[f64; 2]> {
        let mut span = [0.0, 1.0];
        for (d, bounds) in row.chunks_exact(2).enumerate() {
            span = self.slab_span(d, [bounds[0], bounds[1]], span)?;
        }
        Some(span)
    }

    /// `within` narrowed to the fractions outside which no computed point's coordinate `d`
    /// lies in `[lo, hi]` (loose, never short; see [`span`](Self::span)), or `None` if empty.
    pub(crate) fn slab_span(
        &self,
        d: usize,
        [lo, hi]: [f64; 2],
        within: [f64; 2],
    ) -> Option<[f64; 2]> {
        let (a, delta, slack) = (self.start[d], self.delta[d], self.slack[d]);
        let (lo, hi) = (lo - slack, hi + slack);
        if delta == 0.0 {
            return (a >= lo && a <= hi).then_some(within);
        }
        let (enter, exit) = ((lo - a) / delta, (hi - a) / delta);
        let (enter, exit) = if delta > 0.0 {
            (enter, exit)
        } else {
            (exit, enter)
        };
        // |computed − exact| ≤ 3u(|bound| + slack + |a|)/|δ| + u|t| per end, with room;
        // a non-finite end (NaN included) leaves that side open: `max`/`min` skip NaN.
        let scale = (lo.abs().max(hi.abs()) + slack + a.abs()) / delta.abs();
        let error = ROUNDING * (scale + enter.abs().max(exit.abs()));
        let (t0, t1) = (within[0].max(enter - error), within[1].min(exit + error));
        (t0 <= t1).then_some([t0, t1])
    }

    /// Turns the [`candidates`](Self::candidates) into the crossings of the boxes the segment
    /// crosses — the [`span`](Self::span), then the exact [`crossing`](Self::crossing) within
    /// it — appended to the anti-obstacles' list if `anti`, the obstacles' otherwise; the
    /// candidates are used up.
    pub(crate) fn cross(&mut self, anti: bool) {
        let width = 2 * self.dimension();
        let candidates = std::mem::take(&mut self.candidates);
        let mut crossings = std::mem::take(if anti {
            &mut self.anti_crossings
        } else {
            &mut self.obstacle_crossings
        });
        crossings.extend(
            candidates
                .chunks_exact(width)
                .filter_map(|row| self.span(row).and_then(|span| self.crossing(row, span))),
        );
        *(if anti {
            &mut self.anti_crossings
        } else {
            &mut self.obstacle_crossings
        }) = crossings;
        self.candidates = candidates;
        self.candidates.clear();
    }

    /// The index of the first state among the points at `fractions` that `is_valid` rejects,
    /// testing them one by one in order (the fallback of checkers without lanes).
    pub fn first_invalid_by(
        &mut self,
        fractions: &[f64],
        mut is_valid: impl FnMut(&[f64]) -> bool,
    ) -> Option<usize> {
        let mut state = std::mem::take(&mut self.state);
        state.resize(self.dimension(), 0.0);
        let found = fractions.iter().position(|&t| {
            self.point(t, &mut state);
            !is_valid(&state)
        });
        self.state = state;
        found
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reach_contains_every_computed_point() {
        let cases = [
            ([0.1, -0.7], [0.3, 0.9]),
            ([1e-300, 5.0e8], [-3e-310, 5.0e8 + 1e-7]),
            (
                [0.333_333_333_333_333_3, 1.0],
                [0.333_333_333_333_333_4, 1.0],
            ),
        ];
        for (a, b) in cases {
            let mut segment = Segment::default();
            segment.set(&a, &b);
            let mut p = [0.0; 2];
            for i in 0..=10_000 {
                segment.point(f64::from(i) / 10_000.0, &mut p);
                for (d, &x) in p.iter().enumerate() {
                    let (lo, hi) = segment.reach(d);
                    assert!(
                        lo <= x && x <= hi,
                        "{a:?} → {b:?}: {x} outside [{lo}, {hi}]"
                    );
                }
            }
        }
    }

    #[test]
    fn lanes_compute_the_same_points() {
        let mut segment = Segment::default();
        segment.set(&[0.1, 0.2, 0.3], &[0.7, -0.4, 0.31]);
        let ts = [0.0, 1.0 / 3.0, 0.7, 1.0];
        let mut p = [0.0; 3];
        for d in 0..3 {
            let lanes = segment.lanes(d, f64x4::from(ts)).to_array();
            for (lane, &t) in ts.iter().enumerate() {
                segment.point(t, &mut p);
                assert_eq!(lanes[lane].to_bits(), p[d].to_bits());
            }
        }
    }
}
