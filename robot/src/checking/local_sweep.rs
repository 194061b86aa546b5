//! [`LocalSweep`]: how far a link's spheres can move over a piece of an edge, bounded from the
//! configuration at the piece's middle — much tighter than the lever arms that hold for every
//! configuration, so certification needs fewer, longer pieces.

use glam::Vec3A;

use crate::checking::lanes::{LaneF32, LanePoint, LanePose};
use crate::{Motion, RobotModel};

/// Added to every computed axis distance, in metres: covers the `f32` error of the distance
/// (link poses are placed within a few micrometres).
const DISTANCE_SLACK: f32 = 1e-4;

/// One joint on the chain from the root to a link.
#[derive(Debug, Clone, Copy)]
struct ChainJoint {
    /// The joint's coordinate.
    coordinate: usize,
    /// The link whose frame the joint moves: the axis passes through its origin.
    frame: usize,
    /// The axis in that frame; `None` for a prismatic joint.
    axis: Option<Vec3A>,
    /// A prismatic joint's axis in that frame (its velocity per unit of the coordinate);
    /// zero for a revolute one.
    direction: Vec3A,
    /// `|axis|` for a prismatic joint (its speed per unit of the coordinate).
    slide: f64,
}

/// For every link with spheres, the joints above it, and how far its sphere centres spread
/// around its bounding centre.
///
/// # The bound
/// Over a piece `[m − h, m + h]` of the edge `a → b` (as fractions of the edge), a sphere
/// centre `c` of link `k` moves at most `∫ Σ_j |Δq_j| · dist(c, axis_j) dt` from where it is at
/// `m` (a prismatic joint contributes `|axis_j| · |Δq_j|` instead). A rigid motion of the
/// joints above `j` and the turn of `j` itself keep `dist(c, axis_j)`; only the joints between
/// `j` and `k` change it, by at most `|t − m| · Σ_{i after j} λ_{k,i} |Δq_i|` (the lever arms,
/// [`LeverArms`](crate::LeverArms)). And `dist(c, axis_j) ≤ dist(p, axis_j) + spread`, `p` the
/// link's bounding centre. So every sphere of `k` moves at most
/// `h · Σ_j |Δq_j| (d_j + spread) + h² · Q_k`, with `d_j = dist(p, axis_j)` measured at the
/// middle configuration and `Q_k = Σ_j |Δq_j| Σ_{i after j} λ_{k,i} |Δq_i|`.
#[derive(Debug, Clone)]
pub(crate) struct LocalSweep {
    /// Per link entry (the checker's links with spheres): its joints, root first.
    chains: Vec<Vec<ChainJoint>>,
    /// Per link entry: the largest distance of a sphere centre from the bounding centre.
    spreads: Vec<f64>,
}

/// The parts of the bound fixed by the edge: per link entry, the constant speed (prismatic
/// joints and the spread), `Q_k`, and `Acc_k`, a bound on the acceleration of its sphere
/// centres anywhere on the edge (see [`LocalSweep::link_terms`]), each computed when first
/// needed.
#[derive(Debug, Clone, Default)]
pub(crate) struct EdgeTerms {
    constant: Vec<f64>,
    second: Vec<f64>,
    acceleration: Vec<f64>,
    rates: Vec<f64>,
    /// Per link entry: its terms are computed for the edge at hand.
    ready: Vec<bool>,
}

/// Per link entry and lane, how its spheres move at the lane's configuration, per unit of
/// the edge's fraction: the velocity of its bounding centre and its angular velocity (a
/// sphere centre `c` moves at `velocity + angular × (c − bounding centre)`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LaneMotion {
    pub(crate) velocity: LanePoint,
    pub(crate) angular: LanePoint,
}

impl LaneMotion {
    /// At rest.
    pub(crate) const ZERO: Self = Self {
        velocity: [LaneF32::ZERO; 3],
        angular: [LaneF32::ZERO; 3],
    };
}

impl LocalSweep {
    /// The chains of `links` (the checker's entries: link index, sphere range, local bounding
    /// centre) of `robot`.
    pub(crate) fn new(
        robot: &RobotModel,
        links: &[(usize, std::ops::Range<usize>, Vec3A, f32)],
    ) -> Self {
        let frames = robot.links();
        let chains = links
            .iter()
            .map(|&(link, ..)| {
                let mut chain = Vec::new();
                let mut at = Some(link);
                while let Some(a) = at {
                    match frames[a].motion {
                        Motion::Fixed => {}
                        Motion::Revolute { axis, coordinate } => chain.push(ChainJoint {
                            coordinate,
                            frame: a,
                            axis: Some(axis.as_vec3a()),
                            direction: Vec3A::ZERO,
                            slide: 0.0,
                        }),
                        Motion::Prismatic { axis, coordinate } => chain.push(ChainJoint {
                            coordinate,
                            frame: a,
                            axis: None,
                            direction: axis.as_vec3a(),
                            slide: axis.length(),
                        }),
                    }
                    at = frames[a].parent;
                }
                chain.reverse();
                chain
            })
            .collect();
        let spheres = robot.spheres();
        let spreads = links
            .iter()
            .map(|(_, range, center, _)| {
                let center = center.as_dvec3();
                range
                    .clone()
                    .map(|i| spheres[i].center.distance(center))
                    .fold(0.0, f64::max)
            })
            .collect();
        Self { chains, spreads }
    }

    /// The lever arms of link entries `a` and `b` relative to each other, per coordinate (of
    /// `n`): a coordinate that moves a joint above one entry but not above the other moves
    /// the two apart by at most that entry's lever arm per unit; joints above both move them
    /// together, rigidly, and do not count. `levers` holds the checker's lever arms per link
    /// entry and coordinate.
    pub(crate) fn relative_levers(
        &self,
        (a, b): (usize, usize),
        levers: &[f64],
        n: usize,
    ) -> Vec<f64> {
        let mut out = vec![0.0; n];
        for (this, other) in [(a, b), (b, a)] {
            for joint in &self.chains[this] {
                if !self.chains[other].iter().any(|o| o.frame == joint.frame) {
                    out[joint.coordinate] += levers[this * n + joint.coordinate];
                }
            }
        }
        out
    }

    /// Every link entry's terms of the edge with joint displacements `delta` (see
    /// [`link_terms`](Self::link_terms)).
    #[cfg(test)]
    pub(crate) fn edge_terms(&self, delta: &[f64], levers: &[f64], out: &mut EdgeTerms) {
        out.reset(self.chains.len());
        for k in 0..self.chains.len() {
            self.link_terms(k, delta, levers, out);
        }
    }

    /// Link entry `k`'s terms of the edge with joint displacements `delta`, unless `out`
    /// (reset for the edge with [`EdgeTerms::reset`]) holds them already: certification
    /// computes them only for the links that come near something. `levers` holds the
    /// checker's lever arms per link entry and coordinate.
    ///
    /// # The acceleration bound
    /// Along the edge the joints move at the constant rates `Δq`, so a point `x` of link `k`
    /// moves at `ẋ = Σ_j Δq_j u_j × (x − o_j)` (revolute `j`: axis `u_j` through `o_j`) plus
    /// `Δq_j a_j` (prismatic `j`, axis `a_j`). Differentiating, a revolute joint contributes
    /// `Δq_j (u̇_j × (x − o_j) + u_j × (ẋ − ȯ_j))`, where the axis turns no faster than the
    /// revolute joints above it, `|u̇_j| ≤ W_j = Σ_{i above j} |Δq_i|`, and the point moves
    /// relative to `o_j` no faster than `W_j |x − o_j| + Σ_{i from j on} |Δq_i| λ_{k,i}`; a
    /// prismatic joint contributes `Δq_j ȧ_j`, `|ȧ_j| ≤ W_j |a_j|`. With `|x − o_j| ≤ λ_{k,j}`
    /// (the lever arm bounds the distance to the joint's origin), every sphere centre of `k`
    /// accelerates at most `Acc_k = Σ_{j revolute} |Δq_j| (2 W_j λ_{k,j} + Σ_{i from j on}
    /// |Δq_i| λ_{k,i}) + Σ_{j prismatic} |Δq_j| |a_j| W_j`, anywhere on the edge.
    #[inline]
    pub(crate) fn link_terms(&self, k: usize, delta: &[f64], levers: &[f64], out: &mut EdgeTerms) {
        if out.ready[k] {
            return;
        }
        let n = delta.len();
        let chain = &self.chains[k];
        let lever = &levers[k * n..(k + 1) * n];
        // `after`: `Σ λ_{k,i} |Δq_i|` over the joints below the one at hand, run from the
        // link up.
        let (mut constant, mut second, mut after, mut rates) = (0.0, 0.0, 0.0, 0.0);
        for joint in chain.iter().rev() {
            let d = delta[joint.coordinate].abs();
            rates += d * joint.slide.max(1.0);
            if joint.axis.is_none() {
                constant += joint.slide * d;
            } else {
                constant += d * (self.spreads[k] + f64::from(DISTANCE_SLACK));
                second += d * after;
            }
            after += lever[joint.coordinate] * d;
        }
        // The acceleration, from the root down: `above` is the revolute rates above the
        // joint at hand, `after` what is below it.
        let (mut acceleration, mut above) = (0.0, 0.0);
        for joint in chain {
            let d = delta[joint.coordinate].abs();
            let own = lever[joint.coordinate];
            after -= own * d;
            if joint.axis.is_none() {
                acceleration += d * joint.slide * above;
                continue;
            }
            acceleration += d * (2.0 * above * own + d * own + after.max(0.0));
            above += d;
        }
        out.constant[k] = constant;
        out.second[k] = second;
        // Rounded up, as the lever arms (and for the running sums' rounding).
        out.acceleration[k] = acceleration * (1.0 + 1e-9) + 1e-12;
        out.rates[k] = rates;
        out.ready[k] = true;
    }

    /// Link entry `k`'s speed term in each lane, `A_k = constant_k + Σ_j |Δq_j| d_j` with
    /// `d_j` measured from the lane's link poses and its bounding centre `p`: over a piece of
    /// half-width `h` around the lane's configuration, the entry's spheres move at most
    /// `h · A_k + h² · Q_k` ([`EdgeTerms::second`]). Rounded up. With it, the entry's
    /// [`LaneMotion`] at the lanes' configurations.
    #[inline]
    pub(crate) fn speed_of(
        &self,
        k: usize,
        poses: &[LanePose],
        p: &LanePoint,
        (delta, terms): (&[f64], &EdgeTerms),
    ) -> (LaneF32, LaneMotion) {
        let mut speed = LaneF32::splat(terms.constant[k] as f32);
        let mut motion = LaneMotion::ZERO;
        for joint in &self.chains[k] {
            let pose = &poses[joint.frame];
            let rate = LaneF32::splat(delta[joint.coordinate] as f32);
            let Some(axis) = joint.axis else {
                let a = pose.rotate(joint.direction);
                for (v, a) in motion.velocity.iter_mut().zip(a) {
                    *v += rate * a;
                }
                continue;
            };
            let u = pose.rotate(axis);
            let o = pose.translation();
            let r = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
            let cross = [
                r[1] * u[2] - r[2] * u[1],
                r[2] * u[0] - r[0] * u[2],
                r[0] * u[1] - r[1] * u[0],
            ];
            let distance = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
            speed += distance * LaneF32::splat(delta[joint.coordinate].abs() as f32);
            // `u × r = −(r × u)`.
            for ((v, w), (c, u)) in motion
                .velocity
                .iter_mut()
                .zip(&mut motion.angular)
                .zip(cross.iter().zip(u))
            {
                *v -= rate * *c;
                *w += rate * u;
            }
        }
        (speed * LaneF32::splat(1.0 + 1e-5), motion)
    }
}

impl EdgeTerms {
    /// Forgets every link's terms: a new edge, `links` link entries.
    pub(crate) fn reset(&mut self, links: usize) {
        for v in [
            &mut self.constant,
            &mut self.second,
            &mut self.acceleration,
            &mut self.rates,
        ] {
            v.resize(links, 0.0);
        }
        self.ready.clear();
        self.ready.resize(links, false);
    }

    /// Link entry `k`'s second-order term `Q_k`.
    #[inline]
    pub(crate) fn second(&self, k: usize) -> f64 {
        self.second[k]
    }

    /// Link entry `k`'s acceleration bound `Acc_k`.
    #[inline]
    pub(crate) fn acceleration(&self, k: usize) -> f64 {
        self.acceleration[k]
    }

    /// The sum of link entry `k`'s joint rates, `Σ_j |Δq_j|` over the joints above it (a
    /// prismatic one weighted by its axis's length if that is above 1): how much the `f32`
    /// errors of the link's poses can grow in its computed velocity.
    #[inline]
    pub(crate) fn rates(&self, k: usize) -> f64 {
        self.rates[k]
    }
}

#[cfg(test)]
mod tests;
