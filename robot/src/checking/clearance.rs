//! Certified radii: from the clearance of a batch of configurations of an edge, how far along the
//! edge each one can move and stay collision-free — conservative advancement, one `LaneF32`
//! lane per configuration.
//!
//! # The radius
//! At a configuration `m` of the edge (a fraction of it), let `c_k` be the clearance of link
//! entry `k`: the smallest distance from one of its spheres to an obstacle, less the sphere's
//! radius, the checker's margin and the user's [padding](crate::Padding) (the pairs below are
//! not padded). Over the piece `[m − h, m + h]` its spheres move at most
//! `B_k(h) = min(h · A_k + h² · Q_k, h · S_k)` (the local sweep bound, with `A_k` measured at
//! `m`, and the lever-arm bound `S_k`: see `local_sweep.rs`). So the piece is clear of the
//! scene for link `k` while `B_k(h) ≤ c_k`.
//!
//! That bound ignores the direction of motion, and an edge that slides past an obstacle
//! (every valid edge does so at its closest approach, where the distance stops falling) pays
//! for it with pieces as short as the clearance: a graze of a third of a millimetre took 25
//! batches of the walk. So each sphere `s` is also judged against each obstacle `o` it comes
//! near by how fast it approaches it. Every obstacle is convex, so its distance is a convex
//! function of the point, and `dist(x(t)) ≥ dist(x(m)) + n · (x(t) − x(m))`, `n` the unit
//! direction away from the obstacle at `x(m)`. The centre leaves its tangent line
//! `x(m) + (t − m) v` (`v` its velocity at `m`, from the link's velocity and turn) by at most
//! `Acc_k (t − m)² / 2` (the acceleration bound of `local_sweep.rs`), so `s` stays clear of
//! `o` while `h · |n · v| + h² · Acc_k / 2 ≤ c_so`, its clearance from `o`. The rate `n · v` is
//! computed in `f32` from centres placed within the margin `δ` of the true ones; it is grown
//! by what that can hide — the direction's error `4 δ / d` (`d` the centre's distance from
//! the obstacle) times the speed bound `A_k`, a thousandth of `A_k`, and `4 δ` per unit of
//! the link's joint rates. The radius of `s` against `o` is the larger of this one and the
//! one of `B_k` (both hold); at the closest approach of a graze `n · v` is about zero, and the piece is about
//! `√(2 c / Acc)` long instead of `c / |v|`. A point cloud is not convex, but each point's
//! ball is: a sphere is judged so against every point within the bound `B_k` of its piece
//! (a walk of the cloud's tree whose reach shrinks with the radius), its radius the least
//! over those points of the larger of the two radii.
//!
//! A self-collision pair `(a, b)` only moves apart
//! or together through the joints above one link and not the other (those above both carry
//! the two rigidly): with `S_ab` the lever-arm sweep of those joints over the edge, the piece
//! is clear for the pair while `h · S_ab ≤ c_ab`, the pair's clearance less two margins. That
//! bound too ignores the direction: the UR5's base and upper arm stay about 2 mm apart as its
//! shoulder turns, and it cut every edge into pieces of a fiftieth of a degree. So each pair
//! of spheres `(s, s')` is also judged as a sphere against a ball (convex): their centres'
//! difference `r` moves at `v_s − v_s'` and accelerates at most `Acc_a + Acc_b`, so they stay
//! clear while `h · |n · (v_s − v_s')| + h² · (Acc_a + Acc_b) / 2 ≤ c_ss'`, `n = r / |r|`,
//! with both links' slacks and speeds added, and the direction's error doubled (two centres,
//! each placed within `δ`). The pair of spheres gets the larger of the two radii. The
//! lane's radius is the smallest of its links', its spheres' and its pairs' radii, each
//! solved in closed form and rounded down.
//!
//! Clearances are only computed as far as they matter: the caller names the largest radius
//! it has a use for, and a link (or pair) clear by how far it moves over such a piece — or over
//! a piece of the smallest radius the lane has met so far, if that is smaller — is not looked
//! at more closely, since it cannot lower the lane's radius; a link's bounding
//! sphere (then its distance to the solid) is tested before its small spheres, which are
//! placed only if the bounding sphere comes that close.

use crate::checking::arm_checker::{LaneScratch, Shared, distance_squared, place_link};
use crate::checking::lanes::{LANES, LaneF32, LanePoint};
use crate::checking::local_sweep::{EdgeTerms, LaneMotion};
use crate::checking::obstacle_grid::widest;

/// The relative rounding allowed for in a computed rate of approach (its `f32` arithmetic,
/// the direction's and the velocity's), as a share of the link's speed bound.
const DIRECTION_ROUNDING: f32 = 1e-3;

/// What the radii of an edge's configurations depend on besides the configurations and the
/// local sweep bound's terms: the joint displacements, per link entry the lever-arm sweep
/// over the whole edge, and per self-collision pair the links' sweep relative to each other.
#[derive(Debug, Clone, Copy)]
pub(crate) struct EdgeBounds<'a> {
    pub(crate) delta: &'a [f64],
    pub(crate) sweep: &'a [f64],
    pub(crate) pair_sweep: &'a [f64],
}

/// Per lane of the first `count` of `lanes.lane_q` (at most [`LANES`] configurations of the
/// robot, on the edge of `edge`, whose local sweep terms `terms` computes as the links need
/// them; `outside` the lanes outside the joint limits): its certified radius, as a fraction of
/// the edge, and as bit `l` of the second value whether lane `l` is refused — outside the
/// joint limits, or with a clearance below `floor` metres (in contact, or within a hair of
/// it). Radii are computed up to `useful` (a larger radius is returned as `useful`:
/// clearances are not sought beyond what it needs).
pub(crate) fn certified_radii(
    s: &Shared,
    lanes: &mut LaneScratch,
    (count, outside): (usize, u32),
    edge: &EdgeBounds<'_>,
    terms: &mut EdgeTerms,
    (floor, useful): (f64, f64),
) -> ([f64; LANES], u32) {
    let count = count.min(LANES);
    let live: u32 = (1 << count) - 1;
    let mut refused = outside & live;
    let LaneScratch {
        lane_poses,
        lane_centers,
        lane_bounds,
        placed,
        lane_q,
        candidates,
        motions,
        ..
    } = lanes;
    s.lanes.link_poses(lane_q, lane_poses);
    motions.fill(None);
    for (bound, (link, _, center, _)) in lane_bounds.iter_mut().zip(&s.links) {
        *bound = lane_poses[*link].point(*center);
    }
    placed.fill(false);
    // Rounded up, as the plain checks' margin: `margin` between links (and for the rounding of
    // poses), `keep` (the margin and the padding) from the scene.
    let margin = LaneF32::splat((s.margin * (1.0 + 1e-6)) as f32);
    let keep = LaneF32::splat(((s.margin + s.padding.metres()) * (1.0 + 1e-6)) as f32);
    let floor = LaneF32::splat(floor as f32);
    // Per lane, the smallest radius so far: no lane's is sought beyond `useful`.
    let mut radius = LaneF32::splat(useful as f32);
    for (k, (_, range, _, bound_radius)) in s.links.iter().enumerate() {
        let sweep = LaneF32::splat(edge.sweep[k] as f32);
        let r = LaneF32::splat(*bound_radius);
        // The link's motion at the lanes' configurations (`motions[k]`), computed when a
        // first obstacle comes near enough to need it (a link near none needs no more than
        // the tests below).
        let mut nearest = LaneF32::splat(f32::INFINITY);
        // Obstacles out of the link's reach in every configuration cannot limit its radius.
        // Among many, only those the grid finds within the loosest bound below of a lane
        // (`loose` with the lanes' radii so far, which only fall): the test below would skip
        // the others.
        let list = &s.reachable[k];
        let near = s.grids[k].as_ref().is_some_and(|grid| {
            let loose = radius * sweep + floor + floor + keep + r;
            grid.candidates(&lane_bounds[k], live, widest(loose), &mut candidates.0)
        });
        let (every, picked): (&[crate::Obstacle], &[u32]) = if near {
            (&[], &candidates.0)
        } else {
            (list, &[])
        };
        let picked = picked.iter().map(|&i| &list[i as usize]);
        for obstacle in every.iter().chain(picked) {
            // First the obstacles that come within the link's lever-arm sweep over a piece of
            // the lane's radius so far (and twice the floor, safe from rounding): the others
            // cannot lower the radius. Spheres of the link are no closer than its bounding
            // sphere.
            let loose = radius * sweep + floor + floor + keep + r;
            if obstacle.may_be_within_lanes(&lane_bounds[k], loose) & live == 0 {
                continue;
            }
            let excess = obstacle.excess_lanes(&lane_bounds[k]);
            if excess.simd_lt(loose * loose).to_bitmask() & live == 0 {
                continue;
            }
            let m = motion_of(
                s,
                k,
                (lane_poses, lane_bounds),
                (edge, terms),
                (motions, margin),
            );
            let LinkMotion {
                speed,
                motion: LaneMotion { velocity, angular },
                second,
                acceleration,
                slack,
            } = m;
            // How far the link's spheres move over a piece of the lane's radius so far, by the
            // bounds that hold whatever the direction of motion: a sphere clear by this (and
            // twice the floor) cannot lower the radius.
            let limit = m.sweep_over(radius, sweep) + floor + floor;
            let outer = limit + keep + r;
            if excess.simd_lt(outer * outer).to_bitmask() & live == 0 {
                continue;
            }
            let spheres = &s.spheres[range.clone()];
            place_link(s, k, lane_poses, lane_centers, placed);
            let reaches = &s.reaches[range.clone()];
            for (c, (sphere, &extent)) in lane_centers[range.clone()]
                .iter()
                .zip(spheres.iter().zip(reaches))
            {
                // A sphere whose link's bounding centre is far enough that the sphere is clear
                // by `limit` in every lane cannot lower the radius (nor is it near the floor).
                let far = limit + keep + LaneF32::splat(extent);
                if excess.simd_lt(far * far).to_bitmask() & live == 0 {
                    continue;
                }
                let local = obstacle.local_lanes(c);
                let distance = obstacle.distances_local_lanes(&local);
                let gap = distance - LaneF32::splat(sphere.1);
                nearest = nearest.min(gap);
                let clear = gap - keep;
                if clear.simd_lt(limit).to_bitmask() & live == 0 {
                    continue;
                }
                let moving = centre_velocity(&LaneMotion { velocity, angular }, c, &lane_bounds[k]);
                let rate = obstacle.rates_local_lanes(&local, distance, &moving);
                // The direction from the solid is known to within `4 δ / d` for a centre `d`
                // from it placed within `δ` (the margin) of where it is.
                let aim = margin * LaneF32::splat(4.0) / (distance - margin).max(margin);
                let approach = rate.abs() + slack + aim * speed;
                let directional = reach_approaching(clear, approach, acceleration);
                radius =
                    radius.min(reach(clear, speed, second, edge.sweep[k] as f32).max(directional));
            }
        }
        // Point clouds: a cloud is not convex, but each point's ball is. A lower bound of
        // the bounding centre's distance to the cloud rules out the links far from it; then
        // each sphere is judged against every point within the limit, as against a convex
        // solid.
        for &cloud in &s.reachable_clouds[k] {
            let cloud = &s.clouds[cloud];
            let loose = radius * sweep + floor + floor + keep + r;
            let lower = cloud.distance_lower_bounds_lanes(&lane_bounds[k], loose, live);
            if lower.simd_lt(loose).to_bitmask() & live == 0 {
                continue;
            }
            let m = motion_of(
                s,
                k,
                (lane_poses, lane_bounds),
                (edge, terms),
                (motions, margin),
            );
            let limit = m.sweep_over(radius, sweep) + floor + floor;
            if lower.simd_lt(limit + keep + r).to_bitmask() & live == 0 {
                continue;
            }
            place_link(s, k, lane_poses, lane_centers, placed);
            let reaches = &s.reaches[range.clone()];
            for (c, (sphere, &extent)) in lane_centers[range.clone()]
                .iter()
                .zip(s.spheres[range.clone()].iter().zip(reaches))
            {
                // The sphere's ball is no nearer the cloud than the bounding centre's bound
                // less its extent: clear by `limit` in a lane, it cannot lower the radius
                // there, so the walk follows only the other lanes (the rest get a value
                // between their true distance and the limit: not below `limit + keep`,
                // which changes neither the radius nor the refusal).
                let near = lower
                    .simd_lt(limit + keep + LaneF32::splat(extent))
                    .to_bitmask()
                    & live;
                if near == 0 {
                    continue;
                }
                let own = LaneF32::splat(sphere.1);
                // Each point's ball is convex: the bound of the module docs for a convex
                // solid, per point within the limit, judged by how fast the sphere approaches
                // it (the direction from the point, computed in `f32` from a centre within
                // the margin of its true place, is allowed for as for the primitives).
                let moving = centre_velocity(&m.motion, c, &lane_bounds[k]);
                let sweep_k = edge.sweep[k] as f32;
                let four = LaneF32::splat(4.0);
                let infinite = LaneF32::splat(f32::INFINITY);
                let half_acceleration = m.acceleration * LaneF32::splat(0.5);
                let start = limit + keep + own + floor;
                cloud.visit_balls_lanes(c, start, near, |ball, n, within| {
                    let gap = ball - own;
                    nearest = nearest.min(within.bitselect(gap, infinite));
                    let clear = gap - keep;
                    let rate = n[0] * moving[0] + n[1] * moving[1] + n[2] * moving[2];
                    let aim = margin * four / (ball - margin).max(margin);
                    let approach = rate.abs() + m.slack + aim * m.speed;
                    // Where the bound holds over a piece of the lane's radius so far, the
                    // point cannot lower it (no root needed).
                    let holds = (radius * approach + radius * radius * half_acceleration)
                        .simd_le(clear)
                        .to_bitmask();
                    if within.to_bitmask() & !holds != 0 {
                        let directional = reach_approaching(clear, approach, m.acceleration);
                        let piece = reach(clear, m.speed, m.second, sweep_k).max(directional);
                        radius = radius.min(within.bitselect(piece, infinite));
                    }
                    m.sweep_over(radius, sweep) + floor + floor + keep + own + floor
                });
            }
        }
        refused |= (nearest - keep).simd_lt(floor).to_bitmask() & live;
    }
    for (p, &(a, b)) in s.pairs.iter().enumerate() {
        let (la, lb) = (&s.links[a], &s.links[b]);
        // Joints above both links move them rigidly together: only the pair's relative sweep
        // counts.
        let pair_sweep = edge.pair_sweep[p] as f32;
        let sweep = LaneF32::splat(pair_sweep);
        let margins = margin + margin;
        // As for the links: clear by the sweep over a piece of the lane's radius so far (and
        // twice the floor), a pair of spheres limits nothing.
        let limit = |radius: LaneF32| radius * sweep + floor + floor + margins;
        let reach_ab = LaneF32::splat(la.3 + lb.3);
        if closer(&lane_bounds[a], &lane_bounds[b], limit(radius) + reach_ab) & live == 0 {
            // Clear by more than that in every lane: neither the radius nor a refusal can
            // come from this pair.
            continue;
        }
        for k in [a, b] {
            place_link(s, k, lane_poses, lane_centers, placed);
        }
        let ma = motion_of(
            s,
            a,
            (lane_poses, lane_bounds),
            (edge, terms),
            (motions, margin),
        );
        let mb = motion_of(
            s,
            b,
            (lane_poses, lane_bounds),
            (edge, terms),
            (motions, margin),
        );
        // Judged by their rate of approach as a sphere against a convex solid, with the two
        // links' accelerations, slacks and speeds added (the relative motion's bounds), and
        // the direction's error doubled (both centres placed within the margin).
        let acceleration = ma.acceleration + mb.acceleration;
        let slack = ma.slack + mb.slack;
        let speed = ma.speed + mb.speed;
        let (spheres_a, spheres_b) = (&s.spheres[la.1.clone()], &s.spheres[lb.1.clone()]);
        let (centers_a, centers_b) = (&lane_centers[la.1.clone()], &lane_centers[lb.1.clone()]);
        let (bound_a, bound_b) = (&lane_bounds[a], &lane_bounds[b]);
        let mut nearest = LaneF32::splat(f32::INFINITY);
        for (ca, sa) in centers_a.iter().zip(spheres_a) {
            let ri = sa.1;
            if closer(ca, bound_b, limit(radius) + LaneF32::splat(ri + lb.3)) & live == 0 {
                continue;
            }
            let va = centre_velocity(&ma.motion, ca, bound_a);
            for (cb, sb) in centers_b.iter().zip(spheres_b) {
                let reach = LaneF32::splat(ri + sb.1);
                // No square root where no lane's gap could lower the radius.
                if closer(ca, cb, limit(radius) + reach) & live == 0 {
                    continue;
                }
                let apart = [ca[0] - cb[0], ca[1] - cb[1], ca[2] - cb[2]];
                let distance = distance_squared(ca, cb).sqrt();
                let gap = distance - reach;
                nearest = nearest.min(gap);
                let clear = gap - margins;
                let linear = if pair_sweep > 0.0 {
                    clear.max(LaneF32::ZERO) / sweep
                } else {
                    LaneF32::splat(f32::INFINITY)
                };
                let vb = centre_velocity(&mb.motion, cb, bound_b);
                let rate = (apart[0] * (va[0] - vb[0])
                    + apart[1] * (va[1] - vb[1])
                    + apart[2] * (va[2] - vb[2]))
                    / distance.max(margins);
                let aim = margins * LaneF32::splat(4.0) / (distance - margins).max(margin);
                let approach = rate.abs() + slack + aim * speed;
                let directional = reach_approaching(clear, approach, acceleration);
                radius = radius.min(linear.max(directional));
            }
        }
        refused |= (nearest - margins).simd_lt(floor).to_bitmask() & live;
    }
    let radius = radius.to_array();
    let radii = std::array::from_fn(|l| f64::from(radius[l]) * (1.0 - 1e-4));
    (radii, refused)
}

/// A link's motion at a batch's configurations, as certification bounds it: its speed bound
/// (the local sweep's first-order term), how its bounding centre moves and turns, the
/// second-order term and acceleration bound of the edge, and the rounding a computed rate of
/// approach may miss.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LinkMotion {
    speed: LaneF32,
    motion: LaneMotion,
    second: LaneF32,
    acceleration: LaneF32,
    slack: LaneF32,
}

impl LinkMotion {
    /// How far the link's spheres move over a piece of radius `radius` (per lane), by the
    /// bounds that hold whatever the direction of motion: the local sweep bound, or the
    /// lever-arm one (`sweep`, the link's over the whole edge) where that is smaller.
    #[inline]
    fn sweep_over(&self, radius: LaneF32, sweep: LaneF32) -> LaneF32 {
        (radius * self.speed + radius * radius * self.second).min(radius * sweep)
    }
}

/// Link entry `k`'s motion at the lanes' configurations (its poses and bounding centre
/// given), computing its local sweep terms for the edge.
fn link_motion(
    s: &Shared,
    k: usize,
    (lane_poses, bounding): (&[crate::checking::lanes::LanePose], &LanePoint),
    (edge, terms): (&EdgeBounds<'_>, &mut EdgeTerms),
    margin: LaneF32,
) -> LinkMotion {
    s.local.link_terms(k, edge.delta, &s.levers, terms);
    let (speed, motion) = s
        .local
        .speed_of(k, lane_poses, bounding, (edge.delta, terms));
    LinkMotion {
        speed,
        motion,
        second: LaneF32::splat(terms.second(k) as f32),
        acceleration: LaneF32::splat(terms.acceleration(k) as f32),
        // What the rate of approach computed in `f32` may miss: its relative rounding, and
        // the error of the link's poses carried through its joint rates.
        slack: speed * LaneF32::splat(DIRECTION_ROUNDING)
            + margin * LaneF32::splat(4.0 * terms.rates(k) as f32),
    }
}

/// Link entry `k`'s motion at the batch's configurations: `motions[k]`, computed by
/// [`link_motion`] the first time the batch needs it.
#[inline]
fn motion_of(
    s: &Shared,
    k: usize,
    (lane_poses, lane_bounds): (&[crate::checking::lanes::LanePose], &[LanePoint]),
    (edge, terms): (&EdgeBounds<'_>, &mut EdgeTerms),
    (motions, margin): (&mut [Option<LinkMotion>], LaneF32),
) -> LinkMotion {
    *motions[k].get_or_insert_with(|| {
        link_motion(s, k, (lane_poses, &lane_bounds[k]), (edge, terms), margin)
    })
}

/// The velocity of a sphere centre `c` of a link whose bounding centre `bound` moves and
/// turns as `motion` says: the bounding centre's velocity plus the turn about it.
#[inline]
fn centre_velocity(motion: &LaneMotion, c: &LanePoint, bound: &LanePoint) -> [LaneF32; 3] {
    let LaneMotion { velocity, angular } = motion;
    let arm = [c[0] - bound[0], c[1] - bound[1], c[2] - bound[2]];
    [
        velocity[0] + angular[1] * arm[2] - angular[2] * arm[1],
        velocity[1] + angular[2] * arm[0] - angular[0] * arm[2],
        velocity[2] + angular[0] * arm[1] - angular[1] * arm[0],
    ]
}

/// Per lane, the largest `h` with `min(h · speed + h² · second, h · sweep) ≤ clear` (0 for a
/// clearance of 0 or less; unbounded for what does not move).
#[inline]
fn reach(clear: LaneF32, speed: LaneF32, second: LaneF32, sweep: f32) -> LaneF32 {
    let c = clear.max(LaneF32::ZERO);
    let linear = if sweep > 0.0 {
        c / LaneF32::splat(sweep)
    } else {
        LaneF32::splat(f32::INFINITY)
    };
    let q = second;
    // The root of h² · q + h · speed = c, in the form that stays exact as q → 0.
    let denominator = speed + (speed * speed + LaneF32::splat(4.0) * q * c).sqrt();
    let quadratic = (c + c) / denominator.max(LaneF32::splat(f32::MIN_POSITIVE));
    linear.max(quadratic)
}

/// Per lane, the largest `h` with `h · approach + h² · acceleration / 2 ≤ clear` (0 for a
/// clearance of 0 or less): how far a sphere approaching a convex solid at `approach` at the
/// piece's middle, and accelerating at most `acceleration`, can move either way and stay
/// clear of it.
#[inline]
fn reach_approaching(clear: LaneF32, approach: LaneF32, acceleration: LaneF32) -> LaneF32 {
    let c = clear.max(LaneF32::ZERO);
    let denominator = approach + (approach * approach + (acceleration + acceleration) * c).sqrt();
    (c + c) / denominator.max(LaneF32::splat(f32::MIN_POSITIVE))
}

/// Bit `l` set if lane `l`'s points are closer than `limit[l]` (no square root).
#[inline]
fn closer(a: &LanePoint, b: &LanePoint, limit: LaneF32) -> u32 {
    let positive = limit.simd_gt(LaneF32::ZERO).to_bitmask();
    positive & distance_squared(a, b).simd_lt(limit * limit).to_bitmask()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_radius_meets_the_bound_with_equality() {
        let (speed, second, sweep) = (0.8_f32, 0.5_f32, 2.0_f32);
        for clear in [1e-4_f32, 1e-2, 0.3] {
            let h = reach(
                LaneF32::splat(clear),
                LaneF32::splat(speed),
                LaneF32::splat(second),
                sweep,
            )
            .to_array()[0];
            let bound = (h * speed + h * h * second).min(h * sweep);
            assert!((bound - clear).abs() <= 1e-5 * clear, "{clear}: {bound}");
        }
        // The lever-arm bound wins when it is the tighter one.
        let h = reach(
            LaneF32::splat(0.5),
            LaneF32::splat(3.0),
            LaneF32::splat(10.0),
            1.0,
        )
        .to_array()[0];
        assert!((h - 0.5).abs() < 1e-6, "{h}");
        // Nothing moves: unbounded; no clearance: nothing.
        let h = reach(LaneF32::splat(0.1), LaneF32::ZERO, LaneF32::ZERO, 0.0).to_array()[0];
        assert!(h > 1e6, "{h}");
        let h = reach(
            LaneF32::splat(-0.1),
            LaneF32::splat(1.0),
            LaneF32::splat(1.0),
            1.0,
        )
        .to_array()[0];
        assert_eq!(h, 0.0);
    }
}
