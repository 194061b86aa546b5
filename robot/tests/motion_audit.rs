//! The independent audit of arm motions: conservative advancement in `f64` finds the 1 mm tab
//! every coarse grid misses, a motion it clears has no configuration in collision on a grid of
//! 1e-4 rad, and a collision it reports is one.

use mit_star_robot::{AuditVerdict, MotionAudit, ParryChecker, Scene};
use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;
use proptest::prelude::*;

use crate::arm_cases;
use arm_cases::{HOME, edge, obstacle, panda, reference_hit, tab_scene};

/// A collision the audit reports is real: the reference, every sphere grown by 1 µm, sees it.
fn confirm(reference: &ParryChecker, verdict: &AuditVerdict) -> bool {
    match verdict {
        AuditVerdict::Collides { configuration, .. } => {
            !reference.is_valid_with_margin(configuration, 1e-6)
        }
        _ => false,
    }
}

#[test]
fn the_one_millimetre_tab_is_found_and_a_free_motion_is_cleared() {
    let robot = panda();
    let (scene, a, b) = tab_scene(&robot);
    let audit = MotionAudit::new(&robot, &scene);
    let reference = ParryChecker::new(&robot, &scene);
    let verdict = audit.audit(&a, &b, 1_000_000);
    assert!(confirm(&reference, &verdict), "{verdict:?}");
    let AuditVerdict::Collides { t, contact, .. } = &verdict else {
        unreachable!()
    };
    let truth = reference_hit(&reference, &a, &b, 1e-5, 0.0).unwrap();
    assert!((t - truth).abs() < 1e-3, "audit {t}, reference {truth}");
    assert!(contact.contains("meets an obstacle"), "{contact}");
    // The same turn with the tab gone is clear, in a few hundred configurations.
    let empty = MotionAudit::new(&robot, &Scene::new(vec![]));
    let (_, a, b) = tab_scene(&robot);
    match empty.audit(&a, &b, 1_000_000) {
        AuditVerdict::Clear {
            configurations,
            clearance,
            ..
        } => assert!(
            configurations < 2_000 && clearance > 0.0,
            "{configurations}"
        ),
        other => panic!("{other:?}"),
    }
    // A budget too small to decide says so.
    let undecided = audit.audit(&a, &b, 2);
    assert!(matches!(
        undecided,
        AuditVerdict::Undecided {
            configurations: 2,
            ..
        }
    ));
    // Ends that are not configurations collide at once.
    let short = audit.audit(&HOME[..3], &b, 10);
    assert!(matches!(short, AuditVerdict::Collides { t: 0.0, .. }));
    let mut nan = HOME;
    nan[2] = f64::NAN;
    assert!(matches!(
        audit.audit(&nan, &b, 10),
        AuditVerdict::Collides { .. }
    ));
}

/// The audit of `a → b` in `scene` against the reference at 1e-4 rad: cleared ⇒ no
/// configuration in collision; collides ⇒ the reference sees the reported configuration in
/// collision; never undecided. Ends in collision are rejected as inputs.
fn agrees_with_the_dense_reference(
    scene: &Scene,
    a: &[f64],
    b: &[f64],
) -> Result<(), TestCaseError> {
    let robot = panda();
    let audit = MotionAudit::new(&robot, scene);
    let reference = ParryChecker::new(&robot, scene);
    prop_assume!(reference.is_valid(a) && reference.is_valid(b));
    let verdict = audit.audit(a, b, 1_000_000);
    match &verdict {
        AuditVerdict::Clear { .. } => {
            prop_assert_eq!(reference_hit(&reference, a, b, 1e-4, 0.0), None);
        }
        AuditVerdict::Collides { .. } => prop_assert!(confirm(&reference, &verdict)),
        AuditVerdict::Undecided { .. } => prop_assert!(false, "{:?}", verdict),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Cleared ⇒ no configuration in collision at 1e-4 rad (parry, f64); collides ⇒ the
    /// reference sees the reported configuration in collision.
    #[test]
    fn audits_agree_with_the_dense_reference(
        obstacles in prop::collection::vec(obstacle(), 1..6),
        (a, b) in edge(),
    ) {
        agrees_with_the_dense_reference(&Scene::new(obstacles), &a, &b)?;
    }
}

/// Self-collision on its own, where the audit bounds a pair's closing speed by the joints
/// between its two links only: a motion between two valid configurations that passes through
/// self-collision on the way (found by a dense reference scan over seeded random edges) is
/// reported, with the two links named.
#[test]
fn a_self_collision_between_valid_ends_is_found() {
    let robot = panda();
    let scene = Scene::new(vec![]);
    let audit = MotionAudit::new(&robot, &scene);
    let reference = ParryChecker::new(&robot, &scene);
    let space = robot.joint_space();
    let (lower, upper) = (space.lower(), space.upper());
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut unit = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut found = 0;
    for _ in 0..2_000 {
        let a: Vec<f64> = (0..7)
            .map(|j| lower[j] + unit() * (upper[j] - lower[j]))
            .collect();
        let b: Vec<f64> = (0..7)
            .map(|j| lower[j] + unit() * (upper[j] - lower[j]))
            .collect();
        if !reference.is_valid(&a) || !reference.is_valid(&b) {
            continue;
        }
        if reference_hit(&reference, &a, &b, 2e-3, 0.0).is_none() {
            continue;
        }
        let verdict = audit.audit(&a, &b, 1_000_000);
        assert!(confirm(&reference, &verdict), "{verdict:?}");
        let AuditVerdict::Collides { contact, .. } = &verdict else {
            unreachable!()
        };
        assert!(contact.contains("meets a sphere of"), "{contact}");
        found += 1;
        if found == 5 {
            return;
        }
    }
    panic!("only {found} self-colliding motions between valid ends in 2 000 draws");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// With no obstacles, only self-collision limits the audit's steps: cleared ⇒ no
    /// configuration self-collides at 1e-4 rad.
    #[test]
    fn audits_of_self_collision_agree_with_the_dense_reference((a, b) in edge()) {
        agrees_with_the_dense_reference(&Scene::new(vec![]), &a, &b)?;
    }
}
