//! Robot arms for planning.
//!
//! A robot is a kinematic tree read from URDF whose collision geometry is spheres (the
//! "spherised" models of VAMP and MotionBenchMaker); its actuated joints span a
//! [`spaces::JointSpace`]. A scene is a set of boxes, cylinders and spheres in the robot's base
//! frame, read from MotionBenchMaker's MoveIt YAML. Checking a configuration places every
//! sphere by forward kinematics and tests it against the scene and the robot itself.
//!
//! # Catalogue
//! | item | what it is |
//! |---|---|

#![forbid(unsafe_code)]
