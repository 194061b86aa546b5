//! [`CloudSpec`]: the point cloud of an arm problem as settings — an experiment file's
//! `cloud` table, the cloud options of `bench`, `plan` and `replan` ([`CloudOption`]) — and
//! its preparation into the problem's scene, each step timed ([`CloudSummary`]).

use std::path::{Path, PathBuf};
use std::time::Instant;

use glam::Vec3;
use mit_star_problems::PlanningProblem;
use mit_star_robot::{
    ArmProblem, CloudObstacle, FilterReport, PlyEncoding, PointCloud, SensorPose,
};
use serde::{Deserialize, Serialize};

use crate::definition::cloud_option::CloudOption;
use crate::definition::cloud_summary::{CloudSummary, millis};
use crate::definition::file_contents::FileContents;
use crate::error::HarnessError;

/// The point cloud settings of an arm problem: where the points come from, then the filters,
/// in this order — the files are read (and moved by the sensor pose) or the scene's
/// primitives sampled, then the points are cropped to the robot's reach, cleared of the
/// robot's own at the start, and downsampled (voxels, then minimum distance). Every step is
/// optional but a source. As an experiment file's `cloud` table:
///
/// ```toml
/// [problems.cloud]
/// files = ["scan.ply"]              # PLY, PCD or .npy, relative to the experiment file
/// sensor_pose = [0.9, 0, 0.6, 0, 0.5, 3.14]  # x, y, z, roll, pitch, yaw of the sensor
/// scene_as_cloud = 10000            # or: N points sampled on each primitive, replacing them
/// seed = 7                          # of that sampling (default: the problem's index)
/// point_radius = 0.0025             # metres (the default)
/// crop_reach = true
/// remove_robot = 0.02               # padding, metres, at the problem's start
/// voxel = 0.01
/// min_distance = 0.02
/// drop_primitives = true            # plan among the cloud only
/// ```
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CloudSpec {
    /// Cloud files (PLY, PCD, `.npy`), in metres, together one cloud.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub files: Vec<PathBuf>,
    /// Where the files' sensor is in the robot's base frame: x, y, z, roll, pitch, yaw.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensor_pose: Option<[f64; 6]>,
    /// Replace the primitives by this many points sampled on the surface of each.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scene_as_cloud: Option<usize>,
    /// The sampling's seed (default: the problem's index in its folder).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// The radius of every point, metres (default 0.0025).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point_radius: Option<f64>,
    /// Keep only the points within the robot's reach.
    #[serde(default, skip_serializing_if = "is_false")]
    pub crop_reach: bool,
    /// Remove the points within this padding (metres) of the robot at the problem's start.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub remove_robot: Option<f64>,
    /// Keep one point per voxel of this size (metres).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub voxel: Option<f64>,
    /// Keep points at least this far apart (metres).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_distance: Option<f64>,
    /// Plan among the cloud only: the scene's primitives are dropped.
    #[serde(default, skip_serializing_if = "is_false")]
    pub drop_primitives: bool,
    /// What each of `files` held, in order (`"<length> bytes, crc32 <hex>"`,
    /// [`FileContents`]): `bench` records it in the results folder's `experiment.toml`, and a
    /// file that no longer holds it is refused, naming the file, so that a folder is never
    /// resumed with a cloud that changed under the same name. Empty: not checked.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub contents: Vec<String>,
}

fn is_false(b: &bool) -> bool {
    !*b
}

impl CloudSpec {
    /// The cloud files, relative ones taken from `base`.
    #[must_use]
    pub fn relative_to(mut self, base: Option<&Path>) -> Self {
        if let Some(base) = base {
            for f in &mut self.files {
                if f.is_relative() {
                    *f = base.join(&*f);
                }
            }
        }
        self
    }

    /// The first option set (`files` and `scene_as_cloud` first), for messages about the
    /// settings as a whole.
    pub fn first_option(&self) -> CloudOption {
        if !self.files.is_empty() {
            CloudOption::Files
        } else if self.scene_as_cloud.is_some() {
            CloudOption::SceneAsCloud
        } else {
            self.first_filter()
        }
    }

    /// The first option set, for messages about options that need a source.
    fn first_filter(&self) -> CloudOption {
        [
            (self.sensor_pose.is_some(), CloudOption::SensorPose),
            (self.seed.is_some(), CloudOption::Seed),
            (self.point_radius.is_some(), CloudOption::PointRadius),
            (self.crop_reach, CloudOption::CropReach),
            (self.remove_robot.is_some(), CloudOption::RemoveRobot),
            (self.voxel.is_some(), CloudOption::Voxel),
            (self.min_distance.is_some(), CloudOption::MinDistance),
            (self.drop_primitives, CloudOption::DropPrimitives),
        ]
        .into_iter()
        .find_map(|(set, option)| set.then_some(option))
        .unwrap_or(CloudOption::Files)
    }

    /// Checks what can be checked without reading the files: a source is given (`files`,
    /// points in memory when `has_points`, or `scene_as_cloud`), the sensor pose has files to
    /// move and is finite, the seed has a sampling to seed, and every file exists.
    ///
    /// # Errors
    /// [`HarnessError::CloudOption`] naming `problem` and the option.
    pub fn check(&self, problem: &str, has_points: bool) -> Result<(), HarnessError> {
        let fail = |option: CloudOption, message: String| HarnessError::CloudOption {
            problem: problem.to_owned(),
            option: option.describe(),
            source: Box::new(HarnessError::Usage(message)),
        };
        let given = !self.files.is_empty() || has_points;
        if !given && self.scene_as_cloud.is_none() {
            return Err(fail(
                self.first_filter(),
                "the cloud options filter a cloud: give one (--cloud FILE or --scene-as-cloud; \
                 `files` or `scene_as_cloud` in an experiment's `cloud` table)"
                    .into(),
            ));
        }
        if let Some(p) = self.sensor_pose {
            if !given {
                return Err(fail(
                    CloudOption::SensorPose,
                    "moves the cloud files; there are none".into(),
                ));
            }
            sensor_pose(p).map_err(|e| HarnessError::CloudOption {
                problem: problem.to_owned(),
                option: CloudOption::SensorPose.describe(),
                source: Box::new(e.into()),
            })?;
        }
        match self.seed {
            Some(_) if self.scene_as_cloud.is_none() => {
                return Err(fail(
                    CloudOption::Seed,
                    "seeds the sampling of `scene_as_cloud`, which is not given".into(),
                ));
            }
            Some(s) if i64::try_from(s).is_err() => {
                return Err(fail(
                    CloudOption::Seed,
                    format!("is {s}; give at most {}", i64::MAX),
                ));
            }
            _ => {}
        }
        if let Some(n) = self.scene_as_cloud
            && n > PointCloud::MAX_POINTS
        {
            return Err(fail(
                CloudOption::SceneAsCloud,
                format!(
                    "is {n} points per primitive; a cloud holds at most {}",
                    PointCloud::MAX_POINTS
                ),
            ));
        }
        for file in &self.files {
            match std::fs::metadata(file) {
                Ok(m) if m.is_file() => {}
                Ok(_) => {
                    return Err(fail(
                        CloudOption::Files,
                        format!("`{}` is a folder, not a cloud file", file.display()),
                    ));
                }
                Err(e) => {
                    return Err(fail(
                        CloudOption::Files,
                        format!("`{}` cannot be read: {e}", file.display()),
                    ));
                }
            }
        }
        Ok(())
    }

    /// Checks that every file still holds what `contents` recorded (nothing to check when it
    /// is empty): one entry per file, each equal to the file's [`FileContents`] now.
    ///
    /// # Errors
    /// [`HarnessError::CloudOption`] naming `problem`, `contents` and the file that changed
    /// (what was recorded, what it holds now), or a count that does not match the files.
    pub fn check_contents(&self, problem: &str) -> Result<(), HarnessError> {
        if self.contents.is_empty() {
            return Ok(());
        }
        let fail = |message: String| HarnessError::CloudOption {
            problem: problem.to_owned(),
            option: CloudOption::Contents.describe(),
            source: Box::new(HarnessError::Usage(message)),
        };
        if self.contents.len() != self.files.len() {
            return Err(fail(format!(
                "lists {} entries for {} files",
                self.contents.len(),
                self.files.len()
            )));
        }
        for (file, recorded) in self.files.iter().zip(&self.contents) {
            let now = FileContents::of(file)
                .map_err(|e| fail(format!("`{}` cannot be read: {e}", file.display())))?;
            if now.to_string() != *recorded {
                return Err(fail(format!(
                    "`{}` changed since the experiment was recorded: it held {recorded}, it \
                     holds {now}",
                    file.display()
                )));
            }
        }
        Ok(())
    }

    /// These settings with `contents` recording what every file holds now (a file that
    /// cannot be read is recorded as such, and [`check_contents`](Self::check_contents) then
    /// refuses it).
    #[must_use]
    pub fn with_contents_recorded(mut self) -> Self {
        self.contents = self
            .files
            .iter()
            .map(|f| match FileContents::of(f) {
                Ok(c) => c.to_string(),
                Err(e) => format!("unreadable ({e})"),
            })
            .collect();
        self
    }

    /// `arm` with the cloud these settings make added to its scene (its primitives dropped
    /// with `scene_as_cloud` or `drop_primitives`), and what each step did. `index` is the
    /// problem's index (the sampling's default seed); `given` are points in memory (in the
    /// sensor's frame if a pose is set) joining the files'; `save` writes the cloud as
    /// filtered (`.ply` or `.npy`). Errors name `problem` and the option.
    ///
    /// # Errors
    /// [`HarnessError::CloudOption`]: a setting [`check`](Self::check) refuses, a file that
    /// cannot be read, a filter value refused, a cloud too large, a bad radius;
    /// [`HarnessError::CloudEmptied`]: a step that leaves no point.
    pub fn prepare(
        &self,
        arm: &ArmProblem,
        index: u64,
        given: &[Vec3],
        problem: &str,
        save: Option<&Path>,
    ) -> Result<(ArmProblem, CloudSummary), HarnessError> {
        let started = Instant::now();
        self.check(problem, !given.is_empty())?;
        self.check_contents(problem)?;
        let fail = |option: CloudOption, source: HarnessError| HarnessError::CloudOption {
            problem: problem.to_owned(),
            option: option.describe(),
            source: Box::new(source),
        };
        let emptied = |option: CloudOption, before: usize| HarnessError::CloudEmptied {
            problem: problem.to_owned(),
            option: option.describe(),
            before,
        };
        let pose = self
            .sensor_pose
            .map(sensor_pose)
            .transpose()
            .map_err(|e| fail(CloudOption::SensorPose, e.into()))?;
        let mut steps = Vec::new();
        let mut points: Vec<Vec3> = Vec::new();
        for path in &self.files {
            let start = Instant::now();
            let read =
                mit_star_robot::read_cloud(path).map_err(|e| fail(CloudOption::Files, e.into()))?;
            let (first, count) = (points.len(), read.points.len());
            if points.is_empty() {
                points = read.points;
            } else {
                points.extend_from_slice(&read.points);
            }
            if let Some(pose) = &pose {
                pose.apply(&mut points[first..]);
            }
            let dropped = match read.dropped_non_finite {
                0 => String::new(),
                n => format!(" ({n} NaN or infinite points dropped)"),
            };
            steps.push(format!(
                "{count} points read from `{}`{dropped}{} in {}",
                path.display(),
                if pose.is_some() {
                    ", moved by the sensor pose,"
                } else {
                    ""
                },
                millis(start.elapsed())
            ));
        }
        if !given.is_empty() {
            // Straight into the combined cloud, moved there: the caller's points are not
            // copied twice.
            let first = points.len();
            points.extend_from_slice(given);
            if let Some(pose) = &pose {
                pose.apply(&mut points[first..]);
            }
            steps.push(format!("{} points given", given.len()));
        }
        let primitives = arm.scene().obstacles();
        if let Some(per) = self.scene_as_cloud {
            let start = Instant::now();
            let seed = self.seed.unwrap_or(index);
            let sampled = mit_star_robot::sample_surfaces(primitives, per, seed)
                .map_err(|e| fail(CloudOption::SceneAsCloud, e.into()))?;
            steps.push(format!(
                "{} points sampled on the scene's {} primitives ({per} each, seed {seed}) in {}",
                sampled.len(),
                primitives.len(),
                millis(start.elapsed())
            ));
            if points.is_empty() {
                points = sampled.points;
            } else {
                points.extend_from_slice(&sampled.points);
            }
        }
        let source = if self.files.is_empty() && given.is_empty() {
            CloudOption::SceneAsCloud
        } else if self.files.is_empty() {
            CloudOption::Points
        } else {
            CloudOption::Files
        };
        let input_points = points.len();
        if points.is_empty() {
            return Err(fail(
                source,
                HarnessError::Cloud {
                    name: "cloud".into(),
                    source: mit_star_robot::CloudError::Empty,
                },
            ));
        }
        let point_radius = self.point_radius.unwrap_or(PointCloud::DEFAULT_RADIUS);
        if self.crop_reach {
            // Widened by the points' radius, the problem's collision padding and a centimetre
            // (far more than the checker's margin): no point removed could ever come within
            // the padding of a sphere.
            let (center, reach) = mit_star_robot::reach_ball(arm.robot());
            let radius = reach + point_radius.max(0.0) + arm.padding().metres() + 0.01;
            let report = mit_star_robot::crop_to_ball(&mut points, center, radius)
                .map_err(|e| fail(CloudOption::CropReach, e.into()))?;
            steps.push(step(
                &format!("crop to the robot's reach ({radius:.3} m around its base)"),
                &report,
            ));
            if points.is_empty() {
                return Err(emptied(CloudOption::CropReach, report.before));
            }
        }
        if let Some(padding) = self.remove_robot {
            let report =
                mit_star_robot::remove_robot_points(&mut points, arm.robot(), arm.start(), padding)
                    .map_err(|e| fail(CloudOption::RemoveRobot, e.into()))?;
            steps.push(step(
                &format!("the robot's own points at the start ({padding} m padding)"),
                &report,
            ));
            if points.is_empty() {
                return Err(emptied(CloudOption::RemoveRobot, report.before));
            }
        }
        if let Some(size) = self.voxel {
            let report = mit_star_robot::voxel_downsample(&mut points, size)
                .map_err(|e| fail(CloudOption::Voxel, e.into()))?;
            steps.push(step(&format!("one point per {size} m voxel"), &report));
        }
        if let Some(radius) = self.min_distance {
            let report = mit_star_robot::min_distance_downsample(&mut points, radius)
                .map_err(|e| fail(CloudOption::MinDistance, e.into()))?;
            steps.push(step(&format!("points at least {radius} m apart"), &report));
        }
        let cloud_error = |option: CloudOption| {
            move |source| {
                fail(
                    option,
                    HarnessError::Cloud {
                        name: "cloud".into(),
                        source,
                    },
                )
            }
        };
        let mut cloud = PointCloud::new(points).map_err(cloud_error(source))?;
        if let Some(r) = self.point_radius {
            cloud = cloud
                .with_radius(r)
                .map_err(cloud_error(CloudOption::PointRadius))?;
        }
        let prepare_seconds = started.elapsed().as_secs_f64();
        if let Some(path) = save {
            let start = Instant::now();
            let written = match path.extension().and_then(|e| e.to_str()) {
                Some("npy") => mit_star_robot::write_npy(path, cloud.points()),
                Some("ply") => {
                    mit_star_robot::write_ply(path, cloud.points(), PlyEncoding::BinaryLittleEndian)
                }
                _ => {
                    return Err(fail(
                        CloudOption::SaveCloud,
                        HarnessError::Usage(format!(
                            "`{}`: give a .ply or .npy file",
                            path.display()
                        )),
                    ));
                }
            };
            written.map_err(|e| fail(CloudOption::SaveCloud, e.into()))?;
            steps.push(format!(
                "{} points written to `{}` in {}",
                cloud.len(),
                path.display(),
                millis(start.elapsed())
            ));
        }
        let (count, radius) = (cloud.len(), cloud.radius());
        let start = Instant::now();
        let obstacle = CloudObstacle::new("cloud", cloud);
        let build = start.elapsed();
        steps.push(format!(
            "tree of {count} points of radius {:.1} mm built in {}",
            radius * 1e3,
            millis(build)
        ));
        let scene = if self.scene_as_cloud.is_some() || self.drop_primitives {
            arm.scene().clone().without_primitives()
        } else {
            arm.scene().clone()
        };
        let summary = CloudSummary {
            input_points,
            points: count,
            radius,
            prepare_seconds,
            build_seconds: build.as_secs_f64(),
            steps,
        };
        Ok((arm.clone().with_scene(scene.with_cloud(obstacle)), summary))
    }
}

/// The sensor pose of `x, y, z, roll, pitch, yaw`.
fn sensor_pose(p: [f64; 6]) -> Result<SensorPose, mit_star_robot::CloudInputError> {
    SensorPose::from_xyz_rpy([p[0], p[1], p[2]], [p[3], p[4], p[5]])
}

fn step(what: &str, report: &FilterReport) -> String {
    format!(
        "{what}: {} of {} points kept in {}",
        report.after,
        report.before,
        millis(report.elapsed)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cloud_table_round_trips_through_toml_with_only_the_keys_given() {
        let spec = CloudSpec {
            files: vec!["scan.ply".into()],
            sensor_pose: Some([0.9, 0.0, 0.6, 0.0, 0.5, 3.0]),
            voxel: Some(0.01),
            crop_reach: true,
            ..CloudSpec::default()
        };
        let text = toml::to_string(&spec).unwrap();
        assert!(!text.contains("drop_primitives"), "{text}");
        assert!(!text.contains("seed"), "{text}");
        let again: CloudSpec = toml::from_str(&text).unwrap();
        assert_eq!(again, spec);
        let unknown = toml::from_str::<CloudSpec>("voxle = 0.01");
        assert!(unknown.unwrap_err().to_string().contains("voxle"));
    }

    fn box_panda() -> ArmProblem {
        let folder = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robot/tests/data/mbm/box_panda"
        );
        ArmProblem::panda_mbm(Path::new(folder), 1).unwrap()
    }

    #[test]
    fn given_points_join_the_files_moved_by_the_sensor_pose_in_place() {
        let dir = std::env::temp_dir().join(format!("mit-star-cloud-spec-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("one.npy");
        mit_star_robot::write_npy(&file, &[Vec3::new(0.0, 0.0, 3.0)]).unwrap();
        let given = [Vec3::new(1.0, 0.0, 3.0), Vec3::new(2.0, 0.0, 3.0)];
        let spec = CloudSpec {
            files: vec![file],
            sensor_pose: Some([0.5, 0.0, 0.0, 0.0, 0.0, 0.0]),
            ..CloudSpec::default()
        };
        let arm = box_panda();
        let (planned, summary) = spec.prepare(&arm, 1, &given, "p", None).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        // The file's point, then the given ones, every one moved 0.5 m along x, once.
        let cloud = planned.scene().clouds()[0].cloud();
        let mut xs: Vec<f32> = cloud.points().iter().map(|p| p.x).collect();
        xs.sort_by(f32::total_cmp);
        assert_eq!(xs, [0.5, 1.5, 2.5]);
        assert_eq!((summary.input_points, summary.points), (3, 3));
        assert!(
            summary.steps[0].contains("1 points read from"),
            "{:?}",
            summary.steps
        );
        assert_eq!(summary.steps[1], "2 points given");
        // The primitives stay unless dropped.
        assert_eq!(
            planned.scene().obstacles().len(),
            arm.scene().obstacles().len()
        );
    }

    #[test]
    fn settings_without_a_source_or_with_a_missing_file_are_named() {
        let only_voxel = CloudSpec {
            voxel: Some(0.02),
            ..CloudSpec::default()
        };
        let e = only_voxel.check("p", false).unwrap_err().to_string();
        assert!(e.contains("`cloud.voxel` (--voxel)"), "{e}");
        assert!(e.contains("--cloud FILE or --scene-as-cloud"), "{e}");
        assert!(only_voxel.check("p", true).is_ok());
        let missing = CloudSpec {
            files: vec!["/no/such/cloud.ply".into()],
            ..CloudSpec::default()
        };
        let e = missing.check("p", false).unwrap_err().to_string();
        assert!(
            e.contains("`cloud.files` (--cloud)") && e.contains("/no/such/cloud.ply"),
            "{e}"
        );
        let seed_alone = CloudSpec {
            files: vec!["/".into()],
            seed: Some(3),
            ..CloudSpec::default()
        };
        let e = seed_alone.check("p", false).unwrap_err().to_string();
        assert!(e.contains("`cloud.seed`"), "{e}");
    }
}
