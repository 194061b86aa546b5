//! The Panda's first `cage` problem and MIT*'s batches on it until its first solution, shared
//! by the tests of the defaults arm problems choose.

// Each test binary includes this file and uses a subset.
#![allow(dead_code)]

use std::path::Path;
use std::sync::{Arc, Mutex};

use mit_star::{
    BatchEvent, Connection, FirstSolution, MitStar, Observer, Planner, TerminationExt, TimeLimit,
};
use mit_star_robot::ArmProblem;

/// The Panda's first MotionBenchMaker `cage` problem (the copy under `tests/data`).
pub(crate) fn cage() -> ArmProblem {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm/cage_panda");
    ArmProblem::panda_mbm(&folder, 1).unwrap()
}

/// Records each batch's event.
struct Batches(Arc<Mutex<Vec<BatchEvent>>>);

impl Observer for Batches {
    fn on_batch(&mut self, event: &BatchEvent) {
        self.0.lock().unwrap().push(*event);
    }
}

/// The batches of MIT* (the library's builder for the cage, seed 1) until its first solution,
/// with the connection rule, the batch size and the batch growth set where given.
pub(crate) fn batches(
    connection: Option<Connection>,
    batch_size: Option<usize>,
    batch_growth: Option<f64>,
) -> Vec<BatchEvent> {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let mut builder = MitStar::for_problem(&cage())
        .seed(1)
        .observer(Box::new(Batches(Arc::clone(&seen))));
    if let Some(connection) = connection {
        builder = builder.connection(connection);
    }
    if let Some(batch_size) = batch_size {
        builder = builder.batch_size(batch_size);
    }
    if let Some(growth) = batch_growth {
        builder = builder.batch_growth(growth);
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
