//! [`InstanceProblem`]: the problem of an experiment's instance, whatever its kind.

use mit_star::{BuildError, Configuration, Parameters, Planner};
use problems::{PlanningProblem, Problem, ProblemError};

use crate::PathValidation;

/// The problem of one [`ProblemInstance`](crate::ProblemInstance): a box world (the PDT
/// families and problem files). Every kind plans through [`PlanningProblem`]; what differs is
/// how a path is validated independently, what a picture shows, and what a log describes.
#[derive(Debug, Clone, PartialEq)]
pub enum InstanceProblem {
    /// A point among axis-aligned boxes in `R^n`.
    Boxes(Problem),
}

impl InstanceProblem {
    /// The box-world problem, if this is one.
    pub fn as_boxes(&self) -> Option<&Problem> {
        match self {
            Self::Boxes(p) => Some(p),
        }
    }

    /// Allows (or not) a box world's check step to be coarser than its thinnest obstacle
    /// ([`Problem::allowing_coarse_step`]); other kinds are unchanged.
    #[must_use]
    pub fn allowing_coarse_step(self, allow: bool) -> Self {
        match self {
            Self::Boxes(p) => Self::Boxes(p.allowing_coarse_step(allow)),
        }
    }

    /// The collision-check step, or why the problem refuses it ([`PlanningProblem::check_step`]).
    ///
    /// # Errors
    /// [`ProblemError::StepTooCoarse`] for a box world whose thinnest box is thinner than the
    /// step (unless allowed).
    pub fn check_step(&self) -> Result<f64, ProblemError> {
        match self {
            Self::Boxes(p) => PlanningProblem::check_step(p),
        }
    }

    /// The dimension of the configuration space.
    pub fn dimension(&self) -> usize {
        match self {
            Self::Boxes(p) => p.dimension(),
        }
    }

    /// The start state.
    pub fn start(&self) -> &[f64] {
        match self {
            Self::Boxes(p) => p.start(),
        }
    }

    /// The goal states.
    pub fn goals(&self) -> &[Vec<f64>] {
        match self {
            Self::Boxes(p) => p.goals(),
        }
    }

    /// The collision-check resolution (a fraction of the maximum extent).
    pub fn resolution(&self) -> f64 {
        match self {
            Self::Boxes(p) => p.resolution(),
        }
    }

    /// The collision-check step in the space's units.
    pub fn step(&self) -> f64 {
        match self {
            Self::Boxes(p) => p.step(),
        }
    }

    /// The known optimal cost, if any.
    pub fn optimum(&self) -> Option<f64> {
        match self {
            Self::Boxes(p) => p.optimum(),
        }
    }

    /// The distance from the start to the nearest goal, ignoring obstacles.
    pub fn straight_line_cost(&self) -> f64 {
        match self {
            Self::Boxes(p) => p.straight_line_cost(),
        }
    }

    /// Builds `configuration` for this problem with `parameters`.
    ///
    /// # Errors
    /// As [`mit_star::build_planner`].
    pub fn build_planner(
        &self,
        configuration: Configuration,
        parameters: &Parameters,
    ) -> Result<Box<dyn Planner + Send>, BuildError> {
        match self {
            Self::Boxes(p) => mit_star::build_planner(configuration, p, parameters),
        }
    }

    /// Validates a returned path independently of the planner: exactly for box worlds.
    pub fn validate(&self, path: &[Vec<f64>], reported_cost: f64) -> PathValidation {
        match self {
            Self::Boxes(p) => PathValidation::check(p, path, reported_cost),
        }
    }

    /// The problem as text for logs: a TOML problem file for box worlds.
    pub fn describe(&self) -> String {
        match self {
            Self::Boxes(p) => p.to_toml_string(),
        }
    }
}
