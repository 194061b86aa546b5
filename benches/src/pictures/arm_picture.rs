//! [`ArmPicture`]: a picture of an arm plan — the scene's obstacles and the arm's collision
//! spheres at the start, a few waypoints and the goal, with the hand's trajectory, seen from
//! two viewpoints.

use std::path::Path;

use glam::{DAffine3, DVec3};
use mit_star_problems::PlanningProblem;
use mit_star_robot::{ArmProblem, Kinematics, Shape};
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::HarnessError;
use crate::pictures::plot_style::{Figure, save_svg_and_png};

const OBSTACLE: RGBColor = RGBColor(150, 150, 162);
const START: RGBColor = RGBColor(0, 150, 60);
const WAYPOINT: RGBColor = RGBColor(255, 150, 40);
const GOAL: RGBColor = RGBColor(31, 119, 180);
const HAND: RGBColor = RGBColor(214, 39, 40);
const CLOUD: RGBColor = RGBColor(110, 70, 160);
/// The most cloud points drawn: a larger cloud is drawn every k-th point (and says so).
const CLOUD_DOTS: usize = 20_000;

/// Waypoints drawn between the start and the goal, at equal fractions of the path length.
const WAYPOINTS: usize = 3;
/// Points of the hand's trajectory.
const TRACE_POINTS: usize = 240;
/// Segments approximating a cylinder's circle.
const CYLINDER_SEGMENTS: usize = 32;
/// The two viewpoints: azimuth and elevation in degrees (azimuth 0 looks from +x).
const VIEWS: [(f64, f64); 2] = [(-35.0, 28.0), (-125.0, 28.0)];
/// Squares of the floor grid on each side of the robot's base.
const FLOOR_SQUARES: i32 = 4;
/// The picture's size in pixels.
const SIZE: (u32, u32) = (1500, 820);

/// A picture of an arm plan from two viewpoints.
///
/// Drawn, by depth (far first), in two orthographic views: the scene's boxes, cylinders and
/// spheres (grey, translucent so that the arm shows through, shaded by a light above and
/// behind the viewer), over a floor grid at `z = 0` with 0.25 m squares; the robot's collision
/// spheres at the start (green), at `WAYPOINTS` points evenly spaced along the path (orange,
/// translucent) and at the goal (blue); the trajectory of the last link's origin (the hand,
/// red). Without a path, only the start and the goal are drawn.
#[derive(Debug, Clone)]
pub struct ArmPicture<'a> {
    problem: &'a ArmProblem,
    path: &'a [Vec<f64>],
    title: String,
}

/// A picture with its scene placed (once for both files).
struct Drawn<'p, 'a> {
    picture: &'p ArmPicture<'a>,
    items: Vec<Item>,
    trace: Vec<DVec3>,
}

impl Figure for Drawn<'_, '_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        self.picture
            .draw(root, &self.items, &self.trace)
            .map_err(|e| e.to_string())
    }
}

/// Something to draw in a view: a filled polygon or a ball, with its depth towards the viewer.
#[derive(Debug, Clone)]
enum Item {
    Polygon {
        corners: Vec<DVec3>,
        colour: RGBColor,
    },
    Ball {
        center: DVec3,
        radius: f64,
        colour: RGBColor,
        opacity: f64,
    },
}

/// An orthographic camera: screen axes `right`, `up`, and `toward` the viewer.
#[derive(Debug, Clone, Copy)]
struct View {
    right: DVec3,
    up: DVec3,
    toward: DVec3,
}

impl View {
    fn new(azimuth_degrees: f64, elevation_degrees: f64) -> Self {
        let (sa, ca) = azimuth_degrees.to_radians().sin_cos();
        let (se, ce) = elevation_degrees.to_radians().sin_cos();
        Self {
            right: DVec3::new(-sa, ca, 0.0),
            up: DVec3::new(-se * ca, -se * sa, ce),
            toward: DVec3::new(ce * ca, ce * sa, se),
        }
    }

    fn screen(&self, p: DVec3) -> (f64, f64) {
        (p.dot(self.right), p.dot(self.up))
    }

    fn depth(&self, p: DVec3) -> f64 {
        p.dot(self.toward)
    }
}

impl<'a> ArmPicture<'a> {
    /// A picture of `path` (joint configurations, possibly empty) on `problem`.
    pub fn new(problem: &'a ArmProblem, path: &'a [Vec<f64>], title: String) -> Self {
        Self {
            problem,
            path,
            title,
        }
    }

    /// Writes the picture as SVG and PNG.
    ///
    /// # Errors
    /// [`HarnessError::Plot`] if either file cannot be drawn or written.
    pub fn save(&self, svg: &Path, png: &Path) -> Result<(), HarnessError> {
        let (items, trace) = self.scene_items();
        let drawn = Drawn {
            picture: self,
            items,
            trace,
        };
        save_svg_and_png(&drawn, SIZE, svg, png)
    }

    /// The configurations drawn: start, waypoints, goal, each with its colour and opacity.
    fn configurations(&self) -> Vec<(Vec<f64>, RGBColor, f64)> {
        let start = self.problem.start().to_vec();
        let goal = self.problem.goals()[0].clone();
        if self.path.len() < 2 {
            return vec![(start, START, 0.9), (goal, GOAL, 0.9)];
        }
        let mut drawn = vec![(self.path[0].clone(), START, 0.9)];
        for k in 1..=WAYPOINTS {
            let fraction = k as f64 / (WAYPOINTS + 1) as f64;
            drawn.push((along(self.path, fraction), WAYPOINT, 0.45));
        }
        drawn.push((self.path[self.path.len() - 1].clone(), GOAL, 0.9));
        drawn
    }

    /// The scene's cloud points and the stride they are drawn at (every point up to
    /// [`CLOUD_DOTS`] of them).
    fn cloud_dots(&self) -> (usize, usize) {
        let total: usize = self
            .problem
            .scene()
            .clouds()
            .iter()
            .map(|c| c.cloud().len())
            .sum();
        (total, total.div_ceil(CLOUD_DOTS).max(1))
    }

    /// Everything to draw, in world coordinates, and the hand's trajectory.
    fn scene_items(&self) -> (Vec<Item>, Vec<DVec3>) {
        let mut items = Vec::new();
        for obstacle in self.problem.scene().obstacles() {
            obstacle_items(obstacle.shape(), obstacle.pose(), &mut items);
        }
        let (_, every) = self.cloud_dots();
        for cloud in self.problem.scene().clouds() {
            let radius = cloud.cloud().radius();
            items.extend(
                cloud
                    .cloud()
                    .points()
                    .iter()
                    .step_by(every)
                    .map(|p| Item::Ball {
                        center: p.as_dvec3(),
                        radius,
                        colour: CLOUD,
                        opacity: 1.0,
                    }),
            );
        }
        let fk = Kinematics::new(self.problem.robot());
        let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
        let mut spheres = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
        for (q, colour, opacity) in self.configurations() {
            fk.sphere_centers_f64(&q, &mut links, &mut spheres);
            items.extend(spheres.iter().map(|&(center, radius)| Item::Ball {
                center,
                radius,
                colour,
                opacity,
            }));
        }
        // The hand: the last link named like one, else the last link of the tree.
        let robot = self.problem.robot();
        let hand = robot
            .link_names()
            .enumerate()
            .filter(|(_, name)| name.contains("hand"))
            .map(|(i, _)| i)
            .last()
            .unwrap_or(fk.link_count() - 1);
        let trace = if self.path.len() < 2 {
            Vec::new()
        } else {
            (0..=TRACE_POINTS)
                .map(|i| {
                    fk.link_poses_f64(
                        &along(self.path, i as f64 / TRACE_POINTS as f64),
                        &mut links,
                    );
                    links[hand].translation
                })
                .collect()
        };
        (items, trace)
    }

    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        items: &[Item],
        trace: &[DVec3],
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        root.fill(&WHITE)?;
        let (header, body) = root.split_vertically(80);
        header.draw(&Text::new(
            self.title.clone(),
            (20, 10),
            ("sans-serif", 22).into_font().color(&BLACK),
        ))?;
        let mut legend = Vec::new();
        if !self.problem.scene().obstacles().is_empty() {
            legend.push((OBSTACLE, "obstacles".to_owned()));
        }
        legend.extend([
            (START, "start".to_owned()),
            (WAYPOINT, "waypoints along the path".to_owned()),
            (GOAL, "goal".to_owned()),
            (HAND, "hand trajectory".to_owned()),
        ]);
        match self.cloud_dots() {
            (0, _) => {}
            (total, 1) => legend.push((CLOUD, format!("cloud ({total} points)"))),
            (total, every) => legend.push((CLOUD, format!("cloud (every {every}th of {total})"))),
        }
        let mut x = 20;
        for (colour, label) in legend {
            header.draw(&Circle::new((x + 8, 54), 7, colour.filled()))?;
            header.draw(&Text::new(
                label.as_str(),
                (x + 22, 45),
                ("sans-serif", 15).into_font().color(&BLACK),
            ))?;
            x += 45 + 6 * label.len() as i32;
        }
        let panels = body.split_evenly((1, VIEWS.len()));
        let views: Vec<View> = VIEWS.iter().map(|&(a, e)| View::new(a, e)).collect();
        let fit = Fit::new(&views, items, trace, panels[0].dim_in_pixel());
        for (index, (panel, &(azimuth, elevation))) in panels.iter().zip(&VIEWS).enumerate() {
            panel.draw(&Text::new(
                format!("view from azimuth {azimuth}°, elevation {elevation}°"),
                (20, 4),
                ("sans-serif", 15).into_font().color(&BLACK),
            ))?;
            draw_view(panel, (&views[index], index), &fit, items, trace)?;
        }
        Ok(())
    }
}

/// The configuration `fraction` of the way along `path`, measured by joint-space length.
fn along(path: &[Vec<f64>], fraction: f64) -> Vec<f64> {
    let lengths: Vec<f64> = path
        .windows(2)
        .map(|w| {
            w[0].iter()
                .zip(&w[1])
                .map(|(a, b)| (a - b) * (a - b))
                .sum::<f64>()
                .sqrt()
        })
        .collect();
    let total: f64 = lengths.iter().sum();
    let mut remaining = fraction.clamp(0.0, 1.0) * total;
    for (w, &length) in path.windows(2).zip(&lengths) {
        if remaining <= length && length > 0.0 {
            let t = remaining / length;
            return w[0]
                .iter()
                .zip(&w[1])
                .map(|(a, b)| a + t * (b - a))
                .collect();
        }
        remaining -= length;
    }
    path[path.len() - 1].clone()
}

/// The faces (boxes, cylinders) or ball (spheres) of an obstacle, in world coordinates.
fn obstacle_items(shape: Shape, pose: DAffine3, items: &mut Vec<Item>) {
    // Every face's corners run counter-clockwise seen from outside (the solids are convex
    // and centred on their origin), so that its normal points out.
    let face = |corners: Vec<DVec3>| {
        let mut corners: Vec<DVec3> = corners
            .into_iter()
            .map(|c| pose.transform_point3(c))
            .collect();
        let centroid = corners.iter().copied().sum::<DVec3>() / corners.len() as f64;
        if polygon_normal(&corners).dot(centroid - pose.translation) < 0.0 {
            corners.reverse();
        }
        Item::Polygon {
            corners,
            colour: OBSTACLE,
        }
    };
    match shape {
        Shape::Cuboid { half_extents: h } => {
            let corner = |sx: f64, sy: f64, sz: f64| DVec3::new(sx * h.x, sy * h.y, sz * h.z);
            for axis in 0..3 {
                for sign in [-1.0, 1.0] {
                    // The face `coordinate[axis] = sign`, its corners in cyclic order.
                    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                        .iter()
                        .map(|&(a, b)| match axis {
                            0 => corner(sign, a, b),
                            1 => corner(a, sign, b),
                            _ => corner(a, b, sign),
                        })
                        .collect();
                    items.push(face(corners));
                }
            }
        }
        Shape::Cylinder {
            half_height,
            radius,
        } => {
            let rim = |k: usize, z: f64| {
                let angle = std::f64::consts::TAU * k as f64 / CYLINDER_SEGMENTS as f64;
                DVec3::new(radius * angle.cos(), radius * angle.sin(), z)
            };
            for z in [-half_height, half_height] {
                items.push(face((0..CYLINDER_SEGMENTS).map(|k| rim(k, z)).collect()));
            }
            for k in 0..CYLINDER_SEGMENTS {
                items.push(face(vec![
                    rim(k, -half_height),
                    rim(k + 1, -half_height),
                    rim(k + 1, half_height),
                    rim(k, half_height),
                ]));
            }
        }
        Shape::Sphere { radius } => items.push(Item::Ball {
            center: pose.translation,
            radius,
            colour: OBSTACLE,
            opacity: 1.0,
        }),
    }
}

/// The common scale of both views: world metres to pixels, and each view's centre.
#[derive(Debug, Clone)]
struct Fit {
    scale: f64,
    centres: Vec<(f64, f64)>,
    panel: (u32, u32),
}

impl Fit {
    fn new(views: &[View], items: &[Item], trace: &[DVec3], panel: (u32, u32)) -> Self {
        let margin = 30.0;
        let mut scale = f64::INFINITY;
        let mut centres = Vec::new();
        for view in views {
            let (mut lo, mut hi) = (
                (f64::INFINITY, f64::INFINITY),
                (f64::NEG_INFINITY, f64::NEG_INFINITY),
            );
            let mut grow = |p: DVec3, r: f64| {
                let (x, y) = view.screen(p);
                lo = (lo.0.min(x - r), lo.1.min(y - r));
                hi = (hi.0.max(x + r), hi.1.max(y + r));
            };
            for item in items {
                match item {
                    Item::Polygon { corners, .. } => corners.iter().for_each(|&c| grow(c, 0.0)),
                    Item::Ball { center, radius, .. } => grow(*center, *radius),
                }
            }
            trace.iter().for_each(|&p| grow(p, 0.0));
            let width = (hi.0 - lo.0).max(1e-3);
            let height = (hi.1 - lo.1).max(1e-3);
            scale = scale
                .min((f64::from(panel.0) - 2.0 * margin) / width)
                .min((f64::from(panel.1) - 2.0 * margin - 24.0) / height);
            centres.push((0.5 * (lo.0 + hi.0), 0.5 * (lo.1 + hi.1)));
        }
        Self {
            scale,
            centres,
            panel,
        }
    }

    /// Pixel coordinates in panel `view` of the screen point `(x, y)`.
    fn pixel(&self, view: usize, (x, y): (f64, f64)) -> (i32, i32) {
        let (cx, cy) = self.centres[view];
        (
            (f64::from(self.panel.0) / 2.0 + (x - cx) * self.scale).round() as i32,
            (f64::from(self.panel.1) / 2.0 + 12.0 - (y - cy) * self.scale).round() as i32,
        )
    }
}

/// Draws the items of one view far to near, then the hand's trajectory on top.
fn draw_view<DB: DrawingBackend>(
    panel: &DrawingArea<DB, Shift>,
    (view, index): (&View, usize),
    fit: &Fit,
    items: &[Item],
    trace: &[DVec3],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let light = (view.toward + DVec3::Z).normalize();
    // The floor grid first: the views look down on it.
    let ticks = (-FLOOR_SQUARES..=FLOOR_SQUARES).map(|k| f64::from(k) * 0.25);
    for t in ticks {
        let extent = f64::from(FLOOR_SQUARES) * 0.25;
        for (a, b) in [
            (DVec3::new(t, -extent, 0.0), DVec3::new(t, extent, 0.0)),
            (DVec3::new(-extent, t, 0.0), DVec3::new(extent, t, 0.0)),
        ] {
            panel.draw(&PathElement::new(
                vec![
                    fit.pixel(index, view.screen(a)),
                    fit.pixel(index, view.screen(b)),
                ],
                RGBColor(215, 215, 222).stroke_width(1),
            ))?;
        }
    }
    let mut order: Vec<(f64, usize)> = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        match item {
            Item::Polygon { corners, .. } => {
                let normal = polygon_normal(corners);
                // Back faces of the convex solids are hidden by their front faces.
                if normal.dot(view.toward) > 1e-9 {
                    let centroid = corners.iter().copied().sum::<DVec3>() / corners.len() as f64;
                    order.push((view.depth(centroid), i));
                }
            }
            Item::Ball { center, .. } => order.push((view.depth(*center), i)),
        }
    }
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    for &(_, i) in &order {
        match &items[i] {
            Item::Polygon { corners, colour } => {
                let shade = 0.55 + 0.45 * polygon_normal(corners).dot(light).max(0.0);
                let fill = scaled(*colour, shade);
                let points: Vec<(i32, i32)> = corners
                    .iter()
                    .map(|&c| fit.pixel(index, view.screen(c)))
                    .collect();
                panel.draw(&Polygon::new(points.clone(), fill.mix(0.55).filled()))?;
                let mut outline = points;
                outline.push(outline[0]);
                panel.draw(&PathElement::new(
                    outline,
                    scaled(*colour, 0.6).stroke_width(1),
                ))?;
            }
            Item::Ball {
                center,
                radius,
                colour,
                opacity,
            } => {
                let at = fit.pixel(index, view.screen(*center));
                let r = ((radius * fit.scale).round() as i32).max(1);
                panel.draw(&Circle::new(at, r, colour.mix(*opacity).filled()))?;
                panel.draw(&Circle::new(
                    at,
                    r,
                    scaled(*colour, 0.6).mix(*opacity).stroke_width(1),
                ))?;
            }
        }
    }
    if trace.len() > 1 {
        let points: Vec<(i32, i32)> = trace
            .iter()
            .map(|&p| fit.pixel(index, view.screen(p)))
            .collect();
        panel.draw(&PathElement::new(points, HAND.stroke_width(3)))?;
    }
    Ok(())
}

/// The unit normal of a planar polygon whose corners run counter-clockwise seen from outside.
fn polygon_normal(corners: &[DVec3]) -> DVec3 {
    // Newell's method: robust for any planar polygon.
    let mut n = DVec3::ZERO;
    for (i, a) in corners.iter().enumerate() {
        let b = corners[(i + 1) % corners.len()];
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n.normalize_or_zero()
}

fn scaled(c: RGBColor, factor: f64) -> RGBColor {
    let f = |v: u8| (f64::from(v) * factor).round().clamp(0.0, 255.0) as u8;
    RGBColor(f(c.0), f(c.1), f(c.2))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problem() -> ArmProblem {
        let folder = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../robot/tests/data/mbm/box_panda"
        );
        ArmProblem::panda_mbm(folder.as_ref(), 1).unwrap()
    }

    #[test]
    fn along_measures_by_length() {
        let path = vec![vec![0.0, 0.0], vec![1.0, 0.0], vec![1.0, 3.0]];
        assert_eq!(along(&path, 0.0), vec![0.0, 0.0]);
        assert_eq!(along(&path, 0.125), vec![0.5, 0.0]);
        assert_eq!(along(&path, 0.5), vec![1.0, 1.0]);
        assert_eq!(along(&path, 1.0), vec![1.0, 3.0]);
    }

    #[test]
    fn obstacle_faces_point_outwards() {
        let mut items = Vec::new();
        let pose = DAffine3::from_rotation_translation(
            glam::DQuat::from_rotation_z(0.7) * glam::DQuat::from_rotation_x(0.3),
            DVec3::new(0.4, -0.2, 0.3),
        );
        obstacle_items(
            Shape::Cuboid {
                half_extents: DVec3::new(0.1, 0.2, 0.3),
            },
            pose,
            &mut items,
        );
        obstacle_items(
            Shape::Cylinder {
                half_height: 0.2,
                radius: 0.05,
            },
            pose,
            &mut items,
        );
        assert_eq!(items.len(), 6 + 2 + CYLINDER_SEGMENTS);
        for item in &items {
            let Item::Polygon { corners, .. } = item else {
                panic!("faces only")
            };
            let centroid = corners.iter().copied().sum::<DVec3>() / corners.len() as f64;
            assert!(polygon_normal(corners).dot(centroid - pose.translation) > 0.0);
        }
    }

    #[test]
    fn views_are_orthonormal() {
        for (a, e) in VIEWS {
            let v = View::new(a, e);
            assert!((v.right.cross(v.up) - v.toward).length() < 1e-12);
            assert!((v.right.length() - 1.0).abs() < 1e-12);
            assert!((v.up.length() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_plan_is_drawn_as_svg_and_png() {
        let problem = problem();
        let path = vec![problem.start().to_vec(), problem.goals()[0].clone()];
        let folder = std::env::temp_dir().join(format!("arm-picture-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let (svg, png) = (folder.join("plan.svg"), folder.join("plan.png"));
        ArmPicture::new(&problem, &path, "test".into())
            .save(&svg, &png)
            .unwrap();
        let text = std::fs::read_to_string(&svg).unwrap();
        // Every sphere of the five configurations is a circle (filled and outlined).
        let spheres = Kinematics::new(problem.robot()).sphere_count();
        assert!(text.matches("<circle").count() >= 2 * 5 * spheres);
        let bytes = std::fs::read(&png).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
        std::fs::remove_dir_all(folder).unwrap();
    }
}
