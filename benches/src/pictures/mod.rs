//! Pictures, in SVG and PNG.
//!
//! - [`experiment_figure`]: the figure of a scene or a problem instance of an experiment
//!   (median cost and success rate over time, initial solutions) in `plots/`, drawn with
//!   [`plot_axes`] (1-2-5 log ticks, ranges fitted to the data) and [`step_curves`]
//!   (piecewise-constant curves and their bands).
//! - [`run_picture`]: one run on a 2-D problem (obstacles, samples, trees, informed sets, the
//!   path), drawn by `mit-star plan`.
//! - [`arm_picture`]: an arm plan (the scene, the arm's spheres along the path, the hand's
//!   trajectory), drawn by `mit-star plan`.
//! - [`arm_view`], [`world_view`]: 3-D views (one HTML page each, the `view` crate) of
//!   plans on an arm or in a 2-D/3-D box world, with [`view_frames`] (the moments the slider
//!   steps through) and [`search_view`] (the search overlay), built by [`plan_view`];
//!   [`instance_views`]: the best and worst run of each instance, for `report.html`;
//!   [`robot_sweep`]: a robot on its own, each joint through its range (`robots --view`).
//! - [`trajectory_plot`]: a timed arm trajectory against time (position, velocity and
//!   acceleration per joint, the limits dashed), drawn by `plan --trajectory-plot` and
//!   `check-path --trajectory … --plot`.
//! - [`plot_style`]: the look they share: the embedded font, the planners' colours, saving
//!   SVG and PNG.
//!
//! May use: [`crate::outcome`], [`crate::definition`] (planner names),
//! [`crate::statistics`], [`crate::error`], and the planner, problem and robot crates. Not the
//! result formats or execution.

pub(crate) mod arm_picture;
pub(crate) mod arm_view;
pub(crate) mod experiment_figure;
pub(crate) mod instance_views;
pub(crate) mod plan_view;
pub(crate) mod plot_axes;
pub(crate) mod plot_style;
pub(crate) mod robot_sweep;
pub(crate) mod run_picture;
pub(crate) mod search_view;
pub(crate) mod step_curves;
pub(crate) mod trajectory_plot;
pub(crate) mod view_frames;
pub(crate) mod world_view;
