//! Simplified arm paths stay collision-free along their whole length: RRT-Connect paths on
//! MotionBenchMaker problems, simplified, then audited continuously in `f64` with parry.

use std::time::Duration;

use mit_star::PathSimplifier;
use mit_star_problems::PlanningProblem;
use mit_star_robot::{AuditVerdict, MotionAudit};
use mit_star_validity::StateValidity;

use crate::arm_cases::first_mbm_path;

#[test]
fn simplified_arm_paths_pass_the_continuous_audit() {
    let mut shortened = 0;
    for scene in ["bookshelf_small_panda", "cage_panda", "table_pick_panda"] {
        let (problem, path) = first_mbm_path(scene, 3);
        let simplified = PathSimplifier::new()
            .seed(7)
            .simplify(
                &problem,
                &path,
                &mit_star_spaces::Deadline::after(Duration::from_secs(2)),
            )
            .unwrap();
        assert_eq!(simplified.path.first(), path.first());
        assert_eq!(simplified.path.last(), path.last());
        assert!(simplified.cost <= simplified.original_cost + 1e-12);
        shortened += usize::from(simplified.cost < 0.95 * simplified.original_cost);
        let audit = MotionAudit::new(problem.robot(), problem.scene());
        for w in simplified.path.windows(2) {
            match audit.audit(&w[0], &w[1], 1_000_000) {
                AuditVerdict::Clear { .. } => {}
                other => panic!("{scene}: a simplified edge is not clear: {other:?}"),
            }
        }
        assert!(
            simplified
                .path
                .iter()
                .all(|q| problem.validity().is_valid(q))
        );
    }
    assert!(shortened >= 2, "only {shortened} of 3 paths got shorter");
}
