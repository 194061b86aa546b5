//! [`Padding`]: the clearance a user asks every configuration of a path to keep from every
//! obstacle, beyond the checker's `f32` margin, and [`PaddingError`] for a value that is not
//! one.

use std::fmt;

use thiserror::Error;

/// The largest padding accepted, in metres: 1 m. A padding is a safety distance around a
/// robot's links; one larger than the robot is a mistake (millimetres typed as metres), and
/// it would make every obstacle within a metre of the reach a candidate of every test.
pub const MAX_PADDING: f64 = 1.0;

/// A collision padding in metres, `0 ≤ p ≤` [`MAX_PADDING`]: every robot sphere is grown by
/// it in every test against the scene's obstacles and point clouds (not between the robot's
/// own links), so a configuration called valid keeps every sphere at least `p` (plus the
/// checker's margin, plus a cloud's point radius) from every obstacle, and a certified edge
/// keeps that distance at every configuration — MoveIt's link padding, for the environment.
///
/// Self-collision is not padded: the SRDF's disabled pairs and its adjacency were computed
/// for the links as they are (pairs found never or always in contact by sampling), and links
/// that nearly touch by design — a finger beside the hand, a wrist beside the forearm — would
/// collide in every configuration with a padding of a centimetre.
///
/// ```
/// use mit_star_robot::{MAX_PADDING, Padding, PaddingError};
/// assert_eq!(Padding::new(0.01)?.metres(), 0.01);
/// assert_eq!(Padding::default(), Padding::ZERO);
/// assert!(matches!(Padding::new(-0.01), Err(PaddingError::Negative(_))));
/// assert!(matches!(Padding::new(f64::NAN), Err(PaddingError::NotANumber)));
/// assert!(matches!(Padding::new(2.0 * MAX_PADDING), Err(PaddingError::TooLarge(_))));
/// # Ok::<(), PaddingError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Default)]
pub struct Padding(f64);

/// Why a value is not a [`Padding`].
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum PaddingError {
    /// Not a number.
    #[error("the collision padding is not a number: give metres, e.g. 0.01")]
    NotANumber,
    /// Below zero.
    #[error("the collision padding {0} m is negative: it is the distance kept from obstacles")]
    Negative(f64),
    /// Above [`MAX_PADDING`] (or infinite).
    #[error(
        "the collision padding {0} m is larger than {MAX_PADDING} m: it is in metres (0.01 is a centimetre)"
    )]
    TooLarge(f64),
}

impl Padding {
    /// No padding: obstacles are kept at the checker's margin only.
    pub const ZERO: Padding = Padding(0.0);

    /// The padding of `metres`.
    ///
    /// # Errors
    /// [`PaddingError`] for a value that is not a number, negative, or above [`MAX_PADDING`].
    pub fn new(metres: f64) -> Result<Self, PaddingError> {
        if metres.is_nan() {
            Err(PaddingError::NotANumber)
        } else if metres < 0.0 {
            Err(PaddingError::Negative(metres))
        } else if metres > MAX_PADDING {
            Err(PaddingError::TooLarge(metres))
        } else {
            // -0.0 is taken as 0.
            Ok(Self(metres.max(0.0)))
        }
    }

    /// The padding in metres.
    pub fn metres(self) -> f64 {
        self.0
    }

    /// `true` for no padding.
    pub fn is_zero(self) -> bool {
        self.0 == 0.0
    }
}

impl fmt::Display for Padding {
    /// In millimetres: `10 mm`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} mm", mit_star_spaces::short_number(self.0 * 1e3))
    }
}

impl std::str::FromStr for Padding {
    type Err = PaddingError;

    /// Metres, as a number (`0.01`); text that is not a number is [`PaddingError::NotANumber`].
    fn from_str(text: &str) -> Result<Self, PaddingError> {
        let value: f64 = text.trim().parse().map_err(|_| PaddingError::NotANumber)?;
        Self::new(value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_inclusive_and_text_parses() {
        assert_eq!(Padding::new(0.0).unwrap(), Padding::ZERO);
        assert_eq!(
            Padding::new(-0.0).unwrap().metres().to_bits(),
            0.0_f64.to_bits()
        );
        assert_eq!(Padding::new(MAX_PADDING).unwrap().metres(), MAX_PADDING);
        assert!(matches!(
            Padding::new(f64::INFINITY),
            Err(PaddingError::TooLarge(_))
        ));
        assert_eq!("0.02".parse::<Padding>().unwrap().metres(), 0.02);
        assert_eq!("ten".parse::<Padding>(), Err(PaddingError::NotANumber));
        assert_eq!(Padding::new(0.01).unwrap().to_string(), "10 mm");
    }
}
