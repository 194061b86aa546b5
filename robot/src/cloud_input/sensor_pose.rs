//! [`SensorPose`]: where the camera was, to bring its cloud into the robot's base frame.

use glam::{DAffine3, DMat3, DQuat, DVec3, Vec3};

use super::cloud_input_error::CloudInputError;

/// A rigid transform from a sensor's frame to the robot's base frame: a camera's cloud comes
/// in the camera's frame, and `p_base = rotation · p_camera + translation`.
///
/// ```
/// use glam::{DQuat, DVec3, Vec3};
/// // A camera 1 m above the base, looking down (its z axis along the base's −z).
/// let pose = mit_star_robot::SensorPose::new(
///     DVec3::new(0.0, 0.0, 1.0),
///     DQuat::from_rotation_x(std::f64::consts::PI),
/// )?;
/// let mut points = vec![Vec3::new(0.0, 0.0, 0.75)];
/// pose.apply(&mut points);
/// assert!((points[0] - Vec3::new(0.0, 0.0, 0.25)).length() < 1e-6);
/// # Ok::<(), mit_star_robot::CloudInputError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorPose {
    rotation: DQuat,
    translation: DVec3,
}

impl SensorPose {
    /// The identity: the cloud is already in the base frame.
    pub const IDENTITY: Self = Self {
        rotation: DQuat::IDENTITY,
        translation: DVec3::ZERO,
    };

    /// The sensor at `translation`, turned by `rotation` (normalised here; any non-zero
    /// finite quaternion is accepted, as ROS's `tf` does).
    ///
    /// # Errors
    /// [`CloudInputError::Parameter`] for a coordinate that is not finite or a quaternion
    /// of length 0.
    pub fn new(translation: DVec3, rotation: DQuat) -> Result<Self, CloudInputError> {
        let bad = |message: String| CloudInputError::Parameter {
            what: "sensor pose",
            message,
        };
        if !translation.is_finite() {
            return Err(bad(format!("translation {translation} is not finite")));
        }
        let length = rotation.length();
        if !rotation.is_finite() || length < 1e-9 {
            return Err(bad(format!(
                "rotation {rotation} is not a rotation (a finite, non-zero quaternion)"
            )));
        }
        Ok(Self {
            rotation: rotation / length,
            translation,
        })
    }

    /// The sensor at `xyz`, turned by roll, pitch and yaw (radians, about fixed x, y, z:
    /// URDF's and ROS's `static_transform_publisher` convention).
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn from_xyz_rpy(xyz: [f64; 3], rpy: [f64; 3]) -> Result<Self, CloudInputError> {
        if !rpy.iter().all(|a| a.is_finite()) {
            return Err(CloudInputError::Parameter {
                what: "sensor pose",
                message: format!("roll, pitch, yaw {rpy:?} are not finite"),
            });
        }
        Self::new(
            DVec3::from_array(xyz),
            DQuat::from_mat3(&crate::rpy_matrix(rpy)),
        )
    }

    /// A camera's extrinsic matrix as an affine transform, which must be rigid: its linear
    /// part a rotation within 1e-6 (orthonormal columns, determinant +1).
    ///
    /// # Errors
    /// [`CloudInputError::Parameter`] for a matrix with scale, shear or reflection, or one
    /// that is not finite.
    pub fn from_affine(transform: DAffine3) -> Result<Self, CloudInputError> {
        let m: DMat3 = transform.matrix3;
        let gram = m.transpose() * m;
        let off = (gram - DMat3::IDENTITY)
            .to_cols_array()
            .iter()
            .fold(0.0_f64, |a, &b| a.max(b.abs()));
        if !transform.is_finite() || off > 1e-6 || m.determinant() <= 0.0 {
            return Err(CloudInputError::Parameter {
                what: "sensor pose",
                message: format!(
                    "the matrix is not a rigid transform (a rotation and a translation): \
                     its columns are {off:.3e} from orthonormal, determinant {:.6}",
                    m.determinant()
                ),
            });
        }
        Self::new(transform.translation, DQuat::from_mat3(&m))
    }

    /// The rotation (unit quaternion).
    pub fn rotation(&self) -> DQuat {
        self.rotation
    }

    /// The translation.
    pub fn translation(&self) -> DVec3 {
        self.translation
    }

    /// The transform as an affine map.
    pub fn affine(&self) -> DAffine3 {
        DAffine3::from_rotation_translation(self.rotation, self.translation)
    }

    /// Moves every point from the sensor's frame into the base frame, in place (computed in
    /// `f64`, stored in `f32`).
    pub fn apply(&self, points: &mut [Vec3]) {
        let affine = self.affine();
        for p in points {
            *p = affine.transform_point3(p.as_dvec3()).as_vec3();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn poses_compose_as_the_affine_map_and_refuse_non_rigid_matrices() {
        let pose = SensorPose::from_xyz_rpy([0.5, -0.2, 1.1], [0.3, -1.2, 2.0]).unwrap();
        let mut points = vec![Vec3::new(0.1, 0.2, 0.3), Vec3::new(-1.0, 0.5, 2.0)];
        let expected: Vec<Vec3> = points
            .iter()
            .map(|p| pose.affine().transform_point3(p.as_dvec3()).as_vec3())
            .collect();
        pose.apply(&mut points);
        assert_eq!(points, expected);
        let again = SensorPose::from_affine(pose.affine()).unwrap();
        assert!((again.translation() - pose.translation()).length() < 1e-12);
        assert!(again.rotation().angle_between(pose.rotation()) < 1e-9);
        let scaled = DAffine3::from_scale(DVec3::splat(2.0));
        assert!(SensorPose::from_affine(scaled).is_err());
        let mirror = DAffine3::from_scale(DVec3::new(1.0, 1.0, -1.0));
        assert!(SensorPose::from_affine(mirror).is_err());
        assert!(SensorPose::new(DVec3::ZERO, DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)).is_err());
        assert!(SensorPose::new(DVec3::new(f64::NAN, 0.0, 0.0), DQuat::IDENTITY).is_err());
        let e = SensorPose::from_xyz_rpy([0.0; 3], [f64::INFINITY, 0.0, 0.0]).unwrap_err();
        assert!(e.to_string().starts_with("sensor pose:"), "{e}");
    }
}
