//! Errors for validity checkers and worlds.

use thiserror::Error;

/// A parameter of a validity or edge checker, or a world definition, is malformed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ValidityError {
    /// An edge-checking step or resolution is not a finite positive number.
    #[error("{name} must be finite and positive, got {value}")]
    NotPositive {
        /// Which parameter.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// The sparse refinement factor Ω is outside `(0, 1)`.
    #[error("the sparse refinement factor Ω must lie in (0, 1), got {0}")]
    RefinementFactor(f64),
    /// A box has the wrong number of coordinates.
    #[error(
        "{what} {index} has {got} coordinates in `{field}`, the world has dimension {expected}"
    )]
    BoxDimension {
        /// "obstacle" or "anti-obstacle".
        what: &'static str,
        /// Index of the box.
        index: usize,
        /// `center` or `widths`.
        field: &'static str,
        /// The world's dimension.
        expected: usize,
        /// The number given.
        got: usize,
    },
    /// A box coordinate is NaN or infinite, or a width is negative.
    #[error("{what} {index}: `{field}[{coordinate}]` is {value}; {requirement}")]
    BoxValue {
        /// "obstacle" or "anti-obstacle".
        what: &'static str,
        /// Index of the box.
        index: usize,
        /// `center` or `widths`.
        field: &'static str,
        /// Coordinate index.
        coordinate: usize,
        /// The value given.
        value: f64,
        /// What the value must satisfy.
        requirement: &'static str,
    },
}
