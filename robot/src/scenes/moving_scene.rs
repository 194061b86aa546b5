//! [`MovingScene`]: fixed obstacles and [`MovingObstacle`]s, as a [`Scene`] at any time or
//! swept over a time interval.

use crate::{MovingObstacle, Obstacle, Scene};

/// A scene whose obstacles are partly fixed and partly moving: [`at`](Self::at) is the scene
/// at one time, [`swept`](Self::swept) the scene with every moving obstacle replaced by the
/// box it sweeps over an interval (a scene in which a configuration is free is free of the
/// moving obstacles at every time of the interval).
///
/// ```
/// use glam::DVec3;
/// use robot::{MovingObstacle, MovingScene};
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
/// # Ok::<(), robot::SceneError>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MovingScene {
    fixed: Vec<Obstacle>,
    moving: Vec<MovingObstacle>,
}

impl MovingScene {
    /// A scene of `fixed` obstacles and `moving` ones.
    pub fn new(fixed: Vec<Obstacle>, moving: Vec<MovingObstacle>) -> Self {
        Self { fixed, moving }
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

    /// The scene over `[t0, t1]`: the fixed obstacles, then each moving obstacle's swept box.
    pub fn swept(&self, t0: f64, t1: f64) -> Scene {
        let moving = self
            .moving
            .iter()
            .map(|m| if t0 == t1 { m.at(t0) } else { m.swept(t0, t1) });
        Scene::new(self.fixed.iter().copied().chain(moving).collect())
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
}
