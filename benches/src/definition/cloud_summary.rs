//! [`CloudSummary`]: what preparing a problem's point cloud did, and how long it took.

use std::time::Duration;

/// What preparing a problem's cloud did: the points before and after the filters, their
/// radius, the time to read, sample and filter them and the time to build their tree, and one
/// line per step.
#[derive(Debug, Clone, PartialEq)]
pub struct CloudSummary {
    /// Points read, given and sampled, before the filters.
    pub input_points: usize,
    /// Points in the cloud the problem is planned among.
    pub points: usize,
    /// Their radius, metres.
    pub radius: f64,
    /// Seconds to read, sample and filter the points.
    pub prepare_seconds: f64,
    /// Seconds to build their tree.
    pub build_seconds: f64,
    /// One line per step: what it did and how long it took.
    pub steps: Vec<String>,
}

impl CloudSummary {
    /// One line: `1234 of 6000 points of radius 2.5 mm, prepared in 3.10 ms, tree built in
    /// 0.42 ms`.
    pub fn line(&self) -> String {
        format!(
            "{} of {} points of radius {:.1} mm, prepared in {}, tree built in {}",
            self.points,
            self.input_points,
            self.radius * 1e3,
            millis(Duration::from_secs_f64(self.prepare_seconds)),
            millis(Duration::from_secs_f64(self.build_seconds))
        )
    }
}

/// Milliseconds with two decimals: `3.10 ms`.
pub(crate) fn millis(d: Duration) -> String {
    format!("{:.2} ms", d.as_secs_f64() * 1e3)
}
