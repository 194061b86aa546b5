//! `mit-star compare`: two results folders of one experiment side by side.

use std::path::PathBuf;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::error::HarnessError;
use crate::execution::results_folder::ResultsFolder;
use crate::execution::shard::Shard;
use crate::formats::campaign_comparison::CampaignComparison;
use crate::formats::kpi_table::KpiTable;

/// Options of `mit-star compare`.
#[derive(Debug, Args)]
pub struct CompareArgs {
    /// The results folder before the change.
    pub a: PathBuf,
    /// The results folder after the change.
    pub b: PathBuf,
    /// Compare folders that do not measure the same thing (different time budgets, a shard
    /// or an unfinished folder against a whole one), printing a warning for each difference
    /// instead of refusing.
    #[arg(long)]
    pub allow_mismatch: bool,
}

impl CompareArgs {
    /// Reads both folders and prints, per problem and planner, how the median time to the
    /// first solution, the success rate and the median final cost moved from A to B.
    ///
    /// # Errors
    /// Folders that cannot be read as results folders (see
    /// [`ResultsFolder::read_results`]); [`HarnessError::IncomparableFolders`] for folders
    /// that do not measure the same thing (see [`CampaignComparison::mismatches`]), unless
    /// `--allow-mismatch`.
    pub fn run(&self) -> Result<CommandOutcome, HarnessError> {
        let a = ResultsFolder::read_results(&self.a)?;
        let b = ResultsFolder::read_results(&self.b)?;
        let reasons =
            CampaignComparison::mismatches(&a, Shard::read(&self.a)?, &b, Shard::read(&self.b)?);
        if !reasons.is_empty() {
            if !self.allow_mismatch {
                return Err(HarnessError::IncomparableFolders {
                    a: self.a.clone(),
                    b: self.b.clone(),
                    reasons,
                });
            }
            for reason in &reasons {
                eprintln!("warning: comparing anyway (--allow-mismatch), but {reason}");
            }
        }
        if a.experiment.name != b.experiment.name {
            eprintln!(
                "note: A holds experiment `{}` and B `{}`; rows are matched by problem and planner",
                a.experiment.name, b.experiment.name
            );
        }
        let comparison =
            CampaignComparison::new(&KpiTable::from_results(&a), &KpiTable::from_results(&b));
        if comparison.rows.is_empty() {
            return Err(HarnessError::Usage(format!(
                "`{}` and `{}` have no planner on a common problem to compare",
                self.a.display(),
                self.b.display()
            )));
        }
        say!(
            "# {} ({} runs) → {} ({} runs)\n",
            self.a.display(),
            a.run_count(),
            self.b.display(),
            b.run_count()
        );
        say!("{}", comparison.markdown());
        Ok(CommandOutcome::Success)
    }
}
