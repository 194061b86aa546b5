//! [`ViewFrames`]: the moments a view's slider steps through — a path's states and states
//! interpolated between them (by length), or a timed trajectory's samples.

use mit_star_spaces::StateSpace;

/// About how many frames a path is cut into: enough for smooth scrubbing, few enough that a
/// page stays small (a path of more states keeps one frame per state; the page's limits
/// thin it further).
pub(crate) const FRAMES_PER_PATH: usize = 400;

/// Configurations along a motion, with where the path's own states are among them.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ViewFrames {
    /// One configuration per frame.
    pub(crate) states: Vec<Vec<f64>>,
    /// The frame of each of the path's states (or trajectory knots), ascending.
    pub(crate) waypoints: Vec<usize>,
    /// Each frame's time in seconds, for a trajectory.
    pub(crate) times: Option<Vec<f64>>,
}

impl ViewFrames {
    /// `path`'s states, each segment cut into pieces in proportion to its length in `space`
    /// so that the whole has about [`FRAMES_PER_PATH`] frames, interpolated as `space` does
    /// (the short way round for continuous joints).
    pub(crate) fn along_path<S: StateSpace + ?Sized>(space: &S, path: &[Vec<f64>]) -> Self {
        Self::along_path_in(space, path, FRAMES_PER_PATH)
    }

    /// As [`along_path`](Self::along_path), in about `count` frames.
    pub(crate) fn along_path_in<S: StateSpace + ?Sized>(
        space: &S,
        path: &[Vec<f64>],
        count: usize,
    ) -> Self {
        let lengths: Vec<f64> = path
            .windows(2)
            .map(|w| space.distance(&w[0], &w[1]))
            .collect();
        let total: f64 = lengths.iter().sum();
        let mut states = Vec::new();
        let mut waypoints = Vec::with_capacity(path.len());
        let mut scratch = vec![0.0; space.dimension()];
        for (i, state) in path.iter().enumerate() {
            waypoints.push(states.len());
            states.push(state.clone());
            let (Some(next), Some(&length)) = (path.get(i + 1), lengths.get(i)) else {
                continue;
            };
            let pieces = if total > 0.0 && total.is_finite() {
                ((count as f64 * length / total).round() as usize).max(1)
            } else {
                1
            };
            for k in 1..pieces {
                space.interpolate(state, next, k as f64 / pieces as f64, &mut scratch);
                states.push(scratch.clone());
            }
        }
        Self {
            states,
            waypoints,
            times: None,
        }
    }

    /// A timed motion: `position(t)` at about [`FRAMES_PER_PATH`] evenly spaced times over
    /// `[0, duration]` and at every knot time in `knots` (the waypoints).
    pub(crate) fn along_time(
        duration: f64,
        knots: &[f64],
        mut position: impl FnMut(f64) -> Vec<f64>,
    ) -> Self {
        let steps = FRAMES_PER_PATH.max(1);
        let mut times: Vec<f64> = (0..=steps)
            .map(|k| duration * k as f64 / steps as f64)
            .chain(knots.iter().copied().filter(|t| t.is_finite()))
            .collect();
        times.sort_by(f64::total_cmp);
        times.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * duration.max(1.0));
        let mut waypoints: Vec<usize> = knots
            .iter()
            .map(|&t| {
                times
                    .partition_point(|&s| s < t - 1e-9 * duration.max(1.0))
                    .min(times.len() - 1)
            })
            .collect();
        waypoints.dedup();
        let states = times.iter().map(|&t| position(t)).collect();
        Self {
            states,
            waypoints,
            times: Some(times),
        }
    }

    /// The frames whose configuration `valid` refuses, ascending.
    pub(crate) fn colliding(&self, mut valid: impl FnMut(&[f64]) -> bool) -> Vec<usize> {
        (0..self.states.len())
            .filter(|&i| !valid(&self.states[i]))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::RealVectorSpace;

    #[test]
    fn frames_follow_length_and_keep_every_state() {
        let space = RealVectorSpace::new(vec![0.0, 0.0], vec![10.0, 10.0]).unwrap();
        let path = vec![vec![0.0, 0.0], vec![3.0, 0.0], vec![3.0, 1.0]];
        let frames = ViewFrames::along_path(&space, &path);
        assert_eq!(frames.waypoints.len(), 3);
        for (w, state) in frames.waypoints.iter().zip(&path) {
            assert_eq!(&frames.states[*w], state);
        }
        // Three quarters of the frames on the first segment, a quarter on the second.
        assert_eq!(frames.waypoints[1], 300);
        assert_eq!(frames.waypoints[2], 400);
        assert!((frames.states[150][0] - 1.5).abs() < 1e-12);
    }

    #[test]
    fn timed_frames_hold_the_knots() {
        let frames = ViewFrames::along_time(2.0, &[0.0, 0.7, 2.0], |t| vec![t]);
        let times = frames.times.as_ref().unwrap();
        assert_eq!(times.first(), Some(&0.0));
        assert_eq!(times.last(), Some(&2.0));
        assert_eq!(frames.waypoints.len(), 3);
        assert!((times[frames.waypoints[1]] - 0.7).abs() < 1e-12);
        assert!(times.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn collisions_are_listed_by_frame() {
        let space = RealVectorSpace::new(vec![0.0], vec![10.0]).unwrap();
        let frames = ViewFrames::along_path(&space, &[vec![0.0], vec![4.0]]);
        let bad = frames.colliding(|q| !(1.0..=2.0).contains(&q[0]));
        assert_eq!(bad.first(), Some(&100));
        assert_eq!(bad.last(), Some(&200));
    }
}
