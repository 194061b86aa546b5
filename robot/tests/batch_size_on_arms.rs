//! Arm problems ask the EIT* family for batches of [`ArmProblem::BATCH_SIZE`] samples, growing
//! with the graph by [`ArmProblem::BATCH_GROWTH`]; box worlds keep the papers' fixed 100, and a
//! set `batch_size` or `batch_growth` wins over either.

use mit_star::{BatchEvent, Configuration, Parameters};
use mit_star_problems::{PAPER_BATCH_SIZE, PlanningProblem};
use mit_star_robot::ArmProblem;

use crate::cage_batches;
use cage_batches::{batches, cage};

#[test]
fn arm_problems_sample_smaller_growing_batches_unless_told_otherwise() {
    let arm = cage();
    assert_eq!(arm.batch_size(), ArmProblem::BATCH_SIZE);
    assert_eq!(arm.batch_growth(), ArmProblem::BATCH_GROWTH);
    const { assert!(ArmProblem::BATCH_SIZE < PAPER_BATCH_SIZE && ArmProblem::BATCH_GROWTH > 0.0) };
    let boxes = mit_star_problems::DividingWalls::new(2).build().unwrap();
    assert_eq!(
        (boxes.batch_size(), boxes.batch_growth()),
        (PAPER_BATCH_SIZE, 0.0)
    );
    let defaults = Parameters::default();
    assert_eq!((defaults.batch_size, defaults.batch_growth), (None, None));
    assert_eq!(defaults.samples_per_batch(), PAPER_BATCH_SIZE);
    assert_eq!(defaults.grown_batch(1_000_000), 0);
    // Set values are kept on either problem, the papers' included.
    let set = Parameters {
        batch_size: Some(PAPER_BATCH_SIZE),
        batch_growth: Some(0.0),
        ..Parameters::default()
    };
    for configuration in [
        Configuration::MitStar,
        Configuration::EitStar,
        Configuration::AitStar,
        Configuration::BitStar,
    ] {
        let arm_batches = (Some(ArmProblem::BATCH_SIZE), Some(ArmProblem::BATCH_GROWTH));
        let on_arm = batch_rule(configuration, &arm, &defaults);
        assert_eq!(on_arm, arm_batches, "{configuration}");
        let papers = (Some(PAPER_BATCH_SIZE), Some(0.0));
        let in_boxes = batch_rule(configuration, &boxes, &defaults);
        assert_eq!(in_boxes, papers, "{configuration}");
        let kept = batch_rule(configuration, &arm, &set);
        assert_eq!(kept, papers, "{configuration}");
    }
}

/// The batch size and growth `configuration` runs with on `problem` given `parameters`.
fn batch_rule<P: PlanningProblem>(
    configuration: Configuration,
    problem: &P,
    parameters: &Parameters,
) -> (Option<usize>, Option<f64>) {
    let effective = configuration
        .effective_parameters(problem, parameters)
        .unwrap();
    (effective.batch_size, effective.batch_growth)
}

/// `true` if every batch of `events` holds `base` samples or `growth` of the vertices the
/// graph had before it, whichever is more.
fn sized_by(events: &[BatchEvent], base: usize, growth: f64) -> bool {
    events.iter().all(|b| {
        let before = b.vertices - b.samples;
        b.samples == base.max((growth * before as f64).ceil() as usize)
    })
}

#[test]
fn the_planner_samples_the_problems_batch_size_or_the_one_it_is_given() {
    // Every batch before the first solution is a full one (the sampler never runs dry on
    // the cage), so the counts are exactly the batch sizes.
    let default = batches(None, None, None);
    assert!(
        sized_by(&default, ArmProblem::BATCH_SIZE, ArmProblem::BATCH_GROWTH),
        "{default:?}"
    );
    let set = batches(None, Some(PAPER_BATCH_SIZE), Some(0.0));
    assert!(set.iter().all(|b| b.samples == PAPER_BATCH_SIZE), "{set:?}");
}

#[test]
fn the_planner_grows_its_batches_by_the_fraction_it_is_given() {
    // With half the graph, batches grow from the third on (a graph of 100 vertices); the
    // cage's first solution takes more batches than that.
    let grown = batches(None, None, Some(0.5));
    assert!(sized_by(&grown, ArmProblem::BATCH_SIZE, 0.5), "{grown:?}");
    assert!(
        grown.iter().any(|b| b.samples > ArmProblem::BATCH_SIZE),
        "{grown:?}"
    );
    // No growth: every batch holds the batch size.
    let fixed = batches(None, None, Some(0.0));
    assert!(
        fixed.iter().all(|b| b.samples == ArmProblem::BATCH_SIZE),
        "{fixed:?}"
    );
}
