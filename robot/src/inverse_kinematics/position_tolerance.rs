//! [`PositionTolerance`]: the set of positions a target accepts, and the residual the solver
//! drives to zero (the way from the current position into the set).

use glam::{DMat3, DVec3};

use crate::IkError;

/// Where the frame's origin may end up around the target position.
///
/// Checked (and kept) when attached to a [`PoseTarget`](crate::PoseTarget): sizes must be
/// finite and non-negative. The error the solver measures is the distance from the frame's
/// origin to the set: zero anywhere inside it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PositionTolerance {
    /// Exactly the target position.
    Exact,
    /// A box centred on the target position, axis-aligned in the target's frame (its
    /// orientation), with these half-extents along the target frame's x, y and z axes.
    Box {
        /// Half-extents in metres, each finite and `>= 0`.
        half_extents: DVec3,
    },
    /// A ball about the target position.
    Ball {
        /// Radius in metres, finite and `>= 0`.
        radius: f64,
    },
}

/// The solver's view of one tolerance at the current pose: the correction that takes the
/// frame into the set (zero inside it), the projector onto the constrained directions (the
/// directions the tolerance does not care about are free), and the error (the correction's
/// length for a position; the angle for an orientation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Residual {
    pub(crate) correction: DVec3,
    pub(crate) projector: DMat3,
    pub(crate) error: f64,
}

impl Residual {
    /// No correction, nothing constrained.
    pub(crate) const FREE: Self = Self {
        correction: DVec3::ZERO,
        projector: DMat3::ZERO,
        error: 0.0,
    };
}

impl PositionTolerance {
    /// `Ok` if every size is finite and non-negative.
    pub(crate) fn validate(&self) -> Result<(), IkError> {
        let check = |what, value: f64| {
            if value.is_finite() && value >= 0.0 {
                Ok(())
            } else {
                Err(IkError::BadTolerance {
                    what,
                    value,
                    expected: "a finite length >= 0 m",
                })
            }
        };
        match *self {
            Self::Exact => Ok(()),
            Self::Box { half_extents: h } => {
                check("box half-extent x", h.x)?;
                check("box half-extent y", h.y)?;
                check("box half-extent z", h.z)
            }
            Self::Ball { radius } => check("ball radius", radius),
        }
    }

    /// The residual of position `p` against target position `target` whose frame is
    /// `rotation`.
    pub(crate) fn residual(&self, target: DVec3, rotation: &DMat3, p: DVec3) -> Residual {
        match *self {
            Self::Exact => {
                let correction = target - p;
                Residual {
                    correction,
                    projector: DMat3::IDENTITY,
                    error: correction.length(),
                }
            }
            Self::Box { half_extents } => {
                let d = rotation.transpose() * (p - target);
                let inside = d.clamp(-half_extents, half_extents);
                let local = inside - d;
                // The axes on which the point is outside, or inside but near a face, are
                // constrained (near a face with no correction: the step holds the face).
                let mut projector = DMat3::ZERO;
                for axis in 0..3 {
                    if d[axis].abs() >= half_extents[axis] * (1.0 - ACTIVE_BAND) {
                        let column = rotation.col(axis);
                        projector += outer(column, column);
                    }
                }
                Residual {
                    correction: *rotation * local,
                    projector,
                    error: local.length(),
                }
            }
            Self::Ball { radius: 0.0 } => Self::Exact.residual(target, rotation, p),
            Self::Ball { radius } => {
                let d = p - target;
                let distance = d.length();
                if distance < radius * (1.0 - ACTIVE_BAND) {
                    return Residual::FREE;
                }
                // Outside, or inside near the surface: pulled to the nearest point of the ball,
                // every direction held (a radial constraint alone lets the steps drift
                // sideways by more than a small radius).
                let normal = d / distance;
                let excess = (distance - radius).max(0.0);
                Residual {
                    correction: -normal * excess,
                    projector: DMat3::IDENTITY,
                    error: excess,
                }
            }
        }
    }
}

/// A tolerance constrains the step from this fraction of its size inside its boundary on
/// (with no correction there, only holding the boundary): a constraint switched on only
/// once outside makes the damped steps go back and forth across the boundary.
pub(crate) const ACTIVE_BAND: f64 = 0.1;

/// `a bᵀ`.
pub(crate) fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_points_at_the_target() {
        let r = PositionTolerance::Exact.residual(DVec3::X, &DMat3::IDENTITY, DVec3::ZERO);
        assert_eq!(r.correction, DVec3::X);
        assert_eq!(r.error, 1.0);
    }

    #[test]
    fn a_box_in_a_turned_frame_constrains_only_the_axes_outside() {
        // The target frame turned 90° about z: its x axis is the world's y.
        let rotation = DMat3::from_rotation_z(std::f64::consts::FRAC_PI_2);
        let tolerance = PositionTolerance::Box {
            half_extents: DVec3::new(0.1, 0.5, 0.5),
        };
        // 0.3 along the world's y is 0.3 along the target's x: 0.2 outside.
        let r = tolerance.residual(DVec3::ZERO, &rotation, DVec3::new(0.2, 0.3, 0.0));
        assert!((r.error - 0.2).abs() < 1e-12);
        assert!((r.correction - DVec3::new(0.0, -0.2, 0.0)).length() < 1e-12);
        assert!((r.projector * DVec3::X).length() < 1e-12);
        assert!((r.projector * DVec3::Y - DVec3::Y).length() < 1e-12);
        let inside = tolerance.residual(DVec3::ZERO, &rotation, DVec3::new(0.4, 0.05, 0.0));
        assert_eq!(inside.error, 0.0);
        assert_eq!(inside.projector, DMat3::ZERO);
        // Inside near the x face: held there, not pulled.
        let near = tolerance.residual(DVec3::ZERO, &rotation, DVec3::new(0.0, 0.095, 0.0));
        assert_eq!((near.error, near.correction), (0.0, DVec3::ZERO));
        assert!((near.projector * DVec3::Y - DVec3::Y).length() < 1e-12);
    }

    #[test]
    fn a_ball_is_free_inside_and_pulls_radially_outside() {
        let ball = PositionTolerance::Ball { radius: 0.1 };
        assert_eq!(
            ball.residual(DVec3::ZERO, &DMat3::IDENTITY, DVec3::new(0.05, 0.0, 0.0)),
            Residual::FREE
        );
        let exact = PositionTolerance::Ball { radius: 0.0 };
        let r = exact.residual(DVec3::ZERO, &DMat3::IDENTITY, DVec3::X);
        assert_eq!((r.projector, r.error), (DMat3::IDENTITY, 1.0));
        let r = ball.residual(DVec3::ZERO, &DMat3::IDENTITY, DVec3::new(0.0, 0.3, 0.0));
        assert!((r.error - 0.2).abs() < 1e-12);
        assert!((r.correction - DVec3::new(0.0, -0.2, 0.0)).length() < 1e-12);
    }

    #[test]
    fn negative_and_nan_sizes_are_named() {
        let e = PositionTolerance::Ball { radius: -1.0 }
            .validate()
            .unwrap_err();
        assert!(e.to_string().contains("ball radius"), "{e}");
        let e = PositionTolerance::Box {
            half_extents: DVec3::new(0.1, f64::NAN, 0.1),
        }
        .validate()
        .unwrap_err();
        assert!(e.to_string().contains("half-extent y"), "{e}");
        assert!(PositionTolerance::Exact.validate().is_ok());
    }
}
