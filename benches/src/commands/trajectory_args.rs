//! The trajectory options: `plan --trajectory FILE` times the (simplified) arm path and writes
//! it; `check-path --trajectory FILE` checks a trajectory file against the problem.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use mit_star_robot::{
    ArmChecker, ArmProblem, BlendCertifier, JointLimitsYaml, MotionLimits, Padding, Trajectory,
    TrajectoryFile, check_trajectory, merge_repeated_waypoints,
};

use crate::commands::CommandOutcome;
use crate::error::HarnessError;
use crate::formats::kpi_table::number;
use crate::pictures::plan_view::PlanView;
use crate::pictures::trajectory_plot::TrajectoryPlot;

/// Where the velocity and acceleration limits come from, and their scaling.
#[derive(Debug, Args, Clone)]
pub struct LimitArgs {
    /// A MoveIt `joint_limits.yaml`: its velocity limits replace the URDF's, its acceleration
    /// limits are used (for joints whose `has_…_limits` is true).
    #[arg(long, value_name = "YAML")]
    pub joint_limits: Option<PathBuf>,
    /// One acceleration limit for every joint (rad/s² or m/s²), replacing the YAML's.
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub max_acceleration: Option<f64>,
    /// MoveIt's velocity scaling factor, in (0, 1].
    #[arg(
        long,
        default_value_t = 1.0,
        value_name = "F",
        allow_negative_numbers = true
    )]
    pub velocity_scaling: f64,
    /// MoveIt's acceleration scaling factor, in (0, 1].
    #[arg(
        long,
        default_value_t = 1.0,
        value_name = "F",
        allow_negative_numbers = true
    )]
    pub acceleration_scaling: f64,
}

impl LimitArgs {
    /// The limits of `arm`'s robot.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] naming the file, the joint or the factor that is wrong.
    pub fn limits(&self, arm: &ArmProblem) -> Result<MotionLimits, HarnessError> {
        let usage = |e: mit_star_robot::TrajectoryError| HarnessError::Usage(e.to_string());
        let yaml = self
            .joint_limits
            .as_deref()
            .map(JointLimitsYaml::read)
            .transpose()
            .map_err(usage)?;
        MotionLimits::for_robot(arm.robot(), yaml.as_ref(), self.max_acceleration)
            .and_then(|l| l.scaled(self.velocity_scaling, self.acceleration_scaling))
            .map_err(usage)
    }
}

/// How a timed path passes its corners.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Corners {
    /// Stop at every waypoint: every configuration on the planned segments.
    Stop,
    /// Parabolic blends, each certified collision-free (shrunk or stopped if not).
    Blend,
}

impl Corners {
    /// The option's value naming this.
    pub fn name(self) -> &'static str {
        match self {
            Self::Stop => "stop",
            Self::Blend => "blend",
        }
    }

    /// Times `path` (repeated states merged) on `arm` under `limits`, passing its corners
    /// this way; what became of the corners when blending.
    ///
    /// # Errors
    /// As [`Trajectory::stop_at_corners`]: a path of one distinct state, of the wrong width
    /// or not finite.
    pub fn time(
        self,
        arm: &ArmProblem,
        limits: &MotionLimits,
        path: &[Vec<f64>],
    ) -> Result<(Trajectory, Option<mit_star_robot::BlendReport>), mit_star_robot::TrajectoryError>
    {
        let path = merge_repeated_waypoints(path);
        match self {
            Self::Stop => Ok((Trajectory::stop_at_corners(&path, limits)?, None)),
            Self::Blend => {
                let certifier = BlendCertifier::padded(arm.robot(), arm.scene(), arm.padding());
                let (t, r) = Trajectory::blended(&path, limits, &certifier)?;
                Ok((t, Some(r)))
            }
        }
    }
}

/// Options of `plan` that time the path and write it.
#[derive(Debug, Args, Clone)]
pub struct TrajectoryArgs {
    /// Time the path (the simplified one with `--simplify`; repeated states merged) and write
    /// the trajectory, JSON or CSV by the extension (arm problems only).
    #[arg(long, value_name = "FILE.{json,csv}")]
    pub trajectory: Option<PathBuf>,
    /// Write samples every this many seconds (and at the end) instead of the knots.
    #[arg(
        long,
        value_name = "S",
        requires = "trajectory",
        allow_negative_numbers = true
    )]
    pub sample_period: Option<f64>,
    /// How to pass the corners.
    #[arg(long, value_enum, default_value = "blend", requires = "trajectory")]
    pub corners: Corners,
    /// Room for the blends, in metres (e.g. 0.005–0.01): `--simplify` keeps every robot
    /// sphere this much further from obstacles (beyond the problem's `--padding`) on every edge
    /// it adds, and the blends are then certified against the problem as given — so the
    /// corners of the simplified path do not wrap tightly around obstacles and their blends
    /// need not shrink. It trades path length (the shortcuts keep clear of obstacles) for
    /// speed through the corners: on 175 simplified MotionBenchMaker Panda paths, 0.01 m made
    /// them 0.5 % longer (median) and the trajectories 2.5 % faster; 0.02 m made both longer.
    /// Planning is unchanged, and edges of the planned path the simplifier keeps (near an end
    /// within the room, say) keep only the problem's padding.
    #[arg(
        long,
        value_name = "METRES",
        requires_all = ["trajectory", "simplify"],
        allow_negative_numbers = true
    )]
    pub blend_room: Option<f64>,
    /// Also draw the trajectory — each joint's position, velocity and acceleration against
    /// time, its velocity and acceleration limits dashed, the knots marked — into this PNG
    /// (or `.svg`) file.
    #[arg(long, value_name = "FILE.png", requires = "trajectory")]
    pub trajectory_plot: Option<PathBuf>,
    /// The limits.
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// What `plan --trajectory` did.
#[derive(Debug, Clone)]
pub struct Timed {
    file: PathBuf,
    duration: f64,
    knots: usize,
    samples: usize,
    report: Option<mit_star_robot::BlendReport>,
    trajectory: Trajectory,
    plot: Option<PathBuf>,
}

impl Timed {
    /// The trajectory written.
    pub fn trajectory(&self) -> &Trajectory {
        &self.trajectory
    }

    /// The line for the text report (and one naming the plot, if drawn).
    pub fn line(&self) -> String {
        let corners = self.report.as_ref().map_or_else(String::new, |r| {
            format!(
                "; corners: {} blended, {} blended after shrinking, {} stops",
                r.blended, r.shrunk, r.stopped
            )
        });
        format!(
            "  trajectory: {} ({} s, {} knots, {} samples written{corners})",
            self.file.display(),
            number(self.duration),
            self.knots,
            self.samples
        ) + &self.plot.as_ref().map_or_else(String::new, |p| {
            format!("\n  trajectory plot: {}", p.display())
        })
    }

    /// The JSON object for `--json`.
    pub fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "file": self.file,
            "duration": self.duration,
            "knots": self.knots,
            "samples": self.samples,
            "corners": self.report.as_ref().map(|r| [r.blended, r.shrunk, r.stopped]),
            "plot": self.plot,
        })
    }
}

impl TrajectoryArgs {
    /// Checks the options before planning: `--trajectory` only on an arm problem, a period
    /// that is positive and finite, a `.json` or `.csv` name, limits that resolve.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] saying which.
    pub fn prepare(&self, arm: Option<&ArmProblem>) -> Result<Option<MotionLimits>, HarnessError> {
        let Some(file) = &self.trajectory else {
            return Ok(None);
        };
        let Some(arm) = arm else {
            return Err(HarnessError::Usage(
                "--trajectory is for arm problems (a robot's joints with velocity and acceleration limits)".into(),
            ));
        };
        if !matches!(
            file.extension().and_then(|e| e.to_str()),
            Some("json" | "csv")
        ) {
            return Err(HarnessError::Usage(format!(
                "--trajectory {}: the file is .json or .csv",
                file.display()
            )));
        }
        if let Some(plot) = &self.trajectory_plot {
            plot_name(plot, "--trajectory-plot")?;
        }
        self.blend_room(arm)?;
        if let Some(p) = self.sample_period
            && !(p > 0.0 && p.is_finite())
        {
            return Err(HarnessError::Usage(format!(
                "--sample-period {p}: a positive number of seconds"
            )));
        }
        self.limits.limits(arm).map(Some)
    }

    /// The padding `--simplify` keeps for `--blend-room`: `arm`'s padding plus the room;
    /// `None` without the option.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a room that is not a [`Padding`] (negative, not a number,
    /// above [`MAX_PADDING`](mit_star_robot::MAX_PADDING) with the padding) or with
    /// `--corners stop` (no blends to make room for).
    pub fn blend_room(&self, arm: &ArmProblem) -> Result<Option<Padding>, HarnessError> {
        let Some(room) = self.blend_room else {
            return Ok(None);
        };
        if self.corners == Corners::Stop {
            return Err(HarnessError::Usage(
                "--blend-room makes room for blends: it does nothing with --corners stop".into(),
            ));
        }
        let usage = |e: mit_star_robot::PaddingError| {
            HarnessError::Usage(format!("--blend-room {room}: {e}"))
        };
        Padding::new(room).map_err(usage)?;
        Padding::new(arm.padding().metres() + room)
            .map(Some)
            .map_err(usage)
    }

    /// Times `path` on `arm` under `limits` and writes the file.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a path that cannot be timed (a single state) or a file
    /// that cannot be written.
    pub fn write(
        &self,
        arm: &ArmProblem,
        limits: &MotionLimits,
        path: &[Vec<f64>],
    ) -> Result<Option<Timed>, HarnessError> {
        let Some(file) = &self.trajectory else {
            return Ok(None);
        };
        let usage =
            |e: mit_star_robot::TrajectoryError| HarnessError::Usage(format!("--trajectory: {e}"));
        let (trajectory, report) = self.corners.time(arm, limits, path).map_err(usage)?;
        let written = TrajectoryFile::of(&trajectory, self.sample_period).map_err(usage)?;
        written.write(file).map_err(usage)?;
        if let Some(plot) = &self.trajectory_plot {
            TrajectoryPlot::new(
                format!("{} ({} corners)", file.display(), self.corners.name()),
                limits.names().to_vec(),
                trajectory.knots().to_vec(),
                (limits.velocity().to_vec(), limits.acceleration().to_vec()),
            )
            .save(plot)?;
        }
        Ok(Some(Timed {
            file: file.clone(),
            duration: trajectory.duration(),
            knots: trajectory.knots().len(),
            samples: written.samples.len(),
            report,
            trajectory,
            plot: self.trajectory_plot.clone(),
        }))
    }
}

/// `check-path --trajectory FILE`: the trajectory checked against an arm problem's robot,
/// limits and scene; prints the verdict.
///
/// # Errors
/// [`HarnessError::Usage`] for a box world, an unreadable or malformed file, joints that are
/// not the robot's, times that do not increase, or limits that do not resolve.
pub(crate) fn check_trajectory_file(
    arm: Option<&ArmProblem>,
    file: &std::path::Path,
    limits: &LimitArgs,
    view: Option<&crate::ProblemInstance>,
    (page, plot): (Option<&std::path::Path>, Option<&std::path::Path>),
) -> Result<CommandOutcome, HarnessError> {
    let Some(arm) = arm else {
        return Err(HarnessError::Usage(
            "--trajectory is for arm problems".into(),
        ));
    };
    if let Some(plot) = plot {
        plot_name(plot, "--plot")?;
    }
    let usage = |e: mit_star_robot::TrajectoryError| HarnessError::Usage(e.to_string());
    let motion = limits.limits(arm)?;
    let trajectory = TrajectoryFile::read(file).map_err(usage)?;
    let checker = ArmChecker::padded(arm.robot(), arm.scene(), arm.padding());
    let check = check_trajectory(&trajectory, arm.robot(), arm.scene(), &motion, &checker)
        .map_err(usage)?;
    say!(
        "{}: {} samples, {} s; largest velocity {:+.3e} and acceleration {:+.3e} relative to the limits; {} motions between samples certified, {} audited",
        file.display(),
        check.samples,
        number(check.duration),
        check.velocity_excess,
        check.acceleration_excess,
        check.motions_certified,
        check.motions_audited
    );
    let verdict = if check.is_valid() {
        "valid".to_owned()
    } else {
        format!("INVALID: {} violations", check.violation_count)
    };
    say!("  {verdict}");
    for v in &check.violations {
        say!("    {v:?}");
    }
    if let Some(plot) = plot {
        // The limits in the file's joint order (the check refused joints not the robot's).
        let order = |list: &[f64]| -> Vec<f64> {
            trajectory
                .joints
                .iter()
                .map(|j| {
                    motion
                        .names()
                        .iter()
                        .position(|n| n == j)
                        .map_or(f64::NAN, |k| list[k])
                })
                .collect()
        };
        TrajectoryPlot::new(
            format!("{}: {verdict}", file.display()),
            trajectory.joints.clone(),
            trajectory.samples.clone(),
            (order(motion.velocity()), order(motion.acceleration())),
        )
        .save(plot)?;
        say!("  plot: {}", plot.display());
    }
    if let (Some(instance), Some(page)) = (view, page) {
        let title = format!("{} on {}", file.display(), instance.title());
        let mut drawn = PlanView::new(&instance.problem, title, None)?;
        if let Some(resolver) = instance.mesh_resolver() {
            drawn.meshes(&resolver);
        }
        drawn.subtitle(format!(
            "{} samples, {} s: {verdict}",
            check.samples,
            number(check.duration)
        ));
        match in_robot_order(&trajectory, arm.robot().joint_names()) {
            Some(states) => {
                let times = trajectory.samples.iter().map(|s| s.time).collect();
                drawn.samples("trajectory", times, states);
            }
            None => {
                drawn.note("the file's joints are not the robot's: no motion drawn");
            }
        }
        drawn.write(page)?;
        say!("  view: {}", page.display());
    }
    Ok(if check.is_valid() {
        CommandOutcome::Success
    } else {
        CommandOutcome::InvalidPaths
    })
}

/// Refuses a plot file `name` (given as `option`) that is not `.png` or `.svg`.
fn plot_name(name: &std::path::Path, option: &str) -> Result<(), HarnessError> {
    match name.extension().and_then(|e| e.to_str()) {
        Some("png" | "svg") => Ok(()),
        _ => Err(HarnessError::Usage(format!(
            "{option} {}: the picture is .png or .svg",
            name.display()
        ))),
    }
}

/// The samples' positions in the robot's coordinate order (`robot`'s joint names), or `None`
/// if the file's joints are not those names.
fn in_robot_order(file: &TrajectoryFile, robot: &[String]) -> Option<Vec<Vec<f64>>> {
    let order: Vec<usize> = robot
        .iter()
        .map(|name| file.joints.iter().position(|j| j == name))
        .collect::<Option<_>>()?;
    file.samples
        .iter()
        .map(|s| order.iter().map(|&k| s.position.get(k).copied()).collect())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(blend_room: Option<f64>, corners: Corners) -> TrajectoryArgs {
        TrajectoryArgs {
            trajectory: Some("t.json".into()),
            sample_period: None,
            corners,
            blend_room,
            trajectory_plot: None,
            limits: LimitArgs {
                joint_limits: None,
                max_acceleration: Some(2.0),
                velocity_scaling: 1.0,
                acceleration_scaling: 1.0,
            },
        }
    }

    #[test]
    fn the_blend_room_adds_to_the_problems_padding() {
        let arm = ArmProblem::panda_mbm(
            concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../robot/tests/data/mbm/table_pick_panda"
            )
            .as_ref(),
            1,
        )
        .unwrap();
        let room = |r: Option<f64>, corners, arm: &ArmProblem| args(r, corners).blend_room(arm);
        assert_eq!(room(None, Corners::Blend, &arm).unwrap(), None);
        let padding = room(Some(0.01), Corners::Blend, &arm).unwrap().unwrap();
        assert_eq!(padding.metres(), 0.01);
        let padded = arm.clone().with_padding(Padding::new(0.02).unwrap());
        let padding = room(Some(0.01), Corners::Blend, &padded).unwrap().unwrap();
        assert!((padding.metres() - 0.03).abs() < 1e-15);
        for (bad, corners, says) in [
            (-0.01, Corners::Blend, "negative"),
            (f64::NAN, Corners::Blend, "not a number"),
            (0.995, Corners::Blend, "larger than"),
            (0.01, Corners::Stop, "--corners stop"),
        ] {
            let error = room(Some(bad), corners, &padded).unwrap_err().to_string();
            assert!(error.contains(says), "{bad}: {error}");
        }
        assert!(
            args(Some(-1.0), Corners::Blend)
                .prepare(Some(&arm))
                .is_err()
        );
    }
}
