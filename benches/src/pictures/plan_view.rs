//! [`PlanView`]: the 3-D view of plans on any problem the tool plans on — the one builder
//! behind `plan --view`, `replan --view`, `check-path --view`, Python's `write_view` and the
//! views an experiment report links to.

use std::path::Path;

use mit_star::Snapshot;
use mit_star_robot::Trajectory;
use mit_star_view::{ViewDocument, ViewLimits};

use crate::definition::problem_kind::InstanceProblem;
use crate::error::HarnessError;
use crate::pictures::arm_view::ArmView;
use crate::pictures::view_frames::ViewFrames;
use crate::pictures::world_view::WorldView;

/// What draws the motions: an arm, or a point in a box world.
enum Drawer<'a> {
    Arm(ArmView<'a>),
    World(WorldView<'a>),
}

/// A view page under construction: the problem's robot and scene, then motions (paths,
/// trajectories) and the search, then [`write`](Self::write).
///
/// ```no_run
/// use mit_star_benches::{PlanView, ProblemInstance};
/// # fn show(instance: &ProblemInstance, path: &[Vec<f64>]) -> Result<(), mit_star_benches::HarnessError> {
/// let mut view = PlanView::new(&instance.problem, "RRT-Connect on box", None)?;
/// view.path("plan", path);
/// view.write(std::path::Path::new("plan.html"))?;
/// # Ok(())
/// # }
/// ```
pub struct PlanView<'a> {
    drawer: Drawer<'a>,
    document: ViewDocument,
    /// About how many frames a path is cut into.
    frames: usize,
}

impl<'a> PlanView<'a> {
    /// A page of `problem` titled `title`; on an arm the hand's trace follows link `hand`
    /// (else the arm's tool link).
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a box world of more than three dimensions.
    pub fn new(
        problem: &'a InstanceProblem,
        title: impl Into<String>,
        hand: Option<&str>,
    ) -> Result<Self, HarnessError> {
        let title = title.into();
        let (drawer, document) = match problem {
            InstanceProblem::Arm(arm) => {
                let drawer = ArmView::new(arm, hand);
                let document = drawer.document(title);
                (Drawer::Arm(drawer), document)
            }
            InstanceProblem::Boxes(boxes) => {
                let drawer = WorldView::new(boxes)?;
                let document = drawer.document(title);
                (Drawer::World(drawer), document)
            }
        };
        Ok(Self {
            drawer,
            document,
            frames: crate::pictures::view_frames::FRAMES_PER_PATH,
        })
    }

    /// Draws the robot's visual meshes (its URDF's `<visual>` elements, files found by
    /// `resolver`) besides its spheres; a mesh that cannot be loaded leaves its link drawn as
    /// spheres, with a note on the page naming it. Nothing in a box world.
    pub fn meshes(&mut self, resolver: &mit_star_robot::MeshResolver) -> &mut Self {
        if let Drawer::Arm(arm) = &self.drawer {
            crate::pictures::arm_view::add_meshes(&mut self.document, arm.robot(), resolver);
        }
        self
    }

    /// Cuts each path added after this into about `count` frames (default 400): fewer make a
    /// smaller page, and playing interpolates between them.
    pub fn frames_per_path(&mut self, count: usize) -> &mut Self {
        self.frames = count.max(1);
        self
    }

    /// Adds a line under the title.
    pub fn subtitle(&mut self, line: impl Into<String>) -> &mut Self {
        self.document.subtitle.push(line.into());
        self
    }

    /// Adds a note shown on the page.
    pub fn note(&mut self, line: impl Into<String>) -> &mut Self {
        self.document.notes.push(line.into());
        self
    }

    /// Adds the motion along `path` (a path of one state is shown at rest).
    pub fn path(&mut self, label: impl Into<String>, path: &[Vec<f64>]) -> &mut Self {
        if path.is_empty() {
            return self;
        }
        let motion = match &self.drawer {
            Drawer::Arm(arm) => arm.motion(
                label,
                &ViewFrames::along_path_in(arm.space(), path, self.frames),
            ),
            Drawer::World(world) => world.motion(
                label,
                &ViewFrames::along_path_in(world.space(), path, self.frames),
            ),
        };
        self.document.motions.push(motion);
        self
    }

    /// Adds the timed motion of `trajectory` (arms only; ignored in a box world, which has no
    /// trajectories).
    pub fn trajectory(&mut self, label: impl Into<String>, trajectory: &Trajectory) -> &mut Self {
        if let Drawer::Arm(arm) = &self.drawer {
            let knots: Vec<f64> = trajectory.knots().iter().map(|k| k.time).collect();
            let frames = ViewFrames::along_time(trajectory.duration(), &knots, |t| {
                trajectory.evaluate(t).position
            });
            self.document.motions.push(arm.motion(label, &frames));
        }
        self
    }

    /// Adds a timed motion given by its samples: `states[k]` at `times[k]` (a trajectory
    /// file's), every sample a waypoint (arms only, as [`trajectory`](Self::trajectory)).
    pub fn samples(
        &mut self,
        label: impl Into<String>,
        times: Vec<f64>,
        states: Vec<Vec<f64>>,
    ) -> &mut Self {
        if let Drawer::Arm(arm) = &self.drawer
            && !states.is_empty()
        {
            let frames = ViewFrames {
                waypoints: (0..states.len()).collect(),
                states,
                times: Some(times),
            };
            self.document.motions.push(arm.motion(label, &frames));
        }
        self
    }

    /// Adds the search overlay of `snapshot`.
    pub fn search(&mut self, snapshot: &Snapshot) -> &mut Self {
        self.document.search = Some(match &self.drawer {
            Drawer::Arm(arm) => arm.search(snapshot),
            Drawer::World(world) => world.search(snapshot),
        });
        self
    }

    /// The page's document as built so far.
    pub fn document(&self) -> &ViewDocument {
        &self.document
    }

    /// Writes the page to `path`; its size in bytes.
    ///
    /// # Errors
    /// [`HarnessError::View`] if the document is inconsistent or the file cannot be written.
    pub fn write(&self, path: &Path) -> Result<u64, HarnessError> {
        self.write_with(path, mit_star_view::Viewer::Embedded)
    }

    /// Writes the page to `path`, its viewer embedded or in a file beside it; its size in
    /// bytes.
    ///
    /// # Errors
    /// As [`write`](Self::write).
    pub fn write_with(
        &self,
        path: &Path,
        viewer: mit_star_view::Viewer<'_>,
    ) -> Result<u64, HarnessError> {
        self.document
            .write_html_with(path, ViewLimits::default(), viewer)
            .map_err(|source| HarnessError::View {
                path: path.to_path_buf(),
                source,
            })
    }
}
