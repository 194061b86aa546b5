//! The paper's re-planning experiment (§V-C) on the Panda.
//!
//! Work in progress.

mod motion_judge;
mod replanning_experiment;
mod replanning_scene;
mod rules;
mod summary;
mod timed_path;
mod trial;
mod trial_picture;
mod trial_record;

pub use motion_judge::{MotionJudge, path_is_clear};
pub use replanning_experiment::{REPLANNING_PLANNERS, ReplanningExperiment, TRIAL_SEED_STRIDE};
pub use replanning_scene::{ReplanningScene, ReplanningSetup, hand_position};
pub use rules::{PANDA_VELOCITY_LIMITS, PlanningBudget, ReplanningRules};
pub use summary::{ReplanningSummary, SummaryRow, write_trials_csv};
pub use timed_path::{Piece, TimedPath};
pub use trial::Trial;
pub use trial_picture::TrialPicture;
pub use trial_record::{TrialEnd, TrialRecord};
