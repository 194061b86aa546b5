//! `mit-star replan`: the paper's re-planning experiment (§V-C) on the Panda.

use std::path::PathBuf;
use std::sync::atomic::AtomicBool;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::commands::cloud_args::CloudArgs;
use crate::definition::parameter_overrides::ParameterOverrides;
use crate::definition::problem_source::sanitise;
use crate::error::HarnessError;
use crate::replanning::{
    PlanningBudget, ReplanningExperiment, ReplanningRules, ReplanningScene, ReplanningSetup,
    ReplanningSummary, StaticAudit, TrialPicture, TrialRecord, write_trial_view, write_trials_csv,
};

/// Options of `mit-star replan`. The defaults are the shipped experiment: both scenes, the
/// five planners, 30 trials each, 0.1 s per plan.
#[derive(Debug, Args)]
pub struct ReplanArgs {
    /// Scenes, comma separated: horizontal, vertical.
    #[arg(long, value_delimiter = ',', default_value = "horizontal,vertical")]
    pub scenes: Vec<String>,
    /// Planners, comma separated (`mit-star planners` lists them).
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "mit-star,eit-star,ait-star,aorrtc,rrt-connect"
    )]
    pub planners: Vec<String>,
    /// Trials per planner and scene.
    #[arg(long, default_value_t = 30)]
    pub trials: usize,
    /// The seed of the first trial's first plan.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Parameter override for every planner, e.g. `--set batch_size=200` (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Seconds of one control cycle: one plan's wall-clock budget, and the simulated time
    /// between two plans.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    pub cycle: f64,
    /// Plan for this many planner iterations instead of one cycle of wall clock
    /// (deterministic; the simulated clock still charges a cycle per plan); at most 10⁶.
    #[arg(long)]
    pub iterations: Option<u64>,
    /// Seconds after a plan is taken up over which planners see the moving obstacles' sweep
    /// (halved, down to one cycle, while the arm or the goal is inside it).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub look_ahead: f64,
    /// Fraction of the joint velocity limits the arm moves at.
    #[arg(long, default_value_t = 0.5, allow_negative_numbers = true)]
    pub velocity_scaling: f64,
    /// Journeys between the start and the goal per trial.
    #[arg(long, default_value_t = 5)]
    pub legs: usize,
    /// Simulated seconds within which a trial must finish its legs.
    #[arg(long, default_value_t = 60.0, allow_negative_numbers = true)]
    pub time_limit: f64,
    /// Confidence of the intervals.
    #[arg(long, default_value_t = 0.95)]
    pub confidence: f64,
    /// Folder for the tables and pictures.
    #[arg(long, short, default_value = "results/replanning")]
    pub output: PathBuf,
    /// Do not draw the first trial of each planner and scene.
    #[arg(long)]
    pub no_picture: bool,
    /// Also write an interactive 3-D view of the first trial of each planner and scene
    /// (`<scene>-<planner>-trial<k>.html` beside its picture): the arm over simulated time
    /// among the moving obstacles.
    #[arg(long)]
    pub view: bool,
    /// A point cloud standing among each scene's fixed obstacles (`--scene-as-cloud` samples
    /// the fixed ones — the table, the vertical scene's ceiling and wall — and replaces them;
    /// the moving obstacles stay boxes), prepared once per scene at the first leg's start.
    #[command(flatten)]
    pub clouds: CloudArgs,
    /// The seed of `--scene-as-cloud`'s sampling (default 0).
    #[arg(long, value_name = "SEED")]
    pub cloud_seed: Option<u64>,
}

impl ReplanArgs {
    /// The experiment the options describe.
    ///
    /// # Errors
    /// Unknown scenes or planners, refused parameters, rules that cannot be used.
    pub fn experiment(&self) -> Result<ReplanningExperiment, HarnessError> {
        let scenes = self
            .scenes
            .iter()
            .map(|s| ReplanningScene::parse(s))
            .collect::<Result<Vec<_>, _>>()?;
        let mut overrides = ParameterOverrides::default();
        for s in &self.set {
            overrides.push_assignment(s)?;
        }
        if !(self.confidence > 0.0 && self.confidence < 1.0) {
            return Err(HarnessError::Usage(format!(
                "--confidence {} must be between 0 and 1",
                self.confidence
            )));
        }
        let rules = ReplanningRules {
            cycle: self.cycle,
            budget: match self.iterations {
                Some(n) => PlanningBudget::Iterations(n),
                None => PlanningBudget::WallClock(self.cycle),
            },
            look_ahead: self.look_ahead,
            velocity_scaling: self.velocity_scaling,
            legs: self.legs,
            time_limit: self.time_limit,
            ..ReplanningRules::default()
        };
        let rules = rules.checked(crate::replanning::PANDA_VELOCITY_LIMITS.len())?;
        let cloud = if self.clouds.any() || self.cloud_seed.is_some() {
            if let Some(path) = &self.clouds.save_cloud {
                return Err(HarnessError::Usage(format!(
                    "--save-cloud `{}`: replan prepares one cloud per scene; save one with \
                     `mit-star plan --save-cloud`",
                    path.display()
                )));
            }
            Some(self.clouds.spec(self.cloud_seed)?)
        } else {
            None
        };
        Ok(ReplanningExperiment {
            cloud,
            scenes,
            planners: ReplanningExperiment::planners(&self.planners, &overrides)?,
            trials: self.trials,
            seed: self.seed,
            rules,
        })
    }

    /// Runs the trials, prints the table and writes `trials.csv`, `summary.csv`,
    /// `summary.md` and the pictures into the output folder.
    ///
    /// # Errors
    /// As [`experiment`](Self::experiment), an unwritable folder (before any trial), a
    /// planner that fails, or a file that cannot be written.
    pub fn run(&self, interrupt: &AtomicBool) -> Result<CommandOutcome, HarnessError> {
        let experiment = self.experiment()?;
        crate::writable_folder(&self.output)?;
        let prepared = experiment.setups()?;
        for (setup, cloud) in &prepared {
            for step in cloud.iter().flat_map(|c| &c.steps) {
                eprintln!("cloud: `{}`: {step}", setup.name);
            }
        }
        let setups: Vec<ReplanningSetup> = prepared.into_iter().map(|(s, _)| s).collect();
        let total = experiment.scenes.len() * experiment.planners.len() * experiment.trials;
        let mut count = 0;
        let records = experiment.run_in(&setups, interrupt, |r| {
            count += 1;
            eprintln!(
                "[{count}/{total}] {} {} trial {}: {} at {:.2} s, travelled {:.2}, {} plans ({} without a path, {} adopted), {} stops, {:.1} s wall",
                r.scene,
                r.planner,
                r.trial,
                r.end.label(),
                r.time,
                r.travelled,
                r.plans,
                r.failed_plans,
                r.adopted,
                r.dropped,
                r.wall_seconds
            );
        })?;
        write_trials_csv(&records, &self.output.join("trials.csv"))?;
        let summary = ReplanningSummary::new(&records, self.confidence);
        summary.write_csv(&self.output.join("summary.csv"))?;
        let table = summary.markdown();
        let path = self.output.join("summary.md");
        std::fs::write(&path, &table).map_err(|source| HarnessError::Io { path, source })?;
        say!("{table}");
        let mut unproven = 0;
        if experiment.cloud.is_some() {
            for setup in &setups {
                let trials: Vec<&TrialRecord> =
                    records.iter().filter(|r| r.scene == setup.name).collect();
                let audit = StaticAudit::of(setup, &trials);
                say!("{}: {}", setup.name, audit.line());
                for failure in &audit.failures {
                    eprintln!("WARNING: {failure}");
                }
                unproven += audit.failures.len();
            }
        }
        if !self.no_picture || self.view {
            for setup in &setups {
                for planner in &experiment.planners {
                    let first = records
                        .iter()
                        .find(|r| r.scene == setup.name && r.planner == planner.name());
                    if let Some(record) = first {
                        let stem = format!(
                            "{}-{}-trial{}",
                            setup.name,
                            sanitise(planner.configuration().name()),
                            record.trial
                        );
                        let (svg, png) = (
                            self.output.join(format!("{stem}.svg")),
                            self.output.join(format!("{stem}.png")),
                        );
                        if !self.no_picture {
                            TrialPicture::new(setup, record).save(&svg, &png)?;
                        }
                        if self.view {
                            let page = self.output.join(format!("{stem}.html"));
                            write_trial_view(setup, record, &page)?;
                        }
                    }
                }
            }
        }
        say!("results written to {}", self.output.display());
        Ok(if records.len() < total {
            CommandOutcome::Interrupted
        } else if unproven > 0 {
            CommandOutcome::InvalidPaths
        } else {
            CommandOutcome::Success
        })
    }
}
