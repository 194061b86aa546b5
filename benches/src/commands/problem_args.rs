//! [`ProblemArgs`]: the options that name one problem instance (`plan`, `check-path`).

use std::path::PathBuf;
use std::sync::Arc;

use clap::Args;
use mit_star_problems::PlanningProblem;

use crate::budget::short_number;
use crate::commands::cloud_args::CloudArgs;
use crate::definition::problem_instance::ProblemInstance;
use crate::definition::problem_kind::InstanceProblem;
use crate::definition::problem_source::ProblemSource;
use crate::definition::robot_choice::RobotChoice;
use crate::error::HarnessError;

/// The options that name one problem instance.
#[derive(Debug, Args)]
pub struct ProblemArgs {
    /// Built-in problem name (see `mit-star problems`) or a problem file path.
    #[arg(long, required_unless_present = "problem_file")]
    pub problem: Option<String>,
    /// A TOML problem file.
    #[arg(long, conflicts_with = "problem")]
    pub problem_file: Option<PathBuf>,
    /// The robot a MotionBenchMaker folder (`--problem mbm:PATH`) is planned for: a shipped
    /// robot (`mit-star robots`: panda, the default, ur5, fetch, baxter), a URDF file (the
    /// SRDF beside it: same stem `.srdf` or the folder's only one; without one, the pairs its
    /// spheres rule out are not checked, with a warning), or a folder holding one URDF (a
    /// `*_spherized.urdf` preferred) and one SRDF.
    #[arg(long, value_name = "NAME|URDF|DIR")]
    pub robot: Option<String>,
    /// Plan only this SRDF planning group of the robot (`right_arm`); the other joints are
    /// held at the request's start values. Default: the group the folder's requests name
    /// (`group_name`) if the SRDF has it, else every moving joint.
    #[arg(long, value_name = "GROUP")]
    pub group: Option<String>,
    /// Refuse SRDF and allowed-collision entries naming links the robot lacks (by default they
    /// are skipped with a warning).
    #[arg(long)]
    pub strict_robot: bool,
    /// Dimension of a built-in problem (default 2).
    #[arg(long)]
    pub dim: Option<usize>,
    /// Layout seed of seeded problems (random-rectangles, default 0), or the problem index
    /// in a MotionBenchMaker folder (`--problem mbm:PATH`, default its first problem).
    #[arg(long)]
    pub instance: Option<u64>,
    /// Collision-check resolution (fraction of the maximum extent) instead of the problem's.
    #[arg(long, allow_negative_numbers = true)]
    pub resolution: Option<f64>,
    /// Allow a check that can miss thin obstacles: a box world's step larger than its thinnest
    /// obstacle or anti-obstacle, or an arm planned with certification off
    /// (`--set certification=1`); refused otherwise, since edges could cross thin obstacles
    /// between checked points. Without it, a problem file's `allow_coarse_step` stands.
    #[arg(long)]
    pub allow_coarse_step: bool,
    /// Keep every robot sphere this many metres from every obstacle and point cloud (arm
    /// problems; `0.01`: a centimetre, at most 1): every configuration of every edge of the
    /// path is certified to keep it, and the `f64` re-check measures it. The robot's own links
    /// are not padded. Default 0.
    #[arg(long, value_name = "METRES", allow_negative_numbers = true)]
    pub padding: Option<mit_star_robot::Padding>,
    /// Point clouds among the obstacles of an arm problem.
    #[command(flatten)]
    pub clouds: CloudArgs,
}

impl ProblemArgs {
    /// The instance these options name, with `budget` seconds per run; a warning on stderr
    /// when a box world's step is coarser than its thinnest obstacle (and allowed).
    ///
    /// # Errors
    /// An unknown problem or robot, a dimension the problem file does not have, a bad
    /// resolution, a step the problem refuses, or an arm's start or goal in collision (naming
    /// the colliding links).
    pub fn build(&self, budget: f64) -> Result<ProblemInstance, HarnessError> {
        self.build_checking_ends(budget, true)
    }

    /// [`build`](Self::build), keeping an arm problem whose start or goal is in collision
    /// (for `check-state`, which diagnoses them).
    ///
    /// # Errors
    /// As [`build`](Self::build), but for the ends.
    pub fn build_with_any_ends(&self, budget: f64) -> Result<ProblemInstance, HarnessError> {
        self.build_checking_ends(budget, false)
    }

    fn build_checking_ends(
        &self,
        budget: f64,
        check_ends: bool,
    ) -> Result<ProblemInstance, HarnessError> {
        let robot = RobotChoice::parse(self.robot.as_deref(), None, self.strict_robot)?
            .with_group(self.group.as_deref());
        let source = match (&self.problem, &self.problem_file) {
            (_, Some(path)) => ProblemSource::file(path)?,
            (Some(text), None) => ProblemSource::parse_for_robot(text, None, &robot)?,
            (None, None) => return Err(HarnessError::Usage("give --problem NAME|PATH".into())),
        };
        let dimension = match (source.fixed_dimension()?, self.dim) {
            (Some(n), Some(d)) if n != d => {
                return Err(HarnessError::Usage(format!(
                    "the problem file is {n}-dimensional; --dim {d} does not apply"
                )));
            }
            (Some(n), _) => n,
            (None, d) => d.unwrap_or(2),
        };
        let instance_number = self
            .instance
            .unwrap_or_else(|| crate::commands::bench::first_instance(&source));
        let mut problem = source.build(dimension, instance_number, self.resolution)?;
        // The flag only ever allows: without it, the problem file's choice stands.
        if self.allow_coarse_step {
            problem = problem.allowing_coarse_step(true);
        }
        if let Some(padding) = self.padding {
            problem = problem.with_padding(padding)?;
        }
        if (self.robot.is_some() || self.strict_robot || self.group.is_some())
            && !matches!(source, ProblemSource::Mbm(_))
        {
            return Err(HarnessError::Usage(
                "--robot, --group and --strict-robot apply to MotionBenchMaker problems (--problem mbm:PATH)"
                    .into(),
            ));
        }
        let mut cloud = None;
        if self.clouds.any() {
            let Some(arm) = problem.as_arm() else {
                return Err(HarnessError::Usage(
                    "point clouds (--cloud, --scene-as-cloud, …) are obstacles of arm problems \
                     (--problem mbm:PATH)"
                        .into(),
                ));
            };
            let label = format!("`{}` #{instance_number}", source.label());
            let (with_cloud, summary) = self.clouds.apply(arm, instance_number, &label)?;
            for line in &summary.steps {
                eprintln!("cloud: {line}");
            }
            problem = InstanceProblem::Arm(Arc::new(with_cloud));
            cloud = Some(summary);
        }
        if let Some(arm) = problem.as_arm() {
            for note in arm.notes() {
                eprintln!("note: problem `{}`: {note}", arm.name());
            }
        }
        if let Some(arm) = problem.as_arm().filter(|_| check_ends) {
            // The arm error names the problem: once is enough.
            arm.check_ends().map_err(HarnessError::ArmEnd)?;
        }
        let label = source.label();
        problem
            .check_step()
            .map_err(|source| HarnessError::Problem {
                name: label,
                dimension,
                source,
            })?;
        let seeded = source.is_seeded();
        let instance = ProblemInstance {
            id: ProblemInstance::make_id(
                &source.label(),
                dimension,
                seeded.then_some(instance_number),
            ),
            label: source.label(),
            source,
            dimension,
            instance: instance_number,
            budget,
            problem,
            cloud,
            pose_goal: None,
        };
        if let Some(boxes) = instance.problem.as_boxes()
            && boxes.step_is_coarse()
        {
            let (obstacle, anti) = boxes.thinnest_extents();
            eprintln!(
                "warning: the collision-check step {} is larger than the thinnest obstacle ({}) \
                 or anti-obstacle ({}); edges may cross them between checked points (allowed by \
                 --allow-coarse-step or the problem file)",
                short_number(instance.problem.step()),
                obstacle.map_or_else(|| "none".to_owned(), short_number),
                anti.map_or_else(|| "none".to_owned(), short_number),
            );
        }
        Ok(instance)
    }
}
