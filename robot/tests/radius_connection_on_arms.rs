//! Arm problems ask the EIT* family to join samples within the r-disc radius
//! ([`ArmProblem::RADIUS_CONNECTION`]); box worlds keep the paper's k-nearest, and a set
//! `connection` wins over either.

use mit_star::{Configuration, Connection, Parameters};
use mit_star_problems::PlanningProblem;
use mit_star_spaces::StateSpace;

use crate::cage_batches;
use cage_batches::{batches, cage};

#[test]
fn arm_problems_connect_by_radius_unless_told_otherwise() {
    let arm = cage();
    assert!(arm.radius_connection());
    let boxes = mit_star_problems::DividingWalls::new(2).build().unwrap();
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
    for radius in batches(None, None, None).iter().map(|b| b.connection) {
        assert!(radius > 0.0 && radius < extent, "radius {radius}");
        assert!(radius.fract() != 0.0, "radius {radius} looks like a k");
    }
    for k in batches(Some(Connection::KNearest), None, None)
        .iter()
        .map(|b| b.connection)
    {
        assert!(k >= 1.0 && k.fract() == 0.0, "k {k}");
    }
}
