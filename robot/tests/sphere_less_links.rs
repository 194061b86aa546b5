//! Links without spheres and the self-collision pairs: they join their neighbours along a
//! serial chain (as MoveIt's setup assistant collapses a wrist), or across one moving joint,
//! never across branches with two moving joints between them. A hand-written dual arm whose
//! shoulders overlap, and random trees against an independent brute-force rule.

use mit_star_robot::{ArmChecker, RobotModel, Scene, StateDiagnosis};
use proptest::prelude::*;

const DUAL_ARM: &str = include_str!("data/dual_arm.urdf");

fn pair(model: &RobotModel, a: &str, b: &str) -> (usize, usize) {
    let (i, j) = (model.link_index(a).unwrap(), model.link_index(b).unwrap());
    (i.min(j), i.max(j))
}

#[test]
fn two_arms_on_bases_without_spheres_are_checked_against_each_other() {
    let model = RobotModel::from_urdf_str(DUAL_ARM)
        .unwrap()
        .without_model_pairs();
    let shoulders = pair(&model, "left_shoulder", "right_shoulder");
    assert!(
        !model.adjacent_link_pairs().contains(&shoulders),
        "{:?}",
        model.adjacent_link_pairs()
    );
    // Each arm's own links are adjacent (one joint between them).
    assert!(
        model
            .adjacent_link_pairs()
            .contains(&pair(&model, "left_shoulder", "left_forearm"))
    );
    assert!(model.self_collision_pairs().contains(&shoulders));
    // The shoulders overlap by 96 mm at the zero configuration: in collision.
    let q = model.default_configuration();
    assert_eq!(model.colliding_link_pairs(&q), [shoulders]);
    let scene = Scene::new(Vec::new());
    let checker = ArmChecker::new(&model, &scene);
    let diagnosis = StateDiagnosis::of(&model, &scene, &checker, &q);
    assert!(!diagnosis.valid, "{diagnosis:?}");
    let contact = &diagnosis.itself[0];
    assert!((contact.gap + 0.096).abs() < 1e-9, "{contact:?}");
    // The left arm turned away: free.
    let away = [3.0, 0.0, 0.0, 0.0];
    assert!(StateDiagnosis::of(&model, &scene, &checker, &away).valid);
    // An SRDF disabling the pair is obeyed.
    let srdf = r#"<robot name="dual_arm"><disable_collisions link1="left_shoulder" link2="right_shoulder" reason="Never"/></robot>"#;
    let off = RobotModel::from_urdf_str(DUAL_ARM)
        .unwrap()
        .with_srdf_str(srdf)
        .unwrap();
    assert!(off.colliding_link_pairs(&q).is_empty());
}

/// One link of a random tree: its parent (an earlier link), its joint, whether it has a sphere.
#[derive(Debug, Clone)]
struct RandomLink {
    parent: usize,
    joint: &'static str,
    sphere: bool,
}

fn random_tree() -> impl Strategy<Value = (bool, Vec<RandomLink>)> {
    (
        any::<bool>(),
        prop::collection::vec(
            (
                any::<prop::sample::Index>(),
                prop::sample::select(vec![
                    "fixed",
                    "fixed",
                    "revolute",
                    "continuous",
                    "prismatic",
                ]),
                prop::bool::weighted(0.4),
                any::<bool>(),
            ),
            1..10,
        ),
    )
        .prop_map(|(root_sphere, raw)| {
            let links = raw
                .into_iter()
                .enumerate()
                // Link i + 1: a serial chain (its parent the link before) or a branch.
                .map(|(i, (index, joint, sphere, chain))| RandomLink {
                    parent: if chain { i } else { index.index(i + 1) },
                    joint,
                    sphere,
                })
                .collect();
            (root_sphere, links)
        })
}

fn urdf(root_sphere: bool, links: &[RandomLink]) -> String {
    let sphere = r#"<collision><origin xyz="0 0 0.1" rpy="0 0 0"/><geometry><sphere radius="0.05"/></geometry></collision>"#;
    let mut text = String::from(r#"<robot name="random">"#);
    let with = |s: bool| if s { sphere } else { "" };
    text += &format!(r#"<link name="l0">{}</link>"#, with(root_sphere));
    for (i, link) in links.iter().enumerate() {
        let (n, limit) = (
            i + 1,
            r#"<limit lower="-1" upper="1" effort="1" velocity="1"/>"#,
        );
        text += &format!(r#"<link name="l{n}">{}</link>"#, with(link.sphere));
        text += &format!(
            r#"<joint name="j{n}" type="{}"><parent link="l{}"/><child link="l{n}"/><origin xyz="0 0.1 0.2" rpy="0 0 0"/><axis xyz="0 0 1"/>{limit}</joint>"#,
            link.joint, link.parent
        );
    }
    text + "</robot>"
}

/// The brute-force rule, from the tree alone: links `a`, `b` with spheres are adjacent iff
/// every link strictly between them has no sphere, and one is an ancestor of the other or the
/// relative transform between them depends on at most one moving joint.
fn brute_force(root_sphere: bool, links: &[RandomLink]) -> Vec<(usize, usize)> {
    let n = links.len() + 1;
    let parent = |l: usize| (l > 0).then(|| links[l - 1].parent);
    let sphere = |l: usize| {
        if l == 0 {
            root_sphere
        } else {
            links[l - 1].sphere
        }
    };
    let moving = |l: usize| l > 0 && links[l - 1].joint != "fixed";
    // Each link with its ancestors, itself first.
    let up = |mut l: usize| {
        let mut chain = vec![l];
        while let Some(p) = parent(l) {
            chain.push(p);
            l = p;
        }
        chain
    };
    let mut adjacent = Vec::new();
    for a in (0..n).filter(|&l| sphere(l)) {
        for b in (a + 1..n).filter(|&l| sphere(l)) {
            let (ua, ub) = (up(a), up(b));
            // Links whose joint moves one of them and not the other.
            let only_a: Vec<usize> = ua.iter().copied().filter(|l| !ub.contains(l)).collect();
            let only_b: Vec<usize> = ub.iter().copied().filter(|l| !ua.contains(l)).collect();
            let common = ua.iter().copied().find(|l| ub.contains(l)).unwrap();
            let between = only_a
                .iter()
                .chain(&only_b)
                .copied()
                .chain([common])
                .filter(|&l| l != a && l != b);
            let clear = between.clone().all(|l| !sphere(l));
            let ancestor = common == a || common == b;
            let joints = only_a.iter().chain(&only_b).filter(|&&l| moving(l)).count();
            if clear && (ancestor || joints <= 1) {
                adjacent.push((a, b));
            }
        }
    }
    adjacent
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn adjacency_matches_the_brute_force_rule_on_random_trees((root_sphere, links) in random_tree()) {
        prop_assume!(links.iter().any(|l| l.joint != "fixed"));
        let model = RobotModel::from_urdf_str(&urdf(root_sphere, &links)).unwrap();
        // Links are numbered `l{i}`; the model orders them depth-first.
        let index = |l: usize| model.link_index(&format!("l{l}")).unwrap();
        let mut expected: Vec<(usize, usize)> = brute_force(root_sphere, &links)
            .into_iter()
            .map(|(a, b)| (index(a).min(index(b)), index(a).max(index(b))))
            .collect();
        expected.sort_unstable();
        prop_assert_eq!(model.adjacent_link_pairs(), expected);
    }
}
