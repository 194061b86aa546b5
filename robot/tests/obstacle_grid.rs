//! The arm checker's grid over many obstacles (`obstacle_grid.rs`) changes no answer: among
//! hundreds of small boxes and a few large solids, state checks, batch checks and certified
//! motions come out the same, bit for bit, with the grid on every link and with none; and the
//! independent audit finds every edge certified clear.

use glam::{DQuat, DVec3};
use mit_star_robot::{ArmChecker, AuditVerdict, MotionAudit, Obstacle, Scene, Shape};
use mit_star_spaces::StateSpace;
use mit_star_validity::{MotionProgress, StateValidity};
use proptest::prelude::*;

use crate::arm_cases::{obstacle, panda};

/// `small` boxes of 0.5–3 cm half sides, turned at random, within 1.1 m of the base (up to
/// 1.4 m high) but not within 30 cm of its axis (the fixed links would touch them in every
/// configuration), from `seed`.
fn small_boxes(small: usize, seed: u64) -> Vec<Obstacle> {
    let mut state = seed | 1;
    let mut uniform = move |low: f64, high: f64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        low + (high - low) * (state >> 11) as f64 / (1_u64 << 53) as f64
    };
    let mut boxes = Vec::new();
    while boxes.len() < small {
        let half = DVec3::new(
            uniform(0.005, 0.03),
            uniform(0.005, 0.03),
            uniform(0.005, 0.03),
        );
        let at = DVec3::new(uniform(-1.1, 1.1), uniform(-1.1, 1.1), uniform(-0.1, 1.4));
        if at.x.hypot(at.y) < 0.3 {
            continue;
        }
        let turn = DQuat::from_xyzw(
            uniform(-1.0, 1.0),
            uniform(-1.0, 1.0),
            uniform(-1.0, 1.0),
            uniform(0.1, 1.0),
        );
        boxes.push(Obstacle::new(
            Shape::Cuboid { half_extents: half },
            at,
            turn.normalize(),
        ));
    }
    boxes
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn the_grid_changes_no_answer_and_the_audit_clears_what_it_certifies(
        small in 250..700_usize,
        seed in 1..u64::MAX,
        large in prop::collection::vec(obstacle(), 0..4),
        lengths in prop::collection::vec(0.02..0.6_f64, 12),
    ) {
        let robot = panda();
        let mut obstacles = small_boxes(small, seed);
        obstacles.extend(large);
        let scene = Scene::new(obstacles);
        let on = ArmChecker::with_grid_threshold(&robot, &scene, 0);
        let off = ArmChecker::with_grid_threshold(&robot, &scene, usize::MAX);
        let space = robot.joint_space();
        let mut rng = <mit_star_spaces::SeededRng as mit_star_spaces::rand::SeedableRng>::seed_from_u64(seed);
        let mut states = vec![0.0; 7 * 96];
        for q in states.chunks_exact_mut(7) {
            space.sample_uniform(&mut rng, q);
        }
        // Single states.
        let mut verdicts = Vec::new();
        for q in states.chunks_exact(7) {
            let valid = on.is_valid(q);
            prop_assert_eq!(valid, off.is_valid(q), "{:?}", q);
            verdicts.push(valid);
        }
        let valid = verdicts.iter().filter(|&&v| v).count();
        // A large solid over the base leaves nothing valid: no motion to certify.
        prop_assume!(valid > 0);
        prop_assert!(valid < verdicts.len(), "all {} valid", valid);
        // Batches: first, any and every invalid configuration, from every offset.
        for from in 0..12 {
            let rest = &states[7 * from..];
            prop_assert_eq!(on.first_invalid(rest, 7), off.first_invalid(rest, 7));
            prop_assert_eq!(on.any_invalid(rest, 7), off.any_invalid(rest, 7));
            let (mut a, mut b) = (vec![false; rest.len() / 7], vec![false; rest.len() / 7]);
            on.are_valid(rest, 7, &mut a);
            off.are_valid(rest, 7, &mut b);
            prop_assert_eq!(a, b);
        }
        // Certified motions from valid configurations, of random lengths and directions: the
        // same verdict and progress, and the audit clears every edge certified.
        let audit = MotionAudit::new(&robot, &scene);
        let starts: Vec<&[f64]> = states
            .chunks_exact(7)
            .zip(&verdicts)
            .filter_map(|(q, &v)| v.then_some(q))
            .collect();
        let mut certified = 0;
        for (i, &length) in lengths.iter().enumerate() {
            let a = starts[i % starts.len()];
            let towards = &states[7 * ((i * 37 + 5) % 96)..][..7];
            let norm = mit_star_spaces::euclidean_distance(a, towards).max(1e-9);
            let b: Vec<f64> = a
                .iter()
                .zip(towards)
                .map(|(x, y)| x + (y - x) * (length / norm).min(1.0))
                .collect();
            let (mut p, mut q) = (MotionProgress::new(0.0, 0.0), MotionProgress::new(0.0, 0.0));
            let status = on.certify_motion(space, a, &b, &mut p, &mit_star_spaces::Never);
            prop_assert_eq!(status, off.certify_motion(space, a, &b, &mut q, &mit_star_spaces::Never));
            prop_assert_eq!(p, q);
            if status == Some(mit_star_validity::EdgeStatus::Valid) {
                certified += 1;
                let verdict = audit.audit(a, &b, 2_000_000);
                prop_assert!(matches!(verdict, AuditVerdict::Clear { .. }), "{:?}", verdict);
            }
        }
        prop_assert!(certified > 0, "no edge certified");
    }
}
