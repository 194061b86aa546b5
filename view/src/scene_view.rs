//! [`SceneView`]: the obstacles — solids (boxes, spheres, cylinders) and point clouds.

use serde::Serialize;

use crate::encoding::f32s;

/// The obstacles of a page.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct SceneView {
    /// Solid obstacles.
    pub solids: Vec<SolidView>,
    /// Point clouds.
    pub clouds: Vec<CloudView>,
    /// Obstacles that move (a re-planning trial's): their shapes, placed per frame by
    /// [`MotionView::mover_positions`](crate::MotionView::mover_positions).
    pub movers: Vec<SolidView>,
    /// The planning bounds of a box world, `[lo, hi]` (`None` for arms).
    pub bounds: Option<[[f32; 3]; 2]>,
}

/// The shape of a solid, centred at its position.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum ShapeView {
    /// A box with these half side lengths.
    Cuboid {
        /// Half side lengths along its own x, y, z.
        half_extents: [f32; 3],
    },
    /// A ball.
    Sphere {
        /// Its radius.
        radius: f32,
    },
    /// A cylinder along its own z axis.
    Cylinder {
        /// Its radius.
        radius: f32,
        /// Half its height.
        half_height: f32,
    },
}

/// A solid obstacle at a pose.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SolidView {
    /// Its name (the scene's object id), shown on hover.
    pub name: String,
    /// Its shape.
    pub shape: ShapeView,
    /// Its centre.
    pub position: [f32; 3],
    /// Its rotation as a unit quaternion `[x, y, z, w]`.
    pub rotation: [f32; 4],
}

/// A point cloud: points of one radius.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CloudView {
    /// Its name.
    pub name: String,
    /// The points, `x, y, z` each, flattened.
    #[serde(serialize_with = "f32s")]
    pub points: Vec<f32>,
    /// The radius every point carries.
    pub radius: f32,
}
