//! [`Experiment`]: planners × problem instances × runs, with the seeds and confidence of the
//! statistics.

use std::path::Path;

use crate::definition::cloud_spec::CloudSpec;
use crate::definition::experiment_file::ExperimentFile;
use crate::definition::parameter_overrides::ParameterOverrides;
use crate::definition::planner_spec::PlannerSpec;
use crate::definition::problem_instance::ProblemInstance;
use crate::definition::problem_source::ProblemSource;
use crate::definition::problem_spec::ProblemSpec;
use crate::definition::shipped_experiment::ShippedExperiment;
use crate::error::HarnessError;

/// An experiment: every planner runs `runs` times on every problem instance; run `i` of every
/// planner on the `k`-th instance (from 0) uses seed `seed + k · 100 000 + i`
/// ([`INSTANCE_SEED_STRIDE`](crate::INSTANCE_SEED_STRIDE)).
///
/// Load one from a TOML [experiment file](crate::experiment_file), a
/// [shipped experiment](ShippedExperiment), or build it directly.
///
/// ```
/// use mit_star_benches::Experiment;
/// let e = Experiment::shipped("ablation")?;
/// assert_eq!(e.planners.len(), 6);
/// let ids: Vec<String> = e.instances()?.into_iter().map(|i| i.id).collect();
/// assert_eq!(ids, ["goal-enclosure-n2", "dividing-walls-n4"]);
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Experiment {
    /// The experiment's name (names the default results folder).
    pub name: String,
    /// One line on what it measures.
    pub description: String,
    /// The planners, in report order.
    pub planners: Vec<PlannerSpec>,
    /// The problems.
    pub problems: Vec<ProblemSpec>,
    /// Runs per planner and problem instance.
    pub runs: usize,
    /// Base seed: run `i` on the `k`-th instance uses `seed + k · 100 000 + i`.
    pub seed: u64,
    /// Confidence of the medians' and success rates' intervals, in `(0, 1)`.
    pub confidence: f64,
    /// Each run stops at its first solution (or its budget, whichever comes first): for
    /// studies of the time and work to a first solution, where the anytime phase would only
    /// cost machine time. The counters then measure the work to the first solution.
    pub first_solution: bool,
}

impl Experiment {
    /// Reads an experiment file.
    ///
    /// # Errors
    /// [`HarnessError::ExperimentFile`] if it cannot be read or is malformed,
    /// [`HarnessError::ExperimentField`] naming a malformed field.
    pub fn from_file(path: &Path) -> Result<Self, HarnessError> {
        // Not a file the user can give is an input error (exit code 2), not an I/O failure.
        // Bounded: `/dev/zero` or a 20 GB file is refused before it is read.
        let text = mit_star_problems::read_bounded(
            path,
            mit_star_problems::TEXT_INPUT_LIMIT,
            "experiment file",
        )
        .map_err(|e| HarnessError::ExperimentFile {
            file: path.display().to_string(),
            message: if path.is_dir() {
                "is a folder, not an experiment file".into()
            } else {
                format!("cannot be read: {e}")
            },
        })?;
        let origin = path.display().to_string();
        let stem = path
            .file_stem()
            .map_or_else(|| "experiment".into(), |s| s.to_string_lossy().into_owned());
        ExperimentFile::parse(&text, &origin)?.into_experiment(&origin, &stem, path.parent())
    }

    /// A shipped experiment (`paper-table`, `ablation`, `smoke`), embedded in the binary.
    ///
    /// # Errors
    /// [`HarnessError::UnknownExperiment`] listing the shipped names.
    pub fn shipped(name: &str) -> Result<Self, HarnessError> {
        let shipped = ShippedExperiment::find(name)?;
        Self::from_toml_str(shipped.text, shipped.name, None)
    }

    /// Parses the text of an experiment file; `name` names it in errors and by default.
    ///
    /// # Errors
    /// As [`from_file`](Self::from_file).
    pub fn from_toml_str(
        text: &str,
        name: &str,
        base: Option<&Path>,
    ) -> Result<Self, HarnessError> {
        ExperimentFile::parse(text, name)?.into_experiment(name, name, base)
    }

    /// Checks the experiment's own fields: at least one planner and problem, unique planner
    /// names, at least one run, a confidence in `(0, 1)`.
    ///
    /// # Errors
    /// [`HarnessError::ExperimentField`] naming the field; `origin` names the experiment.
    pub fn validate(&self, origin: &str) -> Result<(), HarnessError> {
        let bad = |field: &str, message: String| HarnessError::ExperimentField {
            experiment: origin.to_owned(),
            field: field.to_owned(),
            message,
        };
        // The name becomes the default output folder `results/<name>`: nothing may escape it.
        if !is_safe_name(&self.name) {
            return Err(bad(
                "name",
                format!(
                    "is {:?}; an experiment name names its results folder: {NAME_RULE}",
                    self.name
                ),
            ));
        }
        if self.planners.is_empty() {
            return Err(bad(
                "planners",
                "is empty; name at least one planner".into(),
            ));
        }
        for (i, p) in self.planners.iter().enumerate() {
            if self.planners[..i].iter().any(|q| q.name() == p.name()) {
                return Err(bad(
                    &format!("planners[{i}]"),
                    format!(
                        "repeats the name `{}`; give planners of the same configuration distinct `name`s",
                        p.name()
                    ),
                ));
            }
        }
        if self.problems.is_empty() {
            return Err(bad(
                "problems",
                "is empty; give at least one problem".into(),
            ));
        }
        if self.runs == 0 {
            return Err(bad("runs", "is 0; it must be at least 1".into()));
        }
        // Refuse a schedule no campaign needs before building an instance or a job: a
        // million instances took gigabytes before the first run.
        for (i, p) in self.problems.iter().enumerate() {
            crate::definition::problem_spec::check_instance_count(Some(p.instances.len() as u64))
                .map_err(|message| bad(&format!("problems[{i}].instances"), message))?;
        }
        let instances: u128 = self
            .problems
            .iter()
            .map(|p| p.dimensions.len() as u128 * p.instances.len() as u128)
            .sum();
        let scheduled = instances * self.planners.len() as u128 * self.runs as u128;
        let cap = crate::definition::problem_spec::MAX_SCHEDULED_RUNS;
        if scheduled > u128::from(cap) {
            return Err(bad(
                "runs",
                format!(
                    "schedules {scheduled} runs ({} planners × {instances} instances × {} runs); \
                     an experiment may schedule at most {cap} (`MAX_SCHEDULED_RUNS`): split it \
                     (several experiments, or fewer runs)",
                    self.planners.len(),
                    self.runs
                ),
            ));
        }
        // Every run's record is kept until the results are written: refuse, before allocating
        // the schedule, what could not fit (`runs = 1e12` aborted on allocation).
        let runs = self.runs as u64;
        let bytes = mit_star_spaces::MemoryBudget::bytes_for(&[
            runs,
            self.planners.len() as u64,
            self.problems.len() as u64,
            crate::RUN_RECORD_BYTES,
        ]);
        if let Err(budget) = mit_star_spaces::MemoryBudget::check_on_machine(bytes) {
            return Err(bad(
                "runs",
                format!(
                    "is {runs}: the runs' records would need about {} of memory per problem \
                     dimension, and this machine has {} available",
                    bytes.map_or_else(
                        || "more than 16 EiB".into(),
                        mit_star_spaces::MemoryBudget::describe
                    ),
                    mit_star_spaces::MemoryBudget::describe(budget.bytes())
                ),
            ));
        }
        if !(self.confidence > 0.0 && self.confidence < 1.0) {
            return Err(bad(
                "confidence",
                format!(
                    "is {}; it must lie in (0, 1), e.g. 0.99",
                    mit_star_spaces::short_number(self.confidence)
                ),
            ));
        }
        if self.seed.checked_add(self.runs as u64).is_none() {
            return Err(bad("seed", format!("{} + runs overflows", self.seed)));
        }
        Ok(())
    }

    /// Every problem instance, in order (problems, then dimensions, then layout seeds). Builds
    /// every problem, so a dimension a family does not support is reported here, before any
    /// planning.
    ///
    /// # Errors
    /// As [`ProblemSpec::instances`]; [`HarnessError::Usage`] when two instances would have
    /// the same id.
    pub fn instances(&self) -> Result<Vec<ProblemInstance>, HarnessError> {
        let mut all: Vec<ProblemInstance> = Vec::new();
        for (i, spec) in self.problems.iter().enumerate() {
            let built = spec
                .instances()
                .map_err(|e| e.in_problem_entry(&format!("problems[{i}]")))?;
            for instance in built {
                if all.iter().any(|i| i.id == instance.id) {
                    return Err(HarnessError::Usage(format!(
                        "problem instance `{}` appears twice in the experiment",
                        instance.id
                    )));
                }
                all.push(instance);
            }
        }
        Ok(all)
    }

    /// The experiment with `overrides` applied on top of every planner's own.
    ///
    /// # Errors
    /// [`HarnessError::Parameter`] if an override is refused.
    pub fn with_overrides(mut self, overrides: &ParameterOverrides) -> Result<Self, HarnessError> {
        if overrides.is_empty() {
            return Ok(self);
        }
        for p in &mut self.planners {
            *p = PlannerSpec::new(
                p.configuration(),
                Some(p.name().to_owned()),
                &p.overrides().then(overrides),
            )?;
        }
        Ok(self)
    }

    /// The experiment as an experiment file (written to the results folder, so that a run can
    /// be repeated exactly).
    pub fn to_toml(&self) -> String {
        let mut t = toml::Table::new();
        t.insert("name".into(), self.name.clone().into());
        if !self.description.is_empty() {
            t.insert("description".into(), self.description.clone().into());
        }
        t.insert("runs".into(), (self.runs as i64).into());
        t.insert("seed".into(), (self.seed as i64).into());
        t.insert("confidence".into(), self.confidence.into());
        if self.first_solution {
            t.insert("first_solution".into(), true.into());
        }
        let planners: Vec<toml::Value> = self
            .planners
            .iter()
            .map(|p| {
                let mut e = toml::Table::new();
                e.insert("configuration".into(), p.configuration().name().into());
                e.insert("name".into(), p.name().into());
                let overrides: toml::Table = p
                    .overrides()
                    .entries()
                    .map(|(k, v)| (k.to_owned(), v.clone()))
                    .collect();
                if !overrides.is_empty() {
                    e.insert("parameters".into(), overrides.into());
                }
                e.into()
            })
            .collect();
        t.insert("planners".into(), planners.into());
        let problems: Vec<toml::Value> = self
            .problems
            .iter()
            .map(|p| {
                let mut e = toml::Table::new();
                match &p.source {
                    ProblemSource::Builtin(name) => {
                        e.insert("name".into(), name.clone().into());
                        let dims: Vec<toml::Value> =
                            p.dimensions.iter().map(|&d| (d as i64).into()).collect();
                        e.insert("dimensions".into(), dims.into());
                    }
                    ProblemSource::File(file) => {
                        let absolute = std::fs::canonicalize(file.path())
                            .unwrap_or_else(|_| file.path().to_path_buf());
                        e.insert("file".into(), absolute.display().to_string().into());
                    }
                    ProblemSource::Mbm(folder) => {
                        let absolute = std::fs::canonicalize(folder.path())
                            .unwrap_or_else(|_| folder.path().to_path_buf());
                        e.insert("name".into(), format!("mbm:{}", absolute.display()).into());
                        let robot = folder.robot();
                        if !robot.is_default() {
                            e.insert("robot".into(), robot.file_value().into());
                        }
                        if let Some(group) = robot.group() {
                            e.insert("group".into(), group.into());
                        }
                        if robot.is_strict() {
                            e.insert("strict_robot".into(), true.into());
                        }
                        let dims: Vec<toml::Value> =
                            p.dimensions.iter().map(|&d| (d as i64).into()).collect();
                        e.insert("dimensions".into(), dims.into());
                    }
                }
                if let Some(cloud) = &p.cloud {
                    e.insert("cloud".into(), cloud_table(cloud).into());
                }
                if let Some(pose) = p
                    .pose_goal
                    .as_ref()
                    .and_then(|g| toml::Table::try_from(g).ok())
                {
                    e.insert("pose_goal".into(), pose.into());
                }
                let time: Vec<toml::Value> = p.budgets.iter().map(|&b| b.into()).collect();
                e.insert("time".into(), time.into());
                if p.source.is_seeded() {
                    let seeds: Vec<toml::Value> =
                        p.instances.iter().map(|&s| (s as i64).into()).collect();
                    e.insert("instance_seeds".into(), seeds.into());
                }
                if let Some(r) = p.resolution {
                    e.insert("resolution".into(), r.into());
                }
                if p.allow_coarse_step {
                    e.insert("allow_coarse_step".into(), true.into());
                }
                // Recorded whenever set: a folder is never resumed with another padding.
                if !p.padding.is_zero() {
                    e.insert("padding".into(), p.padding.metres().into());
                }
                e.into()
            })
            .collect();
        t.insert("problems".into(), problems.into());
        toml::to_string(&t).unwrap_or_default()
    }
}

/// A problem's `cloud` table as the results folder's `experiment.toml` records it: every key
/// given, the files as absolute paths (the folder is resumed from anywhere) and what they hold
/// (`contents`). A changed cloud option or file changes the table, so a folder is never
/// resumed with another cloud.
fn cloud_table(cloud: &CloudSpec) -> toml::Table {
    let mut absolute = cloud.clone().with_contents_recorded();
    for f in &mut absolute.files {
        let path = std::fs::canonicalize(&*f).unwrap_or_else(|_| f.clone());
        // TOML holds UTF-8 only: a path that is not is written as it displays.
        *f = path.to_string_lossy().into_owned().into();
    }
    // Every other value of a checked cloud table fits TOML (seeds and counts within i64).
    toml::Table::try_from(&absolute).unwrap_or_default()
}

/// The rule of experiment names, which name their results folder `results/<name>`.
pub(crate) const NAME_RULE: &str = "use 1 to 100 letters, digits, `-`, `_` or `.`, not starting \
     with `.` and without `..`";

/// Longest experiment name.
const MAX_NAME_LENGTH: usize = 100;

/// `true` if `name` follows [`NAME_RULE`]: a single, visible path component that cannot leave
/// `results/`.
pub(crate) fn is_safe_name(name: &str) -> bool {
    let allowed = |c: char| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.');
    !name.is_empty()
        && name.len() <= MAX_NAME_LENGTH
        && !name.starts_with('.')
        && !name.contains("..")
        && name.chars().all(allowed)
}

/// A name following [`NAME_RULE`] made from `text` (a file's stem, a problem label): other
/// characters become `-`, leading dots and repeated dots are dropped, it is cut to 100
/// characters, and an empty result is `experiment`. Only default names are made this way;
/// names the user gives are checked as given.
pub(crate) fn safe_name(text: &str) -> String {
    let mut name = String::with_capacity(text.len().min(MAX_NAME_LENGTH));
    for c in text.chars() {
        let c = if c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.') {
            c
        } else {
            '-'
        };
        if c == '.' && (name.is_empty() || name.ends_with('.')) {
            continue;
        }
        if name.len() == MAX_NAME_LENGTH {
            break;
        }
        name.push(c);
    }
    if name.is_empty() {
        "experiment".to_owned()
    } else {
        name
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_that_could_leave_the_results_folder_are_refused() {
        for bad in [
            "",
            ".",
            "..",
            "../../escape",
            "a/b",
            "/abs",
            ".hidden",
            "a..b",
            "a\\b",
            "é",
            "a b",
        ] {
            assert!(!is_safe_name(bad), "{bad:?}");
            let mut e = Experiment::shipped("smoke").unwrap();
            e.name = bad.to_owned();
            let message = e.validate("x").unwrap_err().to_string();
            assert!(
                message.contains("`name`") && message.contains(NAME_RULE),
                "{message}"
            );
        }
        assert!(!is_safe_name(&"x".repeat(101)));
        for good in ["smoke", "paper-table", "dw_2.v3", &"x".repeat(100)] {
            assert!(is_safe_name(good), "{good:?}");
        }
    }

    #[test]
    fn default_names_are_made_safe() {
        for (text, name) in [
            ("smoke", "smoke"),
            ("../../escape", "-.-escape"),
            ("", "experiment"),
            ("...", "experiment"),
            (".hidden", "hidden"),
            ("my experiment (2)", "my-experiment--2-"),
            ("a..b", "a.b"),
        ] {
            let made = safe_name(text);
            assert!(is_safe_name(&made), "{text:?} -> {made:?}");
            assert_eq!(made, name, "{text:?}");
        }
        assert_eq!(safe_name(&"y".repeat(300)).len(), 100);
    }

    #[test]
    fn shipped_experiments_load_and_round_trip() {
        for shipped in ShippedExperiment::all() {
            // Experiments reading external data (extracted into the working folder) load only
            // where it is; `tests/arm_experiment.rs` runs them on the sample problems.
            if shipped.data.is_some() {
                continue;
            }
            let e = Experiment::shipped(shipped.name).unwrap();
            assert!(!e.instances().unwrap().is_empty(), "{}", shipped.name);
            let again = Experiment::from_toml_str(&e.to_toml(), shipped.name, None).unwrap();
            assert_eq!(again, e, "{}", shipped.name);
        }
    }

    #[test]
    fn the_paper_table_has_the_papers_budgets() {
        let e = Experiment::shipped("paper-table").unwrap();
        assert_eq!(e.runs, 100);
        let names: Vec<&str> = e.planners.iter().map(PlannerSpec::name).collect();
        assert_eq!(names, ["EIT*", "MIT*"]);
        let instances = e.instances().unwrap();
        // FG, DW, GE: 3 dimensions each; RR: 3 dimensions × 10 layouts.
        assert_eq!(instances.len(), 9 + 30);
        let budget = |id: &str| instances.iter().find(|i| i.id == id).unwrap().budget;
        assert_eq!(budget("flanking-gap-n16"), 0.20);
        assert_eq!(budget("cluttered-rectangles-n8-i9"), 2.00);
        assert_eq!(budget("dividing-walls-n4"), 0.30);
        assert_eq!(budget("goal-enclosure-n8"), 2.00);
    }

    #[test]
    fn overrides_and_validation() {
        let e = Experiment::shipped("ablation").unwrap();
        let o = ParameterOverrides::default()
            .with_assignment("batch_size=7")
            .unwrap();
        let e = e.with_overrides(&o).unwrap();
        assert!(
            e.planners
                .iter()
                .all(|p| p.parameters_for_seed(0).batch_size == Some(7))
        );
        let mut bad = e.clone();
        bad.confidence = 1.0;
        assert!(
            bad.validate("x")
                .unwrap_err()
                .to_string()
                .contains("`confidence`")
        );
        let mut bad = e.clone();
        bad.planners.push(bad.planners[0].clone());
        assert!(
            bad.validate("x")
                .unwrap_err()
                .to_string()
                .contains("repeats the name `MIT*`")
        );
        let mut bad = e;
        bad.problems.push(bad.problems[0].clone());
        assert!(
            bad.instances()
                .unwrap_err()
                .to_string()
                .contains("appears twice")
        );
    }
}
