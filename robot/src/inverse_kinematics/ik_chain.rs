//! [`IkChain`]: the links from the root to the solver's link, their forward kinematics
//! (`Kinematics::link_pose_f64` one link at a time) and the analytic geometric Jacobian of
//! the solver's frame.

use glam::{DAffine3, DVec3};

use crate::{Kinematics, Motion, RobotModel};

/// A joint on the chain that moves the frame: the link it moves, its axis in that link's
/// frame (a mimic joint's multiplier folded in), and the coordinate driving it.
#[derive(Debug, Clone, Copy, PartialEq)]
struct ChainJoint {
    link: usize,
    axis: DVec3,
    coordinate: usize,
    prismatic: bool,
}

/// The kinematic chain of one link.
///
/// Only the link's ancestors are walked: other branches (the other arm of a Baxter, a
/// gripper's fingers) cost nothing. Several links driven by one coordinate (mimic joints)
/// add up in that coordinate's Jacobian column; coordinates not on the chain have zero
/// columns.
#[derive(Debug, Clone)]
pub(crate) struct IkChain {
    kinematics: Kinematics,
    /// The link's ancestors and the link itself, root first.
    links: Vec<usize>,
    joints: Vec<ChainJoint>,
    link: usize,
}

impl IkChain {
    /// The chain from the root of `robot` to `link` (an index of `robot.links()`).
    pub(crate) fn new(robot: &RobotModel, link: usize) -> Self {
        let frames = robot.links();
        let mut links = vec![link];
        while let Some(parent) = frames[*links.last().unwrap_or(&0)].parent {
            links.push(parent);
        }
        links.reverse();
        let joints = links
            .iter()
            .filter_map(|&l| match frames[l].motion {
                Motion::Fixed => None,
                Motion::Revolute { axis, coordinate } => Some(ChainJoint {
                    link: l,
                    axis,
                    coordinate,
                    prismatic: false,
                }),
                Motion::Prismatic { axis, coordinate } => Some(ChainJoint {
                    link: l,
                    axis,
                    coordinate,
                    prismatic: true,
                }),
            })
            .collect();
        Self {
            kinematics: Kinematics::new(robot),
            links,
            joints,
            link,
        }
    }

    /// Whether some coordinate moves the link.
    pub(crate) fn moves(&self) -> bool {
        !self.joints.is_empty()
    }

    /// The number of pose slots [`pose`](Self::pose) needs (every link of the model).
    pub(crate) fn link_count(&self) -> usize {
        self.kinematics.link_count()
    }

    /// The world pose of the link for `q`; the chain's link poses are left in `poses` for
    /// [`jacobian`](Self::jacobian).
    #[inline]
    pub(crate) fn pose(&self, q: &[f64], poses: &mut [DAffine3]) -> DAffine3 {
        for &l in &self.links {
            self.kinematics.link_pose_f64(q, l, poses);
        }
        poses[self.link]
    }

    /// The geometric Jacobian at the point `point` (world frame) for the chain poses in
    /// `poses` (left by [`pose`](Self::pose)): per coordinate, the linear and angular
    /// velocity of a frame attached to the link at `point` per unit of the coordinate.
    /// `columns` has one entry per coordinate.
    #[inline]
    pub(crate) fn jacobian(
        &self,
        poses: &[DAffine3],
        point: DVec3,
        columns: &mut [(DVec3, DVec3)],
    ) {
        columns.fill((DVec3::ZERO, DVec3::ZERO));
        for joint in &self.joints {
            let frame = &poses[joint.link];
            // The axis is the same before and after the joint's own motion.
            let axis = frame.matrix3 * joint.axis;
            let column = &mut columns[joint.coordinate];
            if joint.prismatic {
                column.0 += axis;
            } else {
                column.0 += axis.cross(point - frame.translation);
                column.1 += axis;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Jacobian against central differences of the forward kinematics, on a robot with
    /// a prismatic joint and a mimic joint.
    #[test]
    fn the_jacobian_matches_finite_differences() {
        let urdf = r#"<robot name="r">
          <link name="a"/><link name="b"/><link name="c"/><link name="d"/><link name="e"/>
          <joint name="j1" type="revolute"><parent link="a"/><child link="b"/>
            <origin xyz="0 0 0.3" rpy="0.1 0 0"/><axis xyz="0 0 1"/>
            <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
          <joint name="j2" type="prismatic"><parent link="b"/><child link="c"/>
            <origin xyz="0.2 0 0" rpy="0 0.4 0"/><axis xyz="1 1 0"/>
            <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
          <joint name="j3" type="revolute"><parent link="c"/><child link="d"/>
            <origin xyz="0 0.1 0.2"/><axis xyz="0 1 0"/>
            <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
          <joint name="j4" type="revolute"><parent link="d"/><child link="e"/>
            <origin xyz="0.3 0 0"/><axis xyz="1 0 0"/>
            <mimic joint="j1" multiplier="-1" offset="0.2"/>
            <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
        </robot>"#;
        let robot = RobotModel::from_urdf_str(urdf).unwrap();
        let tip = robot.link_index("e").unwrap();
        let chain = IkChain::new(&robot, tip);
        assert!(chain.moves());
        let mut poses = vec![DAffine3::IDENTITY; chain.link_count()];
        let q = [0.4, 0.3, -0.7];
        let offset = DVec3::new(0.1, -0.05, 0.2);
        let pose = chain.pose(&q, &mut poses);
        let mut columns = vec![(DVec3::ZERO, DVec3::ZERO); 3];
        chain.jacobian(&poses, pose.transform_point3(offset), &mut columns);
        let h = 1e-6;
        for c in 0..3 {
            let (mut plus, mut minus) = (q, q);
            plus[c] += h;
            minus[c] -= h;
            let a = chain.pose(&plus, &mut poses);
            let b = chain.pose(&minus, &mut poses);
            let linear = (a.transform_point3(offset) - b.transform_point3(offset)) / (2.0 * h);
            let turn = glam::DQuat::from_mat3(&(a.matrix3 * b.matrix3.transpose()));
            let angular =
                crate::inverse_kinematics::orientation_tolerance::rotation_vector(turn) / (2.0 * h);
            assert!(
                (linear - columns[c].0).length() < 1e-6,
                "{c}: {linear} {:?}",
                columns[c]
            );
            assert!(
                (angular - columns[c].1).length() < 1e-6,
                "{c}: {angular} {:?}",
                columns[c]
            );
        }
    }
}
