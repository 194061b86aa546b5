//! The listing subcommands: `problems`, `planners`, `robots` (or one robot described), `experiments`.

use clap::Args;
use mit_star::{Configuration, Parameters};

use crate::commands::CommandOutcome;
use crate::definition::shipped_experiment::ShippedExperiment;
use crate::error::HarnessError;
use crate::pictures::robot_sweep::write_robot_sweep;

/// Options of `mit-star problems`.
#[derive(Debug, Args)]
pub struct ProblemsArgs {
    /// Show the defaults in this dimension (some depend on it).
    #[arg(long, default_value_t = 2)]
    pub dim: usize,
    /// Instead of listing, print this built-in problem in `--dim` dimensions as a TOML problem
    /// file (the exact boxes, ends and resolution the planners see; for feeding another
    /// planner, or for editing and `--problem path.toml`).
    #[arg(long, value_name = "NAME")]
    pub write: Option<String>,
    /// The layout of a seeded family to print with `--write` (as `plan --instance`).
    #[arg(long, default_value_t = 0, requires = "write")]
    pub instance: u64,
}

impl ProblemsArgs {
    /// Prints every built-in family with its parameters.
    ///
    /// # Errors
    /// [`HarnessError::Problem`] if a family cannot be built in `--dim` dimensions.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        if let Some(name) = &self.write {
            let problem =
                mit_star_problems::builtin(name, self.dim, self.instance).map_err(|source| {
                    HarnessError::Problem {
                        name: name.clone(),
                        dimension: self.dim,
                        source,
                    }
                })?;
            let text = problem.to_toml_string();
            say!("{}", text.trim_end());
            return Ok(CommandOutcome::Success);
        }
        say!(
            "Built-in problems (space [-0.5, 0.5]^n; defaults shown for n = {}):\n",
            self.dim
        );
        for family in mit_star_problems::catalogue() {
            let problem = family
                .build(self.dim, 0)
                .map_err(|source| HarnessError::Problem {
                    name: family.name().to_owned(),
                    dimension: self.dim,
                    source,
                })?;
            say!("{}", family.name());
            say!("  {}", family.description());
            if family.is_seeded() {
                say!("  layout fixed by a seed (bench: `instances = K`, plan: `--instance S`)");
            }
            let optimum = problem
                .optimum()
                .map_or_else(|| "unknown".to_owned(), |o| format!("{o:.6}"));
            say!(
                "  straight line {:.6}, optimum {optimum}, resolution {} (step {:.3e})",
                problem.straight_line_cost(),
                problem.resolution(),
                problem.step()
            );
            for p in family.parameters(self.dim) {
                say!("    {:<22} {:<36} {}", p.name, p.value, p.meaning);
            }
            say!();
        }
        say!("A TOML problem file can be given instead of a name (`--problem path.toml`).");
        Ok(CommandOutcome::Success)
    }
}

/// Prints the configurations and the parameters with their defaults.
///
/// # Errors
/// Never; the signature matches the other commands.
pub(crate) fn print_planners() -> Result<CommandOutcome, HarnessError> {
    say!("Planner configurations (their parts: the guide's Composing a planner):\n");
    let parts = |c: Configuration| match c {
        Configuration::MitStar => {
            "adaptive sampler, estimated informed set, length-related sparse checks, reverse search yields while the forward queue is empty"
        }
        Configuration::EitStar => {
            "informed sampler, fixed sparse levels (1, 3, 7, … checks), reverse search keeps going while the forward queue is empty (upstream)"
        }
        Configuration::MitStarAs => "EIT* with the adaptive sampler",
        Configuration::MitStarEis => "EIT* with the estimated informed set",
        Configuration::MitStarSc => "EIT* with length-related sparse checks",
        Configuration::MitStarSr => {
            "EIT* with MIT*'s suspension rule (reverse search yields while the forward queue is empty); not in the paper"
        }
        Configuration::RrtConnect => {
            "bidirectional trees, extensions of at most `range`, first solution (parameters: range and the rrt_* switches)"
        }
        Configuration::Aorrtc => {
            "RRT-Connect's first solution, then cost-bounded bidirectional searches with informed samples, each path simplified (parameters: range, aorrtc_simplify, aorrtc_resamples)"
        }
        Configuration::BitStar => {
            "informed sampler, no reverse search: edges in order of g + ĉ + ĥ, full checks (parameters: batch_size, rewire_factor, pruning)"
        }
        Configuration::AbitStar => {
            "BIT* with inflation and truncation (initial_inflation 1e6, inflation_scaling 10, truncation_scaling 5 unless set)"
        }
        Configuration::AitStar => {
            "informed sampler, unchecked lazy reverse search as the forward search's heuristic, full forward checks"
        }
        Configuration::FcitStar => {
            "BIT*'s search (g + ĉ + ĥ order, full checks) on a fully connected graph: every sample a neighbour of every other, no radius or k; each vertex's edges queued one at a time (parameters: batch_size, 200 unless set; pruning)"
        }
        Configuration::InformedRrtStar => {
            "RRT* with k-nearest rewiring, goal bias, direct informed sampling, pruning (parameters: range, goal_bias, rrt_rewire_factor, pruning)"
        }
    };
    for c in Configuration::ALL {
        say!("  {:<14} {:<12} {}", c.name(), c.label(), parts(c));
    }
    say!(
        "\nParameters (override with `--set key=value`; `seed` and `resolution` are set by the harness), their defaults and the planners that read them:\n"
    );
    for (k, v) in Parameters::default().settings() {
        say!("  {k:<36} {v:<12} {}", readers(&k));
    }
    Ok(CommandOutcome::Success)
}

/// The configurations that read parameter `name`
/// ([`Configuration::reads`](mit_star::Configuration::reads)), named shortly: `every planner`,
/// or `the EIT* family` (MIT*, EIT*, their ablations, BIT*, ABIT*, AIT*) with the others that
/// read it or the members that do not, or their names.
fn readers(name: &str) -> String {
    let names = |family: bool, reading: bool| {
        let cs = Configuration::ALL
            .into_iter()
            .filter(|c| c.is_informed_tree() == family && c.reads(name) == reading);
        cs.map(Configuration::name).collect::<Vec<_>>()
    };
    // The family's members that do not read it, and the other planners that do.
    let (missing, others) = (names(true, false), names(false, true));
    let outside = Configuration::ALL
        .iter()
        .filter(|c| !c.is_informed_tree())
        .count();
    match (missing.len(), others.len()) {
        (0, 0) => "the EIT* family".into(),
        (0, n) if n == outside => "every planner".into(),
        (0, _) => format!("the EIT* family, {}", others.join(", ")),
        (1..=2, 0) => format!("the EIT* family but {}", missing.join(", ")),
        _ => [names(true, true), others].concat().join(", "),
    }
}

/// Options of `mit-star experiments`.
#[derive(Debug, Args)]
pub struct ExperimentsArgs {
    /// Print this shipped experiment's file (to copy and edit).
    #[arg(long, value_name = "NAME")]
    pub print: Option<String>,
}

impl ExperimentsArgs {
    /// Lists the shipped experiments or prints one.
    ///
    /// # Errors
    /// [`HarnessError::UnknownExperiment`] for an unknown name.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        if let Some(name) = &self.print {
            {
                use std::io::Write as _;
                let _ = write!(
                    std::io::stdout().lock(),
                    "{}",
                    ShippedExperiment::find(name)?.text
                );
            }
            return Ok(CommandOutcome::Success);
        }
        say!("Shipped experiments (run with `mit-star bench --experiment NAME`):\n");
        for e in ShippedExperiment::all() {
            say!("  {:<12} {}", e.name, e.summary);
        }
        say!(
            "\nThe paper's re-planning experiment (§V-C) has a command of its own: `mit-star replan` (the Panda among moving obstacles: both scenes, MIT*, EIT*, AIT*, AORRTC and RRT-Connect, 30 trials each, 0.1 s per plan; about 20 minutes)."
        );
        Ok(CommandOutcome::Success)
    }
}

/// Options of `mit-star robots`.
#[derive(Debug, Args)]
pub struct RobotsArgs {
    /// Describe this robot instead of listing the shipped ones: a shipped name, a URDF (the
    /// SRDF beside it: same stem `.srdf`, or the folder's only `*.srdf`; without one, the
    /// pairs its spheres rule out are not checked, with a warning), or a folder holding one
    /// URDF and one SRDF. Joints are listed in coordinate order: the order of a state's
    /// values everywhere (`--state`, `check-path`, the paths written).
    #[arg(value_name = "NAME|URDF|DIR")]
    pub robot: Option<String>,
    /// Also write an interactive 3-D view of the robot to this HTML file: each joint swept
    /// through its range, its spheres and its visual meshes side by side (a toggle), the
    /// sphere model's self-collisions in red.
    #[arg(long, value_name = "FILE.html", requires = "robot")]
    pub view: Option<std::path::PathBuf>,
    /// A folder `package://NAME/…` mesh paths are looked up in (as `NAME/…`; repeatable), for
    /// `--view` of a URDF whose meshes live in ROS packages.
    #[arg(long, value_name = "DIR", requires = "view")]
    pub package_root: Vec<std::path::PathBuf>,
}

impl RobotsArgs {
    /// Lists the shipped robots, or describes the one named.
    ///
    /// # Errors
    /// [`HarnessError::Robot`] for a robot that cannot be found or loaded.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        let Some(text) = &self.robot else {
            return print_robots();
        };
        let page = crate::commands::ViewArgs {
            view: self.view.clone(),
            view_search: false,
            view_package_root: Vec::new(),
        };
        let page = page.prepare()?;
        let (source, model) = describe_robot(text)?;
        if let Some(page) = page {
            let resolver = source
                .mesh_resolver()
                .with_package_roots(self.package_root.clone());
            let bytes = write_robot_sweep(&model, &source.label(), &resolver, page)?;
            say!("  view: {} ({bytes} bytes)", page.display());
        }
        Ok(CommandOutcome::Success)
    }
}

/// `mit-star robots ROBOT`: the robot's joints in coordinate order, spheres per link, groups;
/// the robot described, for its view.
fn describe_robot(
    text: &str,
) -> Result<(mit_star_robot::RobotSource, mit_star_robot::RobotModel), HarnessError> {
    let source = mit_star_robot::RobotSource::parse(text)?;
    let model = source.load(false)?;
    say!("{} (robot `{}`)", source.label(), model.name());
    if let Some(srdf) = source.srdf() {
        say!("  SRDF: {}", srdf.display());
    }
    let joints = model.joint_space().joints();
    say!(
        "  {} joints, in coordinate order (the order of a state's values: --state, check-path, the paths written):",
        joints.len()
    );
    let width = joints.iter().map(|j| j.name.len()).max().unwrap_or(0);
    for (i, joint) in joints.iter().enumerate() {
        let (kind, limits) = match joint.kind {
            mit_star_spaces::JointKind::Revolute { lower, upper } => {
                ("revolute", format!("[{lower:.6}, {upper:.6}] rad"))
            }
            mit_star_spaces::JointKind::Prismatic { lower, upper } => {
                ("prismatic", format!("[{lower:.6}, {upper:.6}] m"))
            }
            mit_star_spaces::JointKind::Continuous => (
                "continuous",
                "wraps at ±π (values in [-π, π], moved the short way round)".to_owned(),
            ),
        };
        say!("    {i:>2}  {:<width$}  {kind:<10}  {limits}", joint.name);
    }
    let held = model.held_joints();
    if !held.is_empty() {
        let held: Vec<String> = held.iter().map(|(n, v)| format!("{n} = {v}")).collect();
        say!("  held joints: {}", held.join(", "));
    }
    say!(
        "  {} spheres on {} links; per link with spheres:",
        model.spheres().len(),
        model.links().len()
    );
    for (l, link) in model.links().iter().enumerate() {
        let n = model.link_sphere_range(l).len();
        if n > 0 {
            say!("    {:<width$}  {n}", link.name);
        }
    }
    say!(
        "  {} link pairs checked for self-collision",
        model.self_collision_pairs().len()
    );
    say!(
        "  RRT range: {} rad by default (RRT-Connect, AORRTC, Informed RRT*; `--set range=X` overrides)",
        model.rrt_range()
    );
    let groups = source.groups()?;
    if groups.is_empty() {
        say!("  groups:   none (no SRDF)");
    } else {
        say!("  groups:   {} (`--group NAME`)", groups.join(", "));
    }
    for warning in model.warnings() {
        say!("  warning:  {warning}");
    }
    Ok((source, model))
}

/// `mit-star robots`: the shipped robots, their size, and how to unpack their problems.
fn print_robots() -> Result<CommandOutcome, HarnessError> {
    say!(
        "Shipped robots (`--robot NAME`; or `--robot PATH.urdf`, the SRDF beside it; or `--robot DIR`, a folder with one URDF and one SRDF; `mit-star robots NAME|URDF|DIR` describes one):\n"
    );
    for shipped in mit_star_robot::ShippedRobot::all() {
        let model =
            shipped
                .model(false)
                .map_err(|source| mit_star_robot::RobotSourceError::Model {
                    robot: shipped.name.to_owned(),
                    source,
                })?;
        let default = if shipped.name == mit_star_robot::ShippedRobot::DEFAULT {
            " (default)"
        } else {
            ""
        };
        say!("{}{default}", shipped.name);
        say!("  {}", shipped.description);
        say!(
            "  {} joints (dimension {}): {}",
            model.joint_names().len(),
            model.joint_names().len(),
            model.joint_names().join(", ")
        );
        say!(
            "  {} spheres on {} links",
            model.spheres().len(),
            model.links().len()
        );
        say!(
            "  groups:   {} (`--group NAME`)",
            shipped.groups().join(", ")
        );
        say!("  problems: {}", shipped.problems);
        say!(
            "  unpack:   mkdir -p target && tar xjf {} -C target/",
            shipped.problems
        );
        say!(
            "  plan:     mit-star plan --robot {} --problem mbm:{} --planner mit-star\n",
            shipped.name,
            shipped.unpacked.replace("{scene}", shipped.scene)
        );
    }
    Ok(CommandOutcome::Success)
}
