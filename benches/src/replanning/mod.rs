//! The paper's re-planning experiment (§V-C) on the Panda: the arm travels between two
//! blocks on a table five times while obstacles move along given trajectories, re-planning
//! every 0.1 s; each planner's success rate and median travelled cost over 30 trials.
//!
//! - [`ReplanningScene`], [`ReplanningSetup`] (`replanning_scene.rs`): the two scenes
//!   (`horizontal`, `vertical`) — table, walls, moving boxes ([`mit_star_robot::MovingScene`]), start
//!   and goal.
//! - [`ReplanningRules`], [`PlanningBudget`] (`rules.rs`): the control cycle, the planning
//!   budget (wall clock, or iterations for deterministic runs), look-ahead, joint speeds,
//!   legs, time limit.
//! - [`TimedPath`], [`Piece`] (`timed_path.rs`): a path timed at the joint speeds.
//! - [`MotionJudge`] (`motion_judge.rs`): executed motion certified clear of the moving
//!   obstacles, continuously in time.
//! - [`Trial`] (`trial.rs`): one trial — predict, plan, execute and judge, switch — and what
//!   it records, [`TrialRecord`] (`trial_record.rs`).
//! - [`ReplanningExperiment`] (`replanning_experiment.rs`): planners × scenes × trials;
//!   [`ReplanningSummary`] (`summary.rs`): the table (CSV, markdown); [`TrialPicture`]
//!   (`trial_picture.rs`): one trial over time; [`StaticAudit`] (`static_audit.rs`): the
//!   executed motion checked independently against the fixed obstacles and a point cloud.
//!
//! May use: `definition/` (planner specs), `statistics/`, `pictures/` (the plot style),
//! `budget.rs`, `error.rs`, and the library crates. Used by `commands/replan.rs`
//! (`mit-star replan`). The rules, scenes and the measured table are in the user guide's
//! reference page "Re-planning among moving obstacles".
//!
//! ```
//! use mit_star_benches::replanning::{PlanningBudget, ReplanningRules, ReplanningScene, Trial};
//! use mit_star_benches::{ParameterOverrides, PlannerSpec};
//!
//! let setup = ReplanningScene::Horizontal.setup()?;
//! let planner = PlannerSpec::new(mit_star::Configuration::RrtConnect, None, &ParameterOverrides::default())?;
//! // One leg, 500 iterations per plan: deterministic.
//! let rules = ReplanningRules { legs: 1, budget: PlanningBudget::Iterations(500), ..ReplanningRules::default() }
//!     .checked(7)?;
//! let record = Trial::new(&setup, &planner, &rules).run(1, 0)?;
//! assert!(record.succeeded(), "{record:?}");
//! assert!(record.travelled > 0.0 && record.plans > 1);
//! # Ok::<(), mit_star_benches::HarnessError>(())
//! ```

mod motion_judge;
mod replanning_experiment;
mod replanning_scene;
mod rules;
mod static_audit;
mod summary;
mod timed_path;
mod trial;
mod trial_picture;
mod trial_record;
mod trial_view;

pub use motion_judge::{MotionJudge, path_is_clear};
pub use replanning_experiment::{REPLANNING_PLANNERS, ReplanningExperiment, TRIAL_SEED_STRIDE};
pub use replanning_scene::{ReplanningScene, ReplanningSetup, hand_position};
pub use rules::{MAX_PLAN_ITERATIONS, PANDA_VELOCITY_LIMITS, PlanningBudget, ReplanningRules};
pub use static_audit::StaticAudit;
pub use summary::{ReplanningSummary, SummaryRow, write_trials_csv};
pub use timed_path::{Piece, TimedPath};
pub use trial::Trial;
pub use trial_picture::TrialPicture;
pub use trial_record::{TrialEnd, TrialRecord};
pub use trial_view::write_trial_view;
