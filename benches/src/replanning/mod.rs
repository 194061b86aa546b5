//! The paper's re-planning experiment (§V-C) on the Panda.
//!
//! Work in progress.

mod motion_judge;
mod replanning_scene;
mod rules;
mod timed_path;
mod trial;
mod trial_record;

pub use motion_judge::{MotionJudge, path_is_clear};
pub use replanning_scene::{ReplanningScene, ReplanningSetup, hand_position};
pub use rules::{PANDA_VELOCITY_LIMITS, PlanningBudget, ReplanningRules};
pub use timed_path::{Piece, TimedPath};
pub use trial::Trial;
pub use trial_record::{TrialEnd, TrialRecord};
