//! The 3-D views an experiment report links to: per problem instance, its best and its worst
//! run (`views/<instance>.html`).

use std::path::Path;

use crate::error::HarnessError;
use crate::formats::kpi_table::number;
use crate::outcome::experiment_results::ExperimentResults;
use crate::outcome::run_record::{RunRecord, RunStatus};
use crate::pictures::plan_view::PlanView;

/// The viewer the views of an experiment share, written once beside them in `views/`.
pub(crate) const VIEWER_FILE: &str = "viewer.js";

/// About how many frames each path of an experiment's view is cut into.
const REPORT_FRAMES: usize = 120;

/// The runs an instance's view shows: the solved run of least final cost, and the worst — a
/// run whose path failed the validation if there is one, else the solved run of greatest
/// final cost (when it is another run).
pub(crate) fn best_and_worst(runs: &[RunRecord]) -> (Option<&RunRecord>, Option<&RunRecord>) {
    let cost = |r: &&RunRecord| r.final_cost.unwrap_or(f64::INFINITY);
    let solved = || {
        runs.iter()
            .filter(|r| r.status == RunStatus::Solved && r.path.len() >= 2)
    };
    let best = solved().min_by(|a, b| cost(a).total_cmp(&cost(b)));
    let worst = runs
        .iter()
        .find(|r| r.status == RunStatus::InvalidPath && !r.path.is_empty())
        .or_else(|| solved().max_by(|a, b| cost(a).total_cmp(&cost(b))))
        .filter(|w| best.is_none_or(|b| !std::ptr::eq(*w, b)));
    (best, worst)
}

/// Writes the view of instance `index` of `results` to `page` (loading the viewer from
/// [`VIEWER_FILE`] beside it): its best and worst run, the robot as spheres. What
/// the view shows in a few words, or `None` when there is nothing to show (no solved run, or
/// a box world of more than three dimensions).
///
/// # Errors
/// [`HarnessError::View`] if the page cannot be written.
pub(crate) fn write_instance_view(
    results: &ExperimentResults,
    index: usize,
    page: &Path,
) -> Result<Option<String>, HarnessError> {
    let instance = &results.instances[index];
    let (best, worst) = best_and_worst(&results.runs[index]);
    let Some(best) = best else {
        return Ok(None);
    };
    let Ok(mut view) = PlanView::new(&instance.problem, instance.title(), None) else {
        return Ok(None);
    };
    // An experiment may have hundreds of instances: 120 frames a path keep a UR5 view of two
    // runs near 0.2 MB (the viewer is shared; playing interpolates between frames).
    view.frames_per_path(REPORT_FRAMES);
    if instance.mesh_resolver().is_some() {
        view.note(
            "the robot is drawn as its collision spheres: an experiment's views leave the \
             meshes out to keep the folder small (`mit-star plan --view` draws them)",
        );
    }
    let label = |what: &str, r: &RunRecord| {
        format!(
            "{what}: {} seed {}, cost {}{}",
            r.planner,
            r.seed,
            number(r.final_cost.unwrap_or(f64::INFINITY)),
            if r.status == RunStatus::InvalidPath {
                " (INVALID PATH)"
            } else {
                ""
            }
        )
    };
    let runs = results.runs[index].len();
    view.subtitle(format!(
        "{} of {runs} runs; the best and the worst of them",
        results.runs[index]
            .iter()
            .filter(|r| r.status == RunStatus::Solved)
            .count()
    ));
    view.path(label("best", best), &best.path);
    let mut what = "best run".to_owned();
    if let Some(worst) = worst {
        view.path(label("worst", worst), &worst.path);
        what.push_str(" and worst run");
    }
    view.write_with(page, mit_star_view::Viewer::Beside(VIEWER_FILE))?;
    Ok(Some(what))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(status: RunStatus, cost: Option<f64>) -> RunRecord {
        let mut r = RunRecord::example(status);
        r.final_cost = cost;
        r.path = if cost.is_some() {
            vec![vec![0.0, 0.0], vec![1.0, 1.0]]
        } else {
            Vec::new()
        };
        r
    }

    #[test]
    fn best_is_the_cheapest_solved_and_worst_an_invalid_path_first() {
        let runs = vec![
            run(RunStatus::Solved, Some(2.0)),
            run(RunStatus::Unsolved, None),
            run(RunStatus::Solved, Some(1.5)),
            run(RunStatus::Solved, Some(3.0)),
        ];
        let (best, worst) = best_and_worst(&runs);
        assert_eq!(best.unwrap().final_cost, Some(1.5));
        assert_eq!(worst.unwrap().final_cost, Some(3.0));
        let mut with_invalid = runs.clone();
        with_invalid.push(run(RunStatus::InvalidPath, Some(1.0)));
        let (_, worst) = best_and_worst(&with_invalid);
        assert_eq!(worst.unwrap().status, RunStatus::InvalidPath);
        let one = vec![run(RunStatus::Solved, Some(2.0))];
        assert!(
            best_and_worst(&one).1.is_none(),
            "one run is not its own worst"
        );
        assert_eq!(
            best_and_worst(&[run(RunStatus::Unsolved, None)]),
            (None, None)
        );
    }
}
