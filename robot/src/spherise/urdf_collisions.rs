//! The collision elements of a URDF's links, and where their mesh files are.

use std::ops::Range;
use std::path::{Path, PathBuf};

use glam::{DMat3, DVec3};

use super::mesh_resolver::{MeshResolver, ResolveError};
use super::spherise_error::SpheriseError;
use crate::model::rpy_matrix;

/// A collision element's geometry.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Geometry {
    /// A mesh file, scaled per axis.
    Mesh { filename: String, scale: DVec3 },
    /// A box of these edge lengths, centred.
    Cuboid(DVec3),
    /// A cylinder along `z`, centred.
    Cylinder { radius: f64, length: f64 },
    /// A sphere already.
    Sphere(f64),
}

/// One `<collision>` element: its pose in the link frame, geometry and place in the text.
#[derive(Debug, Clone)]
pub(super) struct Collision {
    pub(super) rotation: DMat3,
    pub(super) translation: DVec3,
    pub(super) geometry: Geometry,
    pub(super) range: Range<usize>,
}

/// A link and its collision elements, in document order.
#[derive(Debug, Clone)]
pub(super) struct LinkCollisions {
    pub(super) name: String,
    pub(super) collisions: Vec<Collision>,
}

/// The links of a URDF's text with their collision elements (links without any included).
pub(super) fn read_collisions(
    document: &roxmltree::Document<'_>,
    origin: &str,
) -> Result<Vec<LinkCollisions>, SpheriseError> {
    let root = document.root_element();
    if root.tag_name().name() != "robot" {
        return Err(SpheriseError::Urdf {
            origin: origin.to_owned(),
            message: format!(
                "the root element is `{}`, not `robot`",
                root.tag_name().name()
            ),
        });
    }
    let mut links = Vec::new();
    for link in root.children().filter(|n| n.has_tag_name("link")) {
        let name = link.attribute("name").ok_or_else(|| SpheriseError::Urdf {
            origin: origin.to_owned(),
            message: "a link without a name".into(),
        })?;
        let mut collisions = Vec::new();
        for element in link.children().filter(|n| n.has_tag_name("collision")) {
            collisions.push(collision(name, element, origin)?);
        }
        links.push(LinkCollisions {
            name: name.to_owned(),
            collisions,
        });
    }
    Ok(links)
}

fn collision(
    link: &str,
    element: roxmltree::Node<'_, '_>,
    origin: &str,
) -> Result<Collision, SpheriseError> {
    let child = |tag: &str| element.children().find(|n| n.has_tag_name(tag));
    let (rotation, translation) = match child("origin") {
        Some(o) => (
            rpy_matrix(numbers(link, "origin rpy", o.attribute("rpy"), [0.0; 3])?),
            DVec3::from_array(numbers(link, "origin xyz", o.attribute("xyz"), [0.0; 3])?),
        ),
        None => (DMat3::IDENTITY, DVec3::ZERO),
    };
    let shape = child("geometry")
        .and_then(|g| g.children().find(roxmltree::Node::is_element))
        .ok_or_else(|| SpheriseError::Urdf {
            origin: origin.to_owned(),
            message: format!("link `{link}`: a collision without geometry"),
        })?;
    let one = |what: &'static str, attribute: &str| {
        numbers::<1>(link, what, shape.attribute(attribute), [f64::NAN]).and_then(|[v]| {
            if v.is_finite() && v >= 0.0 {
                Ok(v)
            } else {
                Err(bad(link, what, shape.attribute(attribute).unwrap_or(""), 1))
            }
        })
    };
    let geometry = match shape.tag_name().name() {
        "mesh" => Geometry::Mesh {
            filename: shape
                .attribute("filename")
                .ok_or_else(|| bad(link, "mesh filename", "", 1))?
                .to_owned(),
            scale: DVec3::from_array(numbers(
                link,
                "mesh scale",
                shape.attribute("scale"),
                [1.0; 3],
            )?),
        },
        "box" => Geometry::Cuboid(DVec3::from_array(numbers(
            link,
            "box size",
            shape.attribute("size"),
            [f64::NAN; 3],
        )?)),
        "cylinder" => Geometry::Cylinder {
            radius: one("cylinder radius", "radius")?,
            length: one("cylinder length", "length")?,
        },
        "sphere" => Geometry::Sphere(one("sphere radius", "radius")?),
        other => {
            return Err(SpheriseError::Urdf {
                origin: origin.to_owned(),
                message: format!("link `{link}`: unknown collision geometry `{other}`"),
            });
        }
    };
    Ok(Collision {
        rotation,
        translation,
        geometry,
        range: element.range(),
    })
}

/// `N` numbers from an attribute (`default` when it is absent).
fn numbers<const N: usize>(
    link: &str,
    what: &'static str,
    text: Option<&str>,
    default: [f64; N],
) -> Result<[f64; N], SpheriseError> {
    let Some(text) = text else {
        return if default.iter().all(|v| v.is_finite()) {
            Ok(default)
        } else {
            Err(bad(link, what, "", N))
        };
    };
    let values: Vec<f64> = text
        .split_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .map_err(|_| bad(link, what, text, N))?;
    match <[f64; N]>::try_from(values) {
        Ok(v) if v.iter().all(|x| x.is_finite()) => Ok(v),
        _ => Err(bad(link, what, text, N)),
    }
}

fn bad(link: &str, what: &'static str, text: &str, count: usize) -> SpheriseError {
    SpheriseError::BadNumber {
        link: link.to_owned(),
        what,
        text: text.to_owned(),
        count,
    }
}

/// Where a mesh file named in a URDF is, as [`MeshResolver`] finds it (`urdf_folder` for
/// relative names, then the package roots). `Ok(Err(tried))` when the name is understood but
/// no such file exists.
pub(super) fn resolve(
    link: &str,
    filename: &str,
    urdf_folder: &Path,
    package_roots: &[PathBuf],
) -> Result<Result<PathBuf, Vec<PathBuf>>, SpheriseError> {
    let resolver = MeshResolver::new(Some(urdf_folder.to_owned()), package_roots.to_vec());
    match resolver.resolve(filename) {
        Ok(path) => Ok(Ok(path)),
        Err(ResolveError::NotFound { tried, .. }) => Ok(Err(tried)),
        Err(ResolveError::NoPackageRoot { .. }) => Err(SpheriseError::UnknownPackage {
            link: link.to_owned(),
            uri: filename.to_owned(),
            tried: "no package root given".into(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const URDF: &str = r#"<robot name="r">
  <link name="a">
    <collision>
      <origin xyz="0 0 1" rpy="0 0 1.5707963267948966"/>
      <geometry><mesh filename="package://pkg/m.stl" scale="0.001 0.001 0.001"/></geometry>
    </collision>
    <collision><geometry><box size="1 2 3"/></geometry></collision>
  </link>
  <link name="b"><collision><geometry><cylinder radius="0.1" length="0.5"/></geometry></collision></link>
  <link name="c"/>
</robot>"#;

    #[test]
    fn collision_elements_are_read_with_their_poses() {
        let document = roxmltree::Document::parse(URDF).unwrap();
        let links = read_collisions(&document, "test").unwrap();
        assert_eq!(links.len(), 3);
        assert_eq!(links[0].collisions.len(), 2);
        let mesh = &links[0].collisions[0];
        assert_eq!(
            mesh.geometry,
            Geometry::Mesh {
                filename: "package://pkg/m.stl".into(),
                scale: DVec3::splat(0.001)
            }
        );
        assert!((mesh.rotation * DVec3::X - DVec3::Y).length() < 1e-12);
        assert_eq!(mesh.translation, DVec3::Z);
        assert!(URDF[mesh.range.clone()].starts_with("<collision>"));
        assert_eq!(
            links[0].collisions[1].geometry,
            Geometry::Cuboid(DVec3::new(1.0, 2.0, 3.0))
        );
        assert_eq!(
            links[1].collisions[0].geometry,
            Geometry::Cylinder {
                radius: 0.1,
                length: 0.5
            }
        );
        assert!(links[2].collisions.is_empty());
    }

    #[test]
    fn bad_numbers_and_geometry_are_errors() {
        for bad in [
            URDF.replace("0 0 1\"", "0 0\""),
            URDF.replace("size=\"1 2 3\"", "size=\"1 2 x\""),
            URDF.replace("radius=\"0.1\"", "radius=\"-0.1\""),
            URDF.replace("<box size=\"1 2 3\"/>", "<capsule/>"),
        ] {
            let document = roxmltree::Document::parse(&bad).unwrap();
            assert!(read_collisions(&document, "test").is_err(), "{bad}");
        }
    }

    #[test]
    fn package_addresses_need_a_root() {
        let here = Path::new(".");
        assert!(matches!(
            resolve("a", "package://pkg/m.stl", here, &[]),
            Err(SpheriseError::UnknownPackage { .. })
        ));
        let roots = [PathBuf::from("/nonexistent")];
        let tried = resolve("a", "package://pkg/m.stl", here, &roots)
            .unwrap()
            .unwrap_err();
        assert_eq!(
            tried,
            [
                PathBuf::from("/nonexistent/pkg/m.stl"),
                PathBuf::from("/nonexistent/m.stl")
            ]
        );
        let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
        let found = resolve(
            "a",
            "package://robot/Cargo.toml",
            here,
            &[manifest.join("..")],
        )
        .unwrap();
        assert_eq!(found, Ok(manifest.join("../robot/Cargo.toml")));
    }
}
