//! [`MovingObstacle`]: an axis-aligned box going back and forth along a straight line at a
//! constant speed, where it is at any time, and the box it sweeps over a time interval.

use glam::{DQuat, DVec3};

use crate::{Obstacle, SceneError, Shape};

/// An axis-aligned box whose centre goes back and forth between two points at a constant
/// speed: from `from` to `to`, then back, forever (a triangle wave; the turns are
/// instantaneous). At time `t` it is where it would be `t + offset` seconds after leaving
/// `from`, so obstacles on the same line with offsets half a period apart move in opposite
/// directions.
///
/// [`swept`](Self::swept) is the smallest axis-aligned box holding every position of the box
/// over a time interval: exactly the swept volume when the line is parallel to an axis (the
/// obstacles of the re-planning scenes move along x, y or z), a box holding it otherwise.
///
/// ```
/// use glam::DVec3;
/// use mit_star_robot::MovingObstacle;
/// let lift = MovingObstacle::new(
///     "lift",
///     DVec3::splat(0.05),
///     (DVec3::new(0.5, 0.0, 0.1), DVec3::new(0.5, 0.0, 0.5)),
///     0.2,
///     0.0,
/// )?;
/// assert!((lift.period() - 4.0).abs() < 1e-12);
/// assert!((lift.center_at(1.0).z - 0.3).abs() < 1e-12); // going up
/// assert!((lift.center_at(3.0).z - 0.3).abs() < 1e-12); // coming down
/// let (low, high) = lift.swept_bounds(1.5, 2.5); // over the top turn
/// assert!((low.z - 0.35).abs() < 1e-12 && (high.z - 0.55).abs() < 1e-12);
/// # Ok::<(), mit_star_robot::SceneError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MovingObstacle {
    id: String,
    half_extents: DVec3,
    from: DVec3,
    to: DVec3,
    speed: f64,
    offset: f64,
}

impl MovingObstacle {
    /// A box of `half_extents` whose centre goes back and forth between `ends` at `speed`
    /// metres per second, `offset` seconds into its cycle at time 0. Equal ends or a zero speed
    /// make a box that stands still.
    ///
    /// # Errors
    /// [`SceneError::Field`] naming the obstacle for a half extent that is not in
    /// (0, [`Scene::MAX_LENGTH`](crate::Scene::MAX_LENGTH)], an end coordinate that is not
    /// finite within ±`MAX_LENGTH`, or a speed or offset that is negative or not finite.
    pub fn new(
        id: impl Into<String>,
        half_extents: DVec3,
        (from, to): (DVec3, DVec3),
        speed: f64,
        offset: f64,
    ) -> Result<Self, SceneError> {
        let id = id.into();
        let max = crate::Scene::MAX_LENGTH;
        let fail = |field: &str, message: String| SceneError::Field {
            origin: format!("moving obstacle `{id}`"),
            field: field.to_owned(),
            message,
        };
        if !half_extents.to_array().iter().all(|&h| h > 0.0 && h <= max) {
            return Err(fail(
                "half_extents",
                format!("{half_extents} must be in (0, 1e6] m"),
            ));
        }
        for (field, end) in [("from", from), ("to", to)] {
            if !end
                .to_array()
                .iter()
                .all(|&c| c.is_finite() && c.abs() <= max)
            {
                return Err(fail(field, format!("{end} must be finite, within ±1e6 m")));
            }
        }
        for (field, value) in [("speed", speed), ("offset", offset)] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(fail(field, format!("{value} must be finite and ≥ 0")));
            }
        }
        Ok(Self {
            id,
            half_extents,
            from,
            to,
            speed,
            offset,
        })
    }

    /// The obstacle's name.
    pub fn id(&self) -> &str {
        &self.id
    }

    /// Half side lengths of the box.
    pub fn half_extents(&self) -> DVec3 {
        self.half_extents
    }

    /// The two ends of the centre's line.
    pub fn ends(&self) -> (DVec3, DVec3) {
        (self.from, self.to)
    }

    /// Speed in metres per second.
    pub fn speed(&self) -> f64 {
        self.speed
    }

    /// Seconds for one round trip (`∞` for a box that stands still).
    pub fn period(&self) -> f64 {
        let length = self.from.distance(self.to);
        if length == 0.0 || self.speed == 0.0 {
            f64::INFINITY
        } else {
            2.0 * length / self.speed
        }
    }

    /// Where along the line the centre is at `t`: 0 at `from`, 1 at `to`.
    pub fn fraction_at(&self, t: f64) -> f64 {
        let period = self.period();
        if !period.is_finite() {
            return 0.0;
        }
        let u = ((t + self.offset) / period).rem_euclid(1.0);
        if u < 0.5 { 2.0 * u } else { 2.0 - 2.0 * u }
    }

    /// The centre at time `t`.
    pub fn center_at(&self, t: f64) -> DVec3 {
        self.from.lerp(self.to, self.fraction_at(t))
    }

    /// The box at time `t`.
    pub fn at(&self, t: f64) -> Obstacle {
        cuboid(self.center_at(t), self.half_extents)
    }

    /// The smallest and largest fractions along the line over `[t0, t1]` (`t0 ≤ t1`; swapped
    /// otherwise).
    pub fn fraction_range(&self, t0: f64, t1: f64) -> (f64, f64) {
        let (t0, t1) = (t0.min(t1), t0.max(t1));
        let period = self.period();
        if !period.is_finite() {
            return (0.0, 0.0);
        }
        if t1 - t0 >= period {
            return (0.0, 1.0);
        }
        let (a, b) = (self.fraction_at(t0), self.fraction_at(t1));
        let (mut low, mut high) = (a.min(b), a.max(b));
        // The turns inside the interval: at `to` (half a cycle) and at `from` (whole cycles).
        let (u0, u1) = ((t0 + self.offset) / period, (t1 + self.offset) / period);
        if (u1 - 0.5).floor() > (u0 - 0.5).floor() {
            high = 1.0;
        }
        if u1.floor() > u0.floor() {
            low = 0.0;
        }
        (low, high)
    }

    /// The corners (lowest, highest) of the axis-aligned box holding every position of the
    /// box over `[t0, t1]`.
    pub fn swept_bounds(&self, t0: f64, t1: f64) -> (DVec3, DVec3) {
        let (low, high) = self.fraction_range(t0, t1);
        let (a, b) = (self.from.lerp(self.to, low), self.from.lerp(self.to, high));
        (a.min(b) - self.half_extents, a.max(b) + self.half_extents)
    }

    /// The axis-aligned box holding every position of the box over `[t0, t1]`, as an obstacle.
    pub fn swept(&self, t0: f64, t1: f64) -> Obstacle {
        let (low, high) = self.swept_bounds(t0, t1);
        cuboid((low + high) * 0.5, (high - low) * 0.5)
    }
}

/// An axis-aligned box obstacle.
fn cuboid(center: DVec3, half_extents: DVec3) -> Obstacle {
    Obstacle::new(Shape::Cuboid { half_extents }, center, DQuat::IDENTITY)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lift(offset: f64) -> MovingObstacle {
        MovingObstacle::new(
            "lift",
            DVec3::new(0.1, 0.1, 0.05),
            (DVec3::new(0.5, 0.0, 0.0), DVec3::new(0.5, 0.0, 1.0)),
            0.5,
            offset,
        )
        .unwrap()
    }

    #[test]
    fn goes_back_and_forth() {
        let o = lift(0.0);
        assert_eq!(o.period(), 4.0);
        for (t, z) in [
            (0.0, 0.0),
            (1.0, 0.5),
            (2.0, 1.0),
            (3.0, 0.5),
            (4.0, 0.0),
            (5.0, 0.5),
        ] {
            assert!((o.center_at(t).z - z).abs() < 1e-12, "t {t}");
        }
        // Half a period apart: opposite directions, mirrored heights.
        let (a, b) = (lift(0.0), lift(2.0));
        for t in [0.3, 1.1, 2.7, 3.9] {
            assert!((a.center_at(t).z + b.center_at(t).z - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn the_swept_box_holds_every_position_and_no_more_than_needed() {
        let o = lift(0.7);
        for &(t0, t1) in &[
            (0.0, 0.1),
            (1.2, 1.4),
            (1.9, 2.6),
            (3.5, 4.6),
            (0.0, 9.0),
            (5.0, 5.0),
        ] {
            let (low, high) = o.swept_bounds(t0, t1);
            let mut seen = (f64::INFINITY, f64::NEG_INFINITY);
            for k in 0..=1000 {
                let t = t0 + (t1 - t0) * f64::from(k) / 1000.0;
                let c = o.center_at(t);
                assert!(c.z - 0.05 >= low.z - 1e-12 && c.z + 0.05 <= high.z + 1e-12);
                seen = (seen.0.min(c.z - 0.05), seen.1.max(c.z + 0.05));
            }
            // Tight: within the distance moved in one sample step.
            assert!((seen.0 - low.z).abs() < 2e-3 && (seen.1 - high.z).abs() < 2e-3);
            assert!((low.x - 0.4).abs() < 1e-12 && (high.x - 0.6).abs() < 1e-12);
        }
        let swept = o.swept(1.0, 1.6); // holds the top turn (t + offset = 2)
        assert!(swept.collides_sphere_f64(DVec3::new(0.5, 0.0, 1.04), 0.0));
    }

    #[test]
    fn bad_values_are_refused_by_name() {
        let ends = (DVec3::ZERO, DVec3::X);
        let e = MovingObstacle::new("w", DVec3::ZERO, ends, 1.0, 0.0).unwrap_err();
        assert!(e.to_string().contains("`w`") && e.to_string().contains("half_extents"));
        let e = MovingObstacle::new("w", DVec3::ONE, ends, -1.0, 0.0).unwrap_err();
        assert!(e.to_string().contains("speed"), "{e}");
        let e = MovingObstacle::new("w", DVec3::ONE, (DVec3::NAN, DVec3::X), 1.0, 0.0);
        assert!(e.unwrap_err().to_string().contains("from"));
        let still = MovingObstacle::new("s", DVec3::ONE, (DVec3::X, DVec3::X), 1.0, 0.0).unwrap();
        assert_eq!(still.period(), f64::INFINITY);
        assert_eq!(still.center_at(3.0), DVec3::X);
        assert_eq!(
            still.swept_bounds(0.0, 10.0),
            (DVec3::new(0.0, -1.0, -1.0), DVec3::new(2.0, 1.0, 1.0))
        );
    }
}
