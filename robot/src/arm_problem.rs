//! [`ArmProblem`]: a robot arm, a scene, a start and a goal configuration — a
//! [`PlanningProblem`] every planner accepts.

use std::path::Path;
use std::sync::Arc;

use mit_star_problems::{PlanningProblem, ProblemError};
use mit_star_spaces::{JointSpace, StateSpace};
use mit_star_validity::StateValidity;

use crate::{ArmChecker, ArmError, LeverArms, MbmProblem, Padding, RobotModel, Scene};

/// The default collision-check density of arm problems: 16 checks per unit of joint-space
/// distance, half VAMP's 32. With certification on, the grid only finds collisions early — the
/// certification proves every configuration between its points ([`CERTIFICATION`]) — so its
/// density trades speed, not safety. Measured on the `panda-mbm` experiment to first solutions
/// (RRT-Connect, range 1: 0.476 → 0.465 ms median against the 32-per-unit grid with the 4×
/// grid certification it replaced; MIT*: 1.257 → 1.302 ms), and 16 instead of 32 takes 13 %
/// off RRT-Connect's planning time with continuous certification (`examples/check_density.rs`;
/// the user guide's reference page on arm planning, "The check grid's density").
pub const CHECKS_PER_UNIT: f64 = 16.0;

/// The certification factor arm problems ask planners for. Any factor above 1 turns
/// certification on, and on an arm it is continuous whatever the factor: every configuration
/// of a solution's edge is proven collision-free ([`ArmChecker`]'s `certify_motion`), so a
/// contact grazed between two configurations of the planning grid never reaches a returned
/// path. (The factor's value matters only for checkers that certify on a finer grid.)
pub const CERTIFICATION: u32 = 4;

/// A planning problem for a robot arm: plan the arm's joints from `start` to `goal` among the
/// scene's obstacles without self-collision.
///
/// The collision-check step defaults to 16 checks per unit of joint-space distance
/// ([`CHECKS_PER_UNIT`]); [`with_resolution`](Self::with_resolution) selects a fraction of the
/// maximum extent instead (the paper's `5e-3`).
///
/// ```
/// use mit_star_problems::PlanningProblem;
/// use mit_star_validity::StateValidity;
/// let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm/box_panda");
/// let problem = mit_star_robot::ArmProblem::panda_mbm(folder.as_ref(), 1)?;
/// assert_eq!(problem.name(), "box_panda/0001");
/// assert_eq!(problem.start().len(), 7);
/// assert!(problem.validity().is_valid(problem.start()));
/// # Ok::<(), mit_star_robot::ArmError>(())
/// ```
#[derive(Debug, Clone)]
pub struct ArmProblem {
    name: String,
    robot: Arc<RobotModel>,
    scene: Arc<Scene>,
    checker: ArmChecker,
    start: Vec<f64>,
    goals: Vec<Vec<f64>>,
    resolution: f64,
    certification: u32,
    uncertified: bool,
    /// What the request asked that is not planned as asked ([`notes`](Self::notes)).
    notes: Vec<String>,
}

impl ArmProblem {
    /// The problem of `robot` (its SRDF already applied) in `scene` from `start` to `goal`
    /// (joint values in the order of [`RobotModel::joint_space`]). The scene's allowed-collision
    /// pairs are removed from the robot's self-collision pairs.
    ///
    /// # Errors
    /// [`ArmError::Model`] for an allowed pair naming an unknown link, [`ArmError::Query`] for
    /// a start or goal of the wrong length, not finite, or outside the joint limits.
    pub fn new(
        name: impl Into<String>,
        robot: RobotModel,
        scene: Scene,
        start: Vec<f64>,
        goal: Vec<f64>,
    ) -> Result<Self, ArmError> {
        let name = name.into();
        let robot = robot.allow_collisions(
            scene
                .allowed_pairs()
                .iter()
                .map(|(a, b)| (a.as_str(), b.as_str())),
        )?;
        let space = robot.joint_space();
        for (what, state) in [("start", &start), ("goal", &goal)] {
            space.check_state(state).map_err(|source| ArmError::Query {
                problem: name.clone(),
                what,
                source,
            })?;
        }
        let resolution = 1.0 / (CHECKS_PER_UNIT * space.maximum_extent());
        let (robot, scene) = (Arc::new(robot), Arc::new(scene));
        let checker = ArmChecker::new(&robot, &scene);
        Ok(Self {
            name,
            robot,
            scene,
            checker,
            start,
            goals: vec![goal],
            resolution,
            certification: CERTIFICATION,
            uncertified: false,
            notes: Vec::new(),
        })
    }

    /// MotionBenchMaker problem `index` (1-based, as in `scene0001.yaml`) of `folder`, for the
    /// Panda sphere model shipped with this crate.
    ///
    /// # Errors
    /// [`ArmError::Scene`] for missing or malformed files, [`ArmError::Query`] for joint values
    /// outside the limits.
    pub fn panda_mbm(folder: &Path, index: usize) -> Result<Self, ArmError> {
        Self::mbm(Self::panda()?, folder, index)
    }

    /// How far outside a joint limit a MotionBenchMaker start or goal value may be and still be
    /// taken as the limit ([`mbm`](Self::mbm)): `1e-5` (radians or metres).
    pub const LIMIT_TOLERANCE: f64 = 1e-5;

    /// The start and the goal are free and can be joined by certified motions, or what makes
    /// them invalid: the link pairs in self-collision, else the scene; or, with certification
    /// on, a clearance beyond the checker's margin below the
    /// [`CERTIFICATION_FLOOR`](crate::CERTIFICATION_FLOOR), which every configuration of a
    /// certified edge keeps, so no planner could return a path to that end.
    ///
    /// # Errors
    /// [`ArmError::EndInCollision`] naming the end and what it collides with;
    /// [`ArmError::EndWithinPadding`] for an end clear of everything but within the
    /// [padding](Self::with_padding) of an obstacle, naming the obstacles;
    /// [`ArmError::EndWithinFloor`] naming the end and what it is closest to.
    pub fn check_ends(&self) -> Result<(), ArmError> {
        let ends =
            std::iter::once(("start", &self.start)).chain(self.goals.iter().map(|g| ("goal", g)));
        for (what, q) in ends {
            if self.checker.is_valid(q) {
                if self.joinable(q) {
                    continue;
                }
                let padding = self.checker.padding().metres();
                let reach = self.checker.margin() + padding + crate::CERTIFICATION_FLOOR;
                let near = match self.diagnose(q).nearest.filter(|c| c.gap < reach) {
                    Some(c) if padding > 0.0 => format!(
                        "obstacle {} (link {}, gap {:.3} mm, margin {:.3} mm, padding {:.3} mm)",
                        c.other,
                        c.link,
                        c.gap * 1e3,
                        self.checker.margin() * 1e3,
                        padding * 1e3
                    ),
                    Some(c) => format!(
                        "obstacle {} (link {}, gap {:.3} mm, margin {:.3} mm)",
                        c.other,
                        c.link,
                        c.gap * 1e3,
                        self.checker.margin() * 1e3
                    ),
                    None => "a link of the robot's own".to_owned(),
                };
                return Err(ArmError::EndWithinFloor {
                    problem: self.name.clone(),
                    what,
                    floor_um: crate::CERTIFICATION_FLOOR * 1e6,
                    near,
                });
            }
            let diagnosis = self.diagnose(q);
            if diagnosis.only_padding() {
                return Err(ArmError::EndWithinPadding {
                    problem: self.name.clone(),
                    what,
                    padding_mm: diagnosis.padding * 1e3,
                    near: listed(&diagnosis.scene, 3, |c| {
                        format!(
                            "obstacle {} (link {}, gap {:.3} mm)",
                            c.other,
                            c.link,
                            c.gap * 1e3
                        )
                    }),
                });
            }
            return Err(ArmError::EndInCollision {
                problem: self.name.clone(),
                what,
                with: collision_summary(&diagnosis),
            });
        }
        Ok(())
    }

    /// What configuration `q` touches, by name: joints outside their limits, links meeting
    /// obstacles or each other, the nearest obstacle ([`StateDiagnosis`](crate::StateDiagnosis)).
    pub fn diagnose(&self, q: &[f64]) -> crate::StateDiagnosis {
        crate::StateDiagnosis::of(&self.robot, &self.scene, &self.checker, q)
    }

    /// The certification factor arm problems ask planners for ([`CERTIFICATION`]).
    pub const CERTIFICATION: u32 = CERTIFICATION;

    /// The fraction of samples planners of the EIT* family draw near the start and the goal on
    /// arm problems (the `samplers` crate's `NearTerminals` wrapper; a planner's
    /// `near_terminals` parameter overrides it). Grasps deep in shelf slots and cages are
    /// joined by few of the uniform samples in 7 dimensions; with this fraction MIT* solves
    /// most of the MotionBenchMaker problems it missed (`docs/guide/src/reference/arm-planning.md`).
    pub const NEAR_TERMINALS: f64 = 0.15;

    /// Whether MIT*, EIT* and AIT* repair their reverse search in place on arm problems
    /// instead of restarting it from the goal (a planner's `repair_reverse_search` parameter
    /// overrides it). An arm's lazy paths fail often, in cages far from the goal; repairing
    /// only the branch below the invalid edge keeps the rest of the reverse tree. On the
    /// Panda's cage MIT*'s median first solution comes about a quarter sooner and its 95th
    /// percentile 60 % lower (`docs/guide/src/reference/arm-planning.md`, "MIT*'s arm settings").
    pub const REPAIR_REVERSE_SEARCH: bool = true;

    /// MIT*'s sparse spacing on arm problems, in check steps (`Δ₀`, finest; a planner's
    /// `sparse_initial_steps` and `sparse_min_steps` override it): an edge's every fourth grid
    /// point at the first level, every second at the finest. An arm's edges are tens of steps
    /// long, so the authors' constants (2000, 10) test one or two points of each, and the lazy
    /// reverse search keeps offering paths the forward search finds invalid
    /// (`docs/guide/src/performance-switches.md`).
    pub const SPARSE_SPACING: (f64, f64) = (4.0, 2.0);

    /// Planners of the EIT* family join samples within the r-disc radius on arm problems (a
    /// planner's `connection` parameter overrides it). In 7 dimensions the radius gives each
    /// state tens of times more neighbours than k-nearest's `k`; with the arm's dense sparse
    /// checks MIT* finds its first path sooner on the Panda's cage and box and its paths at
    /// 100 ms and 1 s are a sixth to a quarter shorter (`docs/guide/src/performance-switches.md`).
    pub const RADIUS_CONNECTION: bool = true;

    /// Samples per batch for planners of the EIT* family on arm problems (a planner's
    /// `batch_size` parameter overrides it), half the papers' 100: most MotionBenchMaker
    /// queries are solved within the first batch, and a smaller one reaches that path sooner
    /// (MIT* on the Panda's five scenes: pooled median first solution 0.27 → 0.23 ms) with
    /// paths as short at 10 ms, 100 ms and 1 s (`docs/guide/src/performance-switches.md`).
    pub const BATCH_SIZE: usize = 50;

    /// On arm problems a batch of the EIT* family holds at least this fraction of the graph's
    /// vertices (a planner's `batch_growth` parameter overrides it): batches stay at
    /// [`BATCH_SIZE`](Self::BATCH_SIZE) up to a graph of 1 000 vertices, which most queries
    /// never reach, and then grow by 5 % of the graph each, so a query left unsolved for tens of
    /// thousands of samples (a Fetch grasp deep in a shelf) spends its time on new samples
    /// rather than on restarting its searches every 50 (`docs/guide/src/performance-switches.md`).
    pub const BATCH_GROWTH: f64 = 0.05;

    /// On arm problems, once a planner of the EIT* family has a solution, this fraction of each
    /// batch is placed along its path (a planner's `solution_samples` parameter overrides it):
    /// states on shortcuts between its vertices, some displaced, which the forward search
    /// strings into a straighter path. MIT* on the Panda's seven MotionBenchMaker scenes
    /// (problems 1–20 each): pooled median cost at 1 s 4.61 → 4.33, AORRTC's 4.32; 0.5
    /// rather than 0.3 for the scenes with the longest detours (cage, table_under_pick)
    /// (`docs/guide/src/performance-switches.md`).
    pub const SOLUTION_SAMPLES: f64 = 0.5;

    /// Segment points MIT*'s adaptive sampler tests per repair on arm problems (a planner's
    /// `bridge_checks` parameter overrides it), half the spec's 8: a repair that finds a state
    /// on its segment mostly finds it among the first points of the bisection order, so the
    /// other four cost checks for little. MIT*'s first path, twenty problems of each
    /// MotionBenchMaker scene, five seeds, against 8 run by run: UR5 0.95, Fetch 0.97, Panda
    /// 0.99 of the time; paths at 1 s shorter about as often as longer
    /// (`docs/guide/src/performance-switches.md`).
    pub const BRIDGE_CHECKS: usize = 4;

    /// The Panda sphere model shipped with this crate (VAMP's spherised URDF, 59 spheres),
    /// its SRDF applied.
    ///
    /// # Errors
    /// None in practice (the files are compiled in and tested); typed for form's sake.
    pub fn panda() -> Result<RobotModel, ArmError> {
        // The default shipped robot is the Panda (tested in `robots::shipped_robot`).
        Ok(crate::ShippedRobot::default_robot().model(false)?)
    }

    /// MotionBenchMaker problem `index` of `folder` for `robot` (SRDF applied). Joint values
    /// within [`LIMIT_TOLERANCE`](Self::LIMIT_TOLERANCE) outside a limit are moved onto it
    /// (files round limits: Fetch's `±3.14159` against requests' `±π`); a continuous joint's
    /// value is wrapped into `[-π, π]`. Joints outside the robot's planning group
    /// ([`RobotModel::held_joints`]) are held at the request's start values.
    ///
    /// # Errors
    /// As [`panda_mbm`](Self::panda_mbm).
    pub fn mbm(robot: RobotModel, folder: &Path, index: usize) -> Result<Self, ArmError> {
        let problem = MbmProblem::load(folder, index)?;
        let robot = if robot.held_joints().is_empty() {
            robot
        } else {
            robot.with_joint_positions(problem.start.iter().map(|(n, v)| (n.as_str(), *v)))?
        };
        let names = robot.joint_names();
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let mut start = problem.start_for(&names)?;
        let mut goal = problem.goal_for(&names)?;
        for q in [&mut start, &mut goal] {
            snap_to_limits(robot.joint_space(), q);
        }
        let name = problem.name.clone();
        let notes = held_notes(&robot, &problem);
        let mut arm = Self::new(name, robot, problem.scene, start, goal)?;
        arm.notes = notes;
        Ok(arm)
    }

    /// What the request asks that is not planned as asked, one line each: goal values of
    /// joints outside the planning group (held at the start's values, so the goal's are not
    /// reached), and held joints whose start value was clamped into their limits. Empty when
    /// every joint is planned, and for problems not read from a request.
    pub fn notes(&self) -> &[String] {
        &self.notes
    }

    /// The same problem checked every `resolution × maximum extent` (OMPL's convention; the
    /// paper uses `5e-3`).
    ///
    /// # Errors
    /// [`ArmError::Resolution`] unless `0 < resolution < 1`.
    pub fn with_resolution(mut self, resolution: f64) -> Result<Self, ArmError> {
        if !(resolution > 0.0 && resolution < 1.0) {
            return Err(ArmError::Resolution(resolution));
        }
        self.resolution = resolution;
        Ok(self)
    }

    /// The same problem asking planners for certification `factor` (default
    /// [`CERTIFICATION`]; any value above 1 certifies every configuration of a solution's
    /// edges; 1 turns certification off, which planners refuse unless
    /// [uncertified motion is allowed](Self::allowing_uncertified_motion); 0 is taken as 1).
    #[must_use]
    pub fn with_certification(mut self, factor: u32) -> Self {
        self.certification = factor.max(1);
        self
    }

    /// The same problem letting planners run with certification off (`certification = 1`,
    /// from the problem or a planner's parameters): edges are then checked only at the grid
    /// points of the step, and a returned path may cross an obstacle thinner than a sphere's
    /// sweep over one step. For measurements of what certification costs, never for a robot.
    #[must_use]
    pub fn allowing_uncertified_motion(mut self, allow: bool) -> Self {
        self.uncertified = allow;
        self
    }

    /// The same problem towards `goals` instead of its goal (any of them ends a path): the
    /// configurations a goal region supplied, inverse-kinematics solutions of a hand pose.
    ///
    /// # Errors
    /// [`ArmError::Query`] for no goal, or a goal of the wrong length, not finite or outside
    /// the joint limits.
    pub fn with_goals(mut self, goals: Vec<Vec<f64>>) -> Result<Self, ArmError> {
        let space = self.robot.joint_space();
        if goals.is_empty() {
            return Err(ArmError::Query {
                problem: self.name.clone(),
                what: "goal",
                source: mit_star_spaces::SpaceError::DimensionMismatch {
                    expected: space.dimension(),
                    got: 0,
                },
            });
        }
        for goal in &goals {
            space.check_state(goal).map_err(|source| ArmError::Query {
                problem: self.name.clone(),
                what: "goal",
                source,
            })?;
        }
        self.goals = goals;
        Ok(self)
    }

    /// The same problem in `scene` (the same robot, ends and settings; the checker is built
    /// anew for it). Meant for a scene derived from [`scene`](Self::scene) — clouds added, or
    /// primitives replaced by a cloud sampled on them: the scene's allowed collisions were
    /// applied to the robot when the problem was made and are not applied again.
    #[must_use]
    pub fn with_scene(mut self, scene: Scene) -> Self {
        self.scene = Arc::new(scene);
        self.checker = ArmChecker::padded(&self.robot, &self.scene, self.checker.padding());
        self
    }

    /// The same problem keeping every robot sphere `padding` from every obstacle and point
    /// cloud (beyond the checker's margin; the robot's own links are not padded): its checker
    /// is [padded](ArmChecker::padded), so every configuration of every edge of a returned
    /// path keeps that distance (certified), and so do the ends — check them with
    /// [`check_ends`](Self::check_ends), which names an end within the padding
    /// ([`ArmError::EndWithinPadding`]). Audit paths with [`MotionAudit::padded`](crate::MotionAudit::padded).
    #[must_use]
    pub fn with_padding(mut self, padding: Padding) -> Self {
        self.checker = ArmChecker::padded(&self.robot, &self.scene, padding);
        self
    }

    /// The padding kept from obstacles ([`Padding::ZERO`] unless set by
    /// [`with_padding`](Self::with_padding)).
    pub fn padding(&self) -> Padding {
        self.checker.padding()
    }

    /// The largest radius a contact query of this problem's checker asks of a point cloud
    /// when checking configurations: its largest sphere grown by the padding and the
    /// [margin](ArmChecker::margin), rounded up by a tenth of a millimetre. The radius to build
    /// a cloud's [affordances](crate::CloudObstacle::with_affordances) for; larger queries (a
    /// link's bounding sphere, a sphere grown by the sweep of a certified motion) are answered
    /// by the cloud's tree.
    pub fn cloud_contact_radius(&self) -> f32 {
        let largest = self
            .robot
            .spheres()
            .iter()
            .map(|s| s.radius)
            .fold(0.0, f64::max);
        let grown = largest + self.checker.padding().metres() + self.checker.margin();
        (grown * (1.0 + 1e-6) + 1e-4) as f32
    }

    /// The robot (SRDF and the scene's allowed collisions applied).
    pub fn robot(&self) -> &RobotModel {
        &self.robot
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// `true` if the start and the goal are collision-free and can be joined by certified
    /// motions ([`check_ends`](Self::check_ends); MotionBenchMaker has a few problems where one
    /// is not; benchmarks count and skip them).
    pub fn ends_are_valid(&self) -> bool {
        std::iter::once(&self.start)
            .chain(&self.goals)
            .all(|q| self.checker.is_valid(q) && self.joinable(q))
    }

    /// Whether certified motions can reach the valid configuration `q`: always with
    /// certification off; else if the motion from `q` to itself certifies, that is, if `q`
    /// keeps the clearance beyond the margin that every configuration of a certified edge
    /// keeps ([`CERTIFICATION_FLOOR`](crate::CERTIFICATION_FLOOR)).
    pub fn joinable(&self, q: &[f64]) -> bool {
        if self.certification <= 1 {
            return true;
        }
        let mut progress = mit_star_validity::MotionProgress::new(0.0, 0.0);
        self.checker
            .certify_motion(self.space(), q, q, &mut progress, &mit_star_spaces::Never)
            != Some(mit_star_validity::EdgeStatus::Invalid)
    }
}

impl PlanningProblem for ArmProblem {
    type Space = JointSpace;
    type Validity = ArmChecker;

    fn name(&self) -> &str {
        &self.name
    }

    fn space(&self) -> &JointSpace {
        self.robot.joint_space()
    }

    fn validity(&self) -> &ArmChecker {
        &self.checker
    }

    fn start(&self) -> &[f64] {
        &self.start
    }

    fn goals(&self) -> &[Vec<f64>] {
        &self.goals
    }

    fn resolution(&self) -> f64 {
        self.resolution
    }

    fn check_step(&self) -> Result<f64, ProblemError> {
        Ok(self.resolution * self.space().maximum_extent())
    }

    fn certification(&self) -> u32 {
        self.certification
    }

    fn check_certification(&self, factor: u32) -> Result<(), ProblemError> {
        if factor > 1 || self.uncertified {
            return Ok(());
        }
        let step = self.resolution * self.space().maximum_extent();
        Err(ProblemError::Uncertified {
            problem: self.name.clone(),
            step,
            sweep: step * LeverArms::new(&self.robot).fastest(),
        })
    }

    fn near_terminals(&self) -> f64 {
        Self::NEAR_TERMINALS
    }

    fn repair_reverse_search(&self) -> bool {
        Self::REPAIR_REVERSE_SEARCH
    }

    fn sparse_spacing(&self) -> (f64, f64) {
        Self::SPARSE_SPACING
    }

    fn radius_connection(&self) -> bool {
        Self::RADIUS_CONNECTION
    }

    fn batch_size(&self) -> usize {
        Self::BATCH_SIZE
    }

    fn batch_growth(&self) -> f64 {
        Self::BATCH_GROWTH
    }

    fn solution_samples(&self) -> f64 {
        Self::SOLUTION_SAMPLES
    }

    fn bridge_checks(&self) -> usize {
        Self::BRIDGE_CHECKS
    }

    /// The robot's [`rrt_range`](RobotModel::rrt_range): measured for a shipped robot, a rule
    /// on the joints' spans for any other.
    fn default_range(&self) -> Option<f64> {
        Some(self.robot.rrt_range())
    }
}

/// [`ArmProblem::notes`] of MotionBenchMaker `problem` planned for `robot` (its held joints
/// already set from the request's start).
fn held_notes(robot: &RobotModel, problem: &MbmProblem) -> Vec<String> {
    let held = robot.held_joints();
    let value = |values: &[(String, f64)], joint: &str| {
        values.iter().find(|(n, _)| n == joint).map(|&(_, v)| v)
    };
    // Equal, or one turn apart (a continuous joint's value wrapped).
    let differs = |a: f64, b: f64| {
        let d = (a - b).abs();
        let turns = (d / std::f64::consts::TAU).round() * std::f64::consts::TAU;
        d > ArmProblem::LIMIT_TOLERANCE && (d - turns).abs() > ArmProblem::LIMIT_TOLERANCE
    };
    let mut notes = Vec::new();
    let ignored: Vec<String> = held
        .iter()
        .filter_map(|&(joint, at)| {
            let goal = value(&problem.goal, joint)?;
            differs(goal, at).then(|| format!("{joint} = {goal} (held at {at})"))
        })
        .collect();
    if !ignored.is_empty() {
        notes.push(format!(
            "the goal's values for joints outside the planned group are not planned: {}",
            ignored.join(", ")
        ));
    }
    let clamped: Vec<String> = held
        .iter()
        .filter_map(|&(joint, at)| {
            let start = value(&problem.start, joint)?;
            (start.is_finite() && differs(start, at)).then(|| format!("{joint} = {start} -> {at}"))
        })
        .collect();
    if !clamped.is_empty() {
        notes.push(format!(
            "held joints' start values clamped into their limits: {}",
            clamped.join(", ")
        ));
    }
    notes
}

/// What an invalid configuration's diagnosis says it meets, for [`ArmError::EndInCollision`]:
/// `itself: links a/b (overlap 3.100 mm), …` and `the scene: link l meets obstacle o (overlap
/// 12.000 mm), …`, the deepest first, at most three of each.
fn collision_summary(d: &crate::StateDiagnosis) -> String {
    const SHOWN: usize = 3;
    let depth = |gap: f64| {
        if gap < 0.0 {
            format!("overlap {:.3} mm", -gap * 1e3)
        } else {
            format!("gap {:.3} mm, within the checker's margin", gap * 1e3)
        }
    };
    let mut parts = Vec::new();
    if !d.itself.is_empty() {
        let pairs = listed(&d.itself, SHOWN, |c| {
            format!("{}/{} ({})", c.link, c.other, depth(c.gap))
        });
        parts.push(format!("itself: links {pairs}"));
    }
    if !d.scene.is_empty() {
        let contacts = listed(&d.scene, SHOWN, |c| {
            format!(
                "link {} meets obstacle {} ({})",
                c.link,
                c.other,
                depth(c.gap)
            )
        });
        parts.push(format!("the scene: {contacts}"));
    }
    if !d.limits.is_empty() {
        let joints = listed(&d.limits, usize::MAX, |v| {
            format!(
                "joint {} = {} outside [{}, {}]",
                v.joint, v.value, v.lower, v.upper
            )
        });
        parts.push(format!("its limits: {joints}"));
    }
    if parts.is_empty() {
        "something the diagnosis cannot name (run `mit-star check-state`)".to_owned()
    } else {
        parts.join("; ")
    }
}

/// The first `shown` of `items`, each written by `each`, joined by commas, then `, and N more`
/// for the rest.
fn listed<T>(items: &[T], shown: usize, each: impl Fn(&T) -> String) -> String {
    let mut text: Vec<String> = items.iter().take(shown).map(each).collect();
    if items.len() > shown {
        text.push(format!("and {} more", items.len() - shown));
    }
    text.join(", ")
}

/// Moves values within [`ArmProblem::LIMIT_TOLERANCE`] outside a joint's limits onto them,
/// and wraps a continuous joint's value into `[-π, π]` (a request may say `2π` for `0`).
fn snap_to_limits(space: &JointSpace, q: &mut [f64]) {
    for (v, joint) in q.iter_mut().zip(space.joints()) {
        match joint.kind {
            mit_star_spaces::JointKind::Revolute { lower, upper }
            | mit_star_spaces::JointKind::Prismatic { lower, upper } => {
                let tolerance = ArmProblem::LIMIT_TOLERANCE;
                if *v < lower && *v >= lower - tolerance {
                    *v = lower;
                } else if *v > upper && *v <= upper + tolerance {
                    *v = upper;
                }
            }
            mit_star_spaces::JointKind::Continuous if v.is_finite() => {
                *v = mit_star_spaces::wrap_angle(*v);
            }
            mit_star_spaces::JointKind::Continuous => {}
        }
    }
}
