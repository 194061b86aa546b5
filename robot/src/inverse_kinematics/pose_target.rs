//! [`PoseTarget`]: where a frame of the robot should be, and how closely.

use glam::{DAffine3, DMat3, DQuat, DVec3};

use crate::IkError;
use crate::inverse_kinematics::position_tolerance::Residual;
use crate::{OrientationTolerance, PositionTolerance};

/// A target pose for the solver's frame (its link, or the tool frame offset from it, see
/// [`IkSolver`](crate::IkSolver)) in the robot's base frame: a position and an orientation,
/// each with a tolerance.
///
/// Checked once, when built: a NaN or infinite position, a quaternion with a NaN or infinite
/// component or of norm 0, and negative or NaN tolerances are refused with a typed
/// [`IkError`]. **A finite non-zero quaternion is normalised**: `DQuat::from_xyzw(0, 0, 0, 2)`
/// is the identity.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use mit_star_robot::{OrientationTolerance, PoseTarget, PositionTolerance};
/// // The gripper 0.5 m ahead, pointing down (its z axis along −z), within 5°, spin free.
/// let target = PoseTarget::new(DVec3::new(0.5, 0.0, 0.3), DQuat::from_rotation_x(std::f64::consts::PI))?
///     .with_position_tolerance(PositionTolerance::Ball { radius: 0.005 })?
///     .with_orientation_tolerance(OrientationTolerance::Cone {
///         axis: DVec3::Z,
///         half_angle: 5f64.to_radians(),
///     })?;
/// assert_eq!(target.position(), DVec3::new(0.5, 0.0, 0.3));
/// assert!(PoseTarget::new(DVec3::ZERO, DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)).is_err());
/// # Ok::<(), mit_star_robot::IkError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseTarget {
    position: DVec3,
    orientation: DQuat,
    /// The orientation as a matrix (the residuals' form).
    rotation: DMat3,
    position_tolerance: PositionTolerance,
    orientation_tolerance: OrientationTolerance,
}

impl PoseTarget {
    /// The exact pose `position`, `orientation` (normalised).
    ///
    /// # Errors
    /// [`IkError::BadPosition`] for a non-finite position, [`IkError::BadQuaternion`] for a
    /// quaternion with a non-finite component or of norm 0.
    pub fn new(position: DVec3, orientation: DQuat) -> Result<Self, IkError> {
        if !position.is_finite() {
            return Err(IkError::BadPosition {
                position: position.to_array(),
            });
        }
        let bad = |why| IkError::BadQuaternion {
            quaternion: orientation.to_array(),
            why,
        };
        if !orientation.is_finite() {
            return Err(bad("components must be finite"));
        }
        // Scaled by the largest component first: tiny and huge quaternions normalise too.
        let largest = (orientation.to_array().into_iter()).fold(0.0, |m: f64, c| m.max(c.abs()));
        if largest == 0.0 {
            return Err(bad("norm 0 is not a rotation"));
        }
        let scaled = orientation / largest;
        let orientation = scaled / scaled.length();
        Ok(Self {
            position,
            orientation,
            rotation: DMat3::from_quat(orientation),
            position_tolerance: PositionTolerance::Exact,
            orientation_tolerance: OrientationTolerance::Exact,
        })
    }

    /// The exact pose `pose`.
    ///
    /// # Errors
    /// As [`new`](Self::new), for the position and the quaternion of the rotation part;
    /// [`IkError::BadQuaternion`] also for a rotation part that is not orthonormal with
    /// determinant 1 (within 1e-6): a scaled or sheared transform is not a pose.
    pub fn from_pose(pose: &DAffine3) -> Result<Self, IkError> {
        let m = pose.matrix3;
        if !m.is_finite() {
            let nan = DQuat::from_xyzw(f64::NAN, f64::NAN, f64::NAN, f64::NAN);
            return Self::new(pose.translation, nan);
        }
        let quaternion = DQuat::from_mat3(&m);
        let rigid = (m.transpose() * m).abs_diff_eq(DMat3::IDENTITY, 1e-6)
            && (m.determinant() - 1.0).abs() <= 1e-6;
        if !rigid {
            return Err(IkError::BadQuaternion {
                quaternion: quaternion.to_array(),
                why: "the pose's rotation part is not a rotation",
            });
        }
        Self::new(pose.translation, quaternion)
    }

    /// This target with the position tolerance `tolerance`.
    ///
    /// # Errors
    /// [`IkError::BadTolerance`] for a negative, NaN or infinite size.
    pub fn with_position_tolerance(
        mut self,
        tolerance: PositionTolerance,
    ) -> Result<Self, IkError> {
        tolerance.validate()?;
        self.position_tolerance = tolerance;
        Ok(self)
    }

    /// This target with the orientation tolerance `tolerance` (its axis normalised).
    ///
    /// # Errors
    /// [`IkError::BadAxis`] for a zero or non-finite axis, [`IkError::BadTolerance`] for a
    /// half-angle outside `[0, π]` or NaN.
    pub fn with_orientation_tolerance(
        mut self,
        tolerance: OrientationTolerance,
    ) -> Result<Self, IkError> {
        self.orientation_tolerance = tolerance.validated()?;
        Ok(self)
    }

    /// The target position.
    pub fn position(&self) -> DVec3 {
        self.position
    }

    /// The target orientation (a unit quaternion).
    pub fn orientation(&self) -> DQuat {
        self.orientation
    }

    /// The position tolerance.
    pub fn position_tolerance(&self) -> PositionTolerance {
        self.position_tolerance
    }

    /// The orientation tolerance (its axis normalised).
    pub fn orientation_tolerance(&self) -> OrientationTolerance {
        self.orientation_tolerance
    }

    /// How far `pose` is from this target: the distance from its origin to the position
    /// tolerance set (metres) and the angle from its orientation to the orientation tolerance
    /// set (radians); both zero inside the sets.
    pub fn errors(&self, pose: &DAffine3) -> (f64, f64) {
        let (p, o) = self.residuals(pose);
        (p.error, o.error)
    }

    /// The position and orientation residuals of `pose`.
    pub(crate) fn residuals(&self, pose: &DAffine3) -> (Residual, Residual) {
        (
            self.position_tolerance
                .residual(self.position, &self.rotation, pose.translation),
            self.orientation_tolerance
                .residual(&self.rotation, &pose.matrix3),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternions_are_normalised_and_bad_ones_named() {
        let t = PoseTarget::new(DVec3::ZERO, DQuat::from_xyzw(0.0, 0.0, 0.0, 2.0)).unwrap();
        assert_eq!(t.orientation(), DQuat::IDENTITY);
        for (q, why) in [
            (DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), "norm 0"),
            (DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0), "finite"),
            (DQuat::from_xyzw(0.0, f64::INFINITY, 0.0, 1.0), "finite"),
        ] {
            let e = PoseTarget::new(DVec3::ZERO, q).unwrap_err();
            assert!(matches!(e, IkError::BadQuaternion { .. }), "{e}");
            assert!(e.to_string().contains(why), "{e}");
        }
        // Tiny or huge but non-zero and finite: normalised, not refused.
        for scale in [1e-200, 1e300] {
            let q = DQuat::from_xyzw(0.0, scale, 0.0, scale);
            let t = PoseTarget::new(DVec3::ZERO, q).unwrap();
            assert!((t.orientation().length() - 1.0).abs() < 1e-12);
        }
        let e = PoseTarget::new(DVec3::new(0.0, f64::NAN, 0.0), DQuat::IDENTITY).unwrap_err();
        assert!(matches!(e, IkError::BadPosition { .. }), "{e}");
    }

    #[test]
    fn errors_are_zero_inside_the_tolerances() {
        let t = PoseTarget::new(DVec3::ZERO, DQuat::IDENTITY)
            .unwrap()
            .with_position_tolerance(PositionTolerance::Ball { radius: 0.1 })
            .unwrap()
            .with_orientation_tolerance(OrientationTolerance::Free)
            .unwrap();
        let near =
            DAffine3::from_rotation_translation(DQuat::from_rotation_y(1.0), DVec3::X * 0.05);
        assert_eq!(t.errors(&near), (0.0, 0.0));
        let far = DAffine3::from_translation(DVec3::X * 0.3);
        let (p, o) = t.errors(&far);
        assert!((p - 0.2).abs() < 1e-12 && o == 0.0);
        assert!(PoseTarget::from_pose(&far).is_ok());
        let bad = DAffine3::from_translation(DVec3::new(f64::INFINITY, 0.0, 0.0));
        assert!(PoseTarget::from_pose(&bad).is_err());
        let scaled = DAffine3::from_scale(DVec3::new(1.0, 2.0, 1.0));
        let e = PoseTarget::from_pose(&scaled).unwrap_err();
        assert!(e.to_string().contains("not a rotation"), "{e}");
    }
}
