//! [`ProblemSpec`]: a problem of an experiment over several dimensions and instances.

use std::sync::Arc;

use crate::definition::cloud_spec::CloudSpec;
use crate::definition::pose_goal_spec::PoseGoalSpec;
use crate::definition::problem_instance::ProblemInstance;
use crate::definition::problem_kind::InstanceProblem;
use crate::definition::problem_source::ProblemSource;
use crate::error::HarnessError;

/// The most instances (layout seeds or folder problems) one problem entry may ask for:
/// 10 000. Every instance is built before the first run (a box world is a few kilobytes, an
/// arm problem more), so a million would take gigabytes; split larger sets over several
/// experiments.
pub const MAX_INSTANCES: u64 = 10_000;

/// The most runs one experiment may schedule (planners × instances × runs, over every
/// problem and dimension): 10⁷. Each run's record is kept until the summaries are written.
pub const MAX_SCHEDULED_RUNS: u64 = 10_000_000;

/// Refuses more than [`MAX_INSTANCES`] instances in one problem entry: the message says how
/// many were asked (`count`, `None` for more than `u64` holds).
pub(crate) fn check_instance_count(count: Option<u64>) -> Result<(), String> {
    match count {
        Some(n) if n <= MAX_INSTANCES => Ok(()),
        _ => Err(format!(
            "asks for {} instances; at most {MAX_INSTANCES} per problem (every instance is \
             built before the first run): split the seeds over several experiments",
            count.map_or_else(|| "more than 2^64".to_owned(), |n| n.to_string())
        )),
    }
}

/// A problem entry of an experiment: a source, the dimensions to run it in with one time
/// budget per dimension, the layout seeds (seeded families), and optionally another
/// collision-check resolution and a point cloud.
///
/// ```
/// use mit_star_benches::{ProblemSource, ProblemSpec};
/// let spec = ProblemSpec {
///     source: ProblemSource::parse("random-rectangles", None)?,
///     dimensions: vec![4, 8],
///     budgets: vec![0.8, 2.0],
///     instances: vec![0, 1, 2],
///     resolution: None,
///     allow_coarse_step: false,
///     padding: mit_star_robot::Padding::ZERO,
///     cloud: None,
///     pose_goal: None,
/// };
/// let instances = spec.instances()?;
/// assert_eq!(instances.len(), 6);
/// assert_eq!(instances[4].id, "random-rectangles-n8-i1");
/// assert_eq!(instances[4].budget, 2.0);
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ProblemSpec {
    /// The problem.
    pub source: ProblemSource,
    /// Dimensions (for a problem file: its own dimension).
    pub dimensions: Vec<usize>,
    /// Time budget per run in seconds, one per dimension.
    pub budgets: Vec<f64>,
    /// Layout seeds (one `0` for families that do not use a seed).
    pub instances: Vec<u64>,
    /// Collision-check resolution, if not the problem's own.
    pub resolution: Option<f64>,
    /// Allow checks that can miss thin obstacles: a box world's step coarser than its
    /// thinnest obstacle, an arm planned with certification off
    /// ([`ProblemInstance`]'s `allowing_coarse_step`). A problem file's own
    /// `allow_coarse_step` stands either way.
    pub allow_coarse_step: bool,
    /// The collision padding every arm instance keeps from its obstacles
    /// ([`mit_star_robot::ArmProblem::with_padding`]; zero: none). Box worlds take none.
    pub padding: mit_star_robot::Padding,
    /// A point cloud among the obstacles of every instance (MotionBenchMaker problems only),
    /// prepared once per instance when it is built.
    pub cloud: Option<CloudSpec>,
    /// A link's pose as every instance's goal instead of its goal configuration
    /// (MotionBenchMaker problems only).
    pub pose_goal: Option<PoseGoalSpec>,
}

impl ProblemSpec {
    /// Builds every instance: dimensions in order, and instances within each dimension.
    ///
    /// # Errors
    /// As [`ProblemSource::build`]; [`HarnessError::Usage`] when the budgets do not match the
    /// dimensions, a budget is not positive, or several instances are asked of a family that
    /// does not use a seed.
    pub fn instances(&self) -> Result<Vec<ProblemInstance>, HarnessError> {
        if self.budgets.len() != self.dimensions.len() {
            return Err(HarnessError::Usage(format!(
                "problem `{}`: {} time budgets for {} dimensions",
                self.source.label(),
                self.budgets.len(),
                self.dimensions.len()
            )));
        }
        for &b in &self.budgets {
            crate::budget_duration(b).map_err(|source| HarnessError::Budget {
                what: format!("problem `{}`, `time`", self.source.label()),
                source,
            })?;
        }
        let seeded = self.source.is_seeded();
        if !seeded && self.instances.len() > 1 {
            return Err(HarnessError::Usage(format!(
                "problem `{}` does not depend on a seed: it has one instance",
                self.source.label()
            )));
        }
        let label = self.source.label();
        let mut out = Vec::new();
        // Notes of held joints, each said once with the count of problems it applies to.
        let mut notes: Vec<(String, String, usize)> = Vec::new();
        for (&dimension, &budget) in self.dimensions.iter().zip(&self.budgets) {
            for &instance in &self.instances {
                let mut problem = self.source.build(dimension, instance, self.resolution)?;
                if self.allow_coarse_step {
                    problem = problem.allowing_coarse_step(true);
                }
                problem = problem.with_padding(self.padding)?;
                let mut cloud = None;
                if let Some(spec) = &self.cloud {
                    let named = format!("`{label}` #{instance}");
                    let Some(arm) = problem.as_arm() else {
                        return Err(HarnessError::CloudOption {
                            problem: named,
                            option: "table".into(),
                            source: Box::new(HarnessError::Usage(
                                "point clouds are obstacles of arm problems (mbm:PATH)".into(),
                            )),
                        });
                    };
                    let (with_cloud, summary) = spec.prepare(arm, instance, &[], &named, None)?;
                    problem = InstanceProblem::Arm(Arc::new(with_cloud));
                    cloud = Some(summary);
                }
                for note in problem.as_arm().map_or(&[][..], |a| a.notes()) {
                    // The same note for another problem: counted, not repeated.
                    let kind = note.split(':').next().unwrap_or_default().to_owned();
                    match notes.iter_mut().find(|(k, _, _)| *k == kind) {
                        Some((_, _, n)) => *n += 1,
                        None => notes.push((
                            kind,
                            format!(
                                "problem `{}`: {note}",
                                problem
                                    .as_arm()
                                    .map_or("", |a| mit_star_problems::PlanningProblem::name(&**a))
                            ),
                            1,
                        )),
                    }
                }
                if let Some(arm) = problem.as_arm()
                    && let Err(e) = arm.check_ends()
                {
                    // The error names the problem (folder and index).
                    eprintln!("note: skipped: {e}");
                    continue;
                }
                problem
                    .check_step()
                    .map_err(|source| HarnessError::Problem {
                        name: label.clone(),
                        dimension,
                        source,
                    })?;
                let id = ProblemInstance::make_id(&label, dimension, seeded.then_some(instance));
                out.push(ProblemInstance {
                    id,
                    label: label.clone(),
                    source: self.source.clone(),
                    dimension,
                    instance: if seeded { instance } else { 0 },
                    budget,
                    problem,
                    cloud,
                    pose_goal: self.pose_goal.clone(),
                });
            }
        }
        for (_, note, n) in notes {
            let others = match n {
                1 => String::new(),
                2 => " (and the same in 1 more problem)".to_owned(),
                _ => format!(" (and the same in {} more problems)", n - 1),
            };
            eprintln!("note: {note}{others}");
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(name: &str, dims: Vec<usize>, budgets: Vec<f64>, instances: Vec<u64>) -> ProblemSpec {
        ProblemSpec {
            source: ProblemSource::parse(name, None).unwrap(),
            dimensions: dims,
            budgets,
            instances,
            resolution: None,
            allow_coarse_step: false,
            padding: mit_star_robot::Padding::ZERO,
            cloud: None,
            pose_goal: None,
        }
    }

    #[test]
    fn bad_specs_are_refused_before_building() {
        let e = spec("flanking-gap", vec![4, 8], vec![0.1], vec![0]).instances();
        assert!(
            e.unwrap_err()
                .to_string()
                .contains("1 time budgets for 2 dimensions")
        );
        let e = spec("flanking-gap", vec![4], vec![-0.1], vec![0]).instances();
        assert!(e.unwrap_err().to_string().contains("-0.1"));
        let e = spec("flanking-gap", vec![4], vec![0.1], vec![0, 1]).instances();
        assert!(
            e.unwrap_err()
                .to_string()
                .contains("does not depend on a seed")
        );
        let e = spec("flanking-gap", vec![1], vec![0.1], vec![0]).instances();
        assert!(matches!(e, Err(HarnessError::Problem { dimension: 1, .. })));
    }

    #[test]
    fn ids_are_unique_and_titles_readable() {
        let s = spec("goal-enclosure", vec![2, 4], vec![0.05, 0.1], vec![0]);
        let i = s.instances().unwrap();
        assert_eq!(i[0].id, "goal-enclosure-n2");
        assert_eq!(i[1].title(), "goal-enclosure R^4");
        assert_eq!(i[1].budget, 0.1);
        let r = spec("random-rectangles", vec![2], vec![0.1], vec![5])
            .instances()
            .unwrap();
        assert_eq!(r[0].title(), "random-rectangles R^2 #5");
        assert_eq!(r[0].instance, 5);
    }
}
