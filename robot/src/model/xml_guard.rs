//! A linear scan of a URDF before it is parsed: its size, its elements' nesting depth and its
//! number of root elements. The URDF parser (urdf-rs, through RustyXML) builds and drops its
//! element tree recursively, so a document nested 30 000 deep overflowed the stack and
//! aborted the process; this scan refuses it first, in constant stack.

use crate::{ModelError, RobotModel};

impl RobotModel {
    /// The largest URDF read, in bytes (64 MiB): a spherised humanoid of 6 000 spheres is
    /// about 2 MB.
    pub const MAX_URDF_BYTES: usize = 64 << 20;

    /// The deepest nesting of elements a URDF may have. A URDF needs 5
    /// (`robot/link/collision/geometry/sphere`); 256 leaves room for any extension.
    pub const MAX_URDF_DEPTH: usize = 256;
}

/// Refuses `text` if it is larger than [`RobotModel::MAX_URDF_BYTES`], nests elements deeper
/// than [`RobotModel::MAX_URDF_DEPTH`], or has more than one root element. Anything else the
/// scan does not understand is left to the parser to refuse.
pub(super) fn check_shape(text: &str, origin: &str) -> Result<(), ModelError> {
    if text.len() > RobotModel::MAX_URDF_BYTES {
        return Err(ModelError::TooLarge {
            origin: origin.to_owned(),
            bytes: text.len() as u64,
            limit: RobotModel::MAX_URDF_BYTES as u64,
        });
    }
    let bytes = text.as_bytes();
    let (mut i, mut depth, mut roots) = (0, 0_usize, 0_usize);
    // The end of the first `end` at or after `from` (the end of the text if none).
    let skip = |from: usize, end: &str| {
        text[from..]
            .find(end)
            .map_or(text.len(), |p| from + p + end.len())
    };
    while i < bytes.len() {
        let Some(p) = text[i..].find('<') else {
            break;
        };
        i += p;
        let rest = &text[i..];
        if rest.starts_with("<!--") {
            i = skip(i + 4, "-->");
        } else if rest.starts_with("<![CDATA[") {
            i = skip(i + 9, "]]>");
        } else if rest.starts_with("<?") {
            i = skip(i + 2, "?>");
        } else if rest.starts_with("<!") {
            // A declaration (DOCTYPE): to its `>`, past an internal subset in brackets.
            let mut brackets = 0_usize;
            i += 2;
            while i < bytes.len() {
                match bytes[i] {
                    b'[' => brackets += 1,
                    b']' => brackets = brackets.saturating_sub(1),
                    b'>' if brackets == 0 => break,
                    _ => {}
                }
                i += 1;
            }
            i += 1;
        } else if rest.starts_with("</") {
            depth = depth.saturating_sub(1);
            i = skip(i + 2, ">");
        } else {
            // A start tag: to its `>`, outside quoted attribute values.
            let mut quote = None;
            i += 1;
            while i < bytes.len() {
                match (quote, bytes[i]) {
                    (None, q @ (b'"' | b'\'')) => quote = Some(q),
                    (Some(q), c) if c == q => quote = None,
                    (None, b'>') => break,
                    _ => {}
                }
                i += 1;
            }
            let empty = i > 0 && bytes.get(i - 1) == Some(&b'/');
            i += 1;
            if depth == 0 {
                roots += 1;
                if roots > 1 {
                    return Err(ModelError::SeveralRoots {
                        origin: origin.to_owned(),
                    });
                }
            }
            if !empty {
                depth += 1;
                if depth > RobotModel::MAX_URDF_DEPTH {
                    return Err(ModelError::TooDeep {
                        origin: origin.to_owned(),
                        limit: RobotModel::MAX_URDF_DEPTH,
                    });
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_declarations_and_quoted_brackets_do_not_count() {
        let ok = r#"<?xml version="1.0"?><!DOCTYPE r [<!ENTITY a "b">]><!-- <x> <y> -->
            <robot name="a>b"><link name='c/>'/><![CDATA[<z>]]></robot><!-- after -->"#;
        assert!(check_shape(ok, "t").is_ok());
        let two = "<robot/><robot/>";
        assert!(matches!(
            check_shape(two, "t"),
            Err(ModelError::SeveralRoots { .. })
        ));
        let deep = "<a>".repeat(257);
        assert!(matches!(
            check_shape(&deep, "t"),
            Err(ModelError::TooDeep { .. })
        ));
        let fine = format!("{}{}", "<a>".repeat(256), "</a>".repeat(256));
        assert!(check_shape(&fine, "t").is_ok());
    }
}
