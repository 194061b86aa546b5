//! [`CloudArgs`]: the options that put point clouds into an arm problem's scene (`plan`,
//! `check-state`, `check-path`).

use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::Args;
use glam::Vec3;
use problems::PlanningProblem;
use robot::{ArmProblem, CloudObstacle, FilterReport, PlyEncoding, PointCloud, SensorPose};

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
    /// (VAMP's benchmark protocol, default 10 000; seeded by the problem's index).
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
    /// another tool or to plan with it again (`--cloud FILE`).
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

    /// `arm` with the cloud these options make added to its scene (its primitives replaced
    /// by it with `--scene-as-cloud`), and one line per step saying what it did and how long
    /// it took. `seed` seeds the sampling on the primitives.
    ///
    /// # Errors
    /// Filter or sensor options without a cloud ([`HarnessError::Usage`]); unreadable cloud
    /// files and bad filter values ([`HarnessError::CloudInput`]); a cloud left empty or too
    /// large, or a bad radius ([`HarnessError::Cloud`]).
    pub fn apply(
        &self,
        arm: &ArmProblem,
        seed: u64,
    ) -> Result<(ArmProblem, Vec<String>), HarnessError> {
        let given = !self.cloud.is_empty() || !self.points.is_empty();
        if !given && self.scene_as_cloud.is_none() {
            return Err(HarnessError::Usage(
                "the cloud options filter a cloud: give --cloud FILE or --scene-as-cloud".into(),
            ));
        }
        if self.sensor_pose.is_some() && !given {
            return Err(HarnessError::Usage(
                "--sensor-pose moves the --cloud files; there are none".into(),
            ));
        }
        let mut lines = Vec::new();
        let mut points: Vec<Vec3> = Vec::new();
        let pose = self.sensor_pose.as_deref().map(parse_pose).transpose()?;
        for path in &self.cloud {
            let start = Instant::now();
            let read = robot::read_cloud(path)?;
            let mut cloud = read.points;
            if let Some(pose) = &pose {
                pose.apply(&mut cloud);
            }
            let dropped = match read.dropped_non_finite {
                0 => String::new(),
                n => format!(" ({n} NaN or infinite points dropped)"),
            };
            lines.push(format!(
                "{} points read from `{}`{dropped}{} in {}",
                cloud.len(),
                path.display(),
                if pose.is_some() {
                    ", moved by the sensor pose,"
                } else {
                    ""
                },
                millis(start.elapsed())
            ));
            points.extend_from_slice(&cloud);
        }
        if !self.points.is_empty() {
            let mut given = self.points.clone();
            if let Some(pose) = &pose {
                pose.apply(&mut given);
            }
            lines.push(format!("{} points given", given.len()));
            points.extend_from_slice(&given);
        }
        let primitives = arm.scene().obstacles();
        if let Some(per) = self.scene_as_cloud {
            let start = Instant::now();
            let sampled = robot::sample_surfaces(primitives, per, seed)?;
            lines.push(format!(
                "{} points sampled on the scene's {} primitives ({per} each, seed {seed}) in {}",
                sampled.len(),
                primitives.len(),
                millis(start.elapsed())
            ));
            points.extend_from_slice(&sampled.points);
        }
        if self.crop_reach {
            // Widened by the points' radius and a centimetre (far more than the checker's
            // margin): no point removed could ever touch a sphere.
            let (center, reach) = robot::reach_ball(arm.robot());
            let point_radius = self.point_radius.unwrap_or(PointCloud::DEFAULT_RADIUS);
            let radius = reach + point_radius.max(0.0) + 0.01;
            let report = robot::crop_to_ball(&mut points, center, radius)?;
            lines.push(step(
                &format!("crop to the robot's reach ({radius:.3} m around its base)"),
                &report,
            ));
        }
        if let Some(padding) = self.remove_robot {
            let report =
                robot::remove_robot_points(&mut points, arm.robot(), arm.start(), padding)?;
            lines.push(step(
                &format!("the robot's own points at the start ({padding} m padding)"),
                &report,
            ));
        }
        if let Some(size) = self.voxel {
            let report = robot::voxel_downsample(&mut points, size)?;
            lines.push(step(&format!("one point per {size} m voxel"), &report));
        }
        if let Some(radius) = self.min_distance {
            let report = robot::min_distance_downsample(&mut points, radius)?;
            lines.push(step(&format!("points at least {radius} m apart"), &report));
        }
        let name = "cloud";
        let cloud = PointCloud::new(points)
            .and_then(|c| match self.point_radius {
                Some(r) => c.with_radius(r),
                None => Ok(c),
            })
            .map_err(|source| HarnessError::Cloud {
                name: name.into(),
                source,
            })?;
        if let Some(path) = &self.save_cloud {
            let start = Instant::now();
            match path.extension().and_then(|e| e.to_str()) {
                Some("npy") => robot::write_npy(path, cloud.points())?,
                Some("ply") => {
                    robot::write_ply(path, cloud.points(), PlyEncoding::BinaryLittleEndian)?;
                }
                _ => {
                    return Err(HarnessError::Usage(format!(
                        "--save-cloud `{}`: give a .ply or .npy file",
                        path.display()
                    )));
                }
            }
            lines.push(format!(
                "{} points written to `{}` in {}",
                cloud.len(),
                path.display(),
                millis(start.elapsed())
            ));
        }
        let (count, radius) = (cloud.len(), cloud.radius());
        let start = Instant::now();
        let obstacle = CloudObstacle::new(name, cloud);
        lines.push(format!(
            "tree of {count} points of radius {:.1} mm built in {}",
            radius * 1e3,
            millis(start.elapsed())
        ));
        let scene = if self.scene_as_cloud.is_some() || self.drop_primitives {
            arm.scene().clone().without_primitives()
        } else {
            arm.scene().clone()
        };
        Ok((arm.clone().with_scene(scene.with_cloud(obstacle)), lines))
    }
}

/// `x,y,z,roll,pitch,yaw` as a sensor pose.
fn parse_pose(text: &str) -> Result<SensorPose, HarnessError> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| pose_usage(text))?;
    let [x, y, z, roll, pitch, yaw] = values[..] else {
        return Err(pose_usage(text));
    };
    Ok(SensorPose::from_xyz_rpy([x, y, z], [roll, pitch, yaw])?)
}

fn pose_usage(text: &str) -> HarnessError {
    HarnessError::Usage(format!(
        "--sensor-pose `{}`: give six numbers x,y,z,roll,pitch,yaw",
        problems::excerpt(text, 80)
    ))
}

fn step(what: &str, report: &FilterReport) -> String {
    format!(
        "{what}: {} of {} points kept in {}",
        report.after,
        report.before,
        millis(report.elapsed)
    )
}

fn millis(d: Duration) -> String {
    format!("{:.2} ms", d.as_secs_f64() * 1e3)
}
