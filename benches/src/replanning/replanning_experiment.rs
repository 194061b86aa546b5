//! [`ReplanningExperiment`]: trials of several planners in several re-planning scenes.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use mit_star::Configuration;
use mit_star_robot::{ArmProblem, MovingScene, Scene};

use crate::definition::cloud_spec::CloudSpec;
use crate::definition::cloud_summary::CloudSummary;
use crate::definition::parameter_overrides::ParameterOverrides;
use crate::definition::planner_spec::{PlannerSpec, parse_configuration};
use crate::error::HarnessError;
use crate::replanning::replanning_scene::{ReplanningScene, ReplanningSetup};
use crate::replanning::rules::ReplanningRules;
use crate::replanning::trial::Trial;
use crate::replanning::trial_record::TrialRecord;

/// The planners of the paper's re-planning experiment, and AORRTC and RRT-Connect.
pub const REPLANNING_PLANNERS: [&str; 5] =
    ["mit-star", "eit-star", "ait-star", "aorrtc", "rrt-connect"];

/// How far apart the seeds of two trials are: trial `k` (from 1) plans with seeds
/// `seed + (k − 1) · TRIAL_SEED_STRIDE`, `… + 1`, ….
pub const TRIAL_SEED_STRIDE: u64 = 100_000;

/// Trials of planners in scenes under one set of rules: each scene, each planner, trials
/// 1 to `trials`, one after the other (one core: the planning budget is wall-clock time).
#[derive(Debug, Clone)]
pub struct ReplanningExperiment {
    /// The scenes.
    pub scenes: Vec<ReplanningScene>,
    /// The planners.
    pub planners: Vec<PlannerSpec>,
    /// Trials per planner and scene.
    pub trials: usize,
    /// The seed of the first trial's first plan.
    pub seed: u64,
    /// The rules.
    pub rules: ReplanningRules,
    /// A point cloud standing among every scene's fixed obstacles (its primitives sampled
    /// with `scene_as_cloud`: the table, and the vertical scene's ceiling and wall; the moving
    /// obstacles stay boxes), prepared once per scene at the first leg's start.
    pub cloud: Option<CloudSpec>,
}

impl ReplanningExperiment {
    /// The planners called `names`, with `overrides` applied to every one after the
    /// experiment's own: RRT-Connect and AORRTC extend at most 1 rad, as in `panda-mbm`.
    ///
    /// # Errors
    /// [`HarnessError::UnknownPlanner`], [`HarnessError::Parameter`], or
    /// [`HarnessError::Usage`] for an empty list.
    pub fn planners(
        names: &[String],
        overrides: &ParameterOverrides,
    ) -> Result<Vec<PlannerSpec>, HarnessError> {
        if names.is_empty() {
            return Err(HarnessError::Usage("no planner to run".to_owned()));
        }
        names
            .iter()
            .map(|name| {
                let configuration = parse_configuration(name)?;
                let mut own = ParameterOverrides::default();
                if matches!(
                    configuration,
                    Configuration::RrtConnect | Configuration::Aorrtc
                ) {
                    own.push_assignment("range=1.0")?;
                }
                PlannerSpec::new(configuration, None, &own.then(overrides))
            })
            .collect()
    }

    /// Every scene made concrete, with the cloud (if any) among its fixed obstacles and what
    /// preparing it did.
    ///
    /// # Errors
    /// As [`ReplanningScene::setup`] and [`CloudSpec::prepare`] (errors name the scene and the
    /// cloud option); [`HarnessError::ArmEnd`] if the cloud touches the arm at the start or the
    /// goal.
    pub fn setups(&self) -> Result<Vec<(ReplanningSetup, Option<CloudSummary>)>, HarnessError> {
        self.scenes
            .iter()
            .map(|&scene| {
                let setup = scene.setup()?;
                match &self.cloud {
                    None => Ok((setup, None)),
                    Some(cloud) => {
                        let (setup, summary) = with_cloud(setup, cloud)?;
                        Ok((setup, Some(summary)))
                    }
                }
            })
            .collect()
    }

    /// Runs every trial, calling `done` after each; stops early (returning what is done) when
    /// `interrupt` is raised.
    ///
    /// # Errors
    /// [`HarnessError::ReplanningRule`] for rules that cannot be used, else as
    /// [`setups`](Self::setups) and [`Trial::run`].
    pub fn run(
        &self,
        interrupt: &AtomicBool,
        done: impl FnMut(&TrialRecord),
    ) -> Result<Vec<TrialRecord>, HarnessError> {
        let setups: Vec<ReplanningSetup> = self.setups()?.into_iter().map(|(s, _)| s).collect();
        self.run_in(&setups, interrupt, done)
    }

    /// [`run`](Self::run) in `setups` (from [`setups`](Self::setups)) instead of this
    /// experiment's scenes.
    ///
    /// # Errors
    /// As [`run`](Self::run).
    pub fn run_in(
        &self,
        setups: &[ReplanningSetup],
        interrupt: &AtomicBool,
        mut done: impl FnMut(&TrialRecord),
    ) -> Result<Vec<TrialRecord>, HarnessError> {
        let mut records = Vec::new();
        for setup in setups {
            let rules = self
                .rules
                .clone()
                .checked(setup.robot.joint_space().joints().len())?;
            for planner in &self.planners {
                let trial = Trial::new(setup, planner, &rules).interrupted_by(interrupt);
                for k in 1..=self.trials {
                    if interrupt.load(Ordering::SeqCst) {
                        return Ok(records);
                    }
                    let seed = self
                        .seed
                        .wrapping_add((k as u64 - 1).wrapping_mul(TRIAL_SEED_STRIDE));
                    let record = trial.run(k, seed)?;
                    if interrupt.load(Ordering::SeqCst) {
                        // Cut short: its plans were stopped, its record is not a trial's.
                        return Ok(records);
                    }
                    done(&record);
                    records.push(record);
                }
            }
        }
        Ok(records)
    }
}

/// `setup` with the cloud of `cloud` standing among its fixed obstacles (which it replaces
/// with `scene_as_cloud` or `drop_primitives`), prepared at the first leg's start (the
/// sampling's default seed 0); the moving obstacles stay.
fn with_cloud(
    mut setup: ReplanningSetup,
    cloud: &CloudSpec,
) -> Result<(ReplanningSetup, CloudSummary), HarnessError> {
    let name = setup.name;
    let fixed = ArmProblem::new(
        name,
        setup.robot.clone(),
        Scene::new(setup.scene.fixed().to_vec()),
        setup.start.clone(),
        setup.goal.clone(),
    )
    .map_err(|source| HarnessError::Arm {
        name: name.to_owned(),
        source,
    })?;
    let (among, summary) = cloud.prepare(&fixed, 0, &[], &format!("`{name}`"), None)?;
    // A cloud on the arm at either end would end every trial at once: refused, named.
    among.check_ends().map_err(HarnessError::ArmEnd)?;
    let mut scene = MovingScene::new(
        among.scene().obstacles().to_vec(),
        setup.scene.moving().to_vec(),
    );
    for c in among.scene().clouds() {
        scene = scene.with_cloud(Arc::clone(c));
    }
    setup.scene = scene;
    Ok((setup, summary))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::replanning::rules::PlanningBudget;

    #[test]
    fn planners_get_their_range_and_runs_stop_on_interrupt() {
        let overrides = ParameterOverrides::default()
            .with_assignment("batch_size=50")
            .unwrap();
        let names = ["aorrtc".to_owned(), "mit-star".to_owned()];
        let planners = ReplanningExperiment::planners(&names, &overrides).unwrap();
        assert_eq!(planners[0].parameters_for_seed(0).range, Some(1.0));
        assert_eq!(planners[1].parameters_for_seed(0).batch_size, Some(50));
        assert!(ReplanningExperiment::planners(&[], &overrides).is_err());
        assert!(ReplanningExperiment::planners(&["rrt".to_owned()], &overrides).is_err());
        let experiment = ReplanningExperiment {
            scenes: vec![ReplanningScene::Horizontal],
            planners,
            trials: 3,
            seed: 0,
            rules: ReplanningRules {
                budget: PlanningBudget::Iterations(10),
                ..ReplanningRules::default()
            },
            cloud: None,
        };
        let raised = AtomicBool::new(true);
        assert!(experiment.run(&raised, |_| {}).unwrap().is_empty());
        let bad = ReplanningExperiment {
            rules: ReplanningRules {
                legs: 0,
                ..experiment.rules.clone()
            },
            ..experiment
        };
        let e = bad.run(&AtomicBool::new(false), |_| {}).unwrap_err();
        assert!(e.to_string().contains("legs"), "{e}");
    }
}
