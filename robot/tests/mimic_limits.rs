//! A mimic joint's own limits are kept: its leader's range shrinks to the values that keep it
//! within them, or the model is refused by name. Random multipliers, offsets and limits,
//! judged by forward kinematics (where the follower's link actually is).

use glam::{DAffine3, DVec3};
use mit_star_robot::{Kinematics, ModelError, ModelWarning, RobotModel};
use mit_star_spaces::StateSpace;
use proptest::prelude::*;

/// `lead` slides along y; `f1` slides along z following it (`m1`, `o1`) and `f2` along x
/// (`m2`, `o2`), each within its own limits. Every joint's origin is the root's: the link of a
/// follower is where its value says along its axis.
fn robot(lead: (f64, f64), f1: (f64, f64, f64, f64), f2: (f64, f64, f64, f64)) -> String {
    let sphere = r#"<collision><geometry><sphere radius="0.01"/></geometry></collision>"#;
    let joint = |name: &str, axis: &str, (lo, hi): (f64, f64), mimic: Option<(f64, f64)>| {
        let mimic = mimic.map_or(String::new(), |(m, o)| {
            format!(r#"<mimic joint="lead" multiplier="{m:e}" offset="{o:e}"/>"#)
        });
        format!(
            r#"<joint name="{name}" type="prismatic"><parent link="base"/><child link="{name}_link"/><axis xyz="{axis}"/><limit lower="{lo:e}" upper="{hi:e}" effort="1" velocity="1"/>{mimic}</joint>"#
        )
    };
    format!(
        r#"<robot name="mimics"><link name="base">{sphere}</link><link name="lead_link">{sphere}</link><link name="f1_link">{sphere}</link><link name="f2_link">{sphere}</link>{}{}{}</robot>"#,
        joint("lead", "0 1 0", lead, None),
        joint("f1", "0 0 1", (f1.2, f1.3), Some((f1.0, f1.1))),
        joint("f2", "1 0 0", (f2.2, f2.3), Some((f2.0, f2.1))),
    )
}

/// A follower: multiplier (non-zero), offset, limits.
fn follower() -> impl Strategy<Value = (f64, f64, f64, f64)> {
    (
        prop_oneof![-4.0..-0.05, 0.05..4.0],
        -1.0..1.0,
        -2.0..2.0,
        0.01..2.0,
    )
        .prop_map(|(m, o, lo, width): (f64, f64, f64, f64)| (m, o, lo, lo + width))
}

/// The followers' values at `q`, from the links' poses.
fn followers(model: &RobotModel, q: &[f64]) -> (f64, f64) {
    let fk = Kinematics::new(model);
    let mut links = vec![DAffine3::IDENTITY; fk.link_count()];
    let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
    fk.sphere_centers_f64(q, &mut links, &mut centers);
    let at = |name: &str| links[model.link_index(name).unwrap()].translation;
    (at("f1_link").z, at("f2_link").x)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn no_configuration_drives_a_follower_outside_its_limits(
        lo in -2.0..2.0_f64,
        width in 0.01..2.0_f64,
        f1 in follower(),
        f2 in follower(),
        draws in prop::collection::vec(0.0..=1.0_f64, 16),
    ) {
        let lead = (lo, lo + width);
        let text = robot(lead, f1, f2);
        // Where the followers' limits hold, by interval arithmetic written out here.
        let preimage = |(m, o, l, u): (f64, f64, f64, f64)| {
            let (a, b) = ((l - o) / m, (u - o) / m);
            (a.min(b), a.max(b))
        };
        let (p1, p2) = (preimage(f1), preimage(f2));
        let (from, to) = (lead.0.max(p1.0).max(p2.0), lead.1.min(p1.1).min(p2.1));
        match RobotModel::from_urdf_str(&text) {
            Err(e) => {
                prop_assert!(matches!(e, ModelError::MimicLimits { .. }), "{e}");
                prop_assert!(to - from < 1e-9, "refused although [{from}, {to}] keeps both: {e}");
            }
            Ok(model) => {
                prop_assert!(to - from > -1e-9, "accepted although no value keeps both: {text}");
                let space = model.joint_space();
                let (lower, upper) = (space.lower()[0], space.upper()[0]);
                // Not shrunk more than needed.
                prop_assert!((lower - from).abs() < 1e-9 && (upper - to).abs() < 1e-9,
                    "[{lower}, {upper}] instead of [{from}, {to}]");
                let shrunk = lower > lead.0 || upper < lead.1;
                prop_assert_eq!(shrunk, model.warnings().iter().any(|w| matches!(w, ModelWarning::MimicRange { .. })));
                let mut qs: Vec<f64> = draws.iter().map(|u| (lower + u * (upper - lower)).min(upper)).collect();
                qs.extend([lower, upper]);
                for q in qs {
                    prop_assert!(space.contains(&[q]));
                    let (v1, v2) = followers(&model, &[q]);
                    for (v, (_, _, l, u)) in [(v1, f1), (v2, f2)] {
                        prop_assert!(v >= l - 1e-12 && v <= u + 1e-12,
                            "q = {q}: a follower at {v}, outside [{l}, {u}]");
                    }
                }
            }
        }
    }
}

#[test]
fn a_follower_whose_limits_no_leader_value_keeps_is_refused_by_name() {
    // `f1` = 2·lead + 5 with lead in [0, 1] is in [5, 7]; its limits are [-1, 1].
    let text = robot((0.0, 1.0), (2.0, 5.0, -1.0, 1.0), (1.0, 0.0, -1.0, 2.0));
    let e = RobotModel::from_urdf_str(&text).unwrap_err();
    assert!(
        matches!(&e, ModelError::MimicLimits { joint, leader, .. } if joint == "f1" && leader == "lead"),
        "{e}"
    );
    assert!(e.to_string().contains("`f1`"), "{e}");
}

#[test]
fn a_shrunk_range_is_reported_and_held_values_stay_within_it() {
    // `f1` = -lead with limits [-0.5, 1]: lead within [-1, 0.5] of its [-1, 1].
    let text = robot((-1.0, 1.0), (-1.0, 0.0, -0.5, 1.0), (1.0, 0.0, -3.0, 3.0));
    let model = RobotModel::from_urdf_str(&text).unwrap();
    assert_eq!(model.joint_space().upper(), [0.5]);
    let [warning] = model.warnings() else {
        panic!("{:?}", model.warnings())
    };
    assert!(
        warning.to_string().contains("`lead` limited to [-1, 0.5]"),
        "{warning}"
    );
}
