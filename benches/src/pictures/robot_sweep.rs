//! [`write_robot_sweep`]: the 3-D view of a robot on its own — each joint swept through its
//! range in turn, spheres and meshes, its self-collisions in red (`mit-star robots ROBOT
//! --view FILE.html`): how a user checks a robot they bring before planning with it.

use std::path::Path;

use mit_star_robot::{ArmProblem, MeshResolver, RobotModel, Scene};
use mit_star_spaces::JointKind;

use crate::error::HarnessError;
use crate::pictures::arm_view::{ArmView, add_meshes};

/// The rest configuration the sweep starts from: every joint at 0, clamped into its limits.
pub(crate) fn rest_configuration(robot: &RobotModel) -> Vec<f64> {
    robot
        .joint_space()
        .joints()
        .iter()
        .map(|j| match j.kind {
            JointKind::Revolute { lower, upper } | JointKind::Prismatic { lower, upper } => {
                0.0_f64.clamp(lower, upper)
            }
            JointKind::Continuous => 0.0,
        })
        .collect()
}

/// The sweep: from the rest configuration, each joint in coordinate order to its lower limit,
/// its upper limit (a continuous joint half a turn each way) and back.
pub(crate) fn sweep(robot: &RobotModel) -> Vec<Vec<f64>> {
    let rest = rest_configuration(robot);
    let mut path = vec![rest.clone()];
    for (i, joint) in robot.joint_space().joints().iter().enumerate() {
        let (lower, upper) = match joint.kind {
            JointKind::Revolute { lower, upper } | JointKind::Prismatic { lower, upper } => {
                (lower, upper)
            }
            JointKind::Continuous => (-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2),
        };
        for value in [lower, upper] {
            let mut q = rest.clone();
            q[i] = value;
            path.push(q);
        }
        path.push(rest.clone());
    }
    path
}

/// Writes the view of `robot` (called `label`) to `page`, its meshes found by `resolver`; the
/// page's size in bytes.
///
/// # Errors
/// [`HarnessError::Arm`] if the robot's rest configuration is refused; [`HarnessError::View`]
/// if the page cannot be written.
pub(crate) fn write_robot_sweep(
    robot: &RobotModel,
    label: &str,
    resolver: &MeshResolver,
    page: &Path,
) -> Result<u64, HarnessError> {
    let rest = rest_configuration(robot);
    let arm = ArmProblem::new(
        label,
        robot.clone(),
        Scene::new(Vec::new()),
        rest.clone(),
        rest,
    )
    .map_err(|source| HarnessError::Arm {
        name: label.to_owned(),
        source,
    })?;
    let view = ArmView::new(&arm, None);
    let mut document = view.document(format!("{label} (robot `{}`)", robot.name()));
    add_meshes(&mut document, robot, resolver);
    let meshes: usize = document
        .robot
        .as_ref()
        .map_or(0, |r| r.links.iter().map(|l| l.meshes.len()).sum());
    document.subtitle.push(format!(
        "{} joints, {} spheres on {} links, {meshes} visual meshes; each joint swept through its \
         range in coordinate order, the others at 0 (clamped into their limits); self-collisions \
         of the sphere model in red",
        robot.joint_names().len(),
        robot.spheres().len(),
        robot.links().len(),
    ));
    let motion = view.path_motion("each joint through its range", &sweep(robot));
    document.motions.push(motion);
    document
        .write_html(page, mit_star_view::ViewLimits::default())
        .map_err(|source| HarnessError::View {
            path: page.to_path_buf(),
            source,
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sweep_visits_every_limit_and_returns() {
        let robot = mit_star_robot::ShippedRobot::find("panda")
            .unwrap()
            .model(false)
            .unwrap();
        let path = sweep(&robot);
        let rest = rest_configuration(&robot);
        assert_eq!(path.len(), 1 + 3 * 7);
        assert_eq!(path.last(), Some(&rest));
        assert!(mit_star_spaces::StateSpace::check_state(robot.joint_space(), &rest).is_ok());
        for (i, joint) in robot.joint_space().joints().iter().enumerate() {
            if let JointKind::Revolute { lower, upper } = joint.kind {
                assert_eq!(path[1 + 3 * i][i], lower);
                assert_eq!(path[2 + 3 * i][i], upper);
            }
        }
        let page = std::env::temp_dir().join(format!("sweep-{}.html", std::process::id()));
        let resolver = mit_star_robot::ShippedRobot::find("panda")
            .unwrap()
            .mesh_resolver();
        let bytes = write_robot_sweep(&robot, "panda", &resolver, &page).unwrap();
        assert!(bytes > 100_000);
        std::fs::remove_file(page).unwrap();
    }
}
