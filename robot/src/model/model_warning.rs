//! [`ModelWarning`]: what was ignored or changed while loading a robot model.

use std::fmt;

/// Something a [`RobotModel`](crate::RobotModel) ignored rather than refused (outside
/// [strict mode](crate::RobotModel::strict)), or a change it made to its self-collision pairs
/// that the user should review.
#[derive(Debug, Clone, PartialEq)]
pub enum ModelWarning {
    /// Entries of an SRDF or of a scene's allowed-collision matrix naming links the model does
    /// not have, skipped. SRDFs written for a mesh model often name links its spherised copy
    /// drops (sensors, wheels), and MotionBenchMaker scenes allow collisions with objects of
    /// the scene (`box_link`).
    UnknownLinks {
        /// The SRDF file (or `"SRDF text"`), or `"allowed-collision matrix"`.
        origin: String,
        /// The robot's name.
        robot: String,
        /// The unknown link names, each once, in the order first met.
        links: Vec<String>,
        /// How many entries named one of them.
        entries: usize,
    },
    /// Members of a planning group naming joints or links the model does not have, skipped
    /// (a spherised model often drops a gripper's links).
    UnknownGroupMembers {
        /// The SRDF file (or `"SRDF text"`).
        origin: String,
        /// The group.
        group: String,
        /// The unknown names (`joint x`, `link y`), each once.
        names: Vec<String>,
    },
    /// Link pairs no longer checked for self-collision because the sphere model itself says
    /// so ([`RobotModel::without_model_pairs`](crate::RobotModel::without_model_pairs)).
    DisabledPairs {
        /// Why (`adjacent`, `in collision in every sampled configuration`).
        reason: &'static str,
        /// The pairs' link names.
        pairs: Vec<(String, String)>,
    },
    /// A leader's range shrunk so that a mimic joint following it stays within its own
    /// limits.
    MimicRange {
        /// The leading joint.
        leader: String,
        /// The mimic joint.
        follower: String,
        /// The leader's new lower limit.
        lower: f64,
        /// The leader's new upper limit.
        upper: f64,
    },
    /// A URDF loaded without an SRDF: every pair of links with spheres is checked for
    /// self-collision but those the sphere model rules out (the
    /// [`DisabledPairs`](Self::DisabledPairs) that follow), as MoveIt's setup assistant would
    /// generate them; pairs an SRDF would disable for other reasons (never in collision, by
    /// the mechanism) are checked.
    NoSrdf {
        /// The URDF.
        urdf: String,
    },
}

impl fmt::Display for ModelWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::UnknownLinks {
                origin,
                robot,
                links,
                entries,
            } => {
                let s = if *entries == 1 { "y" } else { "ies" };
                write!(
                    f,
                    "{origin}: ignored {entries} entr{s} naming links robot `{robot}` does not have: {}",
                    links.join(", ")
                )
            }
            Self::UnknownGroupMembers {
                origin,
                group,
                names,
            } => write!(
                f,
                "{origin}: planning group `{group}`: ignored members the model does not have: {}",
                names.join(", ")
            ),
            Self::NoSrdf { urdf } => write!(
                f,
                "no SRDF beside `{urdf}` (same stem, or the only *.srdf of its folder): \
                 checking every pair of links with spheres but those the sphere model rules \
                 out, and no planning groups"
            ),
            Self::DisabledPairs { reason, pairs } => {
                let names: Vec<String> = pairs.iter().map(|(a, b)| format!("{a}/{b}")).collect();
                write!(
                    f,
                    "not checking {} link pair{} for self-collision, {reason} in the sphere model: {}",
                    pairs.len(),
                    if pairs.len() == 1 { "" } else { "s" },
                    names.join(", ")
                )
            }
            Self::MimicRange {
                leader,
                follower,
                lower,
                upper,
            } => write!(
                f,
                "joint `{leader}` limited to [{lower}, {upper}] to keep mimic joint `{follower}` within its limits"
            ),
        }
    }
}
