//! [`TrialPicture`]: one re-planning trial over time — the hand's x, y and z against the
//! moving obstacles' extents along the same axis, with the plans marked.

use std::path::Path;

use glam::DVec3;
use mit_star_spaces::StateSpace;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::HarnessError;
use crate::pictures::plot_style::{Figure, save_svg_and_png};
use crate::replanning::replanning_scene::{ReplanningSetup, hand_position};
use crate::replanning::trial_record::TrialRecord;

const HAND: RGBColor = RGBColor(31, 119, 180);
const OBSTACLES: [RGBColor; 3] = [
    RGBColor(214, 39, 40),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
];
const PLAN: RGBColor = RGBColor(44, 160, 44);
const FAILED_PLAN: RGBColor = RGBColor(120, 120, 120);
/// Seconds between the drawn points.
const STEP: f64 = 0.02;
/// The picture's size in pixels.
const SIZE: (u32, u32) = (1400, 1000);

/// A picture of one trial: three panels (the hand's x, y and z over time). In each, the
/// moving obstacles' extents along that axis are bands (one colour each), the grasp point's
/// coordinate is a line, plans are ticks at the bottom (green with a path, grey without), and
/// a collision is a black cross. The hand is near an obstacle where its line is inside that
/// obstacle's band in all three panels at once.
#[derive(Debug, Clone)]
pub struct TrialPicture<'a> {
    setup: &'a ReplanningSetup,
    record: &'a TrialRecord,
}

/// Points of one panel: the hand's coordinate and each obstacle's extent over time.
struct Drawn<'p, 'a> {
    picture: &'p TrialPicture<'a>,
    times: Vec<f64>,
    hand: Vec<DVec3>,
}

impl<'a> TrialPicture<'a> {
    /// The picture of `record`, a trial in `setup`.
    pub fn new(setup: &'a ReplanningSetup, record: &'a TrialRecord) -> Self {
        Self { setup, record }
    }

    /// Writes the picture as SVG and PNG.
    ///
    /// # Errors
    /// [`HarnessError::Plot`] if either file cannot be drawn or written.
    pub fn save(&self, svg: &Path, png: &Path) -> Result<(), HarnessError> {
        let (times, hand) = self.hand_over_time();
        let drawn = Drawn {
            picture: self,
            times,
            hand,
        };
        save_svg_and_png(&drawn, SIZE, svg, png)
    }

    /// The grasp point every [`STEP`] seconds along the recorded trajectory.
    fn hand_over_time(&self) -> (Vec<f64>, Vec<DVec3>) {
        let space = self.setup.robot.joint_space();
        let (mut times, mut hand) = (Vec::new(), Vec::new());
        let trajectory = &self.record.trajectory;
        let mut q = vec![0.0; space.dimension()];
        for w in trajectory.windows(2) {
            let ((t0, a), (t1, b)) = (&w[0], &w[1]);
            let steps = (((t1 - t0) / STEP).ceil() as usize).max(1);
            for k in 0..steps {
                let f = k as f64 / steps as f64;
                space.interpolate(a, b, f, &mut q);
                times.push(t0 + f * (t1 - t0));
                hand.push(hand_position(&self.setup.robot, &q));
            }
        }
        if let Some((t, q)) = trajectory.last() {
            times.push(*t);
            hand.push(hand_position(&self.setup.robot, q));
        }
        (times, hand)
    }

    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        times: &[f64],
        hand: &[DVec3],
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        root.fill(&WHITE)?;
        let r = self.record;
        let title = format!(
            "{} in `{}`, trial {}: {} after {:.2} s, {} legs, travelled {:.2} rad, {} plans",
            r.planner,
            r.scene,
            r.trial,
            r.end.label(),
            r.time,
            r.legs_done,
            r.travelled,
            r.plans
        );
        let (header, body) = root.split_vertically(40);
        header.draw(&Text::new(
            title,
            (20, 10),
            ("sans-serif", 20).into_font().color(&BLACK),
        ))?;
        let end = times.last().copied().unwrap_or(1.0).max(0.1);
        let panels = body.split_evenly((3, 1));
        for (axis, panel) in panels.iter().enumerate() {
            self.draw_axis(panel, axis, (times, hand), end)?;
        }
        Ok(())
    }

    fn draw_axis<DB: DrawingBackend>(
        &self,
        panel: &DrawingArea<DB, Shift>,
        axis: usize,
        (times, hand): (&[f64], &[DVec3]),
        end: f64,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let moving = self.setup.scene.moving();
        let grid: Vec<f64> = (0..=((end / STEP).ceil() as usize))
            .map(|k| k as f64 * STEP)
            .collect();
        let bands: Vec<Vec<(f64, f64, f64)>> = moving
            .iter()
            .map(|m| {
                grid.iter()
                    .map(|&t| {
                        let (lo, hi) = m.swept_bounds(t, t);
                        (t, lo[axis], hi[axis])
                    })
                    .collect()
            })
            .collect();
        let values = hand
            .iter()
            .map(|p| p[axis])
            .chain(bands.iter().flatten().flat_map(|&(_, lo, hi)| [lo, hi]));
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
        let pad = 0.05 * (hi - lo).max(0.1);
        let name = ["x", "y", "z"][axis];
        let mut chart = ChartBuilder::on(panel)
            .margin(12)
            .x_label_area_size(32)
            .y_label_area_size(56)
            .build_cartesian_2d(0.0..end, (lo - 2.0 * pad)..(hi + pad))?;
        chart
            .configure_mesh()
            .light_line_style(RGBColor(235, 235, 240))
            .x_desc("simulated time (s)")
            .y_desc(format!("{name} (m)"))
            .draw()?;
        for (i, (band, m)) in bands.iter().zip(moving).enumerate() {
            let colour = OBSTACLES[i % OBSTACLES.len()];
            let mut outline: Vec<(f64, f64)> = band.iter().map(|&(t, lo, _)| (t, lo)).collect();
            outline.extend(band.iter().rev().map(|&(t, _, hi)| (t, hi)));
            chart
                .draw_series(std::iter::once(Polygon::new(
                    outline,
                    colour.mix(0.3).filled(),
                )))?
                .label(m.id().to_owned())
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 16, y + 5)], colour.filled())
                });
        }
        let line: Vec<(f64, f64)> = times.iter().zip(hand).map(|(&t, p)| (t, p[axis])).collect();
        chart
            .draw_series(LineSeries::new(line, HAND.stroke_width(2)))?
            .label("grasp point")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], HAND.stroke_width(2)));
        let base = lo - 2.0 * pad;
        for &(t, found) in &self.record.plan_times {
            let colour = if found { PLAN } else { FAILED_PLAN };
            chart.draw_series(std::iter::once(PathElement::new(
                vec![(t, base), (t, base + pad)],
                colour.stroke_width(2),
            )))?;
        }
        if let Some(t) = self.record.collision_time() {
            let at = times
                .iter()
                .position(|&s| s >= t)
                .unwrap_or(times.len() - 1);
            chart.draw_series(std::iter::once(Cross::new(
                (t, hand[at][axis]),
                8,
                BLACK.stroke_width(3),
            )))?;
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(RGBColor(200, 200, 200))
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
        Ok(())
    }
}

impl Figure for Drawn<'_, '_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        self.picture
            .draw(root, &self.times, &self.hand)
            .map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::replanning::replanning_scene::ReplanningScene;
    use crate::replanning::trial_record::TrialEnd;

    #[test]
    fn a_trial_is_drawn_as_svg_and_png() {
        let setup = ReplanningScene::Vertical.setup().unwrap();
        let record = TrialRecord {
            scene: "vertical".into(),
            planner: "MIT*".into(),
            trial: 1,
            seed: 0,
            end: TrialEnd::Collision { time: 0.8 },
            time: 0.8,
            legs_done: 0,
            travelled: 1.0,
            plans: 2,
            failed_plans: 1,
            adopted: 1,
            dropped: 0,
            unpadded_plans: 0,
            held: 0.2,
            wall_seconds: 0.2,
            trajectory: vec![
                (0.0, setup.start.clone()),
                (0.1, setup.start.clone()),
                (1.0, setup.goal.clone()),
            ],
            plan_times: vec![(0.0, false), (0.1, true)],
        };
        let folder = std::env::temp_dir().join(format!("replan-picture-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let (svg, png) = (folder.join("t.svg"), folder.join("t.png"));
        TrialPicture::new(&setup, &record).save(&svg, &png).unwrap();
        let text = std::fs::read_to_string(&svg).unwrap();
        assert!(text.contains("rising") && text.contains("grasp point"));
        assert!(std::fs::metadata(&png).unwrap().len() > 1000);
        std::fs::remove_dir_all(&folder).unwrap();
    }
}
