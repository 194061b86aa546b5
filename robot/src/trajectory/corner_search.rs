//! [`Corner`] and the search of the corners' speeds that take least time: a shortest path
//! through the corners, each corner's candidate speeds a grid, refined around the best.
//!
//! The time of a timed polyline is a sum over its segments, and segment `i`'s time (half of
//! each blend at its ends, and its profile between them) depends only on corners `i` and
//! `i + 1`: so the best corners among candidate lists are a shortest path through a layered
//! graph (dynamic programming, exact over the candidates). The candidates are first a grid of
//! `(enter, leave)` shares `0, 1/N, …, 1` of the corner's cap, then finer grids around the best
//! found (each round's step a quarter of the one before).

use super::blend_timing::{Polyline, Profile};

/// How a corner is passed: the speed in as a share of the top speed of the segment before it
/// (`enter`), and the speed out as a share of the top speed of the segment after it (`leave`);
/// both zero: a stop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Corner {
    /// The speed in, as a share of `S_{k−1}`.
    pub(super) enter: f64,
    /// The speed out, as a share of `S_k`.
    pub(super) leave: f64,
}

impl Corner {
    /// At rest.
    pub(super) const STOP: Self = Self {
        enter: 0.0,
        leave: 0.0,
    };

    /// Both speeds times `factor` (the blend's shape kept, its size times `factor²`).
    pub(super) fn scaled(self, factor: f64) -> Self {
        Self {
            enter: self.enter * factor,
            leave: self.leave * factor,
        }
    }

    /// The larger share.
    pub(super) fn size(self) -> f64 {
        self.enter.max(self.leave)
    }
}

/// Steps of the first grid of a corner's candidates: shares `0, 1/GRID, …, 1` of its cap.
const GRID: usize = 10;

/// Rounds of refinement around the best corners, each with a step a quarter of the last.
const REFINEMENTS: usize = 2;

/// Candidates each side of the best in a refinement round, per share.
const REACH: i32 = 3;

/// A candidate corner with its speeds in and out and its blend's duration.
#[derive(Debug, Clone, Copy)]
struct State {
    corner: Corner,
    enter: f64,
    leave: f64,
    blend: f64,
}

/// The corners (rest at the path's ends) with shares of at most `caps[k]` each that take
/// least time, as the module docs say. Always feasible: stopping at every corner is among the
/// candidates.
pub(super) fn best_corners(line: &Polyline<'_>, caps: &[f64]) -> Vec<Corner> {
    let m = line.segments();
    let interior = |k: usize| k > 0 && k < m && caps[k] > 0.0;
    let grid: Vec<Vec<Corner>> = (0..=m)
        .map(|k| {
            if !interior(k) {
                return vec![Corner::STOP];
            }
            let share = |i: usize| caps[k] * i as f64 / GRID as f64;
            (0..=GRID)
                .flat_map(|i| {
                    (0..=GRID).map(move |j| Corner {
                        enter: share(i),
                        leave: share(j),
                    })
                })
                .collect()
        })
        .collect();
    let mut best = shortest(line, &grid);
    let mut step = 1.0 / GRID as f64;
    for _ in 0..REFINEMENTS {
        step /= 4.0;
        let around: Vec<Vec<Corner>> = (0..=m)
            .map(|k| {
                if !interior(k) {
                    return vec![Corner::STOP];
                }
                let near = |x: f64, t: i32| (x + caps[k] * step * f64::from(t)).clamp(0.0, caps[k]);
                let centre = best[k];
                let mut list: Vec<Corner> = (-REACH..=REACH)
                    .flat_map(|i| {
                        (-REACH..=REACH).map(move |j| Corner {
                            enter: near(centre.enter, i),
                            leave: near(centre.leave, j),
                        })
                    })
                    .collect();
                list.push(Corner::STOP);
                list.dedup();
                list
            })
            .collect();
        best = shortest(line, &around);
    }
    best
}

/// The least-time choice of one candidate per corner (dynamic programming over the chain).
fn shortest(line: &Polyline<'_>, candidates: &[Vec<Corner>]) -> Vec<Corner> {
    let states: Vec<Vec<State>> = candidates
        .iter()
        .enumerate()
        .map(|(k, list)| {
            list.iter()
                .map(|&corner| {
                    let (enter, leave) = line.corner_speeds(k, corner);
                    State {
                        corner,
                        enter,
                        leave,
                        blend: line.blend(k, (enter, leave)),
                    }
                })
                .collect()
        })
        .collect();
    // cost[k][s]: least time from the start to the middle of corner k's blend in state s;
    // from[k][s]: the state of corner k − 1 it came from.
    let mut cost: Vec<Vec<f64>> = vec![vec![0.0]];
    let mut from: Vec<Vec<usize>> = vec![vec![0]];
    for i in 0..line.segments() {
        let (before, after) = (&states[i], &states[i + 1]);
        let mut layer = vec![f64::INFINITY; after.len()];
        let mut back = vec![0; after.len()];
        for (b, next) in after.iter().enumerate() {
            for (a, last) in before.iter().enumerate() {
                let so_far = cost[i][a];
                if !so_far.is_finite() {
                    continue;
                }
                let Some(profile) = Profile::new(
                    line.speed[i],
                    (last.leave, last.blend),
                    (next.enter, next.blend),
                ) else {
                    continue;
                };
                let t = so_far + 0.5 * last.blend + profile.duration() + 0.5 * next.blend;
                if t < layer[b] {
                    layer[b] = t;
                    back[b] = a;
                }
            }
        }
        cost.push(layer);
        from.push(back);
    }
    let m = line.segments();
    let mut chosen = vec![Corner::STOP; m + 1];
    let mut s = 0;
    for k in (0..=m).rev() {
        chosen[k] = states[k][s].corner;
        s = from[k][s];
    }
    chosen
}

#[cfg(test)]
mod tests {
    use super::super::blend_timing::polyline;
    use super::*;
    use crate::MotionLimits;

    /// The time of `corners` on `line`, `None` if a segment is infeasible.
    fn total(line: &Polyline<'_>, corners: &[Corner]) -> Option<f64> {
        (0..line.segments())
            .map(|i| {
                let p = line.profile(i, corners[i], corners[i + 1])?;
                let half = |k: usize| 0.5 * line.blend(k, line.corner_speeds(k, corners[k]));
                Some(half(i) + p.duration() + half(i + 1))
            })
            .sum()
    }

    #[test]
    fn the_shortest_path_is_the_best_of_every_combination() {
        let limits =
            MotionLimits::new(vec!["a".into(), "b".into()], vec![1.0, 2.0], vec![1.5, 1.0])
                .unwrap();
        let path = [[0.0, 0.0], [1.0, 0.2], [1.3, 1.5], [0.2, 1.7], [0.0, 3.0]];
        let line = polyline(&path, &limits).unwrap();
        let shares = [0.0, 0.3, 0.6, 1.0];
        let list: Vec<Corner> = shares
            .iter()
            .flat_map(|&enter| shares.iter().map(move |&leave| Corner { enter, leave }))
            .collect();
        let mut candidates = vec![list; 5];
        candidates[0] = vec![Corner::STOP];
        candidates[4] = vec![Corner::STOP];
        let chosen = shortest(&line, &candidates);
        let best = total(&line, &chosen).expect("feasible");
        let mut brute = f64::INFINITY;
        for a in &candidates[1] {
            for b in &candidates[2] {
                for c in &candidates[3] {
                    let corners = [Corner::STOP, *a, *b, *c, Corner::STOP];
                    if let Some(t) = total(&line, &corners) {
                        brute = brute.min(t);
                    }
                }
            }
        }
        assert!((best - brute).abs() <= 1e-12 * brute, "{best} vs {brute}");
        // Some corner is passed moving, and the refinement does no worse than the grid.
        assert!(chosen.iter().any(|c| *c != Corner::STOP));
        let refined = best_corners(&line, &[0.0, 1.0, 1.0, 1.0, 0.0]);
        assert!(total(&line, &refined).unwrap() <= best * (1.0 + 1e-12));
        // Caps bound the shares; a cap of 0 is a stop.
        let capped = best_corners(&line, &[0.0, 0.5, 0.0, 1.0, 0.0]);
        assert!(capped[1].size() <= 0.5 && capped[2] == Corner::STOP);
    }
}
