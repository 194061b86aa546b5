//! [`RunPicture`]: a picture of one run on a 2-D problem — bounds, obstacles, anti-obstacles,
//! samples, forward and reverse trees, informed and estimated informed sets, the path.

use std::path::Path;

use mit_star::Snapshot;
use mit_star_problems::Problem;
use mit_star_samplers::SampleOrigin;
use mit_star_validity::AxisBox;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::HarnessError;
use crate::pictures::plot_style::{Figure, clip_segment, save_svg_and_png};

const OBSTACLE: RGBColor = RGBColor(110, 110, 120);
const ANTI_OBSTACLE: RGBColor = RGBColor(200, 235, 200);
const SAMPLE: RGBColor = RGBColor(150, 150, 150);
const GAUSSIAN_SAMPLE: RGBColor = RGBColor(0, 160, 160);
const BRIDGE_SAMPLE: RGBColor = RGBColor(220, 0, 170);
const FORWARD: RGBColor = RGBColor(20, 90, 200);
const REVERSE: RGBColor = RGBColor(255, 150, 40);
const INFORMED: RGBColor = RGBColor(20, 140, 60);
const ESTIMATED: RGBColor = RGBColor(148, 60, 189);
const PATH: RGBColor = RGBColor(214, 39, 40);

/// A picture of a planner's state after a run on a 2-D problem.
///
/// Drawn: the bounds; obstacles (grey) with the gaps anti-obstacles carve out of them (light
/// green); every sample (grey dots, or cyan for the adaptive sampler's Gaussian repairs and
/// magenta for its bridge repairs); the forward tree (blue); the current reverse tree (orange); the
/// informed set of the best cost (green ellipse) and MIT*'s estimated informed set (purple
/// ellipse), clipped to the bounds; the solution path (red); start and goals.
#[derive(Debug, Clone)]
pub struct RunPicture<'a> {
    problem: &'a Problem,
    snapshot: &'a Snapshot,
    path: &'a [Vec<f64>],
    title: String,
}

impl<'a> RunPicture<'a> {
    /// A picture of `snapshot` (taken after the run) with the returned `path`.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] unless the problem is 2-dimensional.
    pub fn new(
        problem: &'a Problem,
        snapshot: &'a Snapshot,
        path: &'a [Vec<f64>],
        title: String,
    ) -> Result<Self, HarnessError> {
        if problem.dimension() != 2 {
            return Err(HarnessError::Usage(format!(
                "pictures are drawn for 2-D problems only; `{}` has {} dimensions",
                problem.name(),
                problem.dimension()
            )));
        }
        Ok(Self {
            problem,
            snapshot,
            path,
            title,
        })
    }

    /// Writes the picture as SVG and PNG.
    ///
    /// # Errors
    /// [`HarnessError::Plot`] if either file cannot be drawn or written.
    pub fn save(&self, svg: &Path, png: &Path) -> Result<(), HarnessError> {
        save_svg_and_png(self, (860, 960), svg, png)
    }
}

impl Figure for RunPicture<'_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        self.draw(root).map_err(|e| e.to_string())
    }
}

impl RunPicture<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        root.fill(&WHITE)?;
        let (header, body) = root.split_vertically(100);
        header.draw(&Text::new(
            self.title.clone(),
            (20, 10),
            ("sans-serif", 22).into_font().color(&BLACK),
        ))?;
        let has = |o: SampleOrigin| self.snapshot.origins.contains(&o);
        let repaired = has(SampleOrigin::Gaussian) || has(SampleOrigin::Bridge);
        let legend = [
            (ANTI_OBSTACLE, "gap (anti-obstacle)"),
            (
                SAMPLE,
                if repaired {
                    "samples as drawn"
                } else {
                    "samples"
                },
            ),
            (GAUSSIAN_SAMPLE, "Gaussian repairs"),
            (BRIDGE_SAMPLE, "bridge repairs"),
            (FORWARD, "forward tree"),
            (REVERSE, "reverse tree"),
            (INFORMED, "informed set"),
            (ESTIMATED, "estimated informed set"),
            (PATH, "path"),
        ]
        .into_iter()
        .filter(|(colour, _)| repaired || (*colour != GAUSSIAN_SAMPLE && *colour != BRIDGE_SAMPLE));
        let (mut x, mut y) = (20, 50);
        for (colour, label) in legend {
            let width = 40 + 7 * label.len() as i32;
            if x + width > 840 {
                (x, y) = (20, y + 22);
            }
            header.draw(&PathElement::new(
                vec![(x, y + 8), (x + 22, y + 8)],
                colour.stroke_width(4),
            ))?;
            header.draw(&Text::new(
                label,
                (x + 27, y),
                ("sans-serif", 14).into_font().color(&BLACK),
            ))?;
            x += width;
        }
        let world = self.problem.world();
        let (lo, hi) = (
            (world.lower()[0], world.lower()[1]),
            (world.upper()[0], world.upper()[1]),
        );
        let mut chart = ChartBuilder::on(&body)
            .margin(16)
            .x_label_area_size(36)
            .y_label_area_size(48)
            .build_cartesian_2d(lo.0..hi.0, lo.1..hi.1)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x")
            .y_desc("y")
            .draw()?;
        let clip_box = |b: &AxisBox| {
            let half = |d: usize| 0.5 * b.widths[d];
            (
                (
                    (b.center[0] - half(0)).max(lo.0),
                    (b.center[1] - half(1)).max(lo.1),
                ),
                (
                    (b.center[0] + half(0)).min(hi.0),
                    (b.center[1] + half(1)).min(hi.1),
                ),
            )
        };
        for b in world.obstacles() {
            let (a, c) = clip_box(b);
            if a.0 < c.0 && a.1 < c.1 {
                chart.draw_series(std::iter::once(Rectangle::new([a, c], OBSTACLE.filled())))?;
            }
        }
        for lattice in world.lattices() {
            for i in 0..lattice.count {
                for j in 0..lattice.count {
                    let centre =
                        |d: usize, k: usize| world.lower()[d] + (k as f64 + 1.0) * lattice.spacing;
                    let (cx, cy) = (centre(0, i), centre(1, j));
                    let h = 0.5 * lattice.side;
                    chart.draw_series(std::iter::once(Rectangle::new(
                        [(cx - h, cy - h), (cx + h, cy + h)],
                        OBSTACLE.filled(),
                    )))?;
                }
            }
        }
        // Anti-obstacles carve free space out of obstacles: shade where they do.
        for anti in world.anti_obstacles() {
            let (a, c) = clip_box(anti);
            for obstacle in world.obstacles() {
                let (p, q) = clip_box(obstacle);
                let (lo_i, hi_i) = ((a.0.max(p.0), a.1.max(p.1)), (c.0.min(q.0), c.1.min(q.1)));
                if lo_i.0 < hi_i.0 && lo_i.1 < hi_i.1 {
                    chart.draw_series(std::iter::once(Rectangle::new(
                        [lo_i, hi_i],
                        ANTI_OBSTACLE.filled(),
                    )))?;
                }
            }
        }
        let s = self.snapshot;
        let point = |i: usize| (s.states[i][0], s.states[i][1]);
        let colour = |i: usize| match s.origins.get(i) {
            Some(SampleOrigin::Gaussian) => GAUSSIAN_SAMPLE,
            Some(SampleOrigin::Bridge) => BRIDGE_SAMPLE,
            _ => SAMPLE,
        };
        chart.draw_series((0..s.states.len()).map(|i| {
            let size = if colour(i) == SAMPLE { 1 } else { 2 };
            Circle::new(point(i), size, colour(i).filled())
        }))?;
        for &(a, b) in &s.reverse_edges {
            chart.draw_series(std::iter::once(PathElement::new(
                vec![point(a), point(b)],
                REVERSE.mix(0.7).stroke_width(1),
            )))?;
        }
        for &(a, b) in &s.forward_edges {
            chart.draw_series(std::iter::once(PathElement::new(
                vec![point(a), point(b)],
                FORWARD.stroke_width(2),
            )))?;
        }
        let start = self.problem.start();
        for (cost, colour) in [
            (Some(s.best_cost), INFORMED),
            (s.estimated_informed_cost, ESTIMATED),
        ] {
            let Some(cost) = cost.filter(|c| c.is_finite()) else {
                continue;
            };
            for goal in self.problem.goals() {
                for (a, b) in ellipse(start, goal, cost) {
                    if let Some(seg) = clip_segment(a, b, lo, hi) {
                        chart.draw_series(std::iter::once(PathElement::new(
                            vec![seg.0, seg.1],
                            colour.stroke_width(2),
                        )))?;
                    }
                }
            }
        }
        let path: Vec<(f64, f64)> = self.path.iter().map(|p| (p[0], p[1])).collect();
        if path.len() > 1 {
            chart.draw_series(LineSeries::new(path, PATH.stroke_width(3)))?;
        }
        chart.draw_series(std::iter::once(Circle::new(
            (start[0], start[1]),
            7,
            RGBColor(0, 160, 0).filled(),
        )))?;
        for goal in self.problem.goals() {
            chart.draw_series(std::iter::once(Circle::new(
                (goal[0], goal[1]),
                7,
                BLACK.filled(),
            )))?;
        }
        Ok(())
    }
}

/// The boundary of `{x : |x − start| + |goal − x| = cost}` as segments (empty if `cost` is
/// below the foci's distance).
fn ellipse(start: &[f64], goal: &[f64], cost: f64) -> Vec<((f64, f64), (f64, f64))> {
    let (dx, dy) = (goal[0] - start[0], goal[1] - start[1]);
    let d = (dx * dx + dy * dy).sqrt();
    if cost < d || d == 0.0 && cost <= 0.0 {
        return Vec::new();
    }
    let (a, b) = (0.5 * cost, 0.5 * (cost * cost - d * d).max(0.0).sqrt());
    let (cx, cy) = (0.5 * (start[0] + goal[0]), 0.5 * (start[1] + goal[1]));
    let angle = dy.atan2(dx);
    let (sin, cos) = angle.sin_cos();
    let at = |t: f64| {
        let (x, y) = (a * t.cos(), b * t.sin());
        (cx + cos * x - sin * y, cy + sin * x + cos * y)
    };
    let n = 256_u32;
    (0..n)
        .map(|i| {
            let t0 = std::f64::consts::TAU * f64::from(i) / f64::from(n);
            let t1 = std::f64::consts::TAU * f64::from(i + 1) / f64::from(n);
            (at(t0), at(t1))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ellipse_points_have_the_cost() {
        let (s, g) = ([-0.2, 0.1], [0.3, -0.1]);
        let segments = ellipse(&s, &g, 0.8);
        assert_eq!(segments.len(), 256);
        for (p, _) in segments {
            let c = ((p.0 - s[0]).hypot(p.1 - s[1])) + ((p.0 - g[0]).hypot(p.1 - g[1]));
            assert!((c - 0.8).abs() < 1e-12);
        }
        assert!(ellipse(&s, &g, 0.1).is_empty());
    }

    #[test]
    fn only_2d_problems_are_drawn() {
        let p = mit_star_problems::builtin("obstacle-free", 3, 0).unwrap();
        let snapshot = Snapshot {
            states: mit_star_spaces::States::new(3),
            kinds: Vec::new(),
            origins: Vec::new(),
            forward_edges: Vec::new(),
            reverse_edges: Vec::new(),
            solution: Vec::new(),
            best_cost: f64::INFINITY,
            estimated_informed_cost: None,
        };
        assert!(RunPicture::new(&p, &snapshot, &[], String::new()).is_err());
    }
}
