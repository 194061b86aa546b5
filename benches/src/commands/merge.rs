//! `mit-star merge`: combine the results folders of an experiment's shards.

use std::path::PathBuf;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::error::HarnessError;
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
}

impl MergeArgs {
    /// Checks the parts, writes the merged folder, prints its KPIs.
    ///
    /// # Errors
    /// Parts that do not make up one whole experiment (see [`merge_parts`]), and read or write
    /// errors.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        let report = merge_parts(&self.parts, &self.output, !self.no_plots)?;
        let results = &report.results;
        say!(
            "{}",
            crate::kpi_markdown(results, &KpiTable::from_results(results))
        );
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
        for f in &report.files {
            say!("  {}", f.display());
        }
        Ok(CommandOutcome::of_runs(
            false,
            results.failed_runs().len(),
            results.invalid_runs().len(),
        ))
    }
}
