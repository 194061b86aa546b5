//! Arm problems ask the EIT* family for batches of [`ArmProblem::BATCH_SIZE`] samples; box
//! worlds keep the papers' 100, and a set `batch_size` wins over either.

use mit_star::{Configuration, Parameters};
use problems::{PAPER_BATCH_SIZE, PlanningProblem};
use robot::ArmProblem;

#[path = "support/cage_batches.rs"]
mod cage_batches;
use cage_batches::{batches, cage};

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
    let default = batches(None, None);
    assert!(
        default.iter().all(|b| b.samples == ArmProblem::BATCH_SIZE),
        "{default:?}"
    );
    let set = batches(None, Some(PAPER_BATCH_SIZE));
    assert!(set.iter().all(|b| b.samples == PAPER_BATCH_SIZE), "{set:?}");
}
