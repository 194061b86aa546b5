//! [`ModelError`]: why a robot model could not be loaded.

use std::path::PathBuf;

use thiserror::Error;

/// Why a [`RobotModel`](crate::RobotModel) could not be made from a URDF or SRDF, or why a
/// change to its collision pairs was refused. Every variant names the file or element at fault.
#[derive(Debug, Error)]
pub enum ModelError {
    /// A file could not be read.
    #[error("cannot read `{path}`: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The URDF is not well-formed or not a URDF.
    #[error("{origin}: not a readable URDF: {message}")]
    Urdf {
        /// The file (or `"URDF text"`).
        origin: String,
        /// The parser's message.
        message: String,
    },
    /// The URDF is larger than [`MAX_URDF_BYTES`](crate::RobotModel::MAX_URDF_BYTES).
    #[error("{origin}: {bytes} bytes is more than the {limit} bytes a URDF may have")]
    TooLarge {
        /// The file (or `"URDF text"`).
        origin: String,
        /// Its size (at least this many, for a file read only so far).
        bytes: u64,
        /// The limit.
        limit: u64,
    },
    /// The URDF nests elements deeper than
    /// [`MAX_URDF_DEPTH`](crate::RobotModel::MAX_URDF_DEPTH) (refused before parsing: the
    /// parser would overflow the stack).
    #[error("{origin}: elements nested more than {limit} deep (a URDF needs 5)")]
    TooDeep {
        /// The file (or `"URDF text"`).
        origin: String,
        /// The limit.
        limit: usize,
    },
    /// The URDF has more than one root element (two `<robot>`s, say).
    #[error("{origin}: more than one root element (one `<robot>` per URDF)")]
    SeveralRoots {
        /// The file (or `"URDF text"`).
        origin: String,
    },
    /// The SRDF is not well-formed XML.
    #[error("{origin}: not a readable SRDF: {message}")]
    Srdf {
        /// The file (or `"SRDF text"`).
        origin: String,
        /// The parser's message.
        message: String,
    },
    /// A collision element that is not a sphere.
    #[error(
        "link `{link}`: collision geometry `{kind}` is not supported (only spheres: use a spherised model)"
    )]
    UnsupportedGeometry {
        /// The link.
        link: String,
        /// `box`, `cylinder`, `mesh`, …
        kind: &'static str,
    },
    /// A joint type or feature this model cannot represent.
    #[error("joint `{joint}`: {what} is not supported")]
    UnsupportedJoint {
        /// The joint.
        joint: String,
        /// What is unsupported (`a floating joint`, `mimic`, …).
        what: &'static str,
    },
    /// The links do not form one tree.
    #[error("the links do not form one tree: {why}")]
    NotATree {
        /// What is wrong (no root, several roots, a link with two parents, a cycle).
        why: String,
    },
    /// Two joints, or two links, of a URDF share a name: which one is meant is not known.
    #[error("{origin}: two {what}s are called `{name}`")]
    DuplicateName {
        /// The file (or `"URDF text"`).
        origin: String,
        /// `"joint"` or `"link"`.
        what: &'static str,
        /// The shared name.
        name: String,
    },
    /// A joint names a link the URDF does not have.
    #[error("joint `{joint}` names link `{link}`, which the URDF does not define")]
    UnknownJointLink {
        /// The joint.
        joint: String,
        /// The missing link.
        link: String,
    },
    /// A moving joint with a zero (or non-finite) axis.
    #[error("joint `{joint}`: the axis {axis:?} has no direction")]
    BadAxis {
        /// The joint.
        joint: String,
        /// The axis as written.
        axis: [f64; 3],
    },
    /// Joint limits that do not bound an interval.
    #[error(
        "joint `{joint}`: limits [{lower}, {upper}] are not a finite interval with lower < upper"
    )]
    BadLimits {
        /// The joint.
        joint: String,
        /// Lower limit.
        lower: f64,
        /// Upper limit.
        upper: f64,
    },
    /// Joint limits beyond the bound of their kind
    /// ([`MAX_PRISMATIC_LIMIT`](crate::RobotModel::MAX_PRISMATIC_LIMIT),
    /// [`MAX_REVOLUTE_LIMIT`](crate::RobotModel::MAX_REVOLUTE_LIMIT)): a unit error, most
    /// likely.
    #[error(
        "joint `{joint}`: {kind} limits [{lower}, {upper}] are beyond ±{bound} (a unit error?)"
    )]
    LimitsTooWide {
        /// The joint.
        joint: String,
        /// `"revolute"` or `"prismatic"`.
        kind: &'static str,
        /// Lower limit.
        lower: f64,
        /// Upper limit.
        upper: f64,
        /// The bound on either limit's magnitude (metres or radians).
        bound: f64,
    },
    /// A mimic multiplier or offset that is not finite or beyond its bound
    /// ([`MAX_MIMIC_MULTIPLIER`](crate::RobotModel::MAX_MIMIC_MULTIPLIER),
    /// [`MAX_MIMIC_OFFSET`](crate::RobotModel::MAX_MIMIC_OFFSET)).
    #[error("mimic joint `{joint}`: {what} {value} is not within ±{bound}")]
    BadMimic {
        /// The mimic joint.
        joint: String,
        /// `"multiplier"` or `"offset"`.
        what: &'static str,
        /// The value.
        value: f64,
        /// The bound on its magnitude.
        bound: f64,
    },
    /// No value of the leader keeps a mimic joint within its own limits.
    #[error(
        "mimic joint `{joint}`: no value of its leader `{leader}` within the leader's limits keeps it within its own limits [{lower}, {upper}]"
    )]
    MimicLimits {
        /// The mimic joint.
        joint: String,
        /// The planned (or held) joint leading it.
        leader: String,
        /// The mimic joint's lower limit.
        lower: f64,
        /// The mimic joint's upper limit.
        upper: f64,
    },
    /// A number that must be finite (an origin, a radius) is not, is beyond ±10⁶ m (an
    /// origin's `xyz`, a radius), or a radius is not positive.
    #[error("{element}: {what} {value} is not usable")]
    BadNumber {
        /// The link or joint.
        element: String,
        /// The quantity (`sphere radius`, `origin`, …).
        what: &'static str,
        /// The value.
        value: f64,
    },
    /// The model has no joint that moves.
    #[error("the robot has no revolute, continuous or prismatic joint to plan for")]
    NoJoints,
    /// An SRDF or an allowed-collision entry names a link the robot does not have.
    #[error("{origin}: link `{link}` is not a link of robot `{robot}`")]
    UnknownLink {
        /// The SRDF file, or the scene's allowed-collision matrix.
        origin: String,
        /// The unknown name.
        link: String,
        /// The robot's name.
        robot: String,
    },
    /// A mimic joint follows a joint that is not a moving joint of the URDF, or mimic joints
    /// follow each other round in a cycle.
    #[error(
        "mimic joint `{joint}` follows `{leader}`, which is not a revolute, continuous or prismatic joint leading to a planned or held one"
    )]
    MimicLeader {
        /// The mimic joint.
        joint: String,
        /// The joint it names.
        leader: String,
    },
    /// The SRDF has no planning group of that name.
    #[error("{origin}: no planning group `{group}` (groups: {known})")]
    UnknownGroup {
        /// The SRDF file (or `"SRDF text"`).
        origin: String,
        /// The group asked for.
        group: String,
        /// The groups the SRDF defines, comma separated.
        known: String,
    },
    /// A planning group names a joint or link the robot lacks (strict mode), has a chain
    /// whose base is not above its tip, or includes itself.
    #[error("{origin}: planning group `{group}`: {why}")]
    BadGroup {
        /// The SRDF file (or `"SRDF text"`, or `"joint list"`).
        origin: String,
        /// The group.
        group: String,
        /// What is wrong, naming the element.
        why: String,
    },
    /// The joint space could not be made.
    #[error("joint space: {0}")]
    Space(#[from] mit_star_spaces::SpaceError),
}

impl ModelError {
    /// The text of a robot description file (`what`: `"URDF"`, `"SRDF"`), read with
    /// [`mit_star_problems::read_bounded`] at [`mit_star_problems::TEXT_INPUT_LIMIT`]: a device, a folder, a
    /// binary or an oversized file is an [`Io`](Self::Io) error naming the file.
    pub(crate) fn read_text(path: &std::path::Path, what: &'static str) -> Result<String, Self> {
        mit_star_problems::read_bounded(path, mit_star_problems::TEXT_INPUT_LIMIT, what).map_err(
            |e| Self::Io {
                path: path.to_path_buf(),
                source: e.into(),
            },
        )
    }
}
