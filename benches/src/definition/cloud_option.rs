//! [`CloudOption`]: one point cloud setting, by its name in an experiment file and on the
//! command line, for messages.

/// A cloud option, named as an experiment file's `cloud` table and the command line name it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CloudOption {
    /// `files` (`--cloud FILE`).
    Files,
    /// Points given in memory (the Python package's `cloud` array).
    Points,
    /// `sensor_pose` (`--sensor-pose`).
    SensorPose,
    /// `scene_as_cloud` (`--scene-as-cloud`).
    SceneAsCloud,
    /// `seed` (`--cloud-seed`).
    Seed,
    /// `point_radius` (`--point-radius`).
    PointRadius,
    /// `crop_reach` (`--crop-reach`).
    CropReach,
    /// `remove_robot` (`--remove-robot`).
    RemoveRobot,
    /// `voxel` (`--voxel`).
    Voxel,
    /// `min_distance` (`--min-distance`).
    MinDistance,
    /// `drop_primitives` (`--drop-primitives`).
    DropPrimitives,
    /// `--save-cloud` (command line and Python only).
    SaveCloud,
    /// `contents`: what the files held when the experiment was recorded (its results
    /// folder's `experiment.toml` only).
    Contents,
}

impl CloudOption {
    /// The key in an experiment file's `cloud` table and the command-line flag.
    pub fn names(self) -> (&'static str, &'static str) {
        match self {
            Self::Files => ("files", "--cloud"),
            Self::Points => ("points", "the `cloud` array"),
            Self::SensorPose => ("sensor_pose", "--sensor-pose"),
            Self::SceneAsCloud => ("scene_as_cloud", "--scene-as-cloud"),
            Self::Seed => ("seed", "--cloud-seed"),
            Self::PointRadius => ("point_radius", "--point-radius"),
            Self::CropReach => ("crop_reach", "--crop-reach"),
            Self::RemoveRobot => ("remove_robot", "--remove-robot"),
            Self::Voxel => ("voxel", "--voxel"),
            Self::MinDistance => ("min_distance", "--min-distance"),
            Self::DropPrimitives => ("drop_primitives", "--drop-primitives"),
            Self::SaveCloud => ("save_cloud", "--save-cloud"),
            Self::Contents => ("contents", "recorded in `experiment.toml`"),
        }
    }

    /// Both names, for messages: `` `cloud.voxel` (--voxel) ``.
    pub fn describe(self) -> String {
        let (key, flag) = self.names();
        format!("`cloud.{key}` ({flag})")
    }
}
