//! Arm problems ask the EIT* family to join samples within the r-disc radius
//! ([`ArmProblem::RADIUS_CONNECTION`]); box worlds keep the paper's k-nearest, and a set
//! `connection` wins over either.

use std::path::Path;
use std::sync::{Arc, Mutex};

use mit_star::{
    BatchEvent, Configuration, Connection, FirstSolution, MitStar, Observer, Parameters, Planner,
    TerminationExt, TimeLimit,
};
use problems::PlanningProblem;
use robot::ArmProblem;
use spaces::StateSpace;

fn cage() -> ArmProblem {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mbm/cage_panda");
    ArmProblem::panda_mbm(&folder, 1).unwrap()
}

/// Records each batch's connection parameter.
struct Batches(Arc<Mutex<Vec<f64>>>);

impl Observer for Batches {
    fn on_batch(&mut self, event: &BatchEvent) {
        self.0.lock().unwrap().push(event.connection);
    }
}

/// The connection parameters of the batches of MIT* (the library's builder for the cage)
/// with `connection`, until its first solution.
fn batches(connection: Option<Connection>) -> Vec<f64> {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let mut builder = MitStar::for_problem(&cage())
        .seed(1)
        .observer(Box::new(Batches(Arc::clone(&seen))));
    if let Some(connection) = connection {
        builder = builder.connection(connection);
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
fn arm_problems_connect_by_radius_unless_told_otherwise() {
    let arm = cage();
    assert!(arm.radius_connection());
    let boxes = problems::DividingWalls::new(2).build().unwrap();
    assert!(!boxes.radius_connection());
    let defaults = Parameters::default();
    assert_eq!(defaults.connection, None);
    for configuration in [
        Configuration::MitStar,
        Configuration::EitStar,
        Configuration::AitStar,
    ] {
        let on_arm = configuration.effective_parameters(&arm, &defaults).unwrap();
        assert_eq!(
            on_arm.connection,
            Some(Connection::RDisc),
            "{configuration}"
        );
        let in_boxes = configuration
            .effective_parameters(&boxes, &defaults)
            .unwrap();
        assert_eq!(
            in_boxes.connection,
            Some(Connection::KNearest),
            "{configuration}"
        );
        let set = Parameters {
            connection: Some(Connection::KNearest),
            ..Parameters::default()
        };
        let kept = configuration.effective_parameters(&arm, &set).unwrap();
        assert_eq!(kept.connection, Some(Connection::KNearest));
    }
    // The planner built for the arm joins by radius: each batch's connection parameter is a
    // radius below the space's extent, not the k of k-nearest; told otherwise, it is that k.
    let extent = arm.space().maximum_extent();
    for radius in batches(None) {
        assert!(radius > 0.0 && radius < extent, "radius {radius}");
        assert!(radius.fract() != 0.0, "radius {radius} looks like a k");
    }
    for k in batches(Some(Connection::KNearest)) {
        assert!(k >= 1.0 && k.fract() == 0.0, "k {k}");
    }
}
