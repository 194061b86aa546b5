//! [`ViewDocument`]: everything one view page shows, independent of where it came from.

use serde::Serialize;

use crate::{MotionView, RobotView, SceneView, SearchOverlay};

/// What the page draws the moving thing as.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ViewKind {
    /// A robot arm: link poses per frame, spheres and meshes per link.
    Arm,
    /// A point moving through a 2-D box world (drawn in the plane z = 0, seen from above).
    World2d,
    /// A point moving through a 3-D box world.
    World3d,
}

/// One page: a title, the scene, optionally a robot, the motions to scrub through (a plan,
/// a trajectory, the best and the worst run of a problem, the successive plans of a
/// re-planning run), and optionally the search.
///
/// Every array is written as little-endian `f32` in base64, so a page stays small; the page
/// decodes them. Build one, then [`to_html`](Self::to_html) (which applies
/// [`ViewLimits`](crate::ViewLimits)) or [`write_html`](Self::write_html).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ViewDocument {
    /// The page's title (first line of the header).
    pub title: String,
    /// Lines under the title: the problem, the planner, the verdict.
    pub subtitle: Vec<String>,
    /// Notes shown on the page: what was decimated, which meshes failed to load.
    pub notes: Vec<String>,
    /// What moves.
    pub kind: ViewKind,
    /// The robot (`None` in box worlds).
    pub robot: Option<RobotView>,
    /// The obstacles.
    pub scene: SceneView,
    /// The motions, the first shown first (may be empty: a scene and a robot at rest).
    pub motions: Vec<MotionView>,
    /// The search, drawn on request.
    pub search: Option<SearchOverlay>,
}

impl ViewDocument {
    /// An empty page of `kind` titled `title`.
    pub fn new(kind: ViewKind, title: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            subtitle: Vec::new(),
            notes: Vec::new(),
            kind,
            robot: None,
            scene: SceneView::default(),
            motions: Vec::new(),
            search: None,
        }
    }
}
