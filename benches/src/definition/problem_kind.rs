//! [`InstanceProblem`]: the problem of an experiment's instance, whatever its kind.

use std::sync::Arc;

use mit_star::{BuildError, Configuration, Parameters, Planner};
use mit_star_problems::{PlanningProblem, Problem, ProblemError};
use mit_star_robot::{ArmProblem, MotionAudit};

/// Configurations the continuous audit of an arm path may compute per segment before it calls
/// the segment undecided (a failure): far more than a path with a millimetre of clearance
/// needs.
const AUDIT_BUDGET: u64 = 2_000_000;
use mit_star_spaces::StateSpace;

use crate::error::HarnessError;
use crate::path_validation::PathValidation;

/// The problem of one [`ProblemInstance`](crate::ProblemInstance): a box world (the PDT
/// families and problem files) or a robot arm in a scene (MotionBenchMaker). Every kind plans
/// through [`PlanningProblem`]; what differs is how a path is validated independently, what a
/// picture shows, and what a log describes.
// A handful of instances per experiment: the size of the box variant does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum InstanceProblem {
    /// A point among axis-aligned boxes in `R^n`.
    Boxes(Problem),
    /// The Panda among a MotionBenchMaker scene's primitives (shared: the scene and checker
    /// are built once per instance).
    Arm(Arc<ArmProblem>),
}

/// Arm problems are equal when they are the same problem of the same folder at the same
/// resolution.
impl PartialEq for InstanceProblem {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Self::Boxes(a), Self::Boxes(b)) => a == b,
            (Self::Arm(a), Self::Arm(b)) => {
                Arc::ptr_eq(a, b)
                    || (a.name() == b.name()
                        && a.resolution() == b.resolution()
                        && a.start() == b.start()
                        && a.goals() == b.goals())
            }
            _ => false,
        }
    }
}

impl InstanceProblem {
    /// The box-world problem, if this is one.
    pub fn as_boxes(&self) -> Option<&Problem> {
        match self {
            Self::Boxes(p) => Some(p),
            Self::Arm(_) => None,
        }
    }

    /// The arm problem, if this is one.
    pub fn as_arm(&self) -> Option<&Arc<ArmProblem>> {
        match self {
            Self::Boxes(_) => None,
            Self::Arm(p) => Some(p),
        }
    }

    /// What a state's coordinates are, in order: each joint's name and whether it wraps
    /// (a continuous joint), for an arm; `None` for a box world (coordinates `x0, x1, …`).
    pub fn joints(&self) -> Option<(Vec<String>, Vec<bool>)> {
        let arm = self.as_arm()?;
        let joints = arm.robot().joint_space().joints();
        Some((
            joints.iter().map(|j| j.name.clone()).collect(),
            joints
                .iter()
                .map(|j| j.kind == mit_star_spaces::JointKind::Continuous)
                .collect(),
        ))
    }

    /// Allows (or not) a check that may miss thin obstacles: a box world's step coarser than
    /// its thinnest obstacle ([`Problem::allowing_coarse_step`]), an arm's motion checked with
    /// certification off ([`ArmProblem::allowing_uncertified_motion`]).
    #[must_use]
    pub fn allowing_coarse_step(self, allow: bool) -> Self {
        match self {
            Self::Boxes(p) => Self::Boxes(p.allowing_coarse_step(allow)),
            Self::Arm(p) => Self::Arm(Arc::new(
                Arc::unwrap_or_clone(p).allowing_uncertified_motion(allow),
            )),
        }
    }

    /// The problem keeping `padding` from every obstacle ([`ArmProblem::with_padding`]); a box
    /// world is a point among boxes and takes no padding.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a padding above zero on a box world.
    pub fn with_padding(self, padding: mit_star_robot::Padding) -> Result<Self, HarnessError> {
        match self {
            Self::Boxes(_) if !padding.is_zero() => Err(HarnessError::Usage(
                "a collision padding (`--padding`, `padding =`) applies to arm problems \
                 (mbm:PATH): a box world's robot is a point"
                    .into(),
            )),
            Self::Boxes(p) => Ok(Self::Boxes(p)),
            Self::Arm(p) => Ok(Self::Arm(Arc::new(
                Arc::unwrap_or_clone(p).with_padding(padding),
            ))),
        }
    }

    /// The padding kept from obstacles (zero for box worlds).
    pub fn padding(&self) -> mit_star_robot::Padding {
        self.as_arm()
            .map_or(mit_star_robot::Padding::ZERO, |a| a.padding())
    }

    /// The collision-check step, or why the problem refuses it ([`PlanningProblem::check_step`]).
    ///
    /// # Errors
    /// [`ProblemError::StepTooCoarse`] for a box world whose thinnest box is thinner than the
    /// step (unless allowed).
    pub fn check_step(&self) -> Result<f64, ProblemError> {
        match self {
            Self::Boxes(p) => PlanningProblem::check_step(p),
            Self::Arm(p) => p.check_step(),
        }
    }

    /// The dimension of the configuration space.
    pub fn dimension(&self) -> usize {
        match self {
            Self::Boxes(p) => p.dimension(),
            Self::Arm(p) => p.space().dimension(),
        }
    }

    /// The start state.
    pub fn start(&self) -> &[f64] {
        match self {
            Self::Boxes(p) => p.start(),
            Self::Arm(p) => p.start(),
        }
    }

    /// The goal states.
    pub fn goals(&self) -> &[Vec<f64>] {
        match self {
            Self::Boxes(p) => p.goals(),
            Self::Arm(p) => p.goals(),
        }
    }

    /// The collision-check resolution (a fraction of the maximum extent).
    pub fn resolution(&self) -> f64 {
        match self {
            Self::Boxes(p) => p.resolution(),
            Self::Arm(p) => p.resolution(),
        }
    }

    /// The collision-check step in the space's units.
    pub fn step(&self) -> f64 {
        match self {
            Self::Boxes(p) => p.step(),
            Self::Arm(p) => p.resolution() * p.space().maximum_extent(),
        }
    }

    /// The known optimal cost, if any.
    pub fn optimum(&self) -> Option<f64> {
        match self {
            Self::Boxes(p) => p.optimum(),
            Self::Arm(_) => None,
        }
    }

    /// The distance from the start to the nearest goal, ignoring obstacles.
    pub fn straight_line_cost(&self) -> f64 {
        match self {
            Self::Boxes(p) => p.straight_line_cost(),
            Self::Arm(p) => p
                .goals()
                .iter()
                .map(|g| p.space().distance(p.start(), g))
                .fold(f64::INFINITY, f64::min),
        }
    }

    /// The parameters `configuration` runs with on this problem
    /// ([`Configuration::effective_parameters`]): every default decided.
    ///
    /// # Errors
    /// As [`Configuration::effective_parameters`].
    pub fn effective_parameters(
        &self,
        configuration: Configuration,
        parameters: &Parameters,
    ) -> Result<Parameters, BuildError> {
        match self {
            Self::Boxes(p) => configuration.effective_parameters(p, parameters),
            Self::Arm(p) => configuration.effective_parameters(&**p, parameters),
        }
    }

    /// Builds `configuration` for this problem with `parameters`.
    ///
    /// # Errors
    /// As [`mit_star::build_planner`].
    pub fn build_planner(
        &self,
        configuration: Configuration,
        parameters: &Parameters,
    ) -> Result<Box<dyn Planner + Send>, BuildError> {
        match self {
            Self::Boxes(p) => mit_star::build_planner(configuration, p, parameters),
            Self::Arm(p) => mit_star::build_planner(configuration, &**p, parameters),
        }
    }

    /// `path` made shorter by a [`PathSimplifier`](mit_star::PathSimplifier) with `seed` for
    /// at most `seconds` (every new edge checked and certified as the problem asks), with its
    /// smoothing rounds if `smoothing` (the `simplify_smoothing` parameter).
    ///
    /// # Errors
    /// As [`PathSimplifier::simplify`](mit_star::PathSimplifier::simplify).
    pub fn simplify(
        &self,
        path: &[Vec<f64>],
        seconds: f64,
        seed: u64,
        smoothing: bool,
    ) -> Result<mit_star::Simplified, BuildError> {
        let stop = mit_star_spaces::Deadline::after(std::time::Duration::from_secs_f64(seconds));
        let mut simplifier = mit_star::PathSimplifier::new().seed(seed);
        if !smoothing {
            simplifier = simplifier.smoothing_rounds(0);
        }
        match self {
            Self::Boxes(p) => simplifier.simplify(p, path, &stop),
            Self::Arm(p) => simplifier.simplify(&**p, path, &stop),
        }
    }

    /// `path` checked by [`mit_star::check_path`]: the problem's grid and certification.
    ///
    /// # Errors
    /// As [`mit_star::check_path`].
    pub fn check_path(
        &self,
        path: &[Vec<f64>],
        tolerance: f64,
    ) -> Result<mit_star::PathVerdict, BuildError> {
        match self {
            Self::Boxes(p) => mit_star::check_path(p, path, tolerance),
            Self::Arm(p) => mit_star::check_path(&**p, path, tolerance),
        }
    }

    /// [`mit_star::snap_ends`] for this problem.
    pub fn snap_ends(&self, path: &mut [Vec<f64>], tolerance: f64) -> bool {
        match self {
            Self::Boxes(p) => mit_star::snap_ends(p, path, tolerance),
            Self::Arm(p) => mit_star::snap_ends(&**p, path, tolerance),
        }
    }

    /// `false` for an arm problem whose start or goal is in collision (MotionBenchMaker has
    /// a few; experiments skip them). Box worlds refuse such ends when they are built.
    pub fn ends_are_valid(&self) -> bool {
        match self {
            Self::Boxes(_) => true,
            Self::Arm(p) => p.ends_are_valid(),
        }
    }

    /// Validates a returned path independently of the planner: exactly for box worlds,
    /// continuously in `f64` for arms ([`PathValidation::check_continuous`]), keeping the
    /// problem's padding from obstacles ([`MotionAudit::padded`]).
    ///
    /// The check's own time is recorded in [`PathValidation::seconds`], so that reports
    /// show it apart from planning.
    pub fn validate(&self, path: &[Vec<f64>], reported_cost: f64) -> PathValidation {
        let started = std::time::Instant::now();
        let mut validation = match self {
            Self::Boxes(p) => PathValidation::check(p, path, reported_cost),
            Self::Arm(p) => PathValidation::check_continuous(
                &MotionAudit::padded(p.robot(), p.scene(), p.padding()),
                (p.start(), p.goals()),
                path,
                reported_cost,
                AUDIT_BUDGET,
            ),
        };
        validation.seconds = started.elapsed().as_secs_f64();
        validation
    }

    /// The problem as text for logs: a TOML problem file for box worlds.
    pub fn describe(&self) -> String {
        match self {
            Self::Boxes(p) => p.to_toml_string(),
            Self::Arm(p) => describe_arm(p),
        }
    }
}

/// An arm problem as text for logs: robot, scene, ends and resolution, one `key = value` per
/// line.
fn describe_arm(p: &ArmProblem) -> String {
    let numbers = |q: &[f64]| {
        let v: Vec<String> = q.iter().map(|x| format!("{x}")).collect();
        format!("[{}]", v.join(", "))
    };
    let mut kinds = [0usize; 3];
    for o in p.scene().obstacles() {
        kinds[match o.shape() {
            mit_star_robot::Shape::Cuboid { .. } => 0,
            mit_star_robot::Shape::Cylinder { .. } => 1,
            mit_star_robot::Shape::Sphere { .. } => 2,
        }] += 1;
    }
    let clouds: Vec<String> = p
        .scene()
        .clouds()
        .iter()
        .map(|c| {
            format!(
                "{{ points = {}, radius = {} }}",
                c.cloud().len(),
                c.cloud().radius()
            )
        })
        .collect();
    format!(
        "name = \"{}\"\nrobot = \"{}\"\njoints = {}\nspheres = {}\nself_collision_pairs = {}\n\
         obstacles = {{ boxes = {}, cylinders = {}, spheres = {} }}\n{}start = {}\ngoal = {}\nresolution = {}\n{}",
        p.name(),
        p.robot().name(),
        p.space().dimension(),
        p.robot().spheres().len(),
        p.robot().self_collision_pairs().len(),
        kinds[0],
        kinds[1],
        kinds[2],
        if clouds.is_empty() {
            String::new()
        } else {
            format!("clouds = [{}]\n", clouds.join(", "))
        },
        numbers(p.start()),
        numbers(&p.goals()[0]),
        p.resolution(),
        if p.padding().is_zero() {
            String::new()
        } else {
            format!("padding = {}\n", p.padding().metres())
        }
    )
}
