//! An edge with a non-finite end (a NaN, `+inf` or `-inf` coordinate) is never valid: every
//! checker (dense, fixed sparse, length adaptive), sparse and full checks, accelerated or not,
//! from either end, answers [`EdgeStatus::Invalid`], remembers it in the edge's progress, and
//! nothing panics. So does an edge whose length overflows (finite ends 2e308 apart): it has no
//! grid to test.

use mit_star_spaces::{Never, RealVectorSpace};
use mit_star_validity::{
    AllValid, AxisBox, DenseChecker, EdgeChecker, EdgeProgress, EdgeStatus, FixedSparseChecker,
    LengthAdaptiveChecker, StateValidity, World,
};

/// Every checker at `step`, with acceleration on and off, named.
fn checkers<V: StateValidity>(
    step: f64,
) -> Vec<(String, Box<dyn EdgeChecker<RealVectorSpace, V>>)> {
    let mut all: Vec<(String, Box<dyn EdgeChecker<RealVectorSpace, V>>)> = Vec::new();
    for accelerated in [true, false] {
        let tag = if accelerated {
            "accelerated"
        } else {
            "one by one"
        };
        all.push((
            format!("dense, {tag}"),
            Box::new(
                DenseChecker::new(step)
                    .unwrap()
                    .with_acceleration(accelerated),
            ),
        ));
        all.push((
            format!("fixed sparse, {tag}"),
            Box::new(
                FixedSparseChecker::new(step)
                    .unwrap()
                    .with_acceleration(accelerated),
            ),
        ));
        all.push((
            format!("length adaptive, {tag}"),
            Box::new(
                LengthAdaptiveChecker::new(step)
                    .unwrap()
                    .with_acceleration(accelerated),
            ),
        ));
    }
    all
}

/// Edges of `n`-dimensional states with at least one non-finite coordinate: each special value
/// at each coordinate of either end, and both ends spoilt.
fn spoilt_edges(n: usize) -> Vec<(Vec<f64>, Vec<f64>)> {
    let good_a: Vec<f64> = (0..n).map(|d| 0.1 + 0.05 * d as f64).collect();
    let good_b: Vec<f64> = (0..n).map(|d| -0.2 + 0.03 * d as f64).collect();
    let mut edges = Vec::new();
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for d in 0..n {
            let mut a = good_a.clone();
            a[d] = bad;
            edges.push((a.clone(), good_b.clone()));
            edges.push((good_b.clone(), a.clone()));
            let mut b = good_b.clone();
            b[d] = -bad;
            edges.push((a, b));
        }
        edges.push((vec![bad; n], vec![bad; n]));
        edges.push((vec![bad; n], good_a.clone()));
    }
    edges
}

/// Runs every check kind of every checker on every spoilt edge against `validity`; returns the
/// number of checks made and a line for each that did not refuse the edge.
fn checks_not_refusing<V: StateValidity>(validity: &V, n: usize) -> (usize, Vec<String>) {
    let space = RealVectorSpace::cube(n, -0.5, 0.5).unwrap();
    let (mut checks, mut failures) = (0, Vec::new());
    for (a, b) in spoilt_edges(n) {
        for (name, mut checker) in checkers::<V>(1e-3) {
            // A full check from nothing, a sparse one, and a full one after the sparse one.
            let mut progress = EdgeProgress::default();
            let full = checker.check_full(&space, validity, &a, &b, &mut progress, &Never);
            let mut sparse_progress = EdgeProgress::default();
            let sparse =
                checker.check_sparse(&space, validity, &a, &b, &mut sparse_progress, &Never);
            let after = checker.check_full(&space, validity, &b, &a, &mut sparse_progress, &Never);
            for (kind, status, progress) in [
                ("full", full, progress),
                ("sparse", sparse, sparse_progress),
                ("full after sparse", after, sparse_progress),
            ] {
                checks += 1;
                if status != EdgeStatus::Invalid || !progress.is_invalid() {
                    failures.push(format!(
                        "{name}, {kind} check of {a:?} → {b:?}: {status:?}, {progress:?}"
                    ));
                }
            }
        }
    }
    (checks, failures)
}

/// Fails with the count and the list of the checks that did not refuse.
fn assert_all_refused(results: impl IntoIterator<Item = (usize, Vec<String>)>) {
    let (mut checks, mut failures) = (0, Vec::new());
    for (made, failed) in results {
        checks += made;
        failures.extend(failed);
    }
    assert!(
        failures.is_empty(),
        "{} of {checks} checks did not refuse a non-finite edge:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn non_finite_ends_are_invalid_in_an_empty_world() {
    assert_all_refused((1..=3).map(|n| checks_not_refusing(&AllValid, n)));
}

#[test]
fn non_finite_ends_are_invalid_in_a_box_world() {
    assert_all_refused((1..=3).map(|n| {
        let world = World::new(vec![-0.5; n], vec![0.5; n])
            .with_obstacle(AxisBox::cube(vec![0.3; n], 0.05))
            .unwrap()
            .with_anti_obstacle(AxisBox::cube(vec![0.3; n], 0.01))
            .unwrap();
        checks_not_refusing(&world, n)
    }));
}

/// Finite ends whose distance overflows to infinity: no grid can be built, so the edge cannot
/// be shown valid.
#[test]
fn an_edge_whose_length_overflows_is_invalid() {
    let space = RealVectorSpace::cube(2, -0.5, 0.5).unwrap();
    let (a, b) = ([-1e308, 0.0], [1e308, 0.0]);
    for (name, mut checker) in checkers::<AllValid>(1e-3) {
        let mut progress = EdgeProgress::default();
        let full = checker.check_full(&space, &AllValid, &a, &b, &mut progress, &Never);
        let mut sparse_progress = EdgeProgress::default();
        let sparse = checker.check_sparse(&space, &AllValid, &a, &b, &mut sparse_progress, &Never);
        assert_eq!(
            (full, sparse),
            (EdgeStatus::Invalid, EdgeStatus::Invalid),
            "{name}"
        );
    }
}

/// Certification refuses non-finite edges too (a box world's exact test calls them
/// malformed; a checker without one must not certify a grid of nothing).
#[test]
fn certification_refuses_non_finite_edges() {
    let space = RealVectorSpace::cube(2, -0.5, 0.5).unwrap();
    let world = World::in_space(&space);
    for (a, b) in spoilt_edges(2) {
        for (name, mut checker) in checkers::<AllValid>(1e-3) {
            let status = checker.certify(&space, &AllValid, &a, &b, 4, &Never);
            assert_eq!(status, EdgeStatus::Invalid, "{name}: {a:?} → {b:?}");
        }
        for (name, mut checker) in checkers::<World>(1e-3) {
            let status = checker.certify(&space, &world, &a, &b, 4, &Never);
            assert_eq!(status, EdgeStatus::Invalid, "{name}: {a:?} → {b:?}");
        }
    }
}

/// The guard changes nothing for finite edges: an edge of finite ends is still decided by its
/// grid (valid in an empty world, every point tested).
#[test]
fn finite_edges_are_checked_as_before() {
    let space = RealVectorSpace::cube(2, -0.5, 0.5).unwrap();
    for (name, mut checker) in checkers::<AllValid>(1e-2) {
        let mut progress = EdgeProgress::default();
        let status = checker.check_full(
            &space,
            &AllValid,
            &[0.0, 0.0],
            &[0.3, 0.4],
            &mut progress,
            &Never,
        );
        assert_eq!(
            (status, progress.tested()),
            (EdgeStatus::Valid, 49),
            "{name}"
        );
    }
}
