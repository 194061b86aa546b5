//! [`CampaignComparison`]: two results folders of one experiment side by side, per planner and
//! problem, with the confidence intervals that say whether a change is real.

use std::fmt::Write as _;

use crate::kpi_table::number;
use crate::statistics::{ClopperPearson, MedianEstimate};
use crate::{KpiRow, KpiTable};

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
