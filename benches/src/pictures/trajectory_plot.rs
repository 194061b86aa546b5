//! [`TrajectoryPlot`]: a timed trajectory against time — per joint its position, velocity and
//! acceleration, each joint's velocity and acceleration limits dashed, the knots marked — in
//! PNG or SVG.

use std::path::Path;

use mit_star_robot::Sample;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::HarnessError;
use crate::pictures::plot_style;

/// Figure size in pixels.
const SIZE: (u32, u32) = (1400, 1120);

/// Points drawn along the whole duration (more where the samples are denser).
const POINTS: f64 = 900.0;

/// Knots are marked when there are at most this many samples (a file sampled densely is not).
const MARKED_KNOTS: usize = 400;

/// The joints' colours, in order (cycled).
const JOINT_COLOURS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// A trajectory's samples (or knots) drawn per joint in three panels — position, velocity,
/// acceleration against time — with each joint's `±` velocity and acceleration limits dashed
/// in its colour and the knots as grey vertical lines. Between two samples the motion drawn
/// is the one of constant acceleration they give (`q + v τ + a τ² / 2`), as the trajectory's
/// pieces are: exact for the knots of a [`mit_star_robot::Trajectory`].
#[derive(Debug, Clone)]
pub(crate) struct TrajectoryPlot {
    title: String,
    subtitle: String,
    joints: Vec<String>,
    samples: Vec<Sample>,
    velocity: Vec<f64>,
    acceleration: Vec<f64>,
}

impl TrajectoryPlot {
    /// The plot of `samples` (in time order; each of `joints.len()` coordinates) under the
    /// limits `velocity` and `acceleration` (per joint, in the same order), headed `title`.
    pub(crate) fn new(
        title: String,
        joints: Vec<String>,
        samples: Vec<Sample>,
        (velocity, acceleration): (Vec<f64>, Vec<f64>),
    ) -> Self {
        let duration = samples.last().map_or(0.0, |s| s.time);
        let subtitle = format!(
            "{duration:.3} s, {} samples · dashed: each joint's ± velocity and acceleration limits{}",
            samples.len(),
            if samples.len() <= MARKED_KNOTS {
                " · grey verticals: the samples' times (knots)"
            } else {
                ""
            }
        );
        Self {
            title,
            subtitle,
            joints,
            samples,
            velocity,
            acceleration,
        }
    }

    /// Writes the plot: SVG for a `.svg` name, else PNG.
    ///
    /// # Errors
    /// [`HarnessError::Plot`] naming the file that could not be drawn or written.
    pub(crate) fn save(&self, file: &Path) -> Result<(), HarnessError> {
        plot_style::ensure_font();
        let fail = |message: String| HarnessError::Plot {
            path: file.to_path_buf(),
            message,
        };
        let svg = file
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
        if svg {
            let root = SVGBackend::new(file, SIZE).into_drawing_area();
            plot_style::Figure::draw_on(self, &root).map_err(fail)?;
            root.present().map_err(|e| fail(e.to_string()))
        } else {
            let root = BitMapBackend::new(file, SIZE).into_drawing_area();
            plot_style::Figure::draw_on(self, &root).map_err(fail)?;
            root.present().map_err(|e| fail(e.to_string()))
        }
    }

    /// Per joint, the curve of position (`which` 0) or velocity (1) at times along the
    /// pieces; acceleration (2) as steps.
    fn curve(&self, joint: usize, which: usize) -> Vec<(f64, f64)> {
        let duration = self.samples.last().map_or(0.0, |s| s.time);
        let step = if duration > 0.0 {
            duration / POINTS
        } else {
            1.0
        };
        let mut out = Vec::new();
        for w in self.samples.windows(2) {
            let (s, dt) = (&w[0], w[1].time - w[0].time);
            let (q, v, a) = (s.position[joint], s.velocity[joint], s.acceleration[joint]);
            if which == 2 {
                out.extend([(s.time, a), (w[1].time, a)]);
                continue;
            }
            let pieces = (dt / step).ceil().clamp(1.0, 1e4) as usize;
            for i in 0..pieces {
                let tau = dt * i as f64 / pieces as f64;
                let value = if which == 0 {
                    q + v * tau + 0.5 * a * tau * tau
                } else {
                    v + a * tau
                };
                out.push((s.time + tau, value));
            }
        }
        if let Some(last) = self.samples.last() {
            let value = [
                last.position[joint],
                last.velocity[joint],
                last.acceleration[joint],
            ][which];
            out.push((last.time, value));
        }
        out
    }

    fn colour(joint: usize) -> RGBColor {
        JOINT_COLOURS[joint % JOINT_COLOURS.len()]
    }

    fn draw_header<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let joints = self.joints.iter().enumerate();
        let entries = joints.map(|(j, name)| (name.as_str(), Self::colour(j)));
        plot_style::draw_header(area, (&self.title, &self.subtitle), entries, 9)
    }

    /// One panel: `which` 0 position, 1 velocity (limits dashed), 2 acceleration (limits
    /// dashed).
    fn draw_panel<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        which: usize,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let duration = self.samples.last().map_or(0.0, |s| s.time).max(1e-9);
        let curves: Vec<Vec<(f64, f64)>> = (0..self.joints.len())
            .map(|j| self.curve(j, which))
            .collect();
        let limits: &[f64] = match which {
            1 => &self.velocity,
            2 => &self.acceleration,
            _ => &[],
        };
        let values = curves
            .iter()
            .flatten()
            .map(|p| p.1)
            .chain(limits.iter().flat_map(|&l| [l, -l]))
            .filter(|v| v.is_finite());
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (-1.0, 1.0) };
        let pad = 0.06 * (hi - lo).max(1e-9);
        let (caption, unit) = [
            ("Position", "rad (m)"),
            ("Velocity", "rad/s (m/s)"),
            ("Acceleration", "rad/s² (m/s²)"),
        ][which];
        let mut chart = ChartBuilder::on(area)
            .caption(caption, ("sans-serif", 19))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(0.0..duration, (lo - pad)..(hi + pad))?;
        chart
            .configure_mesh()
            .x_desc("time [s]")
            .y_desc(unit)
            .light_line_style(RGBColor(246, 246, 246))
            .axis_desc_style(("sans-serif", 16))
            .label_style(("sans-serif", 13))
            .draw()?;
        if self.samples.len() <= MARKED_KNOTS {
            for s in &self.samples {
                chart.draw_series(LineSeries::new(
                    [(s.time, lo - pad), (s.time, hi + pad)],
                    RGBColor(215, 215, 215).stroke_width(1),
                ))?;
            }
        }
        for (j, &limit) in limits.iter().enumerate() {
            for l in [limit, -limit] {
                chart.draw_series(DashedLineSeries::new(
                    [(0.0, l), (duration, l)],
                    8,
                    6,
                    Self::colour(j).mix(0.8).stroke_width(1),
                ))?;
            }
        }
        for (j, curve) in curves.into_iter().enumerate() {
            chart.draw_series(LineSeries::new(curve, Self::colour(j).stroke_width(2)))?;
        }
        Ok(())
    }
}

impl plot_style::Figure for TrajectoryPlot {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (header, body) = root.split_vertically(86);
        self.draw_header(&header).map_err(|e| e.to_string())?;
        let panels = body.split_evenly((3, 1));
        for (which, panel) in panels.iter().enumerate() {
            self.draw_panel(panel, which).map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plot() -> TrajectoryPlot {
        let limits = mit_star_robot::MotionLimits::new(
            vec!["a".into(), "b".into()],
            vec![1.0, 2.0],
            vec![2.0, 1.0],
        )
        .unwrap();
        let t = mit_star_robot::Trajectory::stop_at_corners(
            &[[0.0, 0.0], [1.0, 0.5], [0.2, 2.0]],
            &limits,
        )
        .unwrap();
        TrajectoryPlot::new(
            "test".into(),
            limits.names().to_vec(),
            t.knots().to_vec(),
            (limits.velocity().to_vec(), limits.acceleration().to_vec()),
        )
    }

    #[test]
    fn curves_follow_the_pieces_and_end_at_the_last_sample() {
        let p = plot();
        let position = p.curve(0, 0);
        assert_eq!(position.first(), Some(&(0.0, 0.0)));
        assert_eq!(position.last().map(|x| x.1), Some(0.2));
        assert!(position.windows(2).all(|w| w[0].0 <= w[1].0));
        // Velocity within its limit; acceleration steps of at most the limit.
        assert!(p.curve(1, 1).iter().all(|x| x.1.abs() <= 2.0 + 1e-9));
        assert!(p.curve(0, 2).iter().all(|x| x.1.abs() <= 2.0 + 1e-9));
        assert!(p.curve(0, 2).iter().any(|x| x.1 != 0.0));
    }

    #[test]
    fn writes_svg_by_name() {
        let dir = std::env::temp_dir().join(format!("trajectory-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let svg = dir.join("plot.svg");
        plot().save(&svg).unwrap();
        let text = std::fs::read_to_string(&svg).unwrap();
        assert!(text.starts_with("<svg") && text.contains("Acceleration"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
