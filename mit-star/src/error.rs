//! [`PlannerError`] (a malformed query) and [`BuildError`] (malformed parameters).

use std::fmt;

use mit_star_spaces::SpaceError;
use thiserror::Error;

/// Which state of a query a [`PlannerError`] is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Endpoint {
    /// The start state.
    Start,
    /// The goal with this index.
    Goal(usize),
}

impl fmt::Display for Endpoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Start => write!(f, "start"),
            Self::Goal(i) => write!(f, "goal {i}"),
        }
    }
}

/// Why a planner refuses a query. Planners report these for misuse only; a query that simply
/// has no solution within the termination condition is not an error
/// ([`Outcome::NoSolution`](crate::Outcome::NoSolution)).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PlannerError {
    /// No goal state was given.
    #[error("the query has no goal state")]
    NoGoals,
    /// The start or a goal is malformed: wrong dimension, not finite, or out of bounds.
    #[error("{endpoint}: {source}")]
    State {
        /// Which state.
        endpoint: Endpoint,
        /// What is wrong with it.
        source: SpaceError,
    },
    /// The start or a goal is not valid (in collision).
    #[error("{endpoint} {state:?} is in collision")]
    InCollision {
        /// Which state.
        endpoint: Endpoint,
        /// Its coordinates.
        state: Vec<f64>,
    },
    /// A planner could not be built over the goals a goal region supplied
    /// ([`LazyGoals`](crate::LazyGoals)): the first goal drawn, or the query, is refused.
    #[error("building the planner over the goals drawn: {0}")]
    GoalSet(Box<BuildError>),
    /// A path failed the planner's own consistency check (a bug: the path is withheld rather
    /// than returned unchecked).
    #[error("internal error: {0}")]
    Internal(String),
}

/// Why a planner could not be built from its parameters.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BuildError {
    /// A parameter is out of its range.
    #[error("parameter `{name}` is {}; {requirement}", crate::error::short(*.value))]
    Parameter {
        /// The parameter's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// What it must satisfy.
        requirement: &'static str,
    },
    /// A parameter asks for more memory than this machine has (refused before allocating).
    #[error("{what} would need about {needed} of memory; this machine has {available} available")]
    TooLarge {
        /// What was asked for.
        what: String,
        /// The estimated size.
        needed: String,
        /// What the machine has available.
        available: String,
    },
    /// An edge checker refused its parameters (step, sparse spacing, refinement factor Ω).
    #[error("edge checker: {0}")]
    Validity(#[from] mit_star_validity::ValidityError),
    /// A sampler refused its parameters or the query.
    #[error("sampler: {0}")]
    Sampler(#[from] mit_star_samplers::SamplerError),
    /// The problem definition is malformed.
    #[error("problem: {0}")]
    Problem(#[from] mit_star_problems::ProblemError),
    /// The query (start, goals) is malformed.
    #[error("query: {0}")]
    Query(#[from] PlannerError),
    /// A path given to [`PathSimplifier`](crate::PathSimplifier) has fewer than two states,
    /// or a state of another dimension than the space's or not finite.
    #[error(
        "a path to simplify needs at least two finite states of dimension {dimension}; state {state} of {states} is not one"
    )]
    BadPath {
        /// The states the path has.
        states: usize,
        /// The first state at fault (its index; `states` itself when there are too few).
        state: usize,
        /// The space's dimension.
        dimension: usize,
    },
    /// A configuration name was not recognised.
    #[error("unknown configuration `{name}`; expected one of {expected}")]
    UnknownConfiguration {
        /// The name given.
        name: String,
        /// The names accepted.
        expected: &'static str,
    },
}

/// A number for a message ([`mit_star_spaces::short_number`]).
pub(crate) fn short(value: f64) -> String {
    mit_star_spaces::short_number(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_culprit() {
        let e = PlannerError::InCollision {
            endpoint: Endpoint::Goal(2),
            state: vec![0.0, 0.5],
        };
        assert_eq!(e.to_string(), "goal 2 [0.0, 0.5] is in collision");
        let e = PlannerError::State {
            endpoint: Endpoint::Start,
            source: SpaceError::DimensionMismatch {
                expected: 4,
                got: 3,
            },
        };
        assert_eq!(
            e.to_string(),
            "start: state has 3 coordinates but the space has dimension 4"
        );
        let e = BuildError::Parameter {
            name: "batch_size",
            value: 0.0,
            requirement: "it must be at least 1",
        };
        assert_eq!(
            e.to_string(),
            "parameter `batch_size` is 0; it must be at least 1"
        );
    }
}
