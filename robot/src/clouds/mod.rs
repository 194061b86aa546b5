//! Point clouds as obstacles: the points, their structure for sphere queries, and the named
//! obstacle a [`Scene`](crate::Scene) holds.
//!
//! - [`PointCloud`] (`point_cloud.rs`): validated points (`glam::Vec3`, contiguous) and their
//!   radius (2.5 mm unless set); [`CloudError`] (`cloud_error.rs`) says what is wrong with
//!   points that are not a cloud.
//! - [`PointTree`] (`point_tree.rs`): the points arranged for the checker's queries — is any
//!   point within a reach of a centre (one centre, or a batch of lanes), and a lower bound of
//!   the distance to the nearest point (certified motion).
//! - [`AffordanceTree`] (`affordance_tree.rs`): per cell of a kd-tree, the points a sphere up
//!   to a radius centred in it could touch (CAPT's idea) — the fast contact query.
//! - [`CloudObstacle`] (`cloud_obstacle.rs`): a named cloud, its tree and (optionally) its
//!   affordances, the obstacle a scene holds.
//!
//! May use: the `glam`, `wide`, `spaces` (its stop condition) and `thiserror` crates, and of
//! this crate the SIMD lane type (`lane_f32.rs`) and the scenes' length limit. Knows nothing
//! of checking. Used by `scenes` and `checking`. The independent audit does not use it (it
//! measures every point itself).

mod affordance_tree;
mod cloud_error;
mod cloud_obstacle;
mod point_cloud;
mod point_tree;

pub use affordance_tree::AffordanceTree;
pub use cloud_error::CloudError;
pub use cloud_obstacle::CloudObstacle;
pub use point_cloud::PointCloud;
pub use point_tree::PointTree;
