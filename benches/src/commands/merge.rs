//! `mit-star merge`: combine the results folders of an experiment's shards.

use std::path::PathBuf;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::commands::bench::file_listing;
use crate::error::HarnessError;
use crate::execution::figures::Figures;
use crate::execution::shard_merge::merge_parts;
use crate::formats::kpi_table::KpiTable;

/// Options of `mit-star merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// The shard folders (`bench --shard K/N` outputs), all N of them.
    #[arg(required = true)]
    pub parts: Vec<PathBuf>,
    /// The merged results folder (fresh, or an earlier merge of the same experiment).
    #[arg(long, short)]
    pub output: PathBuf,
    /// Do not draw the figures.
    #[arg(long)]
    pub no_plots: bool,
    /// Per-problem detail, as `bench --per-problem`: every problem's KPIs printed, every
    /// file listed, a figure and a 3-D view of every problem instance.
    #[arg(long)]
    pub per_problem: bool,
}

impl MergeArgs {
    /// Checks the parts, writes the merged folder, prints its KPIs.
    ///
    /// # Errors
    /// Parts that do not make up one whole experiment (see [`merge_parts`]), and read or write
    /// errors.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        let figures = Figures::from_flags(self.no_plots, self.per_problem);
        let report = merge_parts(&self.parts, &self.output, figures)?;
        let results = &report.results;
        let table = KpiTable::from_results(results);
        if self.per_problem {
            say!("{}", crate::kpi_markdown(results, &table));
        } else {
            say!(
                "{}\n",
                crate::kpi_overview(results, &table, true).trim_end()
            );
        }
        say!(
            "Merged {} shards ({} runs: {}) into {}:",
            self.parts.len(),
            results.run_count(),
            report
                .runs_per_part
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(" + "),
            self.output.display()
        );
        for line in file_listing(&self.output, &report.files, self.per_problem) {
            say!("  {line}");
        }
        Ok(CommandOutcome::of_runs(
            false,
            results.failed_runs().len(),
            results.invalid_runs().len(),
        ))
    }
}
