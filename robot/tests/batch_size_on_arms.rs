//! Arm problems ask the EIT* family for batches of [`ArmProblem::BATCH_SIZE`] samples; box
//! worlds keep the papers' 100, and a set `batch_size` wins over either.

use std::path::Path;
use std::sync::{Arc, Mutex};

use mit_star::{
    BatchEvent, Configuration, FirstSolution, MitStar, Observer, Parameters, Planner,
    TerminationExt, TimeLimit,
};
use problems::{PAPER_BATCH_SIZE, PlanningProblem};
use robot::ArmProblem;

fn cage() -> ArmProblem {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm/cage_panda");
    ArmProblem::panda_mbm(&folder, 1).unwrap()
}

/// Records each batch's number of new samples.
struct Batches(Arc<Mutex<Vec<usize>>>);

impl Observer for Batches {
    fn on_batch(&mut self, event: &BatchEvent) {
        self.0.lock().unwrap().push(event.samples);
    }
}

/// The sizes of the batches MIT* (the library's builder for the cage, seed 1) samples until
/// its first solution, with `batch_size` set or not.
fn batches(batch_size: Option<usize>) -> Vec<usize> {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let mut builder = MitStar::for_problem(&cage())
        .seed(1)
        .observer(Box::new(Batches(Arc::clone(&seen))));
    if let Some(batch_size) = batch_size {
        builder = builder.batch_size(batch_size);
    }
    let mut planner = builder.build().unwrap();
    let outcome = planner
        .solve(&FirstSolution.or(TimeLimit::seconds(20.0)))
        .unwrap();
    assert!(outcome.solution().is_some(), "cage #1 unsolved in 20 s");
    let seen = seen.lock().unwrap().clone();
    assert!(!seen.is_empty(), "no batch before the first solution");
    seen
}

#[test]
fn arm_problems_sample_smaller_batches_unless_told_otherwise() {
    let arm = cage();
    assert_eq!(arm.batch_size(), ArmProblem::BATCH_SIZE);
    const { assert!(ArmProblem::BATCH_SIZE < PAPER_BATCH_SIZE) };
    let boxes = problems::DividingWalls::new(2).build().unwrap();
    assert_eq!(boxes.batch_size(), PAPER_BATCH_SIZE);
    let defaults = Parameters::default();
    assert_eq!(defaults.batch_size, None);
    assert_eq!(defaults.samples_per_batch(), PAPER_BATCH_SIZE);
    for configuration in [
        Configuration::MitStar,
        Configuration::EitStar,
        Configuration::AitStar,
        Configuration::BitStar,
    ] {
        let on_arm = configuration.effective_parameters(&arm, &defaults).unwrap();
        assert_eq!(
            on_arm.batch_size,
            Some(ArmProblem::BATCH_SIZE),
            "{configuration}"
        );
        let in_boxes = configuration
            .effective_parameters(&boxes, &defaults)
            .unwrap();
        assert_eq!(
            in_boxes.batch_size,
            Some(PAPER_BATCH_SIZE),
            "{configuration}"
        );
        // A set batch size is kept on either problem, the papers' value included.
        let set = Parameters {
            batch_size: Some(PAPER_BATCH_SIZE),
            ..Parameters::default()
        };
        let kept = configuration.effective_parameters(&arm, &set).unwrap();
        assert_eq!(kept.batch_size, Some(PAPER_BATCH_SIZE), "{configuration}");
    }
}

#[test]
fn the_planner_samples_the_problems_batch_size_or_the_one_it_is_given() {
    // Every batch before the first solution is a full one (the sampler never runs dry on
    // the cage), so the counts are exactly the batch sizes.
    let default = batches(None);
    assert!(
        default.iter().all(|&n| n == ArmProblem::BATCH_SIZE),
        "{default:?}"
    );
    let set = batches(Some(PAPER_BATCH_SIZE));
    assert!(set.iter().all(|&n| n == PAPER_BATCH_SIZE), "{set:?}");
}
