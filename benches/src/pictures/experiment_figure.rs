//! [`ExperimentFigure`]: the figure of one problem instance — median cost over time, success
//! rate over time, initial solutions — in SVG and PNG.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::error::HarnessError;
use crate::outcome::experiment_results::ExperimentResults;
use crate::pictures::plot_style;
use crate::pictures::plot_style::planner_colours;
use crate::statistics::{AnytimeSeries, MedianEstimate, log_time_grid};

/// Points on each curve.
const GRID_POINTS: usize = 240;
/// Figure size in pixels.
const SIZE: (u32, u32) = (1560, 560);

/// One planner's curves.
#[derive(Debug, Clone)]
struct Curves {
    name: String,
    colour: RGBColor,
    series: AnytimeSeries,
    initial_time: Option<MedianEstimate>,
    initial_cost: Option<MedianEstimate>,
}

/// The figure of one problem instance, in the style of the paper and PDT: three panels with
/// a shared log-scale time axis from a small fraction of the budget to the budget —
/// (1) median best cost with its confidence band, (2) success rate with its Clopper–Pearson
/// band, (3) the initial solutions: median time and median cost with their confidence
/// intervals as error bars. Each planner has the same colour in every figure.
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
        let instance = &results.instances[index];
        let confidence = results.experiment.confidence;
        let budget = instance.budget;
        let first_solution = results.runs[index]
            .iter()
            .filter(|r| r.is_success())
            .filter_map(|r| r.initial_time)
            .fold(f64::INFINITY, f64::min);
        let start = if first_solution.is_finite() {
            (0.5 * first_solution).clamp(budget * 1e-4, budget * 0.1)
        } else {
            budget * 1e-3
        };
        let grid = log_time_grid(start, budget, GRID_POINTS);
        let colours = planner_colours(&results.experiment.planners);
        let planners = results
            .experiment
            .planners
            .iter()
            .zip(colours)
            .map(|(spec, colour)| {
                let runs = results.runs_of(index, spec.name());
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
        let runs = results.runs[index].len() / results.experiment.planners.len().max(1);
        Self {
            title: instance.title(),
            subtitle: format!(
                "{runs} runs per planner · budget {budget} s · {} concurrent runs · medians with {:.0} % confidence intervals",
                results.concurrency,
                100.0 * confidence
            ),
            confidence,
            times: (start, budget),
            optimum: instance.problem.optimum(),
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

impl ExperimentFigure {
    fn draw_header<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let entries = self.planners.iter().map(|p| (p.name.as_str(), p.colour));
        plot_style::draw_header(area, (&self.title, &self.subtitle), entries, 10)
    }

    /// Panel 1: median cost with its confidence band.
    fn draw_cost<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let mut finite: Vec<f64> = self
            .planners
            .iter()
            .flat_map(|p| p.series.median_cost.iter())
            .flat_map(|m| [m.median, m.lower, m.upper])
            .filter(|v| v.is_finite())
            .collect();
        finite.extend(self.optimum);
        let (y_lo, y_hi) = padded_range(&finite);
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!("Median cost ({:.0} % CI)", 100.0 * self.confidence),
                ("sans-serif", 19),
            )
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(62)
            .build_cartesian_2d((self.times.0..self.times.1).log_scale(), y_lo..y_hi)?;
        chart
            .configure_mesh()
            .x_desc("time [s]")
            .y_desc("cost")
            .x_label_formatter(&|v| short(*v))
            .y_label_formatter(&|v| short(*v))
            .light_line_style(RGBColor(246, 246, 246))
            .axis_desc_style(("sans-serif", 16))
            .label_style(("sans-serif", 13))
            .x_labels(6)
            .draw()?;
        if let Some(optimum) = self.optimum {
            chart.draw_series(DashedLineSeries::new(
                [(self.times.0, optimum), (self.times.1, optimum)],
                8,
                6,
                RGBColor(90, 90, 90).stroke_width(1),
            ))?;
        }
        for p in &self.planners {
            let m = &p.series.median_cost;
            let lower: Vec<f64> = m.iter().map(|e| e.lower).collect();
            let upper: Vec<f64> = m.iter().map(|e| e.upper.min(y_hi)).collect();
            for band in bands(&p.series.times, &lower, &upper) {
                chart.draw_series(std::iter::once(Polygon::new(
                    band,
                    p.colour.mix(0.18).filled(),
                )))?;
            }
        }
        for p in &self.planners {
            let median: Vec<f64> = p.series.median_cost.iter().map(|e| e.median).collect();
            for line in steps(&p.series.times, &median) {
                chart.draw_series(LineSeries::new(line, p.colour.stroke_width(2)))?;
            }
        }
        Ok(())
    }

    /// Panel 2: success rate with its Clopper–Pearson band.
    fn draw_success<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!(
                    "Success rate ({:.0} % Clopper–Pearson)",
                    100.0 * self.confidence
                ),
                ("sans-serif", 19),
            )
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(62)
            .build_cartesian_2d((self.times.0..self.times.1).log_scale(), 0.0..102.0)?;
        chart
            .configure_mesh()
            .x_desc("time [s]")
            .y_desc("success [%]")
            .x_label_formatter(&|v| short(*v))
            .y_label_formatter(&|v| format!("{v:.0}"))
            .light_line_style(RGBColor(246, 246, 246))
            .axis_desc_style(("sans-serif", 16))
            .label_style(("sans-serif", 13))
            .x_labels(6)
            .draw()?;
        for p in &self.planners {
            let lower: Vec<f64> = p.series.success.iter().map(|c| 100.0 * c.lower).collect();
            let upper: Vec<f64> = p.series.success.iter().map(|c| 100.0 * c.upper).collect();
            for band in bands(&p.series.times, &lower, &upper) {
                chart.draw_series(std::iter::once(Polygon::new(
                    band,
                    p.colour.mix(0.15).filled(),
                )))?;
            }
        }
        for p in &self.planners {
            let rate: Vec<f64> = p.series.success.iter().map(|c| 100.0 * c.rate).collect();
            for line in steps(&p.series.times, &rate) {
                chart.draw_series(LineSeries::new(line, p.colour.stroke_width(2)))?;
            }
        }
        Ok(())
    }

    /// Panel 3: median initial-solution time and cost with their confidence intervals.
    fn draw_initial<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let finite: Vec<f64> = self
            .planners
            .iter()
            .filter_map(|p| p.initial_cost.as_ref())
            .flat_map(|m| [m.median, m.lower, m.upper])
            .filter(|v| v.is_finite())
            .collect();
        let (y_lo, y_hi) = padded_range(&finite);
        let (t_lo, t_hi) = self.times;
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!(
                    "Initial solutions (median, {:.0} % CI)",
                    100.0 * self.confidence
                ),
                ("sans-serif", 19),
            )
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(62)
            .build_cartesian_2d((t_lo..t_hi).log_scale(), y_lo..y_hi)?;
        chart
            .configure_mesh()
            .x_desc("time to first solution [s]")
            .y_desc("first solution cost")
            .x_label_formatter(&|v| short(*v))
            .y_label_formatter(&|v| short(*v))
            .light_line_style(RGBColor(246, 246, 246))
            .axis_desc_style(("sans-serif", 16))
            .label_style(("sans-serif", 13))
            .x_labels(6)
            .draw()?;
        for p in &self.planners {
            let (Some(t), Some(c)) = (&p.initial_time, &p.initial_cost) else {
                continue;
            };
            if !(t.median.is_finite() && c.median.is_finite()) {
                continue;
            }
            let style = p.colour.stroke_width(2);
            let clamp_t = |v: f64| v.clamp(t_lo, t_hi);
            let clamp_c = |v: f64| v.clamp(y_lo, y_hi);
            chart.draw_series(std::iter::once(PathElement::new(
                vec![(clamp_t(t.lower), c.median), (clamp_t(t.upper), c.median)],
                style,
            )))?;
            chart.draw_series(std::iter::once(PathElement::new(
                vec![(t.median, clamp_c(c.lower)), (t.median, clamp_c(c.upper))],
                style,
            )))?;
            chart.draw_series(std::iter::once(Circle::new(
                (t.median, c.median),
                6,
                p.colour.filled(),
            )))?;
        }
        Ok(())
    }
}

/// `[min, max]` of finite values, padded by 5 % (a unit range around a single value, `[0, 1]`
/// without values).
fn padded_range(values: &[f64]) -> (f64, f64) {
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !lo.is_finite() || !hi.is_finite() {
        return (0.0, 1.0);
    }
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        0.5 * lo.abs().max(1.0)
    };
    (lo - pad, hi + pad)
}

/// The piecewise-constant curve through `(times[i], values[i])`, split where values are not
/// finite.
fn steps(times: &[f64], values: &[f64]) -> Vec<Vec<(f64, f64)>> {
    let mut lines = Vec::new();
    let mut line: Vec<(f64, f64)> = Vec::new();
    for (i, (&t, &v)) in times.iter().zip(values).enumerate() {
        if !v.is_finite() {
            if line.len() > 1 {
                lines.push(std::mem::take(&mut line));
            }
            line.clear();
            continue;
        }
        if let Some(&(_, previous)) = line.last() {
            line.push((t, previous));
        }
        line.push((t, v));
        if i + 1 == times.len() && line.len() > 1 {
            lines.push(std::mem::take(&mut line));
        }
    }
    lines
}

/// Polygons between piecewise-constant lower and upper curves, over the stretches where the
/// lower curve is finite (an infinite upper bound is clamped by the caller).
fn bands(times: &[f64], lower: &[f64], upper: &[f64]) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < times.len() {
        if !(lower[i].is_finite() && upper[i].is_finite()) {
            i += 1;
            continue;
        }
        let start = i;
        while i < times.len() && lower[i].is_finite() && upper[i].is_finite() {
            i += 1;
        }
        let top = steps(&times[start..i], &upper[start..i]);
        let bottom = steps(&times[start..i], &lower[start..i]);
        if let (Some(top), Some(bottom)) = (top.into_iter().next(), bottom.into_iter().next()) {
            let mut polygon = top;
            polygon.extend(bottom.into_iter().rev());
            out.push(polygon);
        }
    }
    out
}

/// A short axis label: three significant digits.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor() as i32;
    let decimals = (2 - magnitude).clamp(0, 8) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_split_at_infinities() {
        let t = [1.0, 2.0, 3.0, 4.0];
        let v = [f64::INFINITY, 5.0, 4.0, 4.0];
        let lines = steps(&t, &v);
        assert_eq!(
            lines,
            vec![vec![
                (2.0, 5.0),
                (3.0, 5.0),
                (3.0, 4.0),
                (4.0, 4.0),
                (4.0, 4.0)
            ]]
        );
        let b = bands(&t, &[f64::INFINITY, 1.0, 1.0, 1.0], &[9.0, 9.0, 8.0, 8.0]);
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].first(), Some(&(2.0, 9.0)));
        assert_eq!(b[0].last(), Some(&(2.0, 1.0)));
    }

    #[test]
    fn labels_and_ranges() {
        assert_eq!(short(0.001_234), "0.00123");
        assert_eq!(short(0.0100), "0.01");
        assert_eq!(short(12.345), "12.3");
        assert_eq!(short(1.5), "1.5");
        assert_eq!(short(1234.5), "1234");
        assert_eq!(padded_range(&[]), (0.0, 1.0));
        let (lo, hi) = padded_range(&[1.0, 2.0]);
        assert!(lo < 1.0 && hi > 2.0);
    }
}
