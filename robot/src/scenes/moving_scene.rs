//! [`MovingScene`]: fixed obstacles and [`MovingObstacle`]s, as a [`Scene`] at any time or
//! swept over a time interval.

use std::sync::Arc;

use crate::{CloudObstacle, MovingObstacle, Obstacle, Scene};

/// A scene whose obstacles are partly fixed and partly moving: [`at`](Self::at) is the scene
/// at one time, [`swept`](Self::swept) the scene with every moving obstacle replaced by the
/// box it sweeps over an interval (a scene in which a configuration is free is free of the
/// moving obstacles at every time of the interval). Point clouds stand still: every scene
/// it makes shares them ([`with_cloud`](Self::with_cloud)).
///
/// ```
/// use glam::DVec3;
/// use mit_star_robot::{MovingObstacle, MovingScene};
/// let slider = MovingObstacle::new(
///     "slider",
///     DVec3::splat(0.05),
///     (DVec3::new(0.5, -0.3, 0.3), DVec3::new(0.5, 0.3, 0.3)),
///     0.3,
///     0.0,
/// )?;
/// let scene = MovingScene::new(Vec::new(), vec![slider]);
/// assert_eq!(scene.at(1.0).obstacles().len(), 1);
/// let (_, high) = scene.moving()[0].swept_bounds(0.0, 1.0);
/// assert!((high.y - 0.05).abs() < 1e-12);
/// # Ok::<(), mit_star_robot::SceneError>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MovingScene {
    fixed: Vec<Obstacle>,
    moving: Vec<MovingObstacle>,
    clouds: Vec<Arc<CloudObstacle>>,
}

impl MovingScene {
    /// A scene of `fixed` obstacles and `moving` ones.
    pub fn new(fixed: Vec<Obstacle>, moving: Vec<MovingObstacle>) -> Self {
        Self {
            fixed,
            moving,
            clouds: Vec::new(),
        }
    }

    /// The scene with `cloud` among its fixed obstacles: every scene [`at`](Self::at) and
    /// [`swept`](Self::swept) make shares it (its tree is built once).
    #[must_use]
    pub fn with_cloud(mut self, cloud: Arc<CloudObstacle>) -> Self {
        self.clouds.push(cloud);
        self
    }

    /// The point clouds, which stand still.
    pub fn clouds(&self) -> &[Arc<CloudObstacle>] {
        &self.clouds
    }

    /// The obstacles that stand still.
    pub fn fixed(&self) -> &[Obstacle] {
        &self.fixed
    }

    /// The obstacles that move.
    pub fn moving(&self) -> &[MovingObstacle] {
        &self.moving
    }

    /// The scene at time `t`: the fixed obstacles, then the moving ones where they are.
    pub fn at(&self, t: f64) -> Scene {
        self.swept(t, t)
    }

    /// The scene over `[t0, t1]`: the fixed obstacles, then each moving obstacle's swept box,
    /// and the clouds.
    pub fn swept(&self, t0: f64, t1: f64) -> Scene {
        let moving = self
            .moving
            .iter()
            .map(|m| if t0 == t1 { m.at(t0) } else { m.swept(t0, t1) });
        let mut scene = Scene::new(self.fixed.iter().copied().chain(moving).collect());
        for cloud in &self.clouds {
            scene.add_shared_cloud(Arc::clone(cloud));
        }
        scene
    }
}

#[cfg(test)]
mod tests {
    use glam::{DQuat, DVec3};

    use super::*;
    use crate::Shape;

    #[test]
    fn fixed_obstacles_stay_and_moving_ones_sweep() {
        let table = Obstacle::new(
            Shape::Cuboid {
                half_extents: DVec3::new(0.3, 0.6, 0.05),
            },
            DVec3::new(0.6, 0.0, -0.05),
            DQuat::IDENTITY,
        );
        let slider = MovingObstacle::new(
            "slider",
            DVec3::splat(0.05),
            (DVec3::new(0.5, -0.3, 0.3), DVec3::new(0.5, 0.3, 0.3)),
            0.3,
            0.0,
        )
        .unwrap();
        let scene = MovingScene::new(vec![table], vec![slider]);
        let now = scene.at(0.0);
        assert_eq!(now.obstacles().len(), 2);
        assert_eq!(now.obstacles()[0], table);
        let probe = DVec3::new(0.5, 0.0, 0.3);
        assert!(!now.obstacles()[1].collides_sphere_f64(probe, 0.01));
        assert!(scene.at(1.0).obstacles()[1].collides_sphere_f64(probe, 0.01));
        assert!(scene.swept(0.5, 1.5).obstacles()[1].collides_sphere_f64(probe, 0.01));
        assert!(!scene.swept(0.0, 0.5).obstacles()[1].collides_sphere_f64(probe, 0.01));
    }

    #[test]
    fn a_cloud_is_in_every_scene_and_shared() {
        let points = vec![
            glam::Vec3::new(0.5, 0.0, 0.3),
            glam::Vec3::new(0.5, 0.1, 0.3),
        ];
        let cloud = Arc::new(CloudObstacle::new(
            "scan",
            crate::PointCloud::new(points).unwrap(),
        ));
        let scene = MovingScene::new(Vec::new(), Vec::new()).with_cloud(Arc::clone(&cloud));
        for snapshot in [scene.at(0.0), scene.swept(1.0, 2.0)] {
            assert_eq!(snapshot.clouds().len(), 1);
            assert!(Arc::ptr_eq(&snapshot.clouds()[0], &cloud));
        }
        assert!(
            MovingScene::new(Vec::new(), Vec::new())
                .at(0.0)
                .clouds()
                .is_empty()
        );
    }
}
