//! Tests of the in-place reverse-search repair: it keeps the reverse tree's child lists exact,
//! and the repaired search, run to its end, reaches the fixpoint a restart reaches.

use std::collections::BTreeMap;

use crate::graph::NONE;
use crate::termination::SolveStop;
use crate::{AitStar, Connection, IterationLimit};

type Ait = AitStar;

/// `ĥ` of every vertex the current reverse search reached, by vertex id.
fn cost_to_go(planner: &Ait) -> BTreeMap<u32, f64> {
    let tag = planner.reverse_tag;
    planner
        .graph
        .vertices()
        .filter_map(|(id, _)| {
            let v = planner.graph.vertex(id.0);
            v.in_reverse_tree(tag).then_some((id.0, v.h))
        })
        .collect()
}

/// Every vertex of the reverse tree but a goal sits exactly once in its reverse parent's child
/// list, the lists hold nothing else, and the tree's `ĥ` adds up along its edges.
fn assert_child_lists(planner: &Ait) {
    let tag = planner.reverse_tag;
    let mut listed = 0;
    let mut members = 0;
    for (id, _) in planner.graph.vertices() {
        let v = planner.graph.vertex(id.0);
        if !v.in_reverse_tree(tag) {
            continue;
        }
        let mut child = v.reverse_first_child;
        let mut previous = NONE;
        while child != NONE {
            let c = planner.graph.vertex(child);
            assert_eq!(
                c.reverse_parent(tag),
                id.0,
                "a listed child of another parent"
            );
            assert_eq!(c.reverse_prev_sibling, previous, "a broken back link");
            assert!(c.in_reverse_tree(tag), "a listed child outside the tree");
            let cost = planner.edge_geometry(id.0, child, NONE).0;
            assert!((c.h - (v.h + cost)).abs() <= 1e-12 * (1.0 + c.h));
            listed += 1;
            previous = child;
            child = c.reverse_next_sibling;
        }
        if !v.is_goal() {
            members += 1;
            assert_ne!(v.reverse_parent(tag), NONE);
        }
    }
    assert_eq!(
        listed, members,
        "tree vertices missing from the child lists"
    );
}

/// Runs the reverse search to its end (no forward steps in between).
fn exhaust_reverse(planner: &mut Ait, stop: &SolveStop<'_>) {
    while planner.peek_reverse().is_some() {
        planner.reverse_step(stop);
    }
}

#[test]
fn a_repaired_search_reaches_the_fixpoint_of_a_restart() {
    // r-disc neighbourhoods are symmetric, so the edges a repair offers a branch are exactly
    // those a restart's expansions would (within the first batch every tree edge is within
    // the radius too).
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    let (mut compared, mut widest) = (0, 0);
    for seed in 0..80 {
        let mut planner = Ait::for_problem(&problem)
            .seed(seed)
            .connection(Connection::RDisc)
            .repair_reverse_search(true)
            .batch_size(300)
            .build()
            .unwrap();
        planner.setup(&stop).unwrap();
        // Stop right after the first repair of a branch of six vertices or more.
        let mut branch = 0;
        while branch < 6
            && planner.best_cost.is_infinite()
            && planner.counters.batches <= 1
            && planner.counters.iterations < 1_000_000
        {
            let repairs = planner.counters.reverse_repairs;
            planner.iterate(&stop);
            if planner.counters.reverse_repairs > repairs {
                branch = planner.branch.len();
            }
        }
        assert_eq!(planner.counters.reverse_restarts, 0, "AIT* restarted");
        if branch < 6
            || planner.best_cost.is_finite()
            || planner.counters.batches != 1
            || planner.reverse_restart_pending
        {
            continue;
        }
        widest = widest.max(branch);
        assert_child_lists(&planner);
        exhaust_reverse(&mut planner, &stop);
        assert_child_lists(&planner);
        let repaired = cost_to_go(&planner);
        planner.restart_reverse(&stop);
        exhaust_reverse(&mut planner, &stop);
        assert_child_lists(&planner);
        let restarted = cost_to_go(&planner);
        assert_eq!(
            repaired.keys().collect::<Vec<_>>(),
            restarted.keys().collect::<Vec<_>>(),
            "seed {seed}: the repair and the restart reach different vertices"
        );
        for (id, h) in &repaired {
            let other = restarted[id];
            assert!(
                (h - other).abs() <= 1e-9 * (1.0 + other),
                "seed {seed}, vertex {id}: ĥ {h} after the repair, {other} after a restart"
            );
        }
        compared += 1;
    }
    assert!(
        compared >= 3,
        "{compared} seeds repaired a branch in their first batch, the widest of {widest}"
    );
}

#[test]
fn restarting_instead_of_repairing_is_a_parameter() {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let limit = IterationLimit::new(20_000);
    for repair in [true, false] {
        let mut planner = Ait::for_problem(&problem)
            .seed(1)
            .repair_reverse_search(repair)
            .build()
            .unwrap();
        crate::Planner::solve(&mut planner, &limit).unwrap();
        let c = planner.counters;
        assert!(
            c.reverse_repairs + c.reverse_restarts > 0,
            "no invalid lazy edge"
        );
        assert_eq!(c.reverse_repairs == 0, !repair);
        assert_eq!(c.reverse_restarts == 0, repair);
    }
}
