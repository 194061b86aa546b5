//! [`ProblemInstance`]: one concrete problem of an experiment, with its time budget.

use crate::definition::cloud_summary::CloudSummary;
use crate::definition::problem_kind::InstanceProblem;
use crate::definition::problem_source::ProblemSource;

/// One problem instance of an experiment: a problem in one dimension (and, for seeded
/// families, one layout), with the time budget of each run. Each instance is one OMPL
/// "experiment": one `.log` file, one row of `experiments` in the database, one figure.
#[derive(Debug, Clone, PartialEq)]
pub struct ProblemInstance {
    /// Unique, file-name-safe id: `dividing-walls-n4`, `random-rectangles-n8-i3`.
    pub id: String,
    /// The problem's label (family name or file stem), used as the experiment name in OMPL
    /// logs and Planner Arena; the dimension and instance are experiment properties there.
    pub label: String,
    /// Where the problem comes from.
    pub source: ProblemSource,
    /// The dimension `n`.
    pub dimension: usize,
    /// The layout seed (seeded families; 0 otherwise).
    pub instance: u64,
    /// Wall-clock budget of each run in seconds (planner construction included).
    pub budget: f64,
    /// The problem.
    pub problem: InstanceProblem,
    /// What preparing the problem's point cloud did, once before its runs (arm problems with
    /// a `cloud`; `None` without one).
    pub cloud: Option<CloudSummary>,
}

impl ProblemInstance {
    /// The instance id for a label, dimension and (for seeded families) instance seed.
    ///
    /// ```
    /// use mit_star_benches::ProblemInstance;
    /// assert_eq!(ProblemInstance::make_id("dividing-walls", 4, None), "dividing-walls-n4");
    /// assert_eq!(ProblemInstance::make_id("random-rectangles", 8, Some(3)), "random-rectangles-n8-i3");
    /// ```
    pub fn make_id(label: &str, dimension: usize, instance: Option<u64>) -> String {
        match instance {
            Some(i) => format!("{label}-n{dimension}-i{i}"),
            None => format!("{label}-n{dimension}"),
        }
    }

    /// A human-readable title: `dividing-walls R^4`, `random-rectangles R^8 #3`.
    pub fn title(&self) -> String {
        if self.source.is_seeded() {
            format!("{} R^{} #{}", self.label, self.dimension, self.instance)
        } else {
            format!("{} R^{}", self.label, self.dimension)
        }
    }
}
