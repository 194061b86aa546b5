//! The audit's broad phase changes its cost, not its verdicts: on random sphere covers of the
//! Panda (each sphere split into smaller ones inside it), random scenes and random motions,
//! the audit and its exhaustive form return the same verdict, to the configuration count, the
//! clearance and the contact's name. An ignored test prints both audits' times on a
//! 2 832-sphere cover.

use mit_star_robot::{ArmProblem, AuditVerdict, MotionAudit, RobotModel, Scene};
use proptest::prelude::*;

use crate::arm_cases;
use arm_cases::{edge, obstacle};

const PANDA_URDF: &str = include_str!("../data/panda/panda_spherized.urdf");
const PANDA_SRDF: &str = include_str!("../data/panda/panda.srdf");

/// The Panda with each sphere replaced by `pieces` smaller spheres inside it (radius
/// `shrink · r`, centres within `(1 − shrink) · r` of the original's, from `seed`): a cover
/// with `pieces` times the spheres, colliding only where the original does.
fn split_panda(pieces: usize, shrink: f64, mut seed: u64) -> RobotModel {
    let mut unit = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let number = |text: &str, key: &str| -> String {
        let start = text.find(key).unwrap() + key.len();
        let end = start + text[start..].find('"').unwrap();
        text[start..end].to_owned()
    };
    let mut out = String::new();
    let mut rest = PANDA_URDF;
    while let Some(start) = rest.find("<collision>") {
        let end = start + rest[start..].find("</collision>").unwrap() + "</collision>".len();
        out += &rest[..start];
        let block = &rest[start..end];
        let radius: f64 = number(block, r#"radius=""#).parse().unwrap();
        let xyz: Vec<f64> = number(block, r#"xyz=""#)
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        for _ in 0..pieces {
            // A direction in the unit ball (rejection), scaled to the room left inside.
            let offset = loop {
                let v: Vec<f64> = (0..3).map(|_| 2.0 * unit() - 1.0).collect();
                if v.iter().map(|x| x * x).sum::<f64>() <= 1.0 {
                    break v;
                }
            };
            let room = (1.0 - shrink) * radius;
            out += &format!(
                r#"<collision><geometry><sphere radius="{}"/></geometry><origin xyz="{} {} {}" rpy="0 0 0"/></collision>"#,
                shrink * radius,
                xyz[0] + room * offset[0],
                xyz[1] + room * offset[1],
                xyz[2] + room * offset[2],
            );
        }
        rest = &rest[end..];
    }
    out += rest;
    RobotModel::from_urdf_str(&out)
        .and_then(|m| m.with_srdf_str(PANDA_SRDF))
        .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn the_broad_phase_returns_the_exhaustive_verdict(
        pieces in 1..4_usize,
        shrink in 0.4..1.0_f64,
        seed in 1..u64::MAX,
        obstacles in prop::collection::vec(obstacle(), 0..6),
        (a, b) in edge(),
        budget in prop_oneof![Just(20_000_u64), 1..50_u64],
    ) {
        let robot = split_panda(pieces, shrink, seed);
        let audit = MotionAudit::new(&robot, &Scene::new(obstacles));
        let (broad, (broad_exact, _)) = audit.audit_counting(&a, &b, budget, true);
        let (exhaustive, (all, _)) = audit.audit_counting(&a, &b, budget, false);
        prop_assert_eq!(&broad, &exhaustive);
        prop_assert_eq!(audit.audit(&a, &b, budget), broad);
        // Never more sphere distances than the exhaustive audit, but for the contact found.
        let contact = matches!(exhaustive, AuditVerdict::Collides { .. });
        prop_assert!(contact || broad_exact <= all, "{broad_exact} > {all}");
    }
}

/// Prints the audit's cost with and without its broad phase on a 2 832-sphere cover of the
/// Panda (each sphere split into 48) among the obstacles of a MotionBenchMaker box problem:
/// `cargo test -p mit-star-robot --test audit_broad_phase -- --ignored --nocapture`.
#[test]
#[ignore = "a measurement: prints times"]
fn the_broad_phase_cost_on_a_large_cover() {
    let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/mbm/box_panda");
    let problem = ArmProblem::panda_mbm(folder.as_ref(), 1).unwrap();
    let robot = split_panda(48, 0.5, 7);
    println!(
        "{} spheres, {} checked link pairs, {} obstacles",
        robot.spheres().len(),
        robot.self_collision_pairs().len(),
        problem.scene().obstacles().len()
    );
    let audit = MotionAudit::new(&robot, problem.scene());
    let start = mit_star_problems::PlanningProblem::start(&problem).to_vec();
    let home = arm_cases::HOME.to_vec();
    let mut goal = home.clone();
    goal[0] += 0.5;
    for (name, a, b) in [
        ("home → turned", &home, &goal),
        ("start → home", &start, &home),
    ] {
        let mut times = Vec::new();
        let mut verdicts = Vec::new();
        for broad in [false, true] {
            let clock = std::time::Instant::now();
            let (verdict, (exact, bounds)) = audit.audit_counting(a, b, 1_000_000, broad);
            let time = clock.elapsed();
            println!(
                "{name}: {} {:>9.1} ms, {exact} sphere distances, {bounds} bound distances: {verdict:?}",
                if broad { "broad     " } else { "exhaustive" },
                time.as_secs_f64() * 1e3,
            );
            times.push(time);
            verdicts.push(verdict);
        }
        assert_eq!(verdicts[0], verdicts[1]);
    }
}
