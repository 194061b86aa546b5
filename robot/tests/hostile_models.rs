//! URDFs nobody should write, each refused with a typed error naming what is wrong: absurd
//! mimic factors, joint limits beyond any robot's, two `<robot>` roots, elements nested
//! 30 000 deep (a stack overflow in the URDF parser before), a document too large.

use mit_star_robot::{ModelError, RobotModel};

const TWO_LINK: &str = include_str!("data/two_link.urdf");

/// The hand-written two-link robot with a mimic finger on the slider: `finger` follows
/// `extend` at `multiplier`, `offset`.
fn with_mimic(multiplier: &str, offset: &str) -> String {
    TWO_LINK.replace(
        "</robot>",
        &format!(
            r#"<link name="finger"><collision><geometry><sphere radius="0.01"/></geometry></collision></link>
  <joint name="finger_joint" type="prismatic">
    <parent link="slider"/><child link="finger"/><axis xyz="0 1 0"/>
    <mimic joint="extend" multiplier="{multiplier}" offset="{offset}"/>
  </joint>
</robot>"#
        ),
    )
}

#[test]
fn absurd_mimic_multipliers_and_offsets_are_refused_by_name() {
    for (multiplier, offset, what) in [
        ("1e300", "0", "multiplier"),
        ("-1001", "0", "multiplier"),
        ("NaN", "0", "multiplier"),
        ("inf", "0", "multiplier"),
        ("1", "1e300", "offset"),
        ("1", "-101", "offset"),
    ] {
        let e = RobotModel::from_urdf_str(&with_mimic(multiplier, offset)).unwrap_err();
        assert!(
            matches!(&e, ModelError::BadMimic { joint, what: w, .. } if joint == "finger_joint" && *w == what),
            "{multiplier}, {offset}: {e}"
        );
    }
    // Within the bounds: loads.
    assert!(RobotModel::from_urdf_str(&with_mimic("-2.5", "0.01")).is_ok());
    assert!(RobotModel::from_urdf_str(&with_mimic("1000", "-100")).is_ok());
}

#[test]
fn joint_limits_beyond_any_robot_are_refused_naming_the_joint() {
    let prismatic = r#"lower="0.0" upper="0.3""#;
    let revolute = r#"lower="-3.0" upper="3.0""#;
    for (from, to, joint, kind) in [
        (
            prismatic,
            r#"lower="0.0" upper="1e6""#,
            "extend",
            "prismatic",
        ),
        (
            prismatic,
            r#"lower="-100.5" upper="0""#,
            "extend",
            "prismatic",
        ),
        // Degrees written as radians.
        (
            revolute,
            r#"lower="-180" upper="180""#,
            "shoulder",
            "revolute",
        ),
    ] {
        let e = RobotModel::from_urdf_str(&TWO_LINK.replace(from, to)).unwrap_err();
        assert!(
            matches!(&e, ModelError::LimitsTooWide { joint: j, kind: k, .. } if j == joint && *k == kind),
            "{to}: {e}"
        );
        assert!(e.to_string().contains(&format!("`{joint}`")), "{e}");
    }
    // At the bounds: loads (a multi-turn joint of ±2π, a 100 m slide).
    for (from, to) in [
        (revolute, r#"lower="-6.2832" upper="6.2832""#),
        (prismatic, r#"lower="-100" upper="100""#),
    ] {
        assert!(RobotModel::from_urdf_str(&TWO_LINK.replace(from, to)).is_ok());
    }
}

#[test]
fn two_robot_roots_are_refused() {
    let body = TWO_LINK.replace(r#"<?xml version="1.0"?>"#, "");
    let e = RobotModel::from_urdf_str(&format!("{body}{body}")).unwrap_err();
    assert!(matches!(e, ModelError::SeveralRoots { .. }), "{e}");
    // A comment or declaration after the root is not a second root.
    assert!(RobotModel::from_urdf_str(&format!("{TWO_LINK}<!-- <robot> -->")).is_ok());
}

#[test]
fn elements_nested_thirty_thousand_deep_are_a_typed_error_not_an_abort() {
    let depth = 30_000;
    let deep = format!(
        r#"<robot name="deep"><link name="a"/>{}{}</robot>"#,
        "<x>".repeat(depth),
        "</x>".repeat(depth)
    );
    let e = RobotModel::from_urdf_str(&deep).unwrap_err();
    assert!(
        matches!(e, ModelError::TooDeep { limit, .. } if limit == RobotModel::MAX_URDF_DEPTH),
        "{e}"
    );
    // Also from a file.
    let path = std::env::temp_dir().join(format!("deep-{}.urdf", std::process::id()));
    std::fs::write(&path, &deep).unwrap();
    let e = RobotModel::from_urdf_file(&path).unwrap_err();
    std::fs::remove_file(&path).unwrap();
    assert!(matches!(e, ModelError::TooDeep { .. }), "{e}");
}

#[test]
fn a_document_too_large_is_refused_before_parsing() {
    let mut big = TWO_LINK.to_owned();
    big.push_str(&" ".repeat(RobotModel::MAX_URDF_BYTES));
    let e = RobotModel::from_urdf_str(&big).unwrap_err();
    assert!(matches!(e, ModelError::TooLarge { .. }), "{e}");
}
