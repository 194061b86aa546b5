//! [`OrientationTolerance`]: the set of orientations a target accepts, and the residual the
//! solver drives to zero (the rotation from the current orientation into the set).

use std::f64::consts::PI;

use glam::{DMat3, DQuat, DVec3};

use crate::IkError;
use crate::inverse_kinematics::position_tolerance::{ACTIVE_BAND, Residual, outer};

/// How the frame may be turned about the target orientation.
///
/// Axes are in the frame's own coordinates (the link's, or the tool's when the solver has a
/// tool offset): `DVec3::Z` is the frame's z axis, e.g. a gripper's approach direction. They
/// are checked and normalised when attached to a [`PoseTarget`](crate::PoseTarget). The
/// error the solver measures is the angle from the frame's orientation to the set: zero
/// anywhere inside it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OrientationTolerance {
    /// Exactly the target orientation.
    Exact,
    /// The frame's `axis` must point within `half_angle` of where the target orientation
    /// puts that axis; rotation about it is free (a grasp that may tilt a little and spin).
    Cone {
        /// The axis, in the frame's coordinates (finite, non-zero; normalised).
        axis: DVec3,
        /// The cone's half-angle in radians, in `[0, π]`.
        half_angle: f64,
    },
    /// The frame's `axis` must point exactly where the target orientation puts it; rotation
    /// about it is free (a symmetric object grasped from above).
    FreeAxis {
        /// The axis, in the frame's coordinates (finite, non-zero; normalised).
        axis: DVec3,
    },
    /// Any orientation: a position-only target.
    Free,
}

impl OrientationTolerance {
    /// This tolerance checked, its axis normalised.
    pub(crate) fn validated(self) -> Result<Self, IkError> {
        let unit = |what, axis: DVec3| {
            let bad = IkError::BadAxis {
                what,
                axis: axis.to_array(),
            };
            if axis.is_finite() {
                axis.try_normalize().ok_or(bad)
            } else {
                Err(bad)
            }
        };
        Ok(match self {
            Self::Exact | Self::Free => self,
            Self::Cone { axis, half_angle } => {
                if !(half_angle.is_finite() && (0.0..=PI).contains(&half_angle)) {
                    return Err(IkError::BadTolerance {
                        what: "cone half-angle",
                        value: half_angle,
                        expected: "an angle in [0, π] rad",
                    });
                }
                Self::Cone {
                    axis: unit("cone", axis)?,
                    half_angle,
                }
            }
            Self::FreeAxis { axis } => Self::FreeAxis {
                axis: unit("free-rotation", axis)?,
            },
        })
    }

    /// The residual of orientation `current` against `target`: the rotation vector (world
    /// frame) into the set, the projector onto the constrained rotation directions, and the
    /// angle.
    pub(crate) fn residual(&self, target: &DMat3, current: &DMat3) -> Residual {
        match *self {
            Self::Exact => {
                let correction =
                    rotation_vector(DQuat::from_mat3(&(*target * current.transpose())));
                Residual {
                    correction,
                    projector: DMat3::IDENTITY,
                    error: correction.length(),
                }
            }
            Self::Cone { axis, half_angle } => axis_residual(target, current, axis, half_angle),
            Self::FreeAxis { axis } => axis_residual(target, current, axis, 0.0),
            Self::Free => Residual::FREE,
        }
    }
}

/// The residual of an axis that must lie within `half_angle` of its target direction: the
/// turn by the excess angle towards it, both turns perpendicular to the axis held (from
/// [`ACTIVE_BAND`] of the half-angle inside the cone on, with no correction there). Rotation
/// about the axis itself is never constrained.
fn axis_residual(target: &DMat3, current: &DMat3, axis: DVec3, half_angle: f64) -> Residual {
    let u = *current * axis;
    let v = *target * axis;
    let angle = angle_between(u, v);
    if angle < half_angle * (1.0 - ACTIVE_BAND) {
        return Residual::FREE;
    }
    let normal = u
        .cross(v)
        .try_normalize()
        .unwrap_or_else(|| u.any_orthonormal_vector());
    let excess = (angle - half_angle).max(0.0);
    Residual {
        correction: normal * excess,
        projector: DMat3::IDENTITY - outer(u, u) / u.length_squared(),
        error: excess,
    }
}

/// The angle between two vectors, accurate near 0 and π (atan2 of the cross and dot
/// products).
pub(crate) fn angle_between(u: DVec3, v: DVec3) -> f64 {
    u.cross(v).length().atan2(u.dot(v))
}

/// The rotation vector (axis times angle in `[0, π]`) of a unit quaternion.
pub(crate) fn rotation_vector(q: DQuat) -> DVec3 {
    let q = if q.w < 0.0 { -q } else { q };
    let v = DVec3::new(q.x, q.y, q.z);
    let s = v.length();
    if s < 1e-300 {
        return DVec3::ZERO;
    }
    v * (2.0 * s.atan2(q.w) / s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_gives_the_rotation_from_current_to_target() {
        let target = DMat3::from_rotation_x(0.3);
        let r = OrientationTolerance::Exact.residual(&target, &DMat3::IDENTITY);
        assert!((r.correction - DVec3::new(0.3, 0.0, 0.0)).length() < 1e-12);
        assert!((r.error - 0.3).abs() < 1e-12);
        let half_turn = DMat3::from_rotation_y(PI);
        let r = OrientationTolerance::Exact.residual(&half_turn, &DMat3::IDENTITY);
        assert!((r.error - PI).abs() < 1e-9, "{}", r.error);
    }

    #[test]
    fn a_cone_is_free_inside_and_turns_by_the_excess_outside() {
        let cone = OrientationTolerance::Cone {
            axis: DVec3::Z,
            half_angle: 0.2,
        };
        // Tilted 0.1 about x, and spun about z: inside.
        let current = DMat3::from_rotation_x(0.1) * DMat3::from_rotation_z(2.0);
        assert_eq!(cone.residual(&DMat3::IDENTITY, &current), Residual::FREE);
        let current = DMat3::from_rotation_x(0.5);
        let r = cone.residual(&DMat3::IDENTITY, &current);
        assert!((r.error - 0.3).abs() < 1e-12);
        // Turning back about −x.
        assert!((r.correction - DVec3::new(-0.3, 0.0, 0.0)).length() < 1e-12);
        // The current axis is free.
        let u = current * DVec3::Z;
        assert!((r.projector * u).length() < 1e-12);
    }

    #[test]
    fn a_free_axis_ignores_spin_about_it() {
        let free = OrientationTolerance::FreeAxis { axis: DVec3::Z };
        let spun = DMat3::from_rotation_z(1.0);
        assert_eq!(free.residual(&DMat3::IDENTITY, &spun).error, 0.0);
        let flipped = DMat3::from_rotation_x(PI);
        let r = free.residual(&DMat3::IDENTITY, &flipped);
        assert!((r.error - PI).abs() < 1e-12);
        assert!(r.correction.length() > 3.0);
    }

    #[test]
    fn validation_names_the_axis_and_the_angle_and_normalises() {
        let e = OrientationTolerance::Cone {
            axis: DVec3::ZERO,
            half_angle: 0.1,
        }
        .validated()
        .unwrap_err();
        assert!(e.to_string().contains("cone axis"), "{e}");
        let e = OrientationTolerance::Cone {
            axis: DVec3::Z,
            half_angle: -0.1,
        }
        .validated()
        .unwrap_err();
        assert!(e.to_string().contains("cone half-angle"), "{e}");
        let e = OrientationTolerance::FreeAxis {
            axis: DVec3::new(f64::INFINITY, 0.0, 0.0),
        }
        .validated()
        .unwrap_err();
        assert!(matches!(e, IkError::BadAxis { .. }), "{e}");
        let ok = OrientationTolerance::FreeAxis {
            axis: DVec3::new(0.0, 0.0, 2.0),
        }
        .validated()
        .unwrap();
        assert_eq!(ok, OrientationTolerance::FreeAxis { axis: DVec3::Z });
    }
}
