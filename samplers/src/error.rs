//! [`SamplerError`]: what is wrong with a sampler's problem definition or parameters.

use thiserror::Error;

/// A sampler, informed set or estimate was given malformed input.
///
/// Raised once, at construction or when a parameter is set; sampling itself only fails with
/// [`SampleError`](crate::SampleError).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SamplerError {
    /// The start state has the wrong number of coordinates.
    #[error("the start has {got} coordinates but the space has dimension {expected}")]
    StartDimension {
        /// The space's dimension.
        expected: usize,
        /// The start's length.
        got: usize,
    },
    /// A goal state has the wrong number of coordinates.
    #[error("goal {goal} has {got} coordinates but the space has dimension {expected}")]
    GoalDimension {
        /// Index of the goal.
        goal: usize,
        /// The space's dimension.
        expected: usize,
        /// The goal's length.
        got: usize,
    },
    /// A coordinate of the start is NaN or infinite.
    #[error("coordinate {coordinate} of the start is not finite ({value})")]
    NonFiniteStart {
        /// Coordinate index.
        coordinate: usize,
        /// The offending value.
        value: f64,
    },
    /// A coordinate of a goal is NaN or infinite.
    #[error("coordinate {coordinate} of goal {goal} is not finite ({value})")]
    NonFiniteGoal {
        /// Index of the goal.
        goal: usize,
        /// Coordinate index.
        coordinate: usize,
        /// The offending value.
        value: f64,
    },
    /// An informed set needs at least one goal.
    #[error("an informed set needs at least one goal, none was given")]
    NoGoals,
    /// A parameter that must be a finite positive number is not.
    #[error("{name} must be finite and positive, got {}", mit_star_spaces::short_number(*.value))]
    NotPositive {
        /// Which parameter.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A cost given to the estimated informed set is negative or not finite.
    #[error(
        "{name} must be finite and non-negative, got {}",
        mit_star_spaces::short_number(*.value)
    )]
    NegativeCost {
        /// Which input.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// The admissible cost `ŝ_adm` of an estimated informed set is zero, so its reliability
    /// `γ = g / ŝ_adm` is undefined.
    #[error("the admissible solution cost is zero; the reliability γ = g / ŝ_adm is undefined")]
    ZeroAdmissibleCost,
    /// A fraction is outside `[0, 1)`.
    #[error("{name} must lie in [0, 1), got {}", mit_star_spaces::short_number(*.value))]
    Fraction {
        /// Which parameter.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// The bridge-check budget is outside `1 ..= MAX_BRIDGE_CHECKS`.
    #[error("the number of bridge checks must lie in 1..={max}, got {got}")]
    BridgeChecks {
        /// The value given.
        got: usize,
        /// The largest accepted value.
        max: usize,
    },
}
