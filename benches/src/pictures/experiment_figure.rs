//! [`ExperimentFigure`]: the figure of a scene or of one problem instance — median cost over
//! time, success rate over time, initial solutions — in SVG and PNG.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::HarnessError;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::run_record::RunRecord;
use crate::outcome::scene::Scene;
use crate::pictures::plot_axes::{
    LogTicks, cost_range, fitted_log_range, log_ticks, round_down_125, significant, time_label,
};
use crate::pictures::plot_style;
use crate::pictures::plot_style::planner_colours;
use crate::pictures::step_curves::{bands, steps};
use crate::statistics::{AnytimeSeries, MedianEstimate, log_time_grid};

/// Points on each curve.
const GRID_POINTS: usize = 240;
/// Figure size in pixels.
const SIZE: (u32, u32) = (1560, 560);
/// At most this many labels on a time axis (a panel is about 440 pixels wide).
const TIME_LABELS: usize = 7;
/// The opacity of all planners' band fills together: each band gets this share of it
/// (within [`BAND_FILL_RANGE`]), so that where every band overlaps the fill stays light and
/// the medians readable; each band is also outlined.
const BAND_FILL_TOTAL: f64 = 0.3;
/// The least and greatest opacity of one band's fill.
const BAND_FILL_RANGE: (f64, f64) = (0.04, 0.12);
/// The opacity of a band's outline.
const BAND_OUTLINE: f64 = 0.45;
/// The optimum's line colour.
const OPTIMUM: RGBColor = RGBColor(70, 70, 70);

/// One planner's curves.
#[derive(Debug, Clone)]
struct Curves {
    name: String,
    colour: RGBColor,
    series: AnytimeSeries,
    initial_time: Option<MedianEstimate>,
    initial_cost: Option<MedianEstimate>,
}

/// The figure of a scene (every problem instance of it pooled) or of one problem instance,
/// in the style of the paper and of Planner Arena: three panels —
/// (1) median best cost over time with its confidence band, the known optimum as a dashed
/// line named in the legend; (2) success rate over time with its Clopper–Pearson band;
/// (3) the initial solutions: median time and median cost with their confidence intervals
/// as error bars. Bands are light fills with outlines, so overlapping planners stay
/// readable. Time axes are logarithmic with 1-2-5 ticks labelled in s, ms or µs. The cost
/// axis fits the curves, not a distant optimum; the first-solution panel's axes fit the
/// medians and their intervals, each bound reaching at most a factor of 10 beyond them.
/// Each planner has the same colour in every figure.
#[derive(Debug, Clone)]
pub struct ExperimentFigure {
    title: String,
    subtitle: String,
    confidence: f64,
    times: (f64, f64),
    optimum: Option<f64>,
    planners: Vec<Curves>,
}

impl ExperimentFigure {
    /// The figure of instance `index` of `results`.
    pub fn from_results(results: &ExperimentResults, index: usize) -> Self {
        Self::from_instances(results, &[index], results.instances[index].title(), None)
    }

    /// The figure of `scene`: the runs of every instance of it pooled (a scene of one
    /// instance draws that instance's figure).
    pub fn from_scene(results: &ExperimentResults, scene: &Scene) -> Self {
        let pooled = (scene.instances.len() > 1)
            .then(|| format!("{} {}", scene.instances.len(), scene.instance_noun()));
        Self::from_instances(
            results,
            &scene.instances,
            scene.title.clone(),
            pooled.as_deref(),
        )
    }

    /// The figure of the runs on `indices`, titled `title`; `pooled` names the instances
    /// when there are several (`100 problems`).
    fn from_instances(
        results: &ExperimentResults,
        indices: &[usize],
        title: String,
        pooled: Option<&str>,
    ) -> Self {
        let confidence = results.experiment.confidence;
        let budget = indices
            .iter()
            .map(|&i| results.instances[i].budget)
            .fold(0.0, f64::max);
        let all: Vec<&RunRecord> = indices.iter().flat_map(|&i| &results.runs[i]).collect();
        let first_solution = all
            .iter()
            .filter(|r| r.is_success())
            .filter_map(|r| r.initial_time)
            .fold(f64::INFINITY, f64::min);
        // From a labelled 1-2-5 tick below half the first solution's time.
        let start = if first_solution.is_finite() {
            round_down_125((0.5 * first_solution).clamp(budget * 1e-4, budget * 0.1))
        } else {
            round_down_125(budget * 1e-3)
        };
        let grid = log_time_grid(start, budget, GRID_POINTS);
        let colours = planner_colours(&results.experiment.planners);
        let planners = results
            .experiment
            .planners
            .iter()
            .zip(colours)
            .map(|(spec, colour)| {
                let runs: Vec<&RunRecord> = all
                    .iter()
                    .copied()
                    .filter(|r| r.planner == spec.name())
                    .collect();
                let traces: Vec<_> = runs.iter().map(|r| r.statistics_trace()).collect();
                let times: Vec<f64> = runs.iter().map(|r| r.initial_time_or_inf()).collect();
                let costs: Vec<f64> = runs.iter().map(|r| r.initial_cost_or_inf()).collect();
                Curves {
                    name: spec.name().to_owned(),
                    colour,
                    series: AnytimeSeries::new(&traces, &grid, confidence),
                    initial_time: MedianEstimate::of(&times, confidence),
                    initial_cost: MedianEstimate::of(&costs, confidence),
                }
            })
            .collect();
        let planners_count = results.experiment.planners.len().max(1);
        let runs = all.len() / planners_count;
        let runs = match pooled {
            Some(what) => format!("{what}, {runs} runs per planner in all (costs pooled)"),
            None => format!("{runs} runs per planner"),
        };
        let optima: Vec<Option<f64>> = indices
            .iter()
            .map(|&i| results.instances[i].problem.optimum())
            .collect();
        let optimum = optima[0].filter(|o| optima.iter().all(|p| *p == Some(*o)));
        Self {
            title,
            subtitle: format!(
                "{runs} · budget {budget} s · {} concurrent runs · medians with {:.0} % confidence intervals",
                results.concurrency,
                100.0 * confidence
            ),
            confidence,
            times: (start, budget),
            optimum,
            planners,
        }
    }

    /// Writes the figure as SVG and PNG.
    ///
    /// # Errors
    /// [`HarnessError::Plot`] if either file cannot be drawn or written.
    pub fn save(&self, svg: &Path, png: &Path) -> Result<(), HarnessError> {
        plot_style::save_svg_and_png(self, SIZE, svg, png)
    }
}

impl plot_style::Figure for ExperimentFigure {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (header, body) = root.split_vertically(82);
        self.draw_header(&header).map_err(|e| e.to_string())?;
        let panels = body.split_evenly((1, 3));
        self.draw_cost(&panels[0]).map_err(|e| e.to_string())?;
        self.draw_success(&panels[1]).map_err(|e| e.to_string())?;
        self.draw_initial(&panels[2]).map_err(|e| e.to_string())
    }
}

/// A chart with a log-scale time axis over `times` (1-2-5 ticks) and a linear `y` axis.
type TimeChart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<
        plotters::coord::combinators::WithKeyPoints<LogCoord<f64>>,
        plotters::coord::types::RangedCoordf64,
    >,
>;

/// Builds a panel's chart on `area`: `caption`, the log-scale time axis over `times` named
/// `x_desc`, the linear axis over `y` named `y_desc` (labelled by `y_label`), light grid lines.
fn time_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    caption: String,
    (times, x_desc): ((f64, f64), &str),
    (y, y_desc): ((f64, f64), &str),
    y_label: &dyn Fn(&f64) -> String,
) -> Result<TimeChart<'a, DB>, DrawingAreaErrorKind<DB::ErrorType>> {
    let LogTicks { labelled, light } = log_ticks(times.0, times.1, TIME_LABELS);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 19))
        .margin(12)
        .margin_right(22)
        .x_label_area_size(44)
        .y_label_area_size(62)
        .build_cartesian_2d(
            (times.0..times.1)
                .log_scale()
                .with_key_points(labelled)
                .with_light_points(light),
            y.0..y.1,
        )?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| time_label(*v))
        .y_label_formatter(y_label)
        .bold_line_style(RGBColor(222, 222, 222))
        .light_line_style(RGBColor(243, 243, 243))
        .axis_desc_style(("sans-serif", 16))
        .label_style(("sans-serif", 14))
        .y_labels(8)
        .y_max_light_lines(2)
        .draw()?;
    Ok(chart)
}

/// Draws a planner's confidence band (one of `planners`) between `lower` and `upper` over
/// `times`, clipped to the chart's `y` range: a light fill, and a thin outline along each bound where it lies within
/// the axis (not along the axis' edge where a bound is cut).
fn draw_band<DB: DrawingBackend>(
    chart: &mut TimeChart<'_, DB>,
    (colour, planners): (RGBColor, usize),
    times: &[f64],
    (lower, upper): (&[f64], &[f64]),
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let (y_lo, y_hi) = {
        let range = chart.y_range();
        (range.start, range.end)
    };
    let fill = (BAND_FILL_TOTAL / planners as f64).clamp(BAND_FILL_RANGE.0, BAND_FILL_RANGE.1);
    let clamped_lower: Vec<f64> = lower.iter().map(|v| v.max(y_lo)).collect();
    let clamped_upper: Vec<f64> = upper.iter().map(|v| v.min(y_hi)).collect();
    for band in bands(times, &clamped_lower, &clamped_upper) {
        chart.draw_series(std::iter::once(Polygon::new(
            band,
            colour.mix(fill).filled(),
        )))?;
    }
    let inside = |v: &f64| {
        if *v >= y_lo && *v <= y_hi {
            *v
        } else {
            f64::INFINITY
        }
    };
    for bound in [lower, upper] {
        let bound: Vec<f64> = bound.iter().map(inside).collect();
        for line in steps(times, &bound) {
            chart.draw_series(LineSeries::new(
                line,
                colour.mix(BAND_OUTLINE).stroke_width(1),
            ))?;
        }
    }
    Ok(())
}

impl ExperimentFigure {
    fn draw_header<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let entries = self.planners.iter().map(|p| (p.name.as_str(), p.colour));
        plot_style::draw_header(area, (&self.title, &self.subtitle), entries, 10)
    }

    /// Panel 1: median cost with its confidence band; the optimum dashed, in the legend.
    fn draw_cost<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let estimates = || {
            self.planners
                .iter()
                .flat_map(|p| p.series.median_cost.iter())
        };
        let core: Vec<f64> = estimates().flat_map(|m| [m.median, m.lower]).collect();
        let upper: Vec<f64> = estimates().map(|m| m.upper).collect();
        let ((y_lo, y_hi), optimum_shown) = cost_range(&core, &upper, self.optimum);
        let mut chart = time_chart(
            area,
            format!("Median cost ({:.0} % CI)", 100.0 * self.confidence),
            (self.times, "time (log scale)"),
            ((y_lo, y_hi), "cost"),
            &|v| significant(*v),
        )?;
        for p in &self.planners {
            let m = &p.series.median_cost;
            let lower: Vec<f64> = m.iter().map(|e| e.lower).collect();
            let upper: Vec<f64> = m.iter().map(|e| e.upper).collect();
            draw_band(
                &mut chart,
                (p.colour, self.planners.len()),
                &p.series.times,
                (&lower, &upper),
            )?;
        }
        for p in &self.planners {
            let median: Vec<f64> = p.series.median_cost.iter().map(|e| e.median).collect();
            for line in steps(&p.series.times, &median) {
                chart.draw_series(LineSeries::new(line, p.colour.stroke_width(2)))?;
            }
        }
        let Some(optimum) = self.optimum else {
            return Ok(());
        };
        let dashed = OPTIMUM.stroke_width(2);
        let legend = move |(x, y): (i32, i32)| {
            plotters::element::DashedPathElement::new(vec![(x, y), (x + 24, y)], 6, 4, dashed)
        };
        if optimum_shown {
            chart
                .draw_series(DashedLineSeries::new(
                    [(self.times.0, optimum), (self.times.1, optimum)],
                    8,
                    6,
                    dashed,
                ))?
                .label(format!("optimum {}", significant(optimum)))
                .legend(legend);
        } else {
            chart
                .draw_series(std::iter::empty::<PathElement<(f64, f64)>>())?
                .label(format!("optimum {} (below the axis)", significant(optimum)))
                .legend(legend);
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.9))
            .border_style(RGBColor(200, 200, 200))
            .label_font(("sans-serif", 14))
            .draw()
    }

    /// Panel 2: success rate with its Clopper–Pearson band.
    fn draw_success<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let mut chart = time_chart(
            area,
            format!(
                "Success rate ({:.0} % Clopper–Pearson)",
                100.0 * self.confidence
            ),
            (self.times, "time (log scale)"),
            ((0.0, 102.0), "success [%]"),
            &|v| format!("{v:.0}"),
        )?;
        for p in &self.planners {
            let lower: Vec<f64> = p.series.success.iter().map(|c| 100.0 * c.lower).collect();
            let upper: Vec<f64> = p.series.success.iter().map(|c| 100.0 * c.upper).collect();
            draw_band(
                &mut chart,
                (p.colour, self.planners.len()),
                &p.series.times,
                (&lower, &upper),
            )?;
        }
        for p in &self.planners {
            let rate: Vec<f64> = p.series.success.iter().map(|c| 100.0 * c.rate).collect();
            for line in steps(&p.series.times, &rate) {
                chart.draw_series(LineSeries::new(line, p.colour.stroke_width(2)))?;
            }
        }
        Ok(())
    }

    /// Panel 3: median initial-solution time and cost with their confidence intervals, on
    /// axes fitted to them; a bar cut at the axis has no cap, and planners without a finite
    /// median are named below the chart.
    fn draw_initial<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let drawn: Vec<(&Curves, &MedianEstimate, &MedianEstimate)> = self
            .planners
            .iter()
            .filter_map(|p| Some((p, p.initial_time.as_ref()?, p.initial_cost.as_ref()?)))
            .filter(|(_, t, c)| t.median.is_finite() && c.median.is_finite())
            .collect();
        let medians: Vec<f64> = drawn.iter().map(|(_, t, _)| t.median).collect();
        let bounds: Vec<f64> = drawn
            .iter()
            .flat_map(|(_, t, _)| [t.lower, t.upper])
            .collect();
        let (t_lo, t_hi) = fitted_log_range(&medians, &bounds, self.times);
        let core: Vec<f64> = drawn
            .iter()
            .flat_map(|(_, _, c)| [c.median, c.lower])
            .collect();
        let upper: Vec<f64> = drawn.iter().map(|(_, _, c)| c.upper).collect();
        let ((y_lo, y_hi), _) = cost_range(&core, &upper, None);
        let mut chart = time_chart(
            area,
            format!(
                "Initial solutions (median, {:.0} % CI)",
                100.0 * self.confidence
            ),
            ((t_lo, t_hi), "time to first solution (log scale)"),
            ((y_lo, y_hi), "first solution cost"),
            &|v| significant(*v),
        )?;
        let cap_t = (t_hi / t_lo).powf(0.012);
        let cap_c = 0.012 * (y_hi - y_lo);
        for (p, t, c) in &drawn {
            let style = p.colour.stroke_width(2);
            let (a, b) = (t.lower.max(t_lo), t.upper.min(t_hi));
            let (d, u) = (c.lower.max(y_lo), c.upper.min(y_hi));
            let mut segments = vec![
                vec![(a, c.median), (b, c.median)],
                vec![(t.median, d), (t.median, u)],
            ];
            for (end, cut) in [(a, t.lower < t_lo), (b, t.upper > t_hi)] {
                if !cut {
                    segments.push(vec![(end, c.median - cap_c), (end, c.median + cap_c)]);
                }
            }
            for (end, cut) in [(d, c.lower < y_lo), (u, c.upper > y_hi)] {
                if !cut {
                    segments.push(vec![(t.median / cap_t, end), (t.median * cap_t, end)]);
                }
            }
            chart.draw_series(segments.into_iter().map(|s| PathElement::new(s, style)))?;
            chart.draw_series([
                Circle::new((t.median, c.median), 7, WHITE.filled()),
                Circle::new((t.median, c.median), 5, p.colour.filled()),
            ])?;
        }
        let missing: Vec<&str> = self
            .planners
            .iter()
            .filter(|p| !drawn.iter().any(|(d, _, _)| std::ptr::eq(*d, *p)))
            .map(|p| p.name.as_str())
            .collect();
        if !missing.is_empty() {
            area.draw(&Text::new(
                format!(
                    "no finite median (over half unsolved): {}",
                    missing.join(", ")
                ),
                (80, 36),
                ("sans-serif", 13).into_font().color(&RGBColor(90, 90, 90)),
            ))?;
        }
        Ok(())
    }
}
