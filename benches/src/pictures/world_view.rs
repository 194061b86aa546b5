//! [`WorldView`]: a 2-D or 3-D box world as a view — bounds, obstacles, lattices, the
//! moving point's motions, the search and the informed set.

use glam::DVec3;
use mit_star::Snapshot;
use mit_star_problems::{PlanningProblem, Problem};
use mit_star_spaces::StateSpace;
use mit_star_validity::{AxisBox, StateValidity};
use mit_star_view::{
    InformedView, MotionView, SceneView, ShapeView, SolidView, ViewDocument, ViewKind,
};

use crate::error::HarnessError;
use crate::pictures::view_frames::ViewFrames;

/// The thickness of a 2-D world's boxes in the view (they lie in the plane z = 0), as a
/// fraction of the world's largest side.
const FLAT: f64 = 0.01;

/// Builds views of plans in one box world of two or three dimensions.
pub(crate) struct WorldView<'a> {
    problem: &'a Problem,
}

impl<'a> WorldView<'a> {
    /// The view of `problem`.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a world of more than three dimensions.
    pub(crate) fn new(problem: &'a Problem) -> Result<Self, HarnessError> {
        let n = problem.dimension();
        if !(2..=3).contains(&n) {
            return Err(HarnessError::Usage(format!(
                "a view draws arms and 2-D or 3-D box worlds; `{}` has {n} dimensions",
                problem.name()
            )));
        }
        Ok(Self { problem })
    }

    /// The world's space.
    pub(crate) fn space(&self) -> &mit_star_spaces::RealVectorSpace {
        self.problem.space()
    }

    fn point(&self, state: &[f64]) -> DVec3 {
        DVec3::new(state[0], state[1], state.get(2).copied().unwrap_or(0.0))
    }

    fn flat(&self) -> bool {
        self.problem.dimension() == 2
    }

    /// A page with the world and no motion yet.
    pub(crate) fn document(&self, title: impl Into<String>) -> ViewDocument {
        let kind = if self.flat() {
            ViewKind::World2d
        } else {
            ViewKind::World3d
        };
        let mut document = ViewDocument::new(kind, title);
        let world = self.problem.world();
        let (lo, hi) = (self.point(world.lower()), self.point(world.upper()));
        let thickness = FLAT * (hi - lo).max_element();
        let solid = |name: String, b: &AxisBox| {
            let centre = self.point(&b.center);
            let mut half = 0.5 * self.point(&b.widths);
            if self.flat() {
                half.z = 0.5 * thickness;
            }
            SolidView {
                name,
                shape: ShapeView::Cuboid {
                    half_extents: half.as_vec3().to_array(),
                },
                position: centre.as_vec3().to_array(),
                rotation: [0.0, 0.0, 0.0, 1.0],
            }
        };
        let mut solids: Vec<SolidView> = world
            .obstacles()
            .iter()
            .enumerate()
            .map(|(i, b)| solid(format!("obstacle {}", i + 1), b))
            .collect();
        for (l, lattice) in world.lattices().iter().enumerate() {
            let n = self.problem.dimension();
            let cells = lattice.count.pow(n as u32);
            for cell in 0..cells {
                let mut index = cell;
                let center: Vec<f64> = (0..n)
                    .map(|d| {
                        let k = index % lattice.count;
                        index /= lattice.count;
                        world.lower()[d] + (k as f64 + 1.0) * lattice.spacing
                    })
                    .collect();
                let b = AxisBox::cube(center, lattice.side);
                solids.push(solid(format!("lattice {} cell {}", l + 1, cell + 1), &b));
            }
        }
        if !world.anti_obstacles().is_empty() {
            let gaps = world.anti_obstacles().len();
            document.notes.push(format!(
                "{gaps} gap{} (anti-obstacle{}) carve{} free space out of the obstacles; the \
                 view draws the obstacles whole",
                if gaps == 1 { "" } else { "s" },
                if gaps == 1 { "" } else { "s" },
                if gaps == 1 { "s" } else { "" },
            ));
        }
        document.scene = SceneView {
            solids,
            clouds: Vec::new(),
            movers: Vec::new(),
            bounds: Some([lo.as_vec3().to_array(), hi.as_vec3().to_array()]),
        };
        document
    }

    /// The point's motion along `path`, labelled `label`, frames refused by the problem's
    /// checker marked.
    #[cfg(test)]
    pub(crate) fn path_motion(&self, label: impl Into<String>, path: &[Vec<f64>]) -> MotionView {
        self.motion(label, &ViewFrames::along_path(self.problem.space(), path))
    }

    /// The point's motion through `frames`, labelled `label`, frames refused by the problem's
    /// checker marked.
    pub(crate) fn motion(&self, label: impl Into<String>, frames: &ViewFrames) -> MotionView {
        let validity = self.problem.validity();
        let n = self.problem.dimension();
        MotionView {
            label: label.into(),
            joint_names: ["x", "y", "z"][..n]
                .iter()
                .map(|s| (*s).to_owned())
                .collect(),
            frames: frames.states.len(),
            joints: frames.states.iter().flatten().map(|&v| v as f32).collect(),
            poses: frames
                .states
                .iter()
                .flat_map(|q| self.point(q).as_vec3().to_array())
                .collect(),
            times: None,
            waypoints: frames.waypoints.clone(),
            colliding: frames.colliding(|q| validity.is_valid(q)),
            mover_positions: Vec::new(),
        }
    }

    /// The forward tree of `snapshot`, coloured by cost-to-come, with the informed set of its
    /// best cost (foci: the start and the first goal) when it has one.
    pub(crate) fn search(&self, snapshot: &Snapshot) -> mit_star_view::SearchOverlay {
        let space = self.problem.space();
        let positions: Vec<DVec3> = (0..snapshot.states.len())
            .map(|i| self.point(&snapshot.states[i]))
            .collect();
        let costs = crate::pictures::search_view::costs_to_come(snapshot, |a, b| {
            space.distance(&snapshot.states[a], &snapshot.states[b])
        });
        let informed = self
            .problem
            .goals()
            .first()
            .filter(|_| snapshot.best_cost.is_finite())
            .map(|goal| InformedView {
                start: self.point(self.problem.start()).as_vec3().to_array(),
                goal: self.point(goal).as_vec3().to_array(),
                cost: snapshot.best_cost as f32,
            });
        crate::pictures::search_view::overlay(snapshot, &positions, &costs, informed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_two_dimensional_world_lies_flat() {
        let problem = mit_star_problems::builtin("wall-gap", 2, 0).unwrap();
        let view = WorldView::new(&problem).unwrap();
        let document = view.document("wall gap");
        assert_eq!(document.kind, ViewKind::World2d);
        assert!(!document.scene.solids.is_empty());
        let path = vec![problem.start().to_vec(), problem.goals()[0].clone()];
        let motion = view.path_motion("straight", &path);
        assert_eq!(motion.poses.len(), 3 * motion.frames);
        assert!(motion.poses.chunks(3).all(|p| p[2] == 0.0));
        // The straight line crosses the wall.
        assert!(!motion.colliding.is_empty());
    }

    #[test]
    fn more_than_three_dimensions_is_refused() {
        let problem = mit_star_problems::builtin("obstacle-free", 4, 0).unwrap();
        assert!(WorldView::new(&problem).is_err());
    }
}
