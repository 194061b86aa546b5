//! [`LeverArms`]: how fast each link's collision spheres can move per unit of each joint
//! coordinate, whatever the configuration — the bound that certified motion rests on.

use mit_star_spaces::StateSpace;

use crate::{Motion, RobotModel};

/// For every link and every joint coordinate `j`, a bound `λ[link][j]` on how far any point of
/// the link's collision spheres can move per unit of `q_j`, over **all** configurations.
///
/// So along any motion in joint space, every sphere of `link` moves at most
/// `Σ_j λ[link][j] · |Δq_j|`: over a sub-interval of an edge `a → b` covering the fraction
/// `w` of it, at most `w · Σ_j λ[link][j] · |b_j − a_j|` from where it is at the
/// sub-interval's middle configuration (for a wrapping joint, `|Δq_j|` is the short way round).
///
/// # How the bound is found
/// A revolute joint turning by `dθ` moves a point by at most `dθ` times its distance from the
/// joint's axis, which passes through the origin of the frame of the link it moves. A link's
/// spheres lie within `|c| + ρ` of that link's origin (`c`, `ρ`: the centre and radius of the
/// link's bounding sphere, [`RobotModel::link_bounding_spheres`]); each step up the tree adds
/// the joint origin's offset (and, for a prismatic joint, its longest travel) to that reach,
/// because rotations keep lengths. A prismatic joint moves a point by `|axis| · dq`. Summing
/// over the joints above the link gives `λ`; it holds for every configuration because every
/// term is a length the joint values cannot change.
///
/// ```
/// let panda = mit_star_robot::ArmProblem::panda()?;
/// let levers = mit_star_robot::LeverArms::new(&panda);
/// let hand = panda.link_index("panda_hand").unwrap();
/// // The hand hangs off all seven joints; the base moves with none.
/// assert!((0..7).all(|j| levers.lever(hand, j) > 0.0));
/// assert!((0..7).all(|j| levers.lever(0, j) == 0.0));
/// // No point of the Panda is more than about 1.3 m from the first joint's axis.
/// assert!(levers.lever(hand, 0) < 1.5);
/// # Ok::<(), mit_star_robot::ArmError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct LeverArms {
    dimension: usize,
    /// `λ[link · dimension + j]`.
    levers: Vec<f64>,
}

impl LeverArms {
    /// The lever arms of every link of `robot` about every joint coordinate.
    pub fn new(robot: &RobotModel) -> Self {
        let links = robot.links();
        let dimension = robot.joint_names().len();
        let space = robot.joint_space();
        let travel = |c: usize| space.lower()[c].abs().max(space.upper()[c].abs());
        let mut levers = vec![0.0; links.len() * dimension];
        for (link, bound) in robot.link_bounding_spheres().iter().enumerate() {
            let Some((center, radius)) = bound else {
                continue;
            };
            let row = &mut levers[link * dimension..(link + 1) * dimension];
            // Distance bound from the current frame's origin to any point of the spheres.
            let mut reach = center.length() + radius;
            let mut at = Some(link);
            while let Some(a) = at {
                let frame = &links[a];
                match frame.motion {
                    Motion::Fixed => {}
                    Motion::Revolute { coordinate, .. } => row[coordinate] += reach,
                    Motion::Prismatic { axis, coordinate } => {
                        row[coordinate] += axis.length();
                        reach += axis.length() * travel(coordinate);
                    }
                }
                reach += frame.origin.translation.length();
                at = frame.parent;
            }
        }
        // Rounded up: the bound must hold for the computed values too.
        for lever in &mut levers {
            *lever *= 1.0 + 1e-9;
        }
        Self { dimension, levers }
    }

    /// The bound for `link` and joint coordinate `coordinate` (metres per radian, or per metre
    /// for a prismatic joint); 0 for a link the coordinate does not move or without spheres.
    #[inline]
    pub fn lever(&self, link: usize, coordinate: usize) -> f64 {
        self.levers[link * self.dimension + coordinate]
    }

    /// How far any sphere of `link` can move along the motion whose joint displacements are
    /// `|delta|`: `Σ_j λ[link][j] · |delta_j|`.
    #[inline]
    pub fn sweep(&self, link: usize, delta: &[f64]) -> f64 {
        self.levers[link * self.dimension..(link + 1) * self.dimension]
            .iter()
            .zip(delta)
            .map(|(l, d)| l * d.abs())
            .sum()
    }

    /// The fastest any sphere can move per unit of joint-space distance (Euclidean metric):
    /// the largest `‖λ[link]‖₂` (by Cauchy–Schwarz, `Σ_j λ_j |Δq_j| ≤ ‖λ‖₂ ‖Δq‖₂`).
    pub fn fastest(&self) -> f64 {
        self.levers
            .chunks_exact(self.dimension.max(1))
            .map(|row| row.iter().map(|l| l * l).sum::<f64>().sqrt())
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use glam::{DAffine3, DVec3};

    use super::*;
    use crate::Kinematics;

    /// Finite differences never exceed the bound: the bound holds at random configurations.
    #[test]
    fn finite_differences_stay_under_the_bound() {
        let panda = crate::ArmProblem::panda().unwrap();
        let levers = LeverArms::new(&panda);
        let fk = Kinematics::new(&panda);
        let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
        let mut here = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
        let mut there = here.clone();
        let space = panda.joint_space();
        let h = 1e-6;
        let mut worst: f64 = 0.0;
        for k in 0..500_u32 {
            let q: Vec<f64> = (0..7)
                .map(|j| {
                    let u = (f64::from(k * 7 + j) * 0.618_034).fract();
                    space.lower()[j as usize]
                        + u * (space.upper()[j as usize] - space.lower()[j as usize])
                })
                .collect();
            fk.sphere_centers_f64(&q, &mut links, &mut here);
            for j in 0..7 {
                let mut moved = q.clone();
                moved[j] += h;
                fk.sphere_centers_f64(&moved, &mut links, &mut there);
                for (s, sphere) in panda.spheres().iter().enumerate() {
                    let speed = here[s].0.distance(there[s].0) / h;
                    let bound = levers.lever(sphere.link, j);
                    assert!(
                        speed <= bound + 1e-6,
                        "sphere {s} joint {j}: {speed} > {bound}"
                    );
                    worst = worst.max(speed / bound.max(1e-12));
                }
            }
        }
        // Not absurdly loose either: some sphere reaches at least a third of its bound.
        assert!(worst > 0.33, "{worst}");
        assert!(
            levers.fastest() > 1.0 && levers.fastest() < 4.0,
            "{}",
            levers.fastest()
        );
    }
}
