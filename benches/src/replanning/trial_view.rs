//! [`write_trial_view`]: the 3-D view of one re-planning trial — the arm's motion over
//! simulated time among the fixed obstacles and the moving ones where they were.

use std::path::Path;

use mit_star_robot::{ArmChecker, ArmProblem, Scene};
use mit_star_validity::StateValidity;
use mit_star_view::{ShapeView, SolidView};

use crate::error::HarnessError;
use crate::pictures::arm_view::{ArmView, add_meshes};
use crate::pictures::view_frames::ViewFrames;
use crate::replanning::{ReplanningSetup, TrialRecord};

/// At most this many frames of a trial are computed (evenly chosen among the configurations
/// it passed through); the page may thin them further.
const TRIAL_FRAMES: usize = 2000;

/// Writes the view of `record`, a trial in `setup`, to `page`: the arm's motion with its
/// simulated times, the moving obstacles where they were at each frame, the configurations
/// that touch an obstacle at their moment marked red, ghosts where a plan was adopted.
///
/// # Errors
/// [`HarnessError::Arm`] if the setup's arm problem cannot be made; [`HarnessError::View`] if
/// the page cannot be written.
pub fn write_trial_view(
    setup: &ReplanningSetup,
    record: &TrialRecord,
    page: &Path,
) -> Result<(), HarnessError> {
    let mut fixed = Scene::new(setup.scene.fixed().to_vec());
    for cloud in setup.scene.clouds() {
        fixed.add_shared_cloud(cloud.clone());
    }
    let arm = ArmProblem::new(
        setup.name,
        setup.robot.clone(),
        fixed,
        setup.start.clone(),
        setup.goal.clone(),
    )
    .map_err(|source| HarnessError::Arm {
        name: setup.name.to_owned(),
        source,
    })?;
    let view = ArmView::new(&arm, None);
    let mut document = view.document(format!(
        "{} · {} · trial {}",
        record.planner, setup.name, record.trial
    ));
    if let Some(shipped) = mit_star_robot::ShippedRobot::find(setup.robot.name()) {
        add_meshes(&mut document, &setup.robot, &shipped.mesh_resolver());
    }
    document.subtitle.push(format!(
        "{} at {:.2} s simulated; {} plans ({} without a path, {} adopted), {} stops",
        record.end.label(),
        record.time,
        record.plans,
        record.failed_plans,
        record.adopted,
        record.dropped
    ));
    let stride = record.trajectory.len().div_ceil(TRIAL_FRAMES).max(1);
    let mut chosen: Vec<&(f64, Vec<f64>)> = record.trajectory.iter().step_by(stride).collect();
    if let (Some(last), Some(kept)) = (record.trajectory.last(), chosen.last())
        && !std::ptr::eq(last, *kept)
    {
        chosen.push(last);
    }
    let times: Vec<f64> = chosen.iter().map(|(t, _)| *t).collect();
    let adopted: Vec<usize> = record
        .plan_times
        .iter()
        .filter(|(_, found)| *found)
        .map(|(t, _)| {
            times
                .partition_point(|&s| s < *t)
                .min(times.len().saturating_sub(1))
        })
        .collect();
    let mut waypoints = adopted;
    waypoints.dedup();
    let frames = ViewFrames {
        states: chosen.iter().map(|(_, q)| q.clone()).collect(),
        waypoints,
        times: Some(times.clone()),
    };
    let colliding = frames
        .states
        .iter()
        .zip(&times)
        .enumerate()
        .filter(|(_, (q, t))| !ArmChecker::new(&setup.robot, &setup.scene.at(**t)).is_valid(q))
        .map(|(i, _)| i)
        .collect();
    let mut motion = view.motion_marked("the arm's motion", &frames, colliding);
    let moving = setup.scene.moving();
    document.scene.movers = moving
        .iter()
        .map(|m| SolidView {
            name: m.id().to_owned(),
            shape: ShapeView::Cuboid {
                half_extents: m.half_extents().as_vec3().to_array(),
            },
            position: m.center_at(0.0).as_vec3().to_array(),
            rotation: [0.0, 0.0, 0.0, 1.0],
        })
        .collect();
    motion.mover_positions = times
        .iter()
        .flat_map(|&t| {
            moving
                .iter()
                .flat_map(move |m| m.center_at(t).as_vec3().to_array())
        })
        .collect();
    document.motions.push(motion);
    document
        .write_html(page, mit_star_view::ViewLimits::default())
        .map(|_| ())
        .map_err(|source| HarnessError::View {
            path: page.to_path_buf(),
            source,
        })
}
