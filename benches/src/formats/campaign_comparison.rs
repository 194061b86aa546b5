//! [`CampaignComparison`]: two results folders of one experiment side by side, per planner and
//! problem, with the confidence intervals that say whether a change is real.

use std::fmt::Write as _;

use crate::execution::shard::Shard;
use crate::formats::kpi_table::number;
use crate::formats::kpi_table::{KpiRow, KpiTable};
use crate::outcome::experiment_results::ExperimentResults;
use crate::statistics::{ClopperPearson, MedianEstimate};

/// How a statistic moved from A to B, judged by its confidence intervals.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Change {
    /// B's interval lies entirely below A's.
    Lower,
    /// B's interval lies entirely above A's.
    Higher,
    /// The intervals overlap: no change this experiment can tell.
    Unclear,
}

impl Change {
    /// The change between two intervals `[a_lo, a_hi]` and `[b_lo, b_hi]`.
    pub fn between((a_lo, a_hi): (f64, f64), (b_lo, b_hi): (f64, f64)) -> Self {
        if b_hi < a_lo {
            Self::Lower
        } else if b_lo > a_hi {
            Self::Higher
        } else {
            Self::Unclear
        }
    }

    /// Of two medians, by their intervals.
    pub fn of_medians(a: &MedianEstimate, b: &MedianEstimate) -> Self {
        Self::between((a.lower, a.upper), (b.lower, b.upper))
    }

    /// Of two success rates, by their Clopper–Pearson intervals.
    pub fn of_rates(a: &ClopperPearson, b: &ClopperPearson) -> Self {
        Self::between((a.lower, a.upper), (b.lower, b.upper))
    }

    /// A word for tables.
    fn word(self) -> &'static str {
        match self {
            Self::Lower => "lower",
            Self::Higher => "higher",
            Self::Unclear => "≈",
        }
    }
}

/// One planner on one problem in both folders.
#[derive(Debug, Clone)]
pub struct ComparedRow {
    /// The row in folder A.
    pub a: KpiRow,
    /// The row in folder B.
    pub b: KpiRow,
}

impl ComparedRow {
    /// Median time to the first solution, B over A (`None` unless both are finite and A's is
    /// positive).
    pub fn t_init_ratio(&self) -> Option<f64> {
        let (a, b) = (self.a.initial_time.median, self.b.initial_time.median);
        (a.is_finite() && b.is_finite() && a > 0.0).then(|| b / a)
    }

    /// How the median time to the first solution moved.
    pub fn t_init_change(&self) -> Change {
        Change::of_medians(&self.a.initial_time, &self.b.initial_time)
    }

    /// How the success rate moved.
    pub fn success_change(&self) -> Change {
        Change::of_rates(&self.a.success, &self.b.success)
    }

    /// How the median final cost moved.
    pub fn final_cost_change(&self) -> Change {
        Change::of_medians(&self.a.final_cost, &self.b.final_cost)
    }
}

/// The KPI tables of two results folders, matched by problem (instance title, pooled rows
/// included) and planner name: `mit-star compare A B`.
///
/// ```
/// use mit_star_benches::{CampaignComparison, Change};
/// assert_eq!(Change::between((1.0, 2.0), (0.2, 0.9)), Change::Lower);
/// assert_eq!(Change::between((1.0, 2.0), (1.9, 3.0)), Change::Unclear);
/// ```
#[derive(Debug, Clone)]
pub struct CampaignComparison {
    /// Confidence of A's intervals (B's are at B's confidence).
    pub confidence: f64,
    /// Rows present in both folders, in A's order.
    pub rows: Vec<ComparedRow>,
    /// `(problem, planner)` rows only A has.
    pub only_a: Vec<(String, String)>,
    /// `(problem, planner)` rows only B has.
    pub only_b: Vec<(String, String)>,
}

impl CampaignComparison {
    /// Matches the rows of `a` and `b`.
    pub fn new(a: &KpiTable, b: &KpiTable) -> Self {
        let mut rows = Vec::new();
        let mut only_a = Vec::new();
        for r in &a.rows {
            match b.row(&r.instance, &r.planner) {
                Some(other) => rows.push(ComparedRow {
                    a: r.clone(),
                    b: other.clone(),
                }),
                None => only_a.push((r.instance.clone(), r.planner.clone())),
            }
        }
        let only_b = b
            .rows
            .iter()
            .filter(|r| a.row(&r.instance, &r.planner).is_none())
            .map(|r| (r.instance.clone(), r.planner.clone()))
            .collect();
        Self {
            confidence: a.confidence,
            rows,
            only_a,
            only_b,
        }
    }

    /// Why the results `a` (of a folder holding `a_shard` of its experiment, `None`: all of
    /// it) and `b` do not measure the same thing, one sentence per difference; empty if they
    /// can be compared. Differences: the time budget of a problem instance both hold; runs
    /// that stop at their first solution against runs to the budget; a shard against the whole
    /// experiment or another shard; and a folder without every run it schedules (an
    /// interrupted `bench`). Planners, parameters, seeds and run counts may differ: they are
    /// what a comparison is for.
    pub fn mismatches(
        a: &ExperimentResults,
        a_shard: Option<Shard>,
        b: &ExperimentResults,
        b_shard: Option<Shard>,
    ) -> Vec<String> {
        let mut reasons = Vec::new();
        let budgets: Vec<String> = a
            .instances
            .iter()
            .filter_map(|i| {
                let other = b.instances.iter().find(|j| j.id == i.id)?;
                (other.budget != i.budget)
                    .then(|| format!("{} {} s in A, {} s in B", i.id, i.budget, other.budget))
            })
            .collect();
        if let Some(first) = budgets.first() {
            let more = match budgets.len() {
                1 => String::new(),
                n => format!(" (and {} more instances)", n - 1),
            };
            reasons.push(format!("the time budgets per run differ: {first}{more}"));
        }
        let stop = |r: &ExperimentResults| {
            if r.experiment.first_solution {
                "stop at their first solution"
            } else {
                "run to the budget"
            }
        };
        if a.experiment.first_solution != b.experiment.first_solution {
            reasons.push(format!("A's runs {} and B's {}", stop(a), stop(b)));
        }
        let part = |s: Option<Shard>| {
            s.map_or("the whole experiment".to_owned(), |s| {
                format!("shard {s} of its experiment")
            })
        };
        if a_shard != b_shard {
            reasons.push(format!("A holds {} and B {}", part(a_shard), part(b_shard)));
        }
        for (name, results, shard) in [("A", a, a_shard), ("B", b, b_shard)] {
            let (recorded, planned) = (results.run_count(), results.planned_runs(shard));
            if recorded < planned {
                reasons.push(format!(
                    "{name} holds {recorded} of the {planned} runs {} schedules (an unfinished \
                     `bench`: resume it)",
                    if shard.is_some() {
                        "its shard"
                    } else {
                        "its experiment"
                    }
                ));
            }
        }
        reasons
    }

    /// The comparison as Markdown: per problem and planner, median `t_init` in A and B with
    /// their intervals, B/A and the verdict; success rates with their Clopper–Pearson
    /// intervals; median final costs with their intervals; then the rows one folder lacks.
    pub fn markdown(&self) -> String {
        let mut s = format!(
            "Changes from A to B; \"lower\"/\"higher\" where the {:.0} % confidence intervals \
             do not overlap, \"≈\" where they do.\n\n\
             | problem | planner | t_init A | t_init B | B/A | t_init | success A | success B | success | c_final A | c_final B | c_final |\n",
            100.0 * self.confidence
        );
        s.push_str(&"|---".repeat(12));
        s.push_str("|\n");
        for r in &self.rows {
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                r.a.instance,
                r.a.planner,
                interval(&r.a.initial_time),
                interval(&r.b.initial_time),
                r.t_init_ratio()
                    .map_or("–".to_owned(), |x| format!("{x:.3}")),
                r.t_init_change().word(),
                rate(&r.a),
                rate(&r.b),
                r.success_change().word(),
                interval(&r.a.final_cost),
                interval(&r.b.final_cost),
                r.final_cost_change().word(),
            );
        }
        for (which, rows) in [("A", &self.only_a), ("B", &self.only_b)] {
            if !rows.is_empty() {
                let names: Vec<String> = rows.iter().map(|(i, p)| format!("{p} on {i}")).collect();
                let _ = writeln!(s, "\nOnly in {which}: {}.", names.join(", "));
            }
        }
        s
    }
}

/// `median [lower, upper]`.
fn interval(m: &MedianEstimate) -> String {
    format!(
        "{} [{}, {}]",
        number(m.median),
        number(m.lower),
        number(m.upper)
    )
}

/// `successes/runs [lower, upper] %`.
fn rate(r: &KpiRow) -> String {
    format!(
        "{}/{} [{:.0}, {:.0}] %",
        r.successes,
        r.runs,
        100.0 * r.success.lower,
        100.0 * r.success.upper
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star::Configuration;

    /// A row of 100 runs: the first `solved` solve, at times `scale · (1 + i/100)` and costs
    /// `cost + i/1000`; the rest fail (∞).
    fn row(instance: &str, planner: &str, solved: usize, scale: f64, cost: f64) -> KpiRow {
        // Run i's value, or ∞ if it failed.
        let series = |value: &dyn Fn(f64) -> f64| -> Vec<f64> {
            (0..100)
                .map(|i| {
                    if i < solved {
                        value(i as f64)
                    } else {
                        f64::INFINITY
                    }
                })
                .collect()
        };
        let times = series(&|i| scale * (1.0 + i / 100.0));
        let costs = series(&|i| cost + i / 1000.0);
        let median = |v: &[f64]| MedianEstimate::of(v, 0.99).unwrap();
        KpiRow {
            instance: instance.to_owned(),
            planner: planner.to_owned(),
            configuration: Configuration::MitStar,
            runs: 100,
            successes: solved,
            invalid: 0,
            initial_time: median(&times),
            initial_time_p95: times[94],
            initial_cost: median(&costs),
            final_cost: median(&costs),
            success: ClopperPearson::new(solved, 100, 0.99),
        }
    }

    fn table(rows: Vec<KpiRow>) -> KpiTable {
        KpiTable {
            confidence: 0.99,
            planners: Vec::new(),
            instances: Vec::new(),
            rows,
            families: Vec::new(),
        }
    }

    #[test]
    fn real_changes_are_called_and_noise_is_not() {
        let a = table(vec![
            row("dividing-walls R^4", "MIT*", 100, 0.010, 2.0),
            row("dividing-walls R^4", "EIT*", 100, 0.010, 2.0),
            row("goal-enclosure R^8", "MIT*", 60, 0.100, 3.0),
            row("flanking-gap R^2", "MIT*", 100, 0.010, 1.0),
        ]);
        let b = table(vec![
            // Twice as fast, a slightly higher final cost within the interval.
            row("dividing-walls R^4", "MIT*", 100, 0.005, 2.001),
            // The same.
            row("dividing-walls R^4", "EIT*", 100, 0.010, 2.0),
            // Solves far more often, and sooner.
            row("goal-enclosure R^8", "MIT*", 99, 0.050, 2.0),
            row("random-rectangles R^4", "MIT*", 100, 0.010, 1.0),
        ]);
        let comparison = CampaignComparison::new(&a, &b);
        assert_eq!(comparison.rows.len(), 3);
        let faster = &comparison.rows[0];
        assert_eq!(faster.t_init_change(), Change::Lower);
        assert!((faster.t_init_ratio().unwrap() - 0.5).abs() < 1e-9);
        assert_eq!(faster.success_change(), Change::Unclear);
        assert_eq!(faster.final_cost_change(), Change::Unclear);
        let same = &comparison.rows[1];
        assert_eq!(same.t_init_change(), Change::Unclear);
        assert_eq!(same.t_init_ratio(), Some(1.0));
        let better = &comparison.rows[2];
        assert_eq!(better.success_change(), Change::Higher);
        assert_eq!(better.t_init_change(), Change::Lower);
        assert_eq!(better.final_cost_change(), Change::Lower);
        assert_eq!(
            comparison.only_a,
            vec![("flanking-gap R^2".to_owned(), "MIT*".to_owned())]
        );
        assert_eq!(
            comparison.only_b,
            vec![("random-rectangles R^4".to_owned(), "MIT*".to_owned())]
        );
        let text = comparison.markdown();
        let line = |p: &str| text.lines().find(|l| l.starts_with(p)).unwrap().to_owned();
        assert!(
            line("| dividing-walls R^4 | MIT* |").contains("| 0.500 | lower |"),
            "{text}"
        );
        assert!(
            line("| goal-enclosure R^8 | MIT* |").contains("| higher |"),
            "{text}"
        );
        assert!(
            text.contains("Only in A: MIT* on flanking-gap R^2."),
            "{text}"
        );
        assert!(
            text.contains("Only in B: MIT* on random-rectangles R^4."),
            "{text}"
        );
    }
}
