//! Interactive 3-D views of plans, in one self-contained HTML file.
//!
//! Build a [`ViewDocument`] — a robot arm or a box world, its scene, the motions to scrub
//! through, optionally the search — and write it as a page that opens offline in any browser
//! with WebGL 2: three.js and the page's own code are bundled into the crate at build time
//! (`build.rs` runs esbuild on `view/web`, which needs Node.js and npm).
//!
//! ```
//! use mit_star_view::{MotionView, SceneView, ShapeView, SolidView, ViewDocument, ViewKind, ViewLimits};
//!
//! let mut doc = ViewDocument::new(ViewKind::World2d, "A point around a wall");
//! doc.subtitle.push("planner: MIT*, cost 3.1".into());
//! doc.scene = SceneView {
//!     solids: vec![SolidView {
//!         name: "wall".into(),
//!         shape: ShapeView::Cuboid { half_extents: [0.1, 0.6, 0.0] },
//!         position: [0.5, 0.4, 0.0],
//!         rotation: [0.0, 0.0, 0.0, 1.0],
//!     }],
//!     clouds: Vec::new(),
//!     movers: Vec::new(),
//!     bounds: Some([[0.0, 0.0, 0.0], [1.0, 1.0, 0.0]]),
//! };
//! doc.motions.push(MotionView {
//!     label: "plan".into(),
//!     joint_names: vec!["x".into(), "y".into()],
//!     frames: 3,
//!     joints: vec![0.1, 0.1, 0.5, 0.9, 0.9, 0.1],
//!     poses: vec![0.1, 0.1, 0.0, 0.5, 0.9, 0.0, 0.9, 0.1, 0.0],
//!     times: None,
//!     waypoints: vec![0, 1, 2],
//!     colliding: Vec::new(),
//!     mover_positions: Vec::new(),
//! });
//! let html = doc.to_html(ViewLimits::default())?;
//! assert!(html.contains("<title>A point around a wall</title>"));
//! # Ok::<(), mit_star_view::ViewError>(())
//! ```
//!
//! What the crate offers:
//! - the document: [`ViewDocument`] and [`ViewKind`]; the robot ([`RobotView`], [`LinkView`],
//!   [`MeshView`]); the obstacles ([`SceneView`], [`SolidView`], [`ShapeView`],
//!   [`CloudView`]); the motions ([`MotionView`]); the search ([`SearchOverlay`],
//!   [`InformedView`]);
//! - [`ViewDocument::check`]: the document agrees with itself;
//! - [`ViewLimits`]: caps on what a page draws, and [`ViewLimits::decimate`], which keeps a
//!   document within them and notes what it dropped;
//! - [`ViewDocument::to_html`] and [`ViewDocument::write_html`]: the page;
//! - [`ViewError`]: why a page could not be made;
//! - [`base64`]: the encoding of the page's arrays (little-endian `f32`/`u32`).
//!
//! The page shows the scene (solids, clouds, bounds), the robot as spheres or meshes, a slider
//! over each motion's frames with play and speed, the time or path fraction, the joint values,
//! the hand's trace, ghosts at waypoints, colliding frames in red, and the search coloured by
//! cost with the informed set. It exposes `window.mitStarView` (`ready`, `frameCount()`,
//! `setFrame(i)`, `motionCount()`, `setMotion(k)`, `render()`) for browser tests.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod document_check;
mod encoding;
mod html_page;
mod motion_view;
mod robot_view;
mod scene_view;
mod search_overlay;
mod view_document;
mod view_error;
mod view_limits;

pub use encoding::base64;
pub use html_page::{Viewer, escape_html, viewer_script};
pub use motion_view::MotionView;
pub use robot_view::{LinkView, MeshView, RobotView};
pub use scene_view::{CloudView, SceneView, ShapeView, SolidView};
pub use search_overlay::{InformedView, SearchOverlay};
pub use view_document::{ViewDocument, ViewKind};
pub use view_error::ViewError;
pub use view_limits::ViewLimits;
