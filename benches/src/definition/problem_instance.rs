//! [`ProblemInstance`]: one concrete problem of an experiment, with its time budget.

use crate::definition::cloud_summary::CloudSummary;
use crate::definition::planner_spec::PlannerSpec;
use crate::definition::pose_goal_source::{PoseGoalSource, pose_goal_planner};
use crate::definition::pose_goal_spec::PoseGoalSpec;
use crate::definition::problem_kind::InstanceProblem;
use crate::definition::problem_source::ProblemSource;
use crate::error::HarnessError;

/// One problem instance of an experiment: a problem in one dimension (and, for seeded
/// families, one layout), with the time budget of each run. Each instance is one OMPL
/// "experiment": one `.log` file, one row of `experiments` in the database, one figure.
#[derive(Debug, Clone, PartialEq)]
pub struct ProblemInstance {
    /// Unique, file-name-safe id: `dividing-walls-n4`, `random-rectangles-n8-i3`.
    pub id: String,
    /// The problem's label (family name or file stem), used as the experiment name in OMPL
    /// logs and Planner Arena; the dimension and instance are experiment properties there.
    pub label: String,
    /// Where the problem comes from.
    pub source: ProblemSource,
    /// The dimension `n`.
    pub dimension: usize,
    /// The layout seed (seeded families; 0 otherwise).
    pub instance: u64,
    /// Wall-clock budget of each run in seconds (planner construction included).
    pub budget: f64,
    /// The problem.
    pub problem: InstanceProblem,
    /// What preparing the problem's point cloud did, once before its runs (arm problems with
    /// a `cloud`; `None` without one).
    pub cloud: Option<CloudSummary>,
    /// A link's pose as the goal instead of the problem's goal configuration (arm problems).
    pub pose_goal: Option<PoseGoalSpec>,
}

impl ProblemInstance {
    /// Builds `planner` with `seed` for this instance: towards its goal, or towards its pose
    /// goal ([`mit_star::LazyGoals`] with the goal region, returned too: it judges the path).
    ///
    /// # Errors
    /// [`HarnessError::Build`] if the planner refuses its parameters or the query;
    /// [`HarnessError::PoseGoal`] or [`HarnessError::Usage`] for a pose goal the robot or the
    /// solver refuses.
    pub fn build_planner(
        &self,
        planner: &PlannerSpec,
        seed: u64,
    ) -> Result<(Box<dyn mit_star::Planner + Send>, Option<PoseGoalSource>), HarnessError> {
        let parameters = planner.parameters_for_seed(seed);
        let built = |source| HarnessError::Build {
            planner: planner.name().to_owned(),
            source,
        };
        match (&self.pose_goal, self.problem.as_arm()) {
            (None, _) => Ok((
                self.problem
                    .build_planner(planner.configuration(), &parameters)
                    .map_err(built)?,
                None,
            )),
            (Some(spec), Some(arm)) => {
                let source = spec.source(arm, seed)?;
                // The parameters are checked once, over the problem's own goal.
                self.problem
                    .effective_parameters(planner.configuration(), &parameters)
                    .map_err(built)?;
                let planner =
                    pose_goal_planner(arm, source.clone(), planner.configuration(), parameters);
                Ok((planner, Some(source)))
            }
            (Some(_), None) => Err(HarnessError::Usage(format!(
                "a pose goal applies to arm problems; `{}` is not one",
                self.label
            ))),
        }
    }

    /// The instance id for a label, dimension and (for seeded families) instance seed.
    ///
    /// ```
    /// use mit_star_benches::ProblemInstance;
    /// assert_eq!(ProblemInstance::make_id("dividing-walls", 4, None), "dividing-walls-n4");
    /// assert_eq!(ProblemInstance::make_id("random-rectangles", 8, Some(3)), "random-rectangles-n8-i3");
    /// ```
    pub fn make_id(label: &str, dimension: usize, instance: Option<u64>) -> String {
        match instance {
            Some(i) => format!("{label}-n{dimension}-i{i}"),
            None => format!("{label}-n{dimension}"),
        }
    }

    /// Where an arm instance's robot finds its visual mesh files (`None` for a box world).
    pub fn mesh_resolver(&self) -> Option<mit_star_robot::MeshResolver> {
        match &self.source {
            ProblemSource::Mbm(folder) => Some(folder.robot().mesh_resolver()),
            _ => None,
        }
    }

    /// A human-readable title: `dividing-walls R^4`, `random-rectangles R^8 #3`.
    pub fn title(&self) -> String {
        if self.source.is_seeded() {
            format!("{} R^{} #{}", self.label, self.dimension, self.instance)
        } else {
            format!("{} R^{}", self.label, self.dimension)
        }
    }
}
