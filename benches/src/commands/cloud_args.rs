//! [`CloudArgs`]: the options that put point clouds into an arm problem's scene (`plan`,
//! `check-state`, `check-path`, `bench`, `replan`).

use std::path::PathBuf;

use clap::Args;
use glam::Vec3;
use mit_star_robot::ArmProblem;

use crate::definition::cloud_spec::CloudSpec;
use crate::definition::cloud_summary::CloudSummary;
use crate::error::HarnessError;

/// The options that make point clouds obstacles of an arm problem. In order: the clouds are
/// read (`--cloud`, moved by `--sensor-pose`) or sampled on the scene's primitives
/// (`--scene-as-cloud`), then cropped to the robot's reach, cleared of the robot's own points
/// at the start, and downsampled (voxels, then minimum distance); each step is timed and
/// reported on stderr.
#[derive(Debug, Default, Args)]
pub struct CloudArgs {
    /// A point cloud obstacle: PLY (ASCII or binary), PCD (ASCII, binary, binary_compressed)
    /// or `.npy` (N×3 floats), in metres, in the robot's base frame unless `--sensor-pose`
    /// says where the sensor is. Repeatable: the files make one cloud.
    #[arg(long, value_name = "FILE")]
    pub cloud: Vec<PathBuf>,
    /// Replace the scene's primitives by a cloud of N points sampled on the surface of each
    /// (VAMP's benchmark protocol, default 10 000; seeded by the problem's index, or by
    /// `bench`'s and `replan`'s `--cloud-seed`).
    #[arg(long, value_name = "N", num_args = 0..=1, default_missing_value = "10000")]
    pub scene_as_cloud: Option<usize>,
    /// The radius of every point, in metres (default 0.0025).
    #[arg(long, value_name = "M", allow_negative_numbers = true)]
    pub point_radius: Option<f64>,
    /// Where the sensor of the `--cloud` files is, in the robot's base frame:
    /// `x,y,z,roll,pitch,yaw` (metres, radians; rotations about fixed x, y, z, as URDF's rpy).
    #[arg(long, value_name = "X,Y,Z,R,P,Y", allow_hyphen_values = true)]
    pub sensor_pose: Option<String>,
    /// Keep the points within the robot's reach (a ball around its base holding every
    /// configuration, widened by the points' radius and 1 cm): what lies beyond can never be
    /// touched.
    #[arg(long)]
    pub crop_reach: bool,
    /// Remove the points within this distance (metres) of the robot's spheres at the
    /// problem's start: the arm as the camera saw it.
    #[arg(long, value_name = "M", allow_negative_numbers = true)]
    pub remove_robot: Option<f64>,
    /// Keep one point per voxel of this size (metres).
    #[arg(long, value_name = "M", allow_negative_numbers = true)]
    pub voxel: Option<f64>,
    /// Keep points at least this far apart (metres; VAMP's benchmark uses 0.02).
    #[arg(long, value_name = "M", allow_negative_numbers = true)]
    pub min_distance: Option<f64>,
    /// Plan among the clouds only: the scene file's primitives are dropped (as with
    /// `--scene-as-cloud`, which samples them first).
    #[arg(long)]
    pub drop_primitives: bool,
    /// Write the cloud as filtered to this file (`.ply`, binary, or `.npy`), to look at it in
    /// another tool or to plan with it again (`--cloud FILE`); one problem's cloud: not for
    /// `bench` and `replan`.
    #[arg(long, value_name = "FILE")]
    pub save_cloud: Option<PathBuf>,
    /// Points given in memory (the Python package's numpy arrays), in the robot's base frame
    /// unless `sensor_pose` is set; they join the files' points.
    #[arg(skip)]
    pub points: Vec<Vec3>,
}

impl CloudArgs {
    /// `true` if any cloud option was given.
    pub fn any(&self) -> bool {
        !self.cloud.is_empty()
            || !self.points.is_empty()
            || self.scene_as_cloud.is_some()
            || self.point_radius.is_some()
            || self.sensor_pose.is_some()
            || self.crop_reach
            || self.remove_robot.is_some()
            || self.voxel.is_some()
            || self.min_distance.is_some()
            || self.drop_primitives
            || self.save_cloud.is_some()
    }

    /// The settings these options give (the points in memory and `--save-cloud` aside), with
    /// the sampling seeded by `seed` when given.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a `--sensor-pose` that is not six numbers.
    pub fn spec(&self, seed: Option<u64>) -> Result<CloudSpec, HarnessError> {
        Ok(CloudSpec {
            files: self.cloud.clone(),
            sensor_pose: self.sensor_pose.as_deref().map(parse_pose).transpose()?,
            scene_as_cloud: self.scene_as_cloud,
            seed,
            point_radius: self.point_radius,
            crop_reach: self.crop_reach,
            remove_robot: self.remove_robot,
            voxel: self.voxel,
            min_distance: self.min_distance,
            drop_primitives: self.drop_primitives,
            contents: Vec::new(),
        })
    }

    /// `arm` with the cloud these options make added to its scene (its primitives replaced
    /// by it with `--scene-as-cloud`), and what each step did and how long it took. `index`
    /// (the problem's) seeds the sampling on the primitives; `problem` names it in errors.
    ///
    /// # Errors
    /// As [`CloudSpec::prepare`]; a `--sensor-pose` that is not six numbers.
    pub fn apply(
        &self,
        arm: &ArmProblem,
        index: u64,
        problem: &str,
    ) -> Result<(ArmProblem, CloudSummary), HarnessError> {
        self.spec(None)?.prepare(
            arm,
            index,
            &self.points,
            problem,
            self.save_cloud.as_deref(),
        )
    }
}

/// `x,y,z,roll,pitch,yaw` as six numbers.
fn parse_pose(text: &str) -> Result<[f64; 6], HarnessError> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| pose_usage(text))?;
    <[f64; 6]>::try_from(values).map_err(|_| pose_usage(text))
}

fn pose_usage(text: &str) -> HarnessError {
    HarnessError::Usage(format!(
        "--sensor-pose `{}`: give six numbers x,y,z,roll,pitch,yaw",
        mit_star_problems::excerpt(text, 80)
    ))
}
