//! [`IkSolver`]: numerical inverse kinematics of one frame of a robot — its construction,
//! settings and scratch. The search itself is in `ik_search.rs`.

use glam::{DAffine3, DVec3};
use mit_star_spaces::rand::SeedableRng;
use mit_star_spaces::{JointKind, JointSpace, SeededRng};

use crate::inverse_kinematics::ik_chain::IkChain;
use crate::{IkError, RobotModel};

/// Inverse kinematics of a link of a [`RobotModel`] (or of a tool frame offset from it):
/// configurations placing it at a [`PoseTarget`](crate::PoseTarget).
///
/// Damped least squares (Levenberg–Marquardt) on the `f64` forward kinematics with the
/// analytic geometric Jacobian, the joint limits kept by clamping after every step
/// (continuous joints wrap), random restarts from a seeded generator (the same calls give
/// the same answers), and only configurations the given
/// [`StateValidity`](mit_star_validity::StateValidity) accepts returned. Nothing allocates per
/// iteration: the buffers live in the solver, which is why solving takes `&mut self`.
///
/// Built argmin-style: [`new`](Self::new) with what is required, then chained setters, each
/// checking its value.
///
/// ```
/// use mit_star_robot::{IkSolver, PoseTarget, ShippedRobot};
/// let panda = ShippedRobot::find("panda").expect("shipped").model(false)?;
/// let mut solver = IkSolver::new(&panda, "panda_hand")?.restarts(20).seed(7);
/// // A reachable pose: the hand where a known configuration puts it.
/// let known = [0.3, -0.4, 0.2, -2.0, 0.1, 1.8, 0.6];
/// let target = PoseTarget::from_pose(&solver.frame_pose(&known)?)?;
/// let start = panda.default_configuration();
/// let solution = solver.solve(&target, &start, &mit_star_validity::AllValid, &mit_star_spaces::Never)?;
/// assert!(solution.position_error < 1e-5 && solution.orientation_error < 1e-4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct IkSolver {
    pub(super) chain: IkChain,
    pub(super) link_name: String,
    pub(super) space: JointSpace,
    /// Per coordinate: the limits, or `None` for a continuous joint (wraps).
    pub(super) limits: Vec<Option<Limits>>,
    pub(super) tool: DAffine3,
    pub(super) restarts: usize,
    pub(super) iterations: usize,
    pub(super) damping: f64,
    pub(super) max_step: f64,
    pub(super) distinct: f64,
    pub(super) accuracy: (f64, f64),
    pub(super) rng: SeededRng,
    pub(super) scratch: Scratch,
}

/// A limited coordinate's range; `turns` for a revolute joint (whose value a full turn away
/// is the same angle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Limits {
    pub(super) lower: f64,
    pub(super) upper: f64,
    pub(super) turns: bool,
}

/// The buffers one solve reuses.
#[derive(Debug, Clone)]
pub(super) struct Scratch {
    pub(super) poses: Vec<DAffine3>,
    pub(super) columns: Vec<(DVec3, DVec3)>,
    pub(super) q: Vec<f64>,
    pub(super) trial: Vec<f64>,
    pub(super) dq: Vec<f64>,
}

impl IkSolver {
    /// Default [`restarts`](Self::restarts).
    pub const RESTARTS: usize = 50;
    /// Default [`iterations`](Self::iterations) per attempt.
    pub const ITERATIONS: usize = 30;
    /// Default [`damping`](Self::damping) (each descent's first λ).
    pub const DAMPING: f64 = 1e-3;
    /// Default [`max_step`](Self::max_step), radians (or metres) per coordinate.
    pub const MAX_STEP: f64 = 1.0;
    /// Default [`distinct_distance`](Self::distinct_distance) in the joint space's metric.
    pub const DISTINCT: f64 = 0.1;
    /// Default [`accuracy`](Self::accuracy): metres and radians.
    pub const ACCURACY: (f64, f64) = (1e-6, 1e-5);

    /// The solver of link `link` of `robot`, with the defaults and seed 0.
    ///
    /// # Errors
    /// [`IkError::UnknownLink`] (naming it and a few of the model's links) if `robot` has no
    /// such link; [`IkError::ImmovableLink`] if no planned coordinate moves it.
    pub fn new(robot: &RobotModel, link: &str) -> Result<Self, IkError> {
        let index = robot.link_index(link).ok_or_else(|| {
            let names: Vec<&str> = robot.link_names().collect();
            let examples = names.iter().rev().take(6).rev().copied();
            IkError::UnknownLink {
                link: link.to_owned(),
                count: names.len(),
                examples: examples.collect::<Vec<_>>().join(", "),
            }
        })?;
        let chain = IkChain::new(robot, index);
        if !chain.moves() {
            return Err(IkError::ImmovableLink {
                link: link.to_owned(),
            });
        }
        let space = robot.joint_space().clone();
        let limits: Vec<Option<Limits>> = space
            .joints()
            .iter()
            .map(|j| match j.kind {
                JointKind::Revolute { lower, upper } => Some(Limits {
                    lower,
                    upper,
                    turns: true,
                }),
                JointKind::Prismatic { lower, upper } => Some(Limits {
                    lower,
                    upper,
                    turns: false,
                }),
                JointKind::Continuous => None,
            })
            .collect();
        let n = limits.len();
        let scratch = Scratch {
            poses: vec![DAffine3::IDENTITY; chain.link_count()],
            columns: vec![(DVec3::ZERO, DVec3::ZERO); n],
            q: vec![0.0; n],
            trial: vec![0.0; n],
            dq: vec![0.0; n],
        };
        Ok(Self {
            chain,
            link_name: link.to_owned(),
            space,
            limits,
            tool: DAffine3::IDENTITY,
            restarts: Self::RESTARTS,
            iterations: Self::ITERATIONS,
            damping: Self::DAMPING,
            max_step: Self::MAX_STEP,
            distinct: Self::DISTINCT,
            accuracy: Self::ACCURACY,
            rng: SeededRng::seed_from_u64(0),
            scratch,
        })
    }

    /// Random restarts after the first attempt (from the given start) fails: at most
    /// `1 + restarts` attempts per solve.
    pub fn restarts(mut self, restarts: usize) -> Self {
        self.restarts = restarts;
        self
    }

    /// Reseeds the random generator of the restarts.
    pub fn seed(mut self, seed: u64) -> Self {
        self.rng = SeededRng::seed_from_u64(seed);
        self
    }

    /// The most iterations (accepted or rejected steps) per attempt.
    ///
    /// # Errors
    /// [`IkError::BadSetting`] for 0.
    pub fn iterations(mut self, iterations: usize) -> Result<Self, IkError> {
        if iterations == 0 {
            return Err(bad("iterations", 0.0, "at least 1"));
        }
        self.iterations = iterations;
        Ok(self)
    }

    /// The damping λ (metres or radians) each descent starts with: a step that fails to
    /// reduce the error is retried with λ raised √10-fold; a step that succeeds lowers it
    /// √10-fold, down to a thousandth of this value (near a solution the steps become
    /// Gauss–Newton's, which converge fast even close to a singular configuration). A descent
    /// whose λ exceeds 10 is abandoned.
    ///
    /// # Errors
    /// [`IkError::BadSetting`] unless finite and in `(0, 1]`.
    pub fn damping(mut self, damping: f64) -> Result<Self, IkError> {
        if !(damping > 0.0 && damping <= 1.0) {
            return Err(bad("damping", damping, "a number in (0, 1]"));
        }
        self.damping = damping;
        Ok(self)
    }

    /// The largest change of one coordinate in one step (a longer step is scaled down).
    ///
    /// # Errors
    /// [`IkError::BadSetting`] unless finite and `> 0`.
    pub fn max_step(mut self, max_step: f64) -> Result<Self, IkError> {
        if !(max_step > 0.0 && max_step.is_finite()) {
            return Err(bad("max_step", max_step, "a finite number > 0"));
        }
        self.max_step = max_step;
        Ok(self)
    }

    /// How far apart, in the joint space's metric, two solutions of one target must be to
    /// count as distinct (see [`PoseGoal`](crate::PoseGoal)).
    ///
    /// # Errors
    /// [`IkError::BadSetting`] unless finite and `>= 0`.
    pub fn distinct_distance(mut self, distance: f64) -> Result<Self, IkError> {
        if !(distance >= 0.0 && distance.is_finite()) {
            return Err(bad("distinct_distance", distance, "a finite number >= 0"));
        }
        self.distinct = distance;
        Ok(self)
    }

    /// When an attempt has converged: position error at most `position` metres and
    /// orientation error at most `orientation` radians (errors measured to the tolerance sets).
    ///
    /// # Errors
    /// [`IkError::BadSetting`] unless both are finite and `> 0`.
    pub fn accuracy(mut self, position: f64, orientation: f64) -> Result<Self, IkError> {
        if !(position > 0.0 && position.is_finite()) {
            return Err(bad("accuracy (position)", position, "a finite length > 0"));
        }
        if !(orientation > 0.0 && orientation.is_finite()) {
            return Err(bad(
                "accuracy (orientation)",
                orientation,
                "a finite angle > 0",
            ));
        }
        self.accuracy = (position, orientation);
        Ok(self)
    }

    /// Solves for the tool frame `tool`, given in the link's frame, instead of the link's own
    /// frame (a gripper's fingertip centre, say).
    ///
    /// # Errors
    /// [`IkError::BadTool`] unless finite with an orthonormal, right-handed rotation part
    /// (within 1e-6).
    pub fn tool(mut self, tool: DAffine3) -> Result<Self, IkError> {
        if !(tool.matrix3.is_finite() && tool.translation.is_finite()) {
            return Err(IkError::BadTool {
                why: "components must be finite",
            });
        }
        let m = tool.matrix3;
        let gram = m.transpose() * m;
        if !gram.abs_diff_eq(glam::DMat3::IDENTITY, 1e-6) || (m.determinant() - 1.0).abs() > 1e-6 {
            return Err(IkError::BadTool {
                why: "the rotation part must be orthonormal with determinant 1",
            });
        }
        self.tool = tool;
        Ok(self)
    }

    /// The link solved for.
    pub fn link(&self) -> &str {
        &self.link_name
    }

    /// The tool offset (identity unless set).
    pub fn tool_offset(&self) -> DAffine3 {
        self.tool
    }

    /// The configuration space (the model's joint space).
    pub fn joint_space(&self) -> &JointSpace {
        &self.space
    }

    /// The distinct-solution distance.
    pub fn distinct(&self) -> f64 {
        self.distinct
    }

    /// The pose of the solver's frame (link times tool offset) at configuration `q`.
    ///
    /// # Errors
    /// [`IkError::WrongLength`] or [`IkError::NonFiniteCoordinate`] for a bad `q`.
    pub fn frame_pose(&mut self, q: &[f64]) -> Result<DAffine3, IkError> {
        self.check_configuration(q)?;
        Ok(self.chain.pose(q, &mut self.scratch.poses) * self.tool)
    }

    /// `Ok` if `q` has one finite value per coordinate.
    pub(super) fn check_configuration(&self, q: &[f64]) -> Result<(), IkError> {
        if q.len() != self.limits.len() {
            return Err(IkError::WrongLength {
                expected: self.limits.len(),
                got: q.len(),
            });
        }
        match q.iter().position(|x| !x.is_finite()) {
            Some(index) => Err(IkError::NonFiniteCoordinate {
                index,
                value: q[index],
            }),
            None => Ok(()),
        }
    }
}

fn bad(setting: &'static str, value: f64, expected: &'static str) -> IkError {
    IkError::BadSetting {
        setting,
        value,
        expected,
    }
}
