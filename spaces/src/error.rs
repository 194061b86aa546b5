//! Errors raised when a space or a state is malformed.

use thiserror::Error;

/// What is wrong with a space definition or with a state given to a space.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SpaceError {
    /// A space needs at least one coordinate.
    #[error("a state space needs at least one dimension")]
    ZeroDimension,
    /// Lower and upper bound vectors differ in length.
    #[error("bounds have {lower} lower and {upper} upper value(s); they must match")]
    BoundsLength {
        /// Number of lower bounds given.
        lower: usize,
        /// Number of upper bounds given.
        upper: usize,
    },
    /// A bound is NaN or infinite.
    #[error("bound of coordinate {index} is not finite ({value})")]
    NonFiniteBound {
        /// Coordinate index.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// The bounds are so far apart (or so close) that the space's diagonal or volume is not a
    /// positive finite `f64`: distances, measures and step sizes would overflow or vanish.
    #[error(
        "the bounds span a space whose {quantity} is {} in f64 arithmetic; rescale the problem so that its sides and volume are finite and positive",
        crate::short_number(*.value)
    )]
    UnrepresentableSize {
        /// `diagonal` or `volume`.
        quantity: &'static str,
        /// What it computed to (`inf`, or `0`).
        value: f64,
    },
    /// A lower bound is not strictly below its upper bound.
    #[error(
        "coordinate {index} has lower bound {} not below upper bound {}",
        crate::short_number(*.lower),
        crate::short_number(*.upper)
    )]
    EmptyInterval {
        /// Coordinate index.
        index: usize,
        /// Lower bound.
        lower: f64,
        /// Upper bound.
        upper: f64,
    },
    /// A joint weight is not a finite positive number.
    #[error("joint {index} has weight {weight}; weights must be finite and positive")]
    BadWeight {
        /// Joint index.
        index: usize,
        /// The offending weight.
        weight: f64,
    },
    /// A state has the wrong number of coordinates.
    #[error("state has {got} coordinates but the space has dimension {expected}")]
    DimensionMismatch {
        /// The space's dimension.
        expected: usize,
        /// The state's length.
        got: usize,
    },
    /// A state coordinate is NaN or infinite.
    #[error("coordinate {index} of the state is not finite ({value})")]
    NonFiniteState {
        /// Coordinate index.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A joint's value is NaN or infinite ([`JointSpace`](crate::JointSpace): the joint named).
    #[error("joint `{joint}` (coordinate {index}) is not finite ({value})")]
    JointNotFinite {
        /// The joint's name.
        joint: String,
        /// Its coordinate index.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A joint's value lies outside its limits ([`JointSpace`](crate::JointSpace): the joint
    /// named; a continuous joint's are `[-π, π]`).
    #[error(
        "joint `{joint}` (coordinate {index}) is {}, outside its limits [{}, {}]",
        crate::short_number(*.value),
        crate::short_number(*.lower),
        crate::short_number(*.upper)
    )]
    JointOutsideLimits {
        /// The joint's name.
        joint: String,
        /// Its coordinate index.
        index: usize,
        /// The offending value.
        value: f64,
        /// Its lower limit.
        lower: f64,
        /// Its upper limit.
        upper: f64,
    },
    /// A state lies outside the space's bounds.
    #[error(
        "coordinate {index} of the state is {}, outside the bounds [{}, {}]",
        crate::short_number(*.value),
        crate::short_number(*.lower),
        crate::short_number(*.upper)
    )]
    OutOfBounds {
        /// Coordinate index.
        index: usize,
        /// The offending value.
        value: f64,
        /// Lower bound of that coordinate.
        lower: f64,
        /// Upper bound of that coordinate.
        upper: f64,
    },
}
