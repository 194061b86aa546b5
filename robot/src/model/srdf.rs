//! Reading the `disable_collisions` pairs of a MoveIt SRDF.

use crate::ModelError;

/// The `(link1, link2)` pairs of the `<disable_collisions>` elements of an SRDF document: the
/// children of its root, which must be `<robot>`.
pub(crate) fn disabled_pairs(
    text: &str,
    origin: &str,
) -> Result<Vec<(String, String)>, ModelError> {
    let document = roxmltree::Document::parse(text).map_err(|e| ModelError::Srdf {
        origin: origin.to_owned(),
        message: e.to_string(),
    })?;
    let root = document.root_element();
    if !root.has_tag_name("robot") {
        return Err(ModelError::Srdf {
            origin: origin.to_owned(),
            message: format!(
                "the root element is <{}>, not <robot>",
                root.tag_name().name()
            ),
        });
    }
    let mut pairs = Vec::new();
    // The root's own children, as MoveIt reads them (not elements nested in other elements).
    for node in root
        .children()
        .filter(|n| n.has_tag_name("disable_collisions"))
    {
        let attribute = |name: &str| {
            node.attribute(name).ok_or_else(|| ModelError::Srdf {
                origin: origin.to_owned(),
                message: format!(
                    "line {}: <disable_collisions> without a `{name}` attribute",
                    document.text_pos_at(node.range().start).row
                ),
            })
        };
        pairs.push((
            attribute("link1")?.to_owned(),
            attribute("link2")?.to_owned(),
        ));
    }
    Ok(pairs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_pairs_and_names_what_is_missing() {
        let text = r#"<robot name="r"><disable_collisions link1="a" link2="b" reason="Adjacent"/>
            <group name="g"/><disable_collisions link1="b" link2="c"/></robot>"#;
        let pairs = disabled_pairs(text, "r.srdf").unwrap();
        assert_eq!(pairs, [("a".into(), "b".into()), ("b".into(), "c".into())]);
        let e = disabled_pairs(
            r#"<robot><disable_collisions link1="a"/></robot>"#,
            "r.srdf",
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains("r.srdf") && e.contains("link2") && e.contains("line 1"),
            "{e}"
        );
        let e = disabled_pairs("<robot>", "r.srdf").unwrap_err().to_string();
        assert!(e.starts_with("r.srdf: not a readable SRDF"), "{e}");
    }

    #[test]
    fn a_root_other_than_robot_is_refused() {
        let text = r#"<urdf><disable_collisions link1="a" link2="b"/></urdf>"#;
        let e = disabled_pairs(text, "r.srdf").unwrap_err().to_string();
        assert!(
            e.starts_with("r.srdf: not a readable SRDF") && e.contains("<urdf>, not <robot>"),
            "{e}"
        );
        // Only the root's children count: a pair inside another element is not MoveIt's.
        let text = r#"<robot name="r"><group name="g"><disable_collisions link1="a" link2="b"/></group></robot>"#;
        assert_eq!(disabled_pairs(text, "r.srdf").unwrap(), []);
    }
}
