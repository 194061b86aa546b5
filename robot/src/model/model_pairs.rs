//! Self-collision pairs the sphere model itself rules out, as MoveIt's setup assistant does:
//! adjacent links, and pairs in collision in every configuration tried.

use glam::{DAffine3, DVec3};
use mit_star_spaces::JointKind;

use crate::{Kinematics, ModelWarning, RobotModel};

impl RobotModel {
    /// The checked [self-collision pairs](Self::self_collision_pairs) whose spheres overlap
    /// at configuration `q` (exact `f64` sphere tests): what makes `q` self-colliding.
    ///
    /// # Panics
    /// If `q` is shorter than the robot's dimension (a caller's bug).
    pub fn colliding_link_pairs(&self, q: &[f64]) -> Vec<(usize, usize)> {
        let fk = Kinematics::new(self);
        let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
        let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
        fk.sphere_centers_f64(q, &mut links, &mut centers);
        self.pairs
            .iter()
            .copied()
            .filter(|&(a, b)| {
                let (mut ra, rb) = (self.link_sphere_range(a), self.link_sphere_range(b));
                ra.any(|i| {
                    rb.clone().any(|j| {
                        let ((ci, ri), (cj, rj)) = (centers[i], centers[j]);
                        ci.distance(cj) < ri + rj
                    })
                })
            })
            .collect()
    }

    /// The default configuration, as MoveIt's: every joint at 0, or at the middle of its
    /// limits when 0 is outside them.
    pub fn default_configuration(&self) -> Vec<f64> {
        self.joint_space()
            .joints()
            .iter()
            .map(|j| crate::model::model_joint::default_value(&j.kind))
            .collect()
    }

    /// The adjacent link pairs among links with spheres, `i < j`: pairs the sphere model
    /// cannot check meaningfully because the links are joined as by one joint. Two links with
    /// spheres are adjacent if every link strictly between them on the tree path has no
    /// spheres, and
    /// - one is an ancestor of the other (a serial chain: MoveIt's setup assistant collapses a
    ///   geometry-less wrist the same way), or
    /// - at most one moving joint lies on the path (siblings on a fixed mount, say).
    ///
    /// Links in two branches with two or more moving joints between them (the shoulders of
    /// two arms on geometry-less bases) are not adjacent: their pair stays checked unless the
    /// SRDF disables it. A joint moves if it is a coordinate or follows one (a mimic joint);
    /// held joints count as fixed.
    pub fn adjacent_link_pairs(&self) -> Vec<(usize, usize)> {
        let links = self.links();
        let has_spheres = |l: usize| !self.link_sphere_range(l).is_empty();
        let moving = |l: usize| !matches!(links[l].motion, crate::Motion::Fixed);
        let mut children = vec![Vec::new(); links.len()];
        for (c, link) in links.iter().enumerate() {
            if let Some(p) = link.parent {
                children[p].push(c);
            }
        }
        let mut pairs = Vec::new();
        for a in (0..links.len()).filter(|&l| has_spheres(l)) {
            // Up from `a` through links without spheres: each ancestor reached is adjacent
            // (a serial chain); from each, down into the other branches.
            let (mut below, mut joints) = (a, usize::from(moving(a)));
            while let Some(up) = links[below].parent {
                if has_spheres(up) {
                    pairs.push((up.min(a), up.max(a)));
                    break;
                }
                // Down from `up` into its other children, through links without spheres,
                // while at most one moving joint lies on the path.
                let mut stack: Vec<(usize, usize)> = children[up]
                    .iter()
                    .filter(|&&c| c != below)
                    .map(|&c| (c, joints + usize::from(moving(c))))
                    .collect();
                while let Some((l, count)) = stack.pop() {
                    if count > 1 {
                        continue;
                    }
                    if has_spheres(l) {
                        pairs.push((l.min(a), l.max(a)));
                        continue;
                    }
                    stack.extend(
                        children[l]
                            .iter()
                            .map(|&c| (c, count + usize::from(moving(c)))),
                    );
                }
                below = up;
                joints += usize::from(moving(up));
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        pairs
    }

    /// The same model without checking the pairs its own geometry rules out, as MoveIt's setup
    /// assistant writes them into an SRDF: [adjacent](Self::adjacent_link_pairs) links, and
    /// pairs [always in collision](Self::always_colliding_link_pairs) (a sphere model's spheres
    /// can overlap where the meshes only touch, so an SRDF written for the meshes can leave a
    /// pair that collides everywhere). Each group of pairs disabled here that was still checked
    /// is recorded as a [`ModelWarning::DisabledPairs`] to review.
    ///
    /// ```
    /// let urdf = include_str!("../../data/ur5/ur5_spherized.urdf");
    /// let srdf = include_str!("../../data/ur5/ur5.srdf");
    /// let ur5 = mit_star_robot::RobotModel::from_urdf_str(urdf)?.with_srdf_str(srdf)?;
    /// // The SRDF leaves wrist_2_link/fts_robotside checked; their spheres always overlap.
    /// assert_eq!(ur5.colliding_link_pairs(&ur5.default_configuration()).len(), 1);
    /// let ur5 = ur5.without_model_pairs();
    /// assert!(ur5.colliding_link_pairs(&ur5.default_configuration()).is_empty());
    /// # Ok::<(), mit_star_robot::ModelError>(())
    /// ```
    #[must_use]
    pub fn without_model_pairs(mut self) -> Self {
        let adjacent = self.adjacent_link_pairs();
        self = self.stop_checking(adjacent, "adjacent");
        let always = self.always_colliding_link_pairs();
        self.stop_checking(always, "in collision in every sampled configuration")
    }

    /// The checked pairs in collision at the [default configuration](Self::default_configuration)
    /// and at each of [`ALWAYS_SAMPLES`](Self::ALWAYS_SAMPLES) configurations drawn uniformly
    /// within the joint limits (a fixed seed: the answer does not change from run to run).
    /// Stricter than MoveIt's 95 %: a pair that is ever free is kept.
    pub fn always_colliding_link_pairs(&self) -> Vec<(usize, usize)> {
        let mut pairs = self.colliding_link_pairs(&self.default_configuration());
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut q = vec![0.0; self.joint_names().len()];
        for _ in 0..Self::ALWAYS_SAMPLES {
            if pairs.is_empty() {
                break;
            }
            for (v, joint) in q.iter_mut().zip(self.joint_space().joints()) {
                let u = unit(&mut state);
                *v = match joint.kind {
                    JointKind::Revolute { lower, upper }
                    | JointKind::Prismatic { lower, upper } => lower + u * (upper - lower),
                    JointKind::Continuous => std::f64::consts::PI * (2.0 * u - 1.0),
                };
            }
            let now = self.colliding_link_pairs(&q);
            pairs.retain(|p| now.contains(p));
        }
        pairs
    }

    /// How many random configurations [`always_colliding_link_pairs`](Self::always_colliding_link_pairs) tries.
    pub const ALWAYS_SAMPLES: usize = 1000;

    fn stop_checking(mut self, pairs: Vec<(usize, usize)>, reason: &'static str) -> Self {
        let checked: Vec<(usize, usize)> = pairs
            .into_iter()
            .filter(|p| self.pairs.contains(p))
            .collect();
        if checked.is_empty() {
            return self;
        }
        self.pairs.retain(|p| !checked.contains(p));
        let name = |l: usize| self.links()[l].name.clone();
        let pairs = checked.iter().map(|&(a, b)| (name(a), name(b))).collect();
        self.warnings
            .push(ModelWarning::DisabledPairs { reason, pairs });
        self
    }
}

/// A uniform number in `[0, 1)` from a SplitMix64 stream.
fn unit(state: &mut u64) -> f64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    (z >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_without_spheres_join_their_neighbours() {
        let urdf = include_str!("../../data/ur5/ur5_spherized.urdf");
        let ur5 = RobotModel::from_urdf_str(urdf).unwrap();
        let name = |(a, b): (usize, usize)| {
            let links = ur5.links();
            (links[a].name.as_str(), links[b].name.as_str())
        };
        let adjacent: Vec<_> = ur5.adjacent_link_pairs().into_iter().map(name).collect();
        // Joined by a joint.
        assert!(
            adjacent.contains(&("wrist_1_link", "wrist_2_link")),
            "{adjacent:?}"
        );
        // Through `ee_link`, which has no spheres.
        assert!(
            adjacent.contains(&("wrist_3_link", "fts_robotside")),
            "{adjacent:?}"
        );
        // Two joints apart: not adjacent.
        assert!(
            !adjacent.contains(&("wrist_2_link", "fts_robotside")),
            "{adjacent:?}"
        );
        let without = ur5.clone().without_model_pairs();
        assert!(without.self_collision_pairs().len() < ur5.self_collision_pairs().len());
        assert!(matches!(
            without.warnings(),
            [
                ModelWarning::DisabledPairs {
                    reason: "adjacent",
                    ..
                },
                ..
            ]
        ));
    }

    #[test]
    fn the_default_configuration_is_zero_or_the_middle_of_the_limits() {
        let urdf = include_str!("../../tests/data/two_link.urdf")
            .replace(r#"lower="0.0" upper="0.3""#, r#"lower="0.1" upper="0.3""#);
        let robot = RobotModel::from_urdf_str(&urdf).unwrap();
        let q = robot.default_configuration();
        assert_eq!(q[0], 0.0);
        assert!((q[1] - 0.2).abs() < 1e-12, "{q:?}");
    }
}
