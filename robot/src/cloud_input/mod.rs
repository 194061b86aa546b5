//! Point clouds as a user has them: files (PLY, PCD, `.npy`), a cloud sampled on a scene's
//! primitives, a sensor pose that brings a camera's cloud into the robot's base frame, and
//! the filters that make a raw cloud fit to plan in (voxel and minimum-distance
//! downsampling, cropping to the robot's reach or a box, removing the points on the robot).
//! It produces points (`Vec<glam::Vec3>`, `f32`, contiguous); the point structure that
//! answers sphere queries is built from them elsewhere. It may use the scenes (`Obstacle`)
//! and the model's forward kinematics; nothing in the crate uses it.
//!
//! # Why this crate reads the files itself
//! Each format's reader is a few hundred lines here, bounded the way the project bounds
//! every input; the crates on crates.io were weighed and not taken:
//! - **PLY**: `ply-rs` (last release 2020, unmaintained) and its fork `ply-rs-bw` build a
//!   `LinkedHashMap` of properties per vertex (an allocation or more per point; 10⁶ points
//!   become 10⁶ maps) and read element counts without a cap. Here the `vertex` element's
//!   `x`, `y`, `z` go straight into a `Vec<Vec3>` with one allocation, the count checked
//!   against [`MAX_CLOUD_POINTS`] and the bytes there are before it is made.
//! - **PCD**: `pcd-rs` (maintained, 0.13) reads all three encodings, but a cloud of unknown
//!   fields goes through its `DynRecord`, a `Vec` of fields of `Vec`s per point, and its
//!   errors do not say which file; its `binary_compressed` path allocates the size the file
//!   claims. The PCD header is eight keywords; the `binary_compressed` layout is PCL's
//!   column-wise one compressed with LZF, whose decoder (`lzf.rs`) is forty lines, bounded
//!   by the declared size, itself bounded by [`MAX_CLOUD_FILE_BYTES`].
//! - **npy**: `npyz` and `ndarray-npy` read `.npy` well, but an N×3 float array needs only
//!   the magic, a one-line Python dictionary (`descr`, `fortran_order`, `shape`) and the data;
//!   a dependency (and `ndarray`) for that would cost more than the sixty lines it saves.
//!
//! # Limits and bad input
//! Files are read whole through [`mit_star_problems::read_bounded_bytes`] (a device, a pipe or a
//! folder is refused; at most [`MAX_CLOUD_FILE_BYTES`]). A header's point count is checked
//! against [`MAX_CLOUD_POINTS`] before anything is allocated, and binary data against the
//! header before it is read: a count larger than the data is [`CloudInputError::Truncated`],
//! data beyond the count [`CloudInputError::TrailingData`] (a lying header is refused, not
//! trusted). Points with a NaN or infinite coordinate are dropped and counted
//! ([`InputCloud::dropped_non_finite`]), as PCL drops them from unorganised clouds; a cloud
//! with no point left is [`CloudInputError::Empty`]. No input panics.
//!
//! # Filters
//! Each filter works in place on a `Vec<Vec3>`, keeps the order of the points it keeps,
//! allocates nothing per point and returns a [`FilterReport`] with its time.

mod cell_hash;
mod cloud_input_error;
mod crop;
mod filter_report;
mod input_cloud;
mod lzf;
mod min_distance_filter;
mod npy;
mod pcd;
mod ply;
mod ply_writer;
mod reach;
mod robot_filter;
mod scalar;
mod sensor_pose;
mod surface_sampling;
mod voxel_filter;

pub use cloud_input_error::CloudInputError;
pub use crop::{crop_to_ball, crop_to_box};
pub use filter_report::FilterReport;
pub use input_cloud::{
    CloudFormat, CloudOrigin, InputCloud, MAX_CLOUD_FILE_BYTES, MAX_CLOUD_POINTS, parse_cloud,
    read_cloud,
};
pub use min_distance_filter::min_distance_downsample;
pub use npy::{npy_bytes, write_npy};
pub use ply_writer::{PlyEncoding, ply_bytes, write_ply};
pub use reach::reach_ball;
pub use robot_filter::remove_robot_points;
pub use sensor_pose::SensorPose;
pub use surface_sampling::{
    DEFAULT_SAMPLES_PER_OBSTACLE, sample_obstacle_surface, sample_surfaces,
};
pub use voxel_filter::voxel_downsample;

#[cfg(test)]
mod reader_tests;
