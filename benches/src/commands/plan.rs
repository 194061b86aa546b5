//! `mit-star plan`: one planner, one problem, one run.

use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

use clap::Args;

use crate::budget::{budget_duration, deadline_after};
use crate::commands::CommandOutcome;
use crate::commands::pose_goal_args::PoseGoalArgs;
use crate::commands::problem_args::ProblemArgs;
use crate::definition::parameter_overrides::ParameterOverrides;
use crate::definition::planner_spec::{PlannerSpec, parse_configuration};
use crate::definition::pose_goal_source::PoseGoalSource;
use crate::definition::problem_instance::ProblemInstance;
use crate::definition::problem_kind::InstanceProblem;
use crate::definition::problem_source::sanitise;
use crate::error::HarnessError;
use crate::execution::interrupt::ReadingInputs;
use crate::execution::run_job::RunJob;
use crate::formats::kpi_table::number;
use crate::outcome::run_record::{RunRecord, RunStatus};
use crate::path_validation::PathValidation;
use crate::pictures::arm_picture::ArmPicture;
use crate::pictures::plan_view::PlanView;
use crate::pictures::run_picture::RunPicture;

/// Options of `mit-star plan`.
#[derive(Debug, Args)]
pub struct PlanArgs {
    /// Planner: mit-star, eit-star, mit-star-as, mit-star-eis, mit-star-sc, mit-star-sr, ait-star,
    /// bit-star, abit-star, informed-rrt-star, rrt-connect, aorrtc (`mit-star planners` lists them).
    #[arg(long, short, default_value = "mit-star")]
    pub planner: String,
    /// The problem.
    #[command(flatten)]
    pub problem: ProblemArgs,
    /// A link's pose as the goal of an arm problem.
    #[command(flatten)]
    pub pose: PoseGoalArgs,
    /// Time budget in seconds (planner construction included).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub time: f64,
    /// The planner's seed.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Parameter override, e.g. `--set batch_size=200` (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Folder for the picture of a 2-D run or an arm plan.
    #[arg(long, short, default_value = "results/plan")]
    pub output: PathBuf,
    /// Do not draw the picture of a 2-D run or an arm plan.
    #[arg(long)]
    pub no_picture: bool,
    /// Print the result as JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Stop at the first solution (or the budget), as `bench --first-solution` does: the
    /// time to a first path of an anytime planner (MIT*, AORRTC, …).
    #[arg(long)]
    pub first_solution: bool,
    /// Simplify the path found (vertex reduction, random and per-coordinate shortcuts and,
    /// unless `--set simplify_smoothing=false`, smoothing; every new edge checked and
    /// certified), validate the result independently, and report and draw it.
    #[arg(long)]
    pub simplify: bool,
    /// Time for `--simplify`, in seconds (after the planning budget).
    #[arg(
        long,
        default_value_t = 0.1,
        requires = "simplify",
        allow_negative_numbers = true
    )]
    pub simplify_time: f64,
    /// Timing the path: `--trajectory FILE` and its options.
    #[command(flatten)]
    pub timing: crate::commands::TrajectoryArgs,
    /// The 3-D view: `--view FILE.html`, `--view-search`.
    #[command(flatten)]
    pub view: crate::commands::ViewArgs,
}

impl PlanArgs {
    /// The pictures' file name without extension: the problem instance, the planner and the
    /// seed, then — when any other setting was given (`--set`, a budget other than 1 s,
    /// `--first-solution`, `--simplify`, the problem's options beyond its name and instance:
    /// resolution, robot, group, clouds, padding; a pose goal; a blend room) — `-s` and eight
    /// hexadecimal digits (CRC-32) of those settings, so that runs with different settings
    /// never share a file.
    fn picture_stem(&self, instance: &str, planner: &str) -> String {
        let stem = format!("{instance}-{}-seed{}", sanitise(planner), self.seed);
        let mut settings: Vec<String> = self.set.clone();
        settings.sort();
        if self.time != 1.0 {
            settings.push(format!("time={}", self.time));
        }
        if self.first_solution {
            settings.push("first-solution".into());
        }
        if self.simplify {
            settings.push(format!("simplify={}", self.simplify_time));
        }
        let p = &self.problem;
        if p.robot.is_some()
            || p.group.is_some()
            || p.resolution.is_some()
            || p.allow_coarse_step
            || p.clouds.any()
        {
            settings.push(format!(
                "{:?} {:?} {:?} {} {:?}",
                p.robot, p.group, p.resolution, p.allow_coarse_step, p.clouds
            ));
        }
        if self.pose.goal_pose.is_some() {
            settings.push(format!("{:?}", self.pose));
        }
        if let Some(padding) = p.padding.filter(|p| !p.is_zero()) {
            settings.push(format!("padding={}", padding.metres()));
        }
        if let Some(room) = self.timing.blend_room {
            settings.push(format!("blend-room={room}"));
        }
        if settings.is_empty() {
            return stem;
        }
        let mut crc = crc32fast::Hasher::new();
        crc.update(settings.join("\n").as_bytes());
        format!("{stem}-s{:08x}", crc.finalize())
    }

    /// Runs the planner and prints the result.
    ///
    /// # Errors
    /// Unknown planner or problem, bad parameters, dimension or budget, an unwritable output
    /// folder (all before planning), or a failed picture.
    pub fn run(&self, interrupt: &AtomicBool) -> Result<CommandOutcome, HarnessError> {
        // Reading the inputs may block (a FIFO, a stalled file system) where nothing polls the
        // flag: until the planner is built, a signal leaves at once.
        let reading = ReadingInputs::begin(interrupt);
        if reading.interrupted() {
            return Ok(CommandOutcome::Interrupted);
        }
        let configuration = parse_configuration(&self.planner)?;
        let mut overrides = ParameterOverrides::default();
        for s in &self.set {
            overrides.push_assignment(s)?;
        }
        let spec = PlannerSpec::new(configuration, None, &overrides)?;
        spec.refuse_unread()?;
        budget_duration(self.time).map_err(|source| HarnessError::Budget {
            what: "--time".into(),
            source,
        })?;
        if self.simplify {
            budget_duration(self.simplify_time).map_err(|source| HarnessError::Budget {
                what: "--simplify-time".into(),
                source,
            })?;
        }
        let mut instance = self.problem.build(self.time)?;
        let arm = instance.problem.as_arm().cloned();
        instance.pose_goal = self.pose.spec();
        if let Some(spec) = &instance.pose_goal {
            spec.check()?;
        }
        let limits = self.timing.prepare(arm.as_deref())?;
        let picture = (instance.dimension == 2 || arm.is_some()) && !self.no_picture;
        if picture {
            crate::writable_folder(&self.output)?;
        }
        self.view.prepare()?;
        drop(reading);
        if interrupt.load(std::sync::atomic::Ordering::SeqCst) {
            return Ok(CommandOutcome::Interrupted);
        }
        let job = RunJob {
            instance: 0,
            planner: 0,
            run: 0,
            seed: self.seed,
            first_solution: self.first_solution,
        };
        // Build once, on the run's clock: construction counts against the budget.
        let started = Instant::now();
        let deadline =
            deadline_after(started, self.time).map_err(|source| HarnessError::Budget {
                what: "--time".into(),
                source,
            })?;
        let (built, pose) = instance.build_planner(&spec, self.seed)?;
        let solved = match &pose {
            None => job.solve_built(&instance, &spec, built, (started, deadline), interrupt),
            Some(source) => {
                let validate = |path: &[Vec<f64>], cost: f64| source.validate(path, cost);
                let times = (started, deadline);
                job.solve_built_validating(&instance, &spec, built, times, interrupt, &validate)
            }
        };
        let Some((record, planner)) = solved else {
            return Ok(CommandOutcome::Interrupted);
        };
        if let Some(source) = &pose {
            report_pose_goal(source, &record);
        }
        let smoothing = spec.parameters_for_seed(self.seed).simplify_smoothing;
        let simplified = self.simplified(&instance, &record, smoothing, pose.as_ref())?;
        let drawn = simplified.as_ref().map_or(&record.path, |(s, _)| &s.path);
        let timed = match (&arm, &limits) {
            (Some(arm), Some(limits)) if drawn.len() >= 2 => {
                self.timing.write(arm, limits, drawn)?
            }
            _ => None,
        };
        let mut files = Vec::new();
        let stem = self.picture_stem(&instance.id, configuration.name());
        let replaced = [
            self.output.join(format!("{stem}.svg")),
            self.output.join(format!("{stem}.png")),
        ]
        .into_iter()
        .filter(|f| picture && f.exists())
        .collect::<Vec<_>>();
        let title = format!(
            "{} on {} · seed {} · {} s · cost {}",
            spec.name(),
            instance.title(),
            self.seed,
            self.time,
            number(
                simplified
                    .as_ref()
                    .map_or(record.final_cost.unwrap_or(f64::INFINITY), |(s, _)| s.cost)
            )
        );
        if picture && let Some(arm) = &arm {
            let svg = self.output.join(format!("{stem}.svg"));
            let png = self.output.join(format!("{stem}.png"));
            // Towards a pose, the goal drawn is the configuration the path reached.
            let reached = pose
                .as_ref()
                .and(drawn.last())
                .and_then(|last| (**arm).clone().with_goals(vec![last.clone()]).ok());
            let arm = reached.as_ref().unwrap_or(&**arm);
            ArmPicture::new(arm, drawn, title.clone()).save(&svg, &png)?;
            files.extend([svg, png]);
        }
        if picture
            && let Some(boxes) = instance.problem.as_boxes()
            && let Some(snapshot) = planner.as_ref().and_then(|p| p.snapshot())
        {
            let svg = self.output.join(format!("{stem}.svg"));
            let png = self.output.join(format!("{stem}.png"));
            RunPicture::new(boxes, &snapshot, drawn, title.clone())?.save(&svg, &png)?;
            files.extend([svg, png]);
        }
        if let Some(file) = &self.view.view {
            let mut view = PlanView::new(
                &instance.problem,
                title,
                instance.pose_goal.as_ref().map(|p| p.link.as_str()),
            )?;
            if let Some(resolver) = instance.mesh_resolver() {
                view.meshes(&resolver.with_package_roots(self.view.view_package_root.clone()));
            }
            view.subtitle(view_verdict(&record));
            if let Some((s, _)) = &simplified {
                view.path("simplified path", &s.path);
            }
            view.path("path as planned", &record.path);
            if let Some(t) = &timed {
                view.trajectory("timed trajectory", t.trajectory());
            }
            if self.view.view_search {
                match planner.as_ref().and_then(|p| p.snapshot()) {
                    Some(snapshot) => {
                        view.search(&snapshot);
                    }
                    None => {
                        view.note(format!("{} keeps no graph to draw", spec.name()));
                    }
                }
            }
            view.write(file)?;
            files.push(file.clone());
        }
        if self.json {
            let mut value = serde_json::to_value(&record).map_err(|e| HarnessError::Serialise {
                path: "stdout".into(),
                message: e.to_string(),
            })?;
            if let Some(o) = value.as_object_mut() {
                o.insert("optimum".into(), instance.problem.optimum().into());
                let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
                o.insert("files".into(), names.into());
                if let Some(t) = &timed {
                    o.insert("trajectory".into(), t.json());
                }
                if let Some((s, validation)) = &simplified {
                    o.insert(
                        "simplified".into(),
                        serde_json::json!({
                            "path": s.path,
                            "cost": s.cost,
                            "original_cost": s.original_cost,
                            "vertices_removed": s.vertices_removed,
                            "shortcuts": s.shortcuts,
                            "partial_shortcuts": s.partial_shortcuts,
                            "smoothing_moves": s.smoothing_moves,
                            "edges_checked": s.edges_checked,
                            "blend_room": self.timing.blend_room,
                            "valid": validation.valid,
                            "validation_failure": validation.failure,
                        }),
                    );
                }
            }
            say!("{value}");
        } else {
            print_record(&record, &instance, &files);
            for f in &replaced {
                say!(
                    "  (replaced {}: an earlier picture of the same problem, planner, seed and \
                     settings)",
                    f.display()
                );
            }
            if let Some((s, validation)) = &simplified {
                print_simplified(s, validation);
                if let Some(room) = self.timing.blend_room {
                    say!(
                        "  blend room: every edge the simplifier added keeps {} m more from obstacles",
                        number(room)
                    );
                }
            }
            if let Some(t) = &timed {
                say!("{}", t.line());
            }
        }
        if simplified.as_ref().is_some_and(|(_, v)| !v.valid) {
            return Ok(CommandOutcome::InvalidPaths);
        }
        if let Some(e) = &record.error {
            return Err(HarnessError::Planning {
                planner: spec.name().to_owned(),
                source: mit_star::PlannerError::Internal(e.clone()),
            });
        }
        Ok(if record.status == RunStatus::InvalidPath {
            CommandOutcome::InvalidPaths
        } else {
            CommandOutcome::Success
        })
    }
}

impl PlanArgs {
    /// The run's path simplified (`--simplify`; smoothed too if `smoothing`) and its
    /// independent validation (towards the pose goal `pose` when there is one); `None` without
    /// the flag or a path.
    ///
    /// # Errors
    /// A problem that refuses its check step (refused before planning in practice).
    fn simplified(
        &self,
        instance: &ProblemInstance,
        record: &RunRecord,
        smoothing: bool,
        pose: Option<&PoseGoalSource>,
    ) -> Result<Option<(mit_star::Simplified, crate::path_validation::PathValidation)>, HarnessError>
    {
        if !self.simplify || record.path.len() < 2 {
            return Ok(None);
        }
        // With `--blend-room`, the simplifier's problem keeps the room too.
        let roomy = match instance.problem.as_arm() {
            Some(arm) => self.timing.blend_room(arm)?.map(|padding| {
                InstanceProblem::Arm(std::sync::Arc::new((**arm).clone().with_padding(padding)))
            }),
            None => None,
        };
        let simplified = roomy
            .as_ref()
            .unwrap_or(&instance.problem)
            .simplify(&record.path, self.simplify_time, self.seed, smoothing)
            .map_err(|source| HarnessError::Build {
                planner: "path simplifier".to_owned(),
                source,
            })?;
        let validation = match pose {
            Some(source) => source.validate(&simplified.path, simplified.cost),
            None => instance.problem.validate(&simplified.path, simplified.cost),
        };
        Ok(Some((simplified, validation)))
    }
}

/// The report of a simplified path.
fn print_simplified(s: &mit_star::Simplified, validation: &crate::path_validation::PathValidation) {
    say!(
        "  simplified: cost {} -> {} ({} states removed, {} shortcuts, {} per-coordinate, {} smoothing moves, {} edges checked{})",
        number(s.original_cost),
        number(s.cost),
        s.vertices_removed,
        s.shortcuts,
        s.partial_shortcuts,
        s.smoothing_moves,
        s.edges_checked,
        if s.stopped {
            ", stopped by --simplify-time"
        } else {
            ""
        }
    );
    if validation.valid {
        say!(
            "  simplified path validated independently, {} ({}, {}):",
            validation.method.describe(),
            validation.coverage(),
            audit_time(validation.seconds)
        );
    } else {
        say!(
            "  INVALID SIMPLIFIED PATH ({}): {}",
            validation.method.describe(),
            validation.failure.clone().unwrap_or_default()
        );
    }
    print_states(&s.path);
}

/// The line naming the joints a path's coordinates are, in order, and those that wrap;
/// `None` without joint names (box worlds).
pub(crate) fn joints_line(joints: &[String], wrapping: &[bool]) -> Option<String> {
    if joints.is_empty() {
        return None;
    }
    let wraps: Vec<&str> = joints
        .iter()
        .zip(wrapping)
        .filter(|(_, w)| **w)
        .map(|(j, _)| j.as_str())
        .collect();
    Some(format!(
        "joints: {}{}",
        joints.join(", "),
        if wraps.is_empty() {
            String::new()
        } else {
            format!(
                " (continuous, wrapping at ±π: {}; interpolate the short way round)",
                wraps.join(", ")
            )
        }
    ))
}

/// The independent check's time in words: `0.42 ms`, `1.3 s`.
pub(crate) fn audit_time(seconds: f64) -> String {
    if seconds < 1.0 {
        format!("{} ms", number(seconds * 1e3))
    } else {
        format!("{} s", number(seconds))
    }
}

/// One line per state, six decimals.
fn print_states(states: &[Vec<f64>]) {
    for state in states {
        let coordinates: Vec<String> = state.iter().map(|x| format!("{x:.6}")).collect();
        say!("    ({})", coordinates.join(", "));
    }
}

/// The human-readable report of one run.
/// The run's verdict in one line, under a view's title.
fn view_verdict(r: &RunRecord) -> String {
    let failure = || {
        r.validation
            .as_ref()
            .and_then(|v| v.failure.clone())
            .or_else(|| r.error.clone())
            .unwrap_or_default()
    };
    match r.status {
        RunStatus::Solved => format!(
            "solved: first path after {} s (cost {}), final cost {}, {} states, validated \
             independently ({})",
            number(r.initial_time.unwrap_or(f64::NAN)),
            number(r.initial_cost.unwrap_or(f64::INFINITY)),
            number(r.final_cost.unwrap_or(f64::INFINITY)),
            r.path.len(),
            r.validation
                .as_ref()
                .map_or_else(String::new, |v| v.method.describe())
        ),
        RunStatus::Unsolved => "no solution within the budget".to_owned(),
        RunStatus::InvalidPath => format!("INVALID PATH: {}", failure()),
        RunStatus::Error => format!("error: {}", failure()),
    }
}

fn print_record(r: &RunRecord, instance: &ProblemInstance, files: &[PathBuf]) {
    say!(
        "{} on {} (seed {}, budget {} s)",
        r.planner,
        instance.title(),
        r.seed,
        r.budget
    );
    let validation = r.validation.as_ref();
    match r.status {
        RunStatus::Solved => say!(
            "  solved; path validated independently, {} ({}, {} apart from planning)",
            validation.map_or_else(String::new, |v| v.method.describe()),
            validation.map_or_else(String::new, PathValidation::coverage),
            audit_time(validation.map_or(0.0, |v| v.seconds))
        ),
        RunStatus::Unsolved => say!("  no solution within the budget"),
        RunStatus::InvalidPath => say!(
            "  INVALID PATH: the returned path failed the independent validation ({}): {}",
            validation.map_or_else(String::new, |v| v.method.describe()),
            validation
                .and_then(|v| v.failure.clone())
                .unwrap_or_default()
        ),
        RunStatus::Error => say!("  error: {}", r.error.clone().unwrap_or_default()),
    }
    let optimum = instance
        .problem
        .optimum()
        .map_or_else(|| "unknown".to_owned(), |o| format!("{o:.6}"));
    say!(
        "  initial solution: {} s, cost {}",
        number(r.initial_time.unwrap_or(f64::INFINITY)),
        number(r.initial_cost.unwrap_or(f64::INFINITY))
    );
    say!(
        "  final cost: {} after {} improvements (straight line {:.6}, optimum {optimum})",
        number(r.final_cost.unwrap_or(f64::INFINITY)),
        r.trace.len(),
        instance.problem.straight_line_cost()
    );
    say!(
        "  time: {:.4} s in total, {:.6} s to build the planner",
        r.run_time,
        r.setup_time
    );
    say!("  counters (zeros left out; `--json` has them all):");
    for (name, value) in r.counter_values() {
        if value != 0 {
            say!("    {name:<32} {value}");
        }
    }
    for (name, value) in r.real_counter_values() {
        if let Some(value) = value {
            say!("    {name:<32} {}", number(value));
        }
    }
    if !r.path.is_empty() {
        say!("  path ({} states):", r.path.len());
        if let Some(line) = joints_line(&r.joints, &r.wrapping) {
            say!("  {line}");
        }
        print_states(&r.path);
    }
    for f in files {
        say!("  picture: {}", f.display());
    }
}

/// The goal configurations drawn for a pose goal, on stderr (stdout may be JSON).
fn report_pose_goal(source: &PoseGoalSource, record: &RunRecord) {
    let drawn = source.given().lock().map(|g| g.len()).unwrap_or(0);
    eprintln!("pose goal: {drawn} goal configurations drawn by inverse kinematics");
    if drawn == 0
        && record.path.is_empty()
        && let Some(why) = source.last_failure()
    {
        eprintln!("pose goal: no configuration reaches the pose: {why}");
    }
}
