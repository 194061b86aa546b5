//! [`TimedPath`]: a joint-space path timed at joint-speed limits, and [`Piece`], a straight
//! stretch of motion between two times.

use mit_star_spaces::{JointSpace, StateSpace};

/// A straight motion in joint space from `a` at time `t0` to `b` at time `t1`, at constant
/// speed (`a == b` holds still).
#[derive(Debug, Clone, PartialEq)]
pub struct Piece {
    /// When the motion starts.
    pub t0: f64,
    /// When it ends.
    pub t1: f64,
    /// The configuration at `t0`.
    pub a: Vec<f64>,
    /// The configuration at `t1`.
    pub b: Vec<f64>,
}

impl Piece {
    /// Holding `q` still from `t0` to `t1`.
    pub fn hold(t0: f64, t1: f64, q: &[f64]) -> Self {
        Self {
            t0,
            t1,
            a: q.to_vec(),
            b: q.to_vec(),
        }
    }

    /// The configuration at time `t` (clamped to the piece).
    pub fn at(&self, space: &JointSpace, t: f64) -> Vec<f64> {
        let span = self.t1 - self.t0;
        let f = if span > 0.0 {
            ((t - self.t0) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let mut out = vec![0.0; self.a.len()];
        space.interpolate(&self.a, &self.b, f, &mut out);
        out
    }

    /// The piece split at its middle time.
    pub fn halves(&self, space: &JointSpace) -> (Self, Self) {
        let mid = 0.5 * (self.t0 + self.t1);
        let q = self.at(space, mid);
        (
            Self {
                t0: self.t0,
                t1: mid,
                a: self.a.clone(),
                b: q.clone(),
            },
            Self {
                t0: mid,
                t1: self.t1,
                a: q,
                b: self.b.clone(),
            },
        )
    }
}

/// A path of straight joint-space edges executed from `start_time` on, each edge at constant
/// speed and taking `max_j |Δq_j| / speed_j` seconds: the joint that needs longest moves at
/// its speed, the others slower, no acceleration limit (the arm starts and stops at once). Time-optimal for
/// a straight edge under per-joint speed limits.
///
/// ```
/// use mit_star_benches::replanning::TimedPath;
/// use mit_star_spaces::{Joint, JointSpace};
/// let joints = vec![Joint::revolute("a", -3.0, 3.0), Joint::revolute("b", -3.0, 3.0)];
/// let space = JointSpace::new(joints).unwrap();
/// let path = vec![vec![0.0, 0.0], vec![1.0, 0.5], vec![1.0, 1.5]];
/// let timed = TimedPath::new(&space, &path, &[0.5, 1.0], 2.0);
/// assert_eq!(timed.end_time(), 2.0 + 2.0 + 1.0);
/// assert_eq!(timed.state_at(3.0), vec![0.5, 0.25]);
/// assert_eq!(timed.pieces(3.0, 4.5).len(), 2);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct TimedPath {
    space: JointSpace,
    states: Vec<Vec<f64>>,
    /// When each state is reached (absolute), `times[0] = start_time`.
    times: Vec<f64>,
}

impl TimedPath {
    /// `path` (at least one state) timed at `speeds` (rad/s per joint, positive) from
    /// `start_time` on.
    pub fn new(space: &JointSpace, path: &[Vec<f64>], speeds: &[f64], start_time: f64) -> Self {
        let mut times = Vec::with_capacity(path.len());
        let mut t = start_time;
        times.push(t);
        for w in path.windows(2) {
            let duration = w[0]
                .iter()
                .zip(&w[1])
                .zip(speeds)
                .map(|((a, b), v)| (b - a).abs() / v)
                .fold(0.0, f64::max);
            t += duration;
            times.push(t);
        }
        Self {
            space: space.clone(),
            states: path.to_vec(),
            times,
        }
    }

    /// When the path starts.
    pub fn start_time(&self) -> f64 {
        self.times[0]
    }

    /// When the last state is reached.
    pub fn end_time(&self) -> f64 {
        self.times[self.times.len() - 1]
    }

    /// The last state.
    pub fn last(&self) -> &[f64] {
        &self.states[self.states.len() - 1]
    }

    /// The edge (index of its first state) being travelled at `t`.
    fn edge_at(&self, t: f64) -> usize {
        let after = self.times.partition_point(|&s| s <= t);
        after.clamp(1, self.times.len().max(2) - 1) - 1
    }

    /// The configuration at time `t` (the first state before the start, the last after the
    /// end).
    pub fn state_at(&self, t: f64) -> Vec<f64> {
        if self.states.len() == 1 || t <= self.start_time() {
            return self.states[0].clone();
        }
        if t >= self.end_time() {
            return self.last().to_vec();
        }
        let i = self.edge_at(t);
        let piece = Piece {
            t0: self.times[i],
            t1: self.times[i + 1],
            a: self.states[i].clone(),
            b: self.states[i + 1].clone(),
        };
        piece.at(&self.space, t)
    }

    /// The motion over `[t0, t1]` (within the path's times), as straight pieces split at the
    /// path's states.
    pub fn pieces(&self, t0: f64, t1: f64) -> Vec<Piece> {
        let t0 = t0.max(self.start_time());
        let t1 = t1.min(self.end_time());
        let mut cuts = vec![t0];
        cuts.extend(self.times.iter().copied().filter(|&s| s > t0 && s < t1));
        cuts.push(t1);
        cuts.windows(2)
            .filter(|w| w[1] > w[0])
            .map(|w| Piece {
                t0: w[0],
                t1: w[1],
                a: self.state_at(w[0]),
                b: self.state_at(w[1]),
            })
            .collect()
    }

    /// The rest of the path from time `t`: the configuration at `t`, then every later state.
    pub fn remaining(&self, t: f64) -> Vec<Vec<f64>> {
        let mut rest = vec![self.state_at(t)];
        rest.extend(
            self.times
                .iter()
                .zip(&self.states)
                .filter(|&(&s, _)| s > t)
                .map(|(_, q)| q.clone()),
        );
        rest
    }

    /// The joint-space length of the motion over `[t0, t1]`.
    pub fn length(&self, t0: f64, t1: f64) -> f64 {
        self.pieces(t0, t1)
            .iter()
            .map(|p| self.space.distance(&p.a, &p.b))
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn space() -> JointSpace {
        let joints = vec![
            mit_star_spaces::Joint::revolute("a", -3.0, 3.0),
            mit_star_spaces::Joint::revolute("b", -3.0, 3.0),
        ];
        JointSpace::new(joints).unwrap()
    }

    #[test]
    fn the_slowest_joint_sets_each_edge_s_duration() {
        let path = vec![vec![0.0, 0.0], vec![1.0, 0.5], vec![1.0, 1.5]];
        let timed = TimedPath::new(&space(), &path, &[0.5, 1.0], 1.0);
        assert_eq!(timed.end_time(), 4.0);
        assert_eq!(timed.state_at(0.0), vec![0.0, 0.0]);
        assert_eq!(timed.state_at(3.0), vec![1.0, 0.5]);
        assert_eq!(timed.state_at(3.5), vec![1.0, 1.0]);
        assert_eq!(timed.state_at(9.0), vec![1.0, 1.5]);
        // No joint exceeds its speed anywhere.
        for p in timed.pieces(1.0, 4.0) {
            let dt = p.t1 - p.t0;
            assert!((p.b[0] - p.a[0]).abs() <= 0.5 * dt + 1e-12);
            assert!((p.b[1] - p.a[1]).abs() <= 1.0 * dt + 1e-12);
        }
        let pieces = timed.pieces(2.0, 3.5);
        assert_eq!(pieces.len(), 2);
        assert_eq!((pieces[0].t0, pieces[0].t1, pieces[1].t1), (2.0, 3.0, 3.5));
        assert_eq!(pieces[0].a, vec![0.5, 0.25]);
        assert_eq!(
            timed.remaining(2.0),
            vec![vec![0.5, 0.25], vec![1.0, 0.5], vec![1.0, 1.5]]
        );
        let total = timed.length(0.0, 10.0);
        assert!((total - (1.25f64.sqrt() + 1.0)).abs() < 1e-12);
        assert!((timed.length(1.0, 2.0) + timed.length(2.0, 4.0) - total).abs() < 1e-12);
    }

    #[test]
    fn a_piece_splits_in_time() {
        let piece = Piece {
            t0: 0.0,
            t1: 2.0,
            a: vec![0.0, 0.0],
            b: vec![2.0, -2.0],
        };
        let (first, second) = piece.halves(&space());
        assert_eq!((first.t1, first.b), (1.0, vec![1.0, -1.0]));
        assert_eq!((second.t0, second.a), (1.0, vec![1.0, -1.0]));
        let single = TimedPath::new(&space(), &[vec![0.5, 0.5]], &[1.0, 1.0], 0.0);
        assert_eq!(single.end_time(), 0.0);
        assert!(single.pieces(0.0, 1.0).is_empty());
        assert_eq!(single.state_at(3.0), vec![0.5, 0.5]);
    }
}
