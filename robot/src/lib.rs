//! Robot arms for planning.
//!
//! A robot is a kinematic tree read from URDF whose collision geometry is spheres (the
//! "spherised" models of VAMP and MotionBenchMaker); its actuated joints span a
//! [`mit_star_spaces::JointSpace`]. A scene is a set of boxes, cylinders and spheres in the robot's base
//! frame, read from MotionBenchMaker's MoveIt YAML. Checking a configuration places every
//! sphere by forward kinematics and tests it against the scene and the robot itself. An
//! [`ArmProblem`] is a [`mit_star_problems::PlanningProblem`]: every planner plans for it.
//!
//! ```
//! use mit_star::{FirstSolution, MitStar, Planner, TerminationExt};
//! let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm/table_pick_panda");
//! let problem = mit_star_robot::ArmProblem::panda_mbm(folder.as_ref(), 1)?;
//! let mut planner = MitStar::for_problem(&problem).seed(1).build()?;
//! let outcome = planner.solve(&FirstSolution.or(mit_star::TimeLimit::seconds(5.0)))?;
//! assert!(outcome.is_solved());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|
//! | [`RobotModel`], [`LinkFrame`], [`Motion`], [`LinkSphere`], [`rpy_matrix`] | a sphere-model robot from URDF (urdf-rs) and SRDF (its disabled pairs), links in tree order |
//! | [`Kinematics`] | forward kinematics: link poses and sphere centres, `f32` and `f64`, no allocation |
//! | [`Obstacle`], [`Shape`] | boxes, cylinders and spheres with poses; exact sphere contact tests |
//! | [`Scene`] | a MoveIt planning scene (MotionBenchMaker YAML): obstacles and allowed collisions, and point clouds |
//! | [`PointCloud`], [`CloudObstacle`], [`PointTree`], [`AffordanceTree`], [`CloudError`] | point clouds as obstacles: validated points with a radius, named in a scene, the tree the checker's sphere queries and certified motion's distance bounds walk, and the affordances that answer the contacts of the robot's spheres faster |
//! | [`MbmProblem`] | a MotionBenchMaker scene + request pair |
//! | [`MovingObstacle`], [`MovingScene`] | boxes going back and forth along lines; a scene at a time or swept over an interval (the re-planning experiment) |
//! | [`ArmChecker`] | the collision checker: joint limits, scene and self-collision with broad phases, one-sided (a margin covers `f32` rounding), and certified motion (every configuration of an edge, not only grid points) |
//! | [`LeverArms`], [`CERTIFICATION_FLOOR`] | how far each link's spheres can move per unit of each joint, over all configurations: the bound certified motion rests on |
//! | [`ParryChecker`] | the reference checker: `f64`, parry queries, no culling (tests and path re-checks) |
//! | [`StateDiagnosis`], [`Contact`], [`LimitViolation`] | what one configuration touches, by name (`f64`): joints outside limits, links meeting obstacles or each other, the nearest obstacle (`mit-star check-state`) |
//! | [`MotionAudit`], [`AuditVerdict`], [`AUDIT_CONTACT`] | an independent continuous check of a motion: conservative advancement in `f64` from parry distances and its own speed bound (the harness's re-check of returned arm paths) |
//! | [`ArmProblem`], [`CHECKS_PER_UNIT`], [`CERTIFICATION`] | an arm planning problem, with its default check density and the certification its edges ask for |
//! | [`ModelError`], [`SceneError`], [`ArmError`] | what is wrong, naming the file and field |
//! | [`ShippedRobot`], [`RobotSource`], [`RobotSourceError`] | the shipped models (Panda, UR5, Fetch, Baxter) and a robot named by name or folder |
//! | [`SphereCover`], [`CoverOptions`], [`CoverSphere`], [`TriangleMesh`], [`read_stl`], [`parse_stl`], [`SpherisedUrdf`], [`SpheriseOptions`], [`LinkReport`], [`LinkSource`], [`SpheriseError`] | spheres from meshes: a conservative cover of a mesh's solid within a tolerance, and a URDF rewritten with them (`mit-star spherise`) |
//! | [`read_cloud`], [`parse_cloud`], [`InputCloud`] (and [`InputCloud::from_xyz`] for arrays in memory), [`CloudFormat`], [`CloudOrigin`], [`write_ply`], [`ply_bytes`], [`PlyEncoding`], [`write_npy`], [`npy_bytes`], [`MAX_CLOUD_POINTS`], [`MAX_CLOUD_FILE_BYTES`], [`CloudInputError`] | point clouds from files: PLY (ASCII, binary), PCD (ASCII, binary, binary_compressed), `.npy` (N×3 floats), bounded, NaN points dropped and counted; writers for PLY and `.npy` |
//! | [`SensorPose`], [`sample_surfaces`], [`sample_obstacle_surface`], [`DEFAULT_SAMPLES_PER_OBSTACLE`] | a camera's pose (its cloud into the base frame); clouds sampled on a scene's primitives (VAMP's benchmark protocol, seeded) |
//! | [`voxel_downsample`], [`min_distance_downsample`], [`crop_to_ball`], [`crop_to_box`], [`reach_ball`], [`remove_robot_points`], [`FilterReport`] | filters, each optional and timed: one point per voxel or per minimum distance, the robot's reach (a ball holding it at every configuration) or a box, the points on the robot at a configuration |
//! | [`IkSolver`], [`PoseTarget`], [`PositionTolerance`], [`OrientationTolerance`], [`PoseGoal`], [`IkSolution`], [`IkError`] | inverse kinematics: configurations placing a link or tool frame at a pose within tolerances (a box or ball; a cone or free rotation about an axis), collision-free, several distinct ones per pose |
//! | [`MotionLimits`], [`JointLimitsYaml`], [`PANDA_JOINT_LIMITS`] | velocity and acceleration limits per coordinate: the URDF's, a MoveIt `joint_limits.yaml`'s or given, scaled; mimic joints bound their leaders |
//! | [`Trajectory`], [`Sample`], [`BlendCertifier`], [`BlendReport`], [`merge_repeated_waypoints`] | timed paths: stop at each corner (time-optimal trapezoids on the segments) or parabolic blends certified collision-free; exact piecewise-quadratic evaluation |
//! | [`TrajectoryFile`], [`check_trajectory`], [`TRAJECTORY_TOLERANCE`], [`TrajectoryCheck`], [`Violation`], [`TrajectoryError`] | trajectories as JSON or CSV, and their check against the robot's limits and the scene |
//! | [`LinkVisual`], [`VisualGeometry`], [`VisualMeshes`], [`LinkMesh`], [`MeshLoadFailure`], [`MeshLoadError`], [`PRIMITIVE_SEGMENTS`], [`MeshResolver`], [`ResolveError`] | what a viewer draws: each link's URDF visual elements (colours resolved), loaded as triangles in the link frame, mesh files found under the URDF's folder and package roots; failures reported per file |
//! | [`ModelWarning`] | what a lenient model ignored: SRDF and allowed-collision entries naming links it lacks |

#![forbid(unsafe_code)]

mod arm_error;
mod arm_problem;
mod checking;
mod cloud_input;
mod clouds;
mod inverse_kinematics;
mod lane_f32;
mod model;
mod robots;
mod scenes;
mod spherise;
mod trajectory;
mod visuals;

pub use arm_error::ArmError;
pub use arm_problem::{ArmProblem, CERTIFICATION, CHECKS_PER_UNIT};
pub use checking::{
    AUDIT_CONTACT, ArmChecker, AuditVerdict, CERTIFICATION_FLOOR, Contact, LimitViolation,
    MAX_PADDING, MotionAudit, Padding, PaddingError, ParryChecker, StateDiagnosis,
};
pub use cloud_input::{
    CloudFormat, CloudInputError, CloudOrigin, DEFAULT_SAMPLES_PER_OBSTACLE, FilterReport,
    InputCloud, MAX_CLOUD_FILE_BYTES, MAX_CLOUD_POINTS, PlyEncoding, SensorPose, crop_to_ball,
    crop_to_box, min_distance_downsample, npy_bytes, parse_cloud, ply_bytes, reach_ball,
    read_cloud, remove_robot_points, sample_obstacle_surface, sample_surfaces, voxel_downsample,
    write_npy, write_ply,
};
pub use clouds::{AffordanceTree, CloudError, CloudObstacle, PointCloud, PointTree};
pub use inverse_kinematics::{
    IkError, IkSolution, IkSolver, OrientationTolerance, PoseGoal, PoseTarget, PositionTolerance,
};
pub use model::{
    Kinematics, LeverArms, LinkFrame, LinkSphere, LinkVisual, ModelError, ModelWarning, Motion,
    RobotModel, VisualGeometry, rpy_matrix,
};
pub use robots::{RobotSource, RobotSourceError, ShippedRobot};
pub use scenes::{MbmProblem, MovingObstacle, MovingScene, Obstacle, Scene, SceneError, Shape};
pub use spherise::{
    CoverOptions, CoverSphere, LinkReport, LinkSource, MAX_COVER_CELLS, MeshResolver, Placement,
    ResolveError, SphereCover, SpheriseError, SpheriseOptions, SpherisedUrdf, TriangleMesh,
    parse_stl, read_stl,
};
pub use trajectory::{
    BlendCertifier, BlendReport, JointLimitsYaml, MotionLimits, PANDA_JOINT_LIMITS, Sample,
    TRAJECTORY_TOLERANCE, Trajectory, TrajectoryCheck, TrajectoryError, TrajectoryFile, Violation,
    check_trajectory, merge_repeated_waypoints,
};
pub use visuals::{LinkMesh, MeshLoadError, MeshLoadFailure, PRIMITIVE_SEGMENTS, VisualMeshes};
