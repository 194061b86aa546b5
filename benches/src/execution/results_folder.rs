//! [`ResultsFolder`]: where an experiment's outputs go, checked before any work starts.

mod agreement;
pub(crate) mod folder_lock;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use folder_lock::FolderLock;

use crate::definition::experiment::Experiment;
use crate::error::HarnessError;
use crate::execution::figures::Figures;
use crate::execution::run_journal::{RunJournal, results_from_records};
use crate::execution::shard::Shard;
use crate::formats::kpi_table::KpiTable;
use crate::formats::ompl_log::benchmark_log::BenchmarkLog;
use crate::formats::planner_arena_database::PlannerArenaDatabase;
use crate::formats::report_page::{ReportInstance, ReportPage};
use crate::formats::scene_summary::SceneSummary;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::run_record::RunRecord;
use crate::outcome::scene::Scene;
use crate::pictures::experiment_figure::ExperimentFigure;
use crate::pictures::instance_views::{VIEWER_FILE, write_instance_view};

/// The name of the Planner Arena database in a results folder.
pub const DATABASE_FILE: &str = "benchmark.db";

/// A results folder:
///
/// | file | what it holds |
/// |---|---|
/// | `experiment.toml` | the experiment as run (command-line overrides applied): rerun it with `mit-star bench experiment.toml`; a folder holds one experiment, and running it again resumes it |
/// | `runs.csv` | one row per run (one line each), appended the moment the run finishes: every per-run figure, counters, the trace |
/// | `runs.jsonl` | one JSON object per run, appended likewise, with the trace, the path and the validation: the journal every summary is rebuilt from |
/// | `logs/<instance>.log` | one OMPL benchmark log per problem instance, rebuilt from every recorded run |
/// | `benchmark.db` | the Planner Arena database: runs committed in batches while they finish (at most 10 s behind), then rebuilt from every recorded run |
/// | `plots/<scene>.svg`, `.png` | the figure of each scene, its instances pooled (a box world is a scene of its own, named as its instance) |
/// | `plots/<instance>.svg`, `.png` | the figure of each instance of a scene of several (with [`Figures::ScenesAndProblems`] only) |
/// | `kpi.md` | the summary by scene, the KPI tables |
/// | `report.html` | the KPI tables, each scene's figure and a link to a 3-D view, on one page |
/// | `views/<instance>.html`, `views/viewer.js` | the 3-D view of an instance's best and worst run (arms, 2-D and 3-D box worlds), sharing one viewer: each scene's hardest instance, or every instance with [`Figures::ScenesAndProblems`] |
/// | `shard.toml` | which part of the experiment's runs the folder holds (`bench --shard K/N` only) |
/// | `.mit-star.lock` | the lock of the one process writing the folder, with its process id and command line while it runs |
///
/// A folder has one writer at a time: [`prepare`](Self::prepare) takes an advisory lock on
/// `.mit-star.lock` (`flock`), held until the `ResultsFolder` is dropped, and refuses a folder
/// another process writes, naming it. The operating system releases the lock when the writer
/// exits however it exits, so a killed writer leaves no stale lock. Readers
/// ([`read_results`](Self::read_results), `merge` reading its parts) take it shared, and refuse
/// a folder being written.
///
/// [`prepare`](Self::prepare) creates the folder, checks it is writable and opens the
/// database before any planning, so that a bad folder fails fast. Nothing is ever written outside the folder: its
/// files are the fixed names above and instance ids, which are file-name safe.
#[derive(Debug)]
pub struct ResultsFolder {
    path: PathBuf,
    database: PlannerArenaDatabase,
    _lock: FolderLock,
}

impl ResultsFolder {
    /// Creates the folder (and `logs/`, `plots/`), takes its write lock, checks that files can
    /// be written in it, and opens (or creates) its database.
    ///
    /// # Errors
    /// [`HarnessError::FolderLocked`] if another process writes (or reads) the folder,
    /// [`HarnessError::OutputFolder`] if the folder cannot be created or written,
    /// [`HarnessError::Database`] if an existing `benchmark.db` is not a database.
    pub fn prepare(path: &Path) -> Result<Self, HarnessError> {
        std::fs::create_dir_all(path).map_err(|source| HarnessError::OutputFolder {
            path: path.to_path_buf(),
            source,
        })?;
        let lock = FolderLock::exclusive(path)?;
        writable_folder(path)?;
        for dir in [path.join("logs"), path.join("plots")] {
            writable_folder(&dir)?;
        }
        let database = PlannerArenaDatabase::open(&path.join(DATABASE_FILE))?;
        Ok(Self {
            path: path.to_path_buf(),
            database,
            _lock: lock,
        })
    }

    /// The folder.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The database.
    pub fn database(&self) -> &PlannerArenaDatabase {
        &self.database
    }

    /// Records every run of `results` in the folder as `bench` does, for library use:
    /// [`claim`](Self::claim)s the folder for `results.experiment`, appends the runs not yet
    /// recorded through a [`RunJournal`], then [`finish`](Self::finish)es from every run
    /// recorded. Returns the files written. Nothing recorded before is overwritten.
    ///
    /// # Errors
    /// Those of [`claim`](Self::claim), [`RunJournal::open`], [`RunJournal::append`] and
    /// [`finish`](Self::finish).
    pub fn write(
        &mut self,
        results: &ExperimentResults,
        figures: Figures,
    ) -> Result<Vec<PathBuf>, HarnessError> {
        self.claim(&results.experiment)?;
        let mut journal = RunJournal::open(&self.path, &results.experiment, &results.instances)?;
        for (index, runs) in results.runs.iter().enumerate() {
            for record in runs {
                if !journal.recorded().contains(&record.key()) {
                    journal.append(results, index, record)?;
                }
            }
        }
        drop(journal);
        let all = results_from_records(
            results,
            RunJournal::read_records(&self.path)?,
            &results.instances,
        );
        self.finish(&all, figures)
    }

    /// Every run recorded in the results folder `path`, as results of the experiment in its
    /// `experiment.toml` (for reading a finished campaign back, e.g. `mit-star compare`).
    /// Reads under the folder's shared lock, and only a folder whose files agree: `runs.jsonl`
    /// and `runs.csv` hold the same runs, each once, and the database as many.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] if `path` is not a results folder;
    /// [`HarnessError::FolderLocked`] if another process is writing it;
    /// [`HarnessError::FolderInconsistent`] naming each file's count if they disagree; the
    /// errors of reading the experiment (its problems included) and the raw runs.
    pub fn read_results(path: &Path) -> Result<ExperimentResults, HarnessError> {
        let file = path.join("experiment.toml");
        if !file.is_file() {
            return Err(HarnessError::Usage(format!(
                "`{}` is not a results folder (it has no experiment.toml)",
                path.display()
            )));
        }
        let _lock = FolderLock::shared(path)?;
        agreement::check_agreement(path)?;
        let experiment = Experiment::from_file(&file)?;
        let instances = experiment.instances()?;
        let template = ExperimentResults {
            experiment,
            instances: instances.clone(),
            runs: Vec::new(),
            started_at: String::new(),
            total_time: 0.0,
            concurrency: 1,
            interrupted: false,
            machine: crate::MachineInfo::detect(),
        };
        Ok(results_from_records(
            &template,
            RunJournal::read_records(path)?,
            &instances,
        ))
    }

    /// Claims the folder for `experiment`: writes `experiment.toml` if the folder holds none,
    /// and refuses a folder that holds another experiment (its runs would be mixed with this
    /// one's) or runs without an `experiment.toml`. The same experiment again resumes: runs
    /// already recorded are skipped.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] naming both experiments, or the runs of unknown origin;
    /// [`HarnessError::Io`] if the file cannot be written.
    pub fn claim(&self, experiment: &Experiment) -> Result<PathBuf, HarnessError> {
        let path = self.path.join("experiment.toml");
        let text = experiment.to_toml();
        match std::fs::read_to_string(&path) {
            Ok(existing) if existing == text => Ok(path),
            Ok(existing) => {
                let other = existing
                    .lines()
                    .find_map(|l| l.strip_prefix("name = "))
                    .unwrap_or("another experiment")
                    .trim_matches('"')
                    .to_owned();
                Err(HarnessError::Usage(format!(
                    "`{}` holds the results of experiment `{other}` (see its experiment.toml), \
                     not those of `{}` as defined now ({}); write to another --output folder \
                     (a folder is resumed only by the same experiment)",
                    self.path.display(),
                    experiment.name,
                    differences(&existing, &text)
                )))
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                let has_runs = ["runs.jsonl", "runs.csv"]
                    .iter()
                    .any(|f| std::fs::metadata(self.path.join(f)).is_ok_and(|m| m.len() > 0));
                if has_runs {
                    return Err(HarnessError::Usage(format!(
                        "`{}` holds runs but no experiment.toml, so they cannot be told apart \
                         from those of `{}`; write to another --output folder",
                        self.path.display(),
                        experiment.name
                    )));
                }
                write_replacing(&path, text.as_bytes())?;
                Ok(path)
            }
            Err(source) => Err(HarnessError::Io { path, source }),
        }
    }

    /// Claims the folder for `shard` of its experiment (after [`claim`](Self::claim)): a shard's
    /// folder records which one in [`SHARD_FILE`](crate::SHARD_FILE). Refuses a folder holding
    /// another shard, a shard's folder for the whole experiment, and a folder holding runs of
    /// the whole experiment for a shard.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] naming both; [`HarnessError::Io`] if the file cannot be read
    /// or written.
    pub fn claim_shard(&self, shard: Option<Shard>) -> Result<(), HarnessError> {
        let existing = Shard::read(&self.path)?;
        let folder = self.path.display();
        match (existing, shard) {
            (Some(e), Some(s)) if e == s => Ok(()),
            (Some(e), Some(s)) => Err(HarnessError::Usage(format!(
                "`{folder}` holds shard {e} of the experiment, not {s}; write to another --output folder"
            ))),
            (Some(e), None) => Err(HarnessError::Usage(format!(
                "`{folder}` holds shard {e} of the experiment; resume it with --shard {e}, or                  write the whole experiment to another --output folder"
            ))),
            (None, Some(s)) => {
                let has_runs =
                    std::fs::metadata(self.path.join("runs.jsonl")).is_ok_and(|m| m.len() > 0);
                if has_runs {
                    return Err(HarnessError::Usage(format!(
                        "`{folder}` holds runs of the whole experiment; write shard {s} to                          another --output folder"
                    )));
                }
                write_replacing(&self.path.join(crate::SHARD_FILE), s.to_toml().as_bytes())
            }
            (None, None) => Ok(()),
        }
    }

    /// Rebuilds everything derived from the raw runs — one OMPL `.log` per instance, the
    /// Planner Arena database, the `figures` and `kpi.md`, each replaced atomically — from
    /// `results`, every run recorded in the folder. The raw files are the journal's and are
    /// not touched.
    ///
    /// # Errors
    /// Whatever cannot be written.
    pub fn finish(
        &mut self,
        results: &ExperimentResults,
        figures: Figures,
    ) -> Result<Vec<PathBuf>, HarnessError> {
        let mut files = vec![
            self.path.join("experiment.toml"),
            self.path.join("runs.csv"),
            self.path.join("runs.jsonl"),
        ];
        let fresh = self.path.join(format!("{DATABASE_FILE}.new"));
        for stale in [
            fresh.clone(),
            self.path.join(format!("{DATABASE_FILE}.new-journal")),
        ] {
            let _ = std::fs::remove_file(stale);
        }
        let mut database = PlannerArenaDatabase::open(&fresh)?;
        // One transaction for every instance (a file left unfinished by an error is never
        // renamed into place).
        database.begin()?;
        for (index, instance) in results.instances.iter().enumerate() {
            if results.runs[index].is_empty() {
                continue;
            }
            let log = BenchmarkLog::from_results(results, index);
            let path = self.path.join("logs").join(format!("{}.log", instance.id));
            write_replacing(&path, log.to_text().as_bytes())?;
            files.push(path);
            database.insert(&log)?;
        }
        database.commit()?;
        drop(database);
        let target = self.path.join(DATABASE_FILE);
        std::fs::rename(&fresh, &target).map_err(|source| HarnessError::Io {
            path: target.clone(),
            source,
        })?;
        self.database = PlannerArenaDatabase::open(&target)?;
        files.push(target);
        let scenes: Vec<Scene> = Scene::of(&results.instances)
            .into_iter()
            .filter(|s| s.instances.iter().any(|&i| !results.runs[i].is_empty()))
            .collect();
        if figures.any() {
            for scene in &scenes {
                let figure = ExperimentFigure::from_scene(results, scene);
                files.extend(self.save_figure(&figure, &scene.id)?);
                if figures.per_problem() && scene.instances.len() > 1 {
                    for &index in &scene.instances {
                        if !results.runs[index].is_empty() {
                            let figure = ExperimentFigure::from_results(results, index);
                            files.extend(self.save_figure(&figure, &results.instances[index].id)?);
                        }
                    }
                }
            }
        }
        let kpi = kpi_markdown(results, &KpiTable::from_results(results));
        let path = self.path.join("kpi.md");
        write_replacing(&path, kpi.as_bytes())?;
        files.push(path);
        files.extend(self.write_report(results, &scenes, kpi, figures)?);
        Ok(files)
    }

    /// Saves `figure` as `plots/<id>.svg` and `.png`; the two files.
    fn save_figure(
        &self,
        figure: &ExperimentFigure,
        id: &str,
    ) -> Result<[PathBuf; 2], HarnessError> {
        let svg = self.path.join("plots").join(format!("{id}.svg"));
        let png = svg.with_extension("png");
        figure.save(&svg, &png)?;
        Ok([svg, png])
    }

    /// Writes `report.html` (the KPI tables `kpi`, each scene's figure when `figures` asks for
    /// any, each instance's too with [`Figures::ScenesAndProblems`]) and the 3-D views they
    /// link to in `views/`: each scene's hardest instance (`hardest_instance`), and every
    /// instance with [`Figures::ScenesAndProblems`]; the files written.
    fn write_report(
        &self,
        results: &ExperimentResults,
        scenes: &[Scene],
        kpi: String,
        figures: Figures,
    ) -> Result<Vec<PathBuf>, HarnessError> {
        let mut files = Vec::new();
        let mut entries = Vec::with_capacity(scenes.len());
        let view_of = |index: usize, files: &mut Vec<PathBuf>| {
            let id = &results.instances[index].id;
            let link = format!("views/{id}.html");
            let page = self.path.join(&link);
            writable_folder(&self.path.join("views"))?;
            let written = write_instance_view(results, index, &page)?;
            if written.is_some() && !files.contains(&page) {
                files.push(page);
            }
            Ok::<_, HarnessError>(written.map(|what| (link, what)))
        };
        for scene in scenes {
            let mut view = None;
            if figures.any() {
                let hardest = hardest_instance(results, &scene.instances);
                view = view_of(hardest, &mut files)?;
                if scene.instances.len() > 1
                    && let Some((_, what)) = &mut view
                {
                    let noun = if scene.arm { "problem" } else { "layout" };
                    *what = format!(
                        "its hardest {noun}, {}: {what}",
                        results.instances[hardest].title()
                    );
                }
            }
            entries.push(ReportInstance {
                title: scene.title.clone(),
                figure: figures.any().then(|| format!("plots/{}.svg", scene.id)),
                view,
            });
            if figures.per_problem() && scene.instances.len() > 1 {
                for &index in &scene.instances {
                    if results.runs[index].is_empty() {
                        continue;
                    }
                    let instance = &results.instances[index];
                    entries.push(ReportInstance {
                        title: instance.title(),
                        figure: Some(format!("plots/{}.svg", instance.id)),
                        view: view_of(index, &mut files)?,
                    });
                }
            }
        }
        if files.iter().any(|f| f.starts_with(self.path.join("views"))) {
            let viewer = self.path.join("views").join(VIEWER_FILE);
            write_replacing(&viewer, mit_star_view::viewer_script().as_bytes())?;
            files.push(viewer);
        }
        let page = ReportPage {
            title: results.experiment.name.clone(),
            kpi_markdown: kpi,
            instances: entries,
        };
        let path = self.path.join("report.html");
        write_replacing(&path, page.to_html().as_bytes())?;
        files.push(path);
        Ok(files)
    }
}

/// The hardest of `indices` that has a path to show: an instance with a path that failed the
/// validation if there is one, else, among those with a solved run, the one with the greatest
/// median time to the first solution over all its runs (failed runs count as `∞`; the first
/// such instance on ties); the first of `indices` if no run solved.
pub(crate) fn hardest_instance(results: &ExperimentResults, indices: &[usize]) -> usize {
    let invalid = indices.iter().copied().find(|&i| {
        results.runs[i]
            .iter()
            .any(|r| r.status == crate::RunStatus::InvalidPath)
    });
    invalid.unwrap_or_else(|| {
        let median = |i: usize| {
            let times: Vec<f64> = results.runs[i]
                .iter()
                .map(|r| r.initial_time_or_inf())
                .collect();
            crate::statistics::MedianEstimate::of(&times, 0.5)
                .map_or(f64::NEG_INFINITY, |m| m.median)
        };
        let solved = |i: &usize| results.runs[*i].iter().any(RunRecord::is_success);
        let mut hardest: Option<usize> = None;
        for i in indices.iter().copied().filter(solved) {
            if hardest.is_none_or(|h| median(i) > median(h)) {
                hardest = Some(i);
            }
        }
        hardest.unwrap_or(indices[0])
    })
}

/// Writes `bytes` to `path` by writing a temporary file beside it and renaming it over
/// `path`: a reader (or a crash) sees the old file or the new one, never half of one.
///
/// # Errors
/// [`HarnessError::Io`] naming the file.
pub(crate) fn write_replacing(path: &Path, bytes: &[u8]) -> Result<(), HarnessError> {
    let mut temporary = path.as_os_str().to_owned();
    temporary.push(".new");
    let temporary = PathBuf::from(temporary);
    std::fs::write(&temporary, bytes)
        .and_then(|()| std::fs::rename(&temporary, path))
        .map_err(|source| HarnessError::Io {
            path: path.to_path_buf(),
            source,
        })
}

/// Creates `path` if needed and checks that a file can be written in it.
///
/// # Errors
/// [`HarnessError::OutputFolder`] naming the folder and the operating system's reason.
pub fn writable_folder(path: &Path) -> Result<(), HarnessError> {
    let fail = |source| HarnessError::OutputFolder {
        path: path.to_path_buf(),
        source,
    };
    std::fs::create_dir_all(path).map_err(fail)?;
    let probe = path.join(".mit-star-write-test");
    std::fs::write(&probe, b"ok").map_err(fail)?;
    std::fs::remove_file(&probe).map_err(fail)
}

/// `kpi.md`: how the experiment ran, the summary by scene, then the paper-style table, the
/// problems with several layouts and the full table.
pub fn kpi_markdown(results: &ExperimentResults, table: &KpiTable) -> String {
    let mut s = kpi_overview(results, table, false);
    if let Some(families) = table.families_markdown() {
        let _ = writeln!(
            s,
            "## Problems with several layouts\n\nEvery layout pooled (a MotionBenchMaker scene's \
             problems, random rectangles' seeds); failed runs count as ∞.\n\n{families}"
        );
    }
    let _ = writeln!(
        s,
        "## All KPIs\n\nmin, median [{:.0} % confidence interval], max.\n\n{}",
        100.0 * table.confidence,
        table.full_markdown()
    );
    s
}

/// The head of `kpi.md`, what `bench` prints by default: how the experiment ran (point
/// clouds and invalid paths included), the summary by scene ([`SceneSummary`]), and the
/// medians in the paper's Table I layout — always in `kpi.md` (`brief` false), and with
/// `brief` only when it has the t_init gain column (MIT* and EIT* both ran), one row per
/// scene.
pub fn kpi_overview(results: &ExperimentResults, table: &KpiTable, brief: bool) -> String {
    let e = &results.experiment;
    let mut s = format!("# {}\n\n", e.name);
    if !e.description.is_empty() {
        let _ = writeln!(s, "{}\n", e.description);
    }
    let planned = results.instances.len() * e.planners.len() * e.runs;
    let _ = writeln!(
        s,
        "Started {} UTC on `{}` ({}); {} runs per planner and instance, seeds {}..{} on the first \
         instance and {} higher on each next one; {} of {planned} runs recorded; the last \
         `bench` took {:.1} s with **{} runs executing concurrently**.{}\n",
        results.started_at,
        results.machine.hostname,
        results.machine.cpu,
        e.runs,
        e.seed,
        e.seed.saturating_add(e.runs as u64).saturating_sub(1),
        crate::INSTANCE_SEED_STRIDE,
        results.run_count(),
        results.total_time,
        results.concurrency,
        if results.interrupted {
            " **Interrupted (SIGINT or SIGTERM): only finished runs are included.**"
        } else {
            ""
        }
    );
    if let Some(clouds) = cloud_markdown(results) {
        s.push_str(&clouds);
    }
    let invalid = results.invalid_runs();
    if !invalid.is_empty() {
        let _ = writeln!(
            s,
            "**WARNING: {} runs returned a path that failed the independent full-resolution \
             validation; they count as failures:**\n",
            invalid.len()
        );
        for r in invalid {
            let _ = writeln!(
                s,
                "- {} run {} (seed {}) on {}: {}",
                r.planner,
                r.run,
                r.seed,
                r.instance,
                r.validation
                    .as_ref()
                    .and_then(|v| v.failure.clone())
                    .unwrap_or_default()
            );
        }
        s.push('\n');
    }
    let summary = SceneSummary::from_results(results);
    let _ = writeln!(
        s,
        "## Summary by {}\n\n{}Failed runs count as ∞. Planning includes construction; the \
         independent audit of a path is timed apart, in no planner's time.\n\n{}",
        if summary.pooled { "scene" } else { "problem" },
        if summary.pooled {
            "A planner's runs on every instance of a scene (its problems, or a problem's \
             layouts) pooled. "
        } else {
            ""
        },
        summary.markdown()
    );
    if !brief || table.has_gain() {
        let _ = writeln!(
            s,
            "## Medians (paper's Table I layout)\n\nMedian time to the first solution `t_init` [s], \
             median first-solution cost `c_init`, median final cost `c_final`; failed runs count \
             as ∞. t_init gain = 1 − t_MIT / t_EIT.\n\n{}",
            table.paper_markdown()
        );
    }
    s
}

/// The `## Point clouds` section of `kpi.md`: one row per instance planned among a cloud,
/// with its points before and after the filters and the time to prepare it; `None` without
/// a cloud.
fn cloud_markdown(results: &ExperimentResults) -> Option<String> {
    let rows: Vec<String> = results
        .instances
        .iter()
        .filter_map(|i| {
            i.cloud.as_ref().map(|c| {
                format!(
                    "| {} | {} | {} | {:.1} | {:.2} | {:.2} |",
                    i.id,
                    c.input_points,
                    c.points,
                    c.radius * 1e3,
                    c.prepare_seconds * 1e3,
                    c.build_seconds * 1e3
                )
            })
        })
        .collect();
    if rows.is_empty() {
        return None;
    }
    Some(format!(
        "## Point clouds\n\nEach instance's cloud was prepared once, when the last `bench` built \
         its instances, before any run; the time is not counted in any planner's. Every \
         returned path is validated against every point of the cloud (the independent \
         continuous audit). The steps are in each instance's log (`logs/<instance>.log`).\n\n\
         | instance | points read or sampled | points kept | radius [mm] | read, sample and \
         filter [ms] | tree built [ms] |\n|---|---:|---:|---:|---:|---:|\n{}\n\n",
        rows.join("\n")
    ))
}

/// What differs between the folder's `experiment.toml` (`existing`) and the experiment as
/// defined now (`now`), line by line: `runs = 10 in the folder, runs = 20 now`; at most three
/// differences, each line cut short.
fn differences(existing: &str, now: &str) -> String {
    let (old, new): (Vec<&str>, Vec<&str>) = (existing.lines().collect(), now.lines().collect());
    let only_old: Vec<&str> = old.iter().filter(|l| !new.contains(l)).copied().collect();
    let only_new: Vec<&str> = new.iter().filter(|l| !old.contains(l)).copied().collect();
    fn key(line: &str) -> Option<&str> {
        line.split_once(" = ").map(|(k, _)| k.trim())
    }
    fn quote(line: &str) -> String {
        format!("`{}`", mit_star_problems::excerpt(line.trim(), 100))
    }
    let mut said = Vec::new();
    let mut used = vec![false; only_new.len()];
    for &line in &only_old {
        let partner = (0..only_new.len())
            .find(|&i| !used[i] && key(only_new[i]).is_some() && key(only_new[i]) == key(line));
        match partner {
            Some(i) => {
                used[i] = true;
                said.push(format!(
                    "{} in the folder, {} now",
                    quote(line),
                    quote(only_new[i])
                ));
            }
            None => said.push(format!("{} in the folder only", quote(line))),
        }
    }
    for (i, &line) in only_new.iter().enumerate() {
        if !used[i] {
            said.push(format!("{} now only", quote(line)));
        }
    }
    let total = said.len();
    if total == 0 {
        return "the same lines in another order".to_owned();
    }
    said.truncate(3);
    let more = if total > 3 {
        format!(" and {} more differences", total - 3)
    } else {
        String::new()
    };
    format!("differs: {}{more}", said.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("mit-star-folder-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn a_folder_holds_one_experiment() {
        let dir = scratch("claim");
        let folder = ResultsFolder::prepare(&dir).unwrap();
        let smoke = Experiment::shipped("smoke").unwrap();
        let toml = folder.claim(&smoke).unwrap();
        let written = std::fs::read_to_string(&toml).unwrap();
        folder.claim(&smoke).unwrap();
        let mut other = smoke.clone();
        other.runs += 1;
        let message = folder.claim(&other).unwrap_err().to_string();
        assert!(
            message.contains("holds the results of experiment `smoke`"),
            "{message}"
        );
        assert_eq!(
            std::fs::read_to_string(&toml).unwrap(),
            written,
            "not clobbered"
        );

        std::fs::remove_file(&toml).unwrap();
        std::fs::write(dir.join("runs.csv"), "instance\n").unwrap();
        let message = folder.claim(&smoke).unwrap_err().to_string();
        assert!(
            message.contains("holds runs but no experiment.toml"),
            "{message}"
        );
        assert!(!toml.exists());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn replacing_a_file_leaves_no_temporary() {
        let dir = scratch("replace");
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("kpi.md");
        write_replacing(&path, b"old").unwrap();
        write_replacing(&path, b"new").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new");
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
