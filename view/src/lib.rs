//! Interactive 3-D views of plans, in one self-contained HTML file.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod encoding;
mod motion_view;
mod robot_view;
mod scene_view;
mod search_overlay;
mod view_document;

pub use encoding::base64;
pub use motion_view::MotionView;
pub use robot_view::{LinkView, MeshView, RobotView};
pub use scene_view::{CloudView, SceneView, ShapeView, SolidView};
pub use search_overlay::{InformedView, SearchOverlay};
pub use view_document::{ViewDocument, ViewKind};
