//! [`AuditClouds`]: the reference checks' own view of a scene's point clouds — every point
//! in `f64`, measured by brute force. Shares no code with the planners' structure
//! ([`PointTree`](crate::PointTree)): only the points and their radius, as given.

use glam::DVec3;

use crate::Scene;

/// One cloud: its points in `f64` and their radius.
#[derive(Debug, Clone)]
struct AuditCloud {
    points: Vec<DVec3>,
    radius: f64,
}

/// A scene's clouds for the reference checker and the motion audit.
#[derive(Debug, Clone, Default)]
pub(crate) struct AuditClouds {
    clouds: Vec<AuditCloud>,
}

impl AuditClouds {
    /// The clouds of `scene`, in its order.
    pub(crate) fn of(scene: &Scene) -> Self {
        Self {
            clouds: scene
                .clouds()
                .iter()
                .map(|c| AuditCloud {
                    points: c.cloud().points().iter().map(|p| p.as_dvec3()).collect(),
                    radius: c.cloud().radius(),
                })
                .collect(),
        }
    }

    /// How many clouds.
    pub(crate) fn len(&self) -> usize {
        self.clouds.len()
    }

    /// The gap between the ball (`center`, `radius`) and the nearest point's ball of cloud
    /// `c`, 0 if they touch or overlap (as parry's distances): every point measured.
    pub(crate) fn gap(&self, c: usize, center: DVec3, radius: f64) -> f64 {
        let cloud = &self.clouds[c];
        let nearest = cloud
            .points
            .iter()
            .map(|p| p.distance_squared(center))
            .fold(f64::INFINITY, f64::min)
            .sqrt();
        (nearest - radius - cloud.radius).max(0.0)
    }

    /// The smallest [`gap`](Self::gap) over every cloud (`f64::INFINITY` without clouds).
    pub(crate) fn nearest_gap(&self, center: DVec3, radius: f64) -> f64 {
        (0..self.clouds.len())
            .map(|c| self.gap(c, center, radius))
            .fold(f64::INFINITY, f64::min)
    }

    /// `true` if the ball (`center`, `radius`) shares a point with some point's ball.
    pub(crate) fn touches(&self, center: DVec3, radius: f64) -> bool {
        self.clouds.iter().any(|cloud| {
            let reach = radius + cloud.radius;
            cloud
                .points
                .iter()
                .any(|p| p.distance_squared(center) <= reach * reach)
        })
    }
}
