//! [`LinkVisual`]: a link's URDF `<visual>` elements — what a viewer draws, not what is
//! checked — with their materials' colours resolved as ROS's URDF parser resolves them.

use std::collections::HashMap;

use glam::{DAffine3, DVec3};

use super::robot_model::{LinkFrame, pose};
use crate::ModelError;

/// A visual element's shape, in its own frame (URDF conventions: boxes, cylinders, capsules
/// and spheres centred on the origin, cylinders and capsules along `z`).
#[derive(Debug, Clone, PartialEq)]
pub enum VisualGeometry {
    /// A mesh file as the URDF names it (`package://…`, relative or absolute), scaled per
    /// axis (a negative factor mirrors it).
    Mesh {
        /// The file name, unresolved.
        filename: String,
        /// The `<mesh scale>` (`1 1 1` when absent).
        scale: DVec3,
    },
    /// A box of these edge lengths.
    Box {
        /// Edge lengths along `x`, `y`, `z`.
        size: DVec3,
    },
    /// A cylinder.
    Cylinder {
        /// Radius.
        radius: f64,
        /// Length along `z`.
        length: f64,
    },
    /// A capsule: a cylinder with hemispherical caps beyond its length.
    Capsule {
        /// Radius.
        radius: f64,
        /// Length of the cylindrical part along `z`.
        length: f64,
    },
    /// A sphere.
    Sphere {
        /// Radius.
        radius: f64,
    },
}

/// One `<visual>` element of a link.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkVisual {
    /// Index of its link in [`RobotModel::links`](crate::RobotModel::links).
    pub link: usize,
    /// Its `<origin>`: the geometry's frame in the link frame.
    pub origin: DAffine3,
    /// Its shape.
    pub geometry: VisualGeometry,
    /// Its material's colour, RGBA: the element's own `<color>`, or the colour of the
    /// material it names (declared at the robot's top level or by an earlier visual element);
    /// `None` without one (a texture only, or no material).
    pub colour: Option<[f32; 4]>,
}

/// The visual elements of every link, in tree order (document order within a link).
///
/// Materials are resolved as ROS's URDF parser (`urdfdom`) does: a material named by a
/// visual element takes the colour of the material of that name declared at the top level of
/// the robot or, failing that, by an earlier link's visual element in document order; a
/// material not known by its name keeps its own `<color>` and becomes known by its name.
pub(super) fn read_visuals(
    urdf: &urdf_rs::Robot,
    links: &[LinkFrame],
) -> Result<Vec<LinkVisual>, ModelError> {
    let index: HashMap<&str, usize> = links
        .iter()
        .enumerate()
        .map(|(i, l)| (l.name.as_str(), i))
        .collect();
    let mut known: HashMap<String, Option<[f32; 4]>> = HashMap::new();
    for material in &urdf.materials {
        let colour = colour(material, "robot material")?;
        known.insert(material.name.clone(), colour);
    }
    let mut visuals = Vec::new();
    for link in &urdf.links {
        let Some(&link_index) = index.get(link.name.as_str()) else {
            continue;
        };
        for visual in &link.visual {
            let colour = match &visual.material {
                None => None,
                Some(m) => match known.get(&m.name) {
                    Some(c) if !m.name.is_empty() => *c,
                    _ => {
                        let own = colour(m, &link.name)?;
                        if !m.name.is_empty() {
                            known.insert(m.name.clone(), own);
                        }
                        own
                    }
                },
            };
            visuals.push(LinkVisual {
                link: link_index,
                origin: pose(&visual.origin, &link.name)?,
                geometry: geometry(&visual.geometry, &link.name)?,
                colour,
            });
        }
    }
    // Tree order, document order within a link (the sort is stable).
    visuals.sort_by_key(|v| v.link);
    Ok(visuals)
}

fn colour(material: &urdf_rs::Material, element: &str) -> Result<Option<[f32; 4]>, ModelError> {
    let Some(color) = &material.color else {
        return Ok(None);
    };
    let rgba = color.rgba.0;
    if let Some(&v) = rgba.iter().find(|v| !(0.0..=1.0).contains(*v)) {
        return Err(bad(element, "material colour (rgba in [0, 1])", v));
    }
    Ok(Some(rgba.map(|v| v as f32)))
}

fn geometry(g: &urdf_rs::Geometry, link: &str) -> Result<VisualGeometry, ModelError> {
    let length = |what: &'static str, v: f64| {
        if (0.0..=MAX_LENGTH).contains(&v) {
            Ok(v)
        } else {
            Err(bad(link, what, v))
        }
    };
    Ok(match g {
        urdf_rs::Geometry::Mesh { filename, scale } => {
            let scale = scale.map_or([1.0; 3], |s| s.0);
            if let Some(&v) = scale
                .iter()
                .find(|v| !(v.is_finite() && v.abs() <= MAX_LENGTH))
            {
                return Err(bad(link, "visual mesh scale (finite, within ±1e6)", v));
            }
            VisualGeometry::Mesh {
                filename: filename.clone(),
                scale: DVec3::from_array(scale),
            }
        }
        urdf_rs::Geometry::Box { size } => {
            for v in size.0 {
                length("visual box size (in [0, 1e6] m)", v)?;
            }
            VisualGeometry::Box {
                size: DVec3::from_array(size.0),
            }
        }
        &urdf_rs::Geometry::Cylinder { radius, length: l } => VisualGeometry::Cylinder {
            radius: length("visual cylinder radius (in [0, 1e6] m)", radius)?,
            length: length("visual cylinder length (in [0, 1e6] m)", l)?,
        },
        &urdf_rs::Geometry::Capsule { radius, length: l } => VisualGeometry::Capsule {
            radius: length("visual capsule radius (in [0, 1e6] m)", radius)?,
            length: length("visual capsule length (in [0, 1e6] m)", l)?,
        },
        &urdf_rs::Geometry::Sphere { radius } => VisualGeometry::Sphere {
            radius: length("visual sphere radius (in [0, 1e6] m)", radius)?,
        },
    })
}

const MAX_LENGTH: f64 = crate::Scene::MAX_LENGTH;

fn bad(element: &str, what: &'static str, value: f64) -> ModelError {
    ModelError::BadNumber {
        element: element.to_owned(),
        what,
        value,
    }
}

#[cfg(test)]
mod tests {
    use crate::RobotModel;

    use super::*;

    const URDF: &str = r#"<robot name="r">
  <material name="blue"><color rgba="0 0 1 1"/></material>
  <link name="base">
    <visual>
      <origin xyz="1 2 3" rpy="0 0 1.5707963267948966"/>
      <geometry><mesh filename="package://pkg/base.stl" scale="0.001 0.001 0.001"/></geometry>
      <material name="blue"/>
    </visual>
    <visual>
      <geometry><box size="1 2 3"/></geometry>
      <material name="red"><color rgba="1 0 0 1"/></material>
    </visual>
    <collision><geometry><sphere radius="0.1"/></geometry></collision>
  </link>
  <link name="tip">
    <visual><geometry><sphere radius="0.05"/></geometry><material name="red"/></visual>
    <visual><geometry><cylinder radius="0.1" length="0.5"/></geometry>
      <material name=""><color rgba="0.5 0.5 0.5 1"/></material></visual>
    <visual><geometry><sphere radius="0.05"/></geometry><material name="textured"/></visual>
  </link>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="tip"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
</robot>"#;

    #[test]
    fn visuals_carry_their_origin_geometry_and_resolved_colour() {
        let model = RobotModel::from_urdf_str(URDF).unwrap();
        let v = model.visuals();
        assert_eq!(v.len(), 5);
        assert_eq!(
            v.iter().map(|v| v.link).collect::<Vec<_>>(),
            [0, 0, 1, 1, 1]
        );
        assert_eq!(
            v[0].geometry,
            VisualGeometry::Mesh {
                filename: "package://pkg/base.stl".into(),
                scale: DVec3::splat(0.001)
            }
        );
        assert_eq!(v[0].origin.translation, DVec3::new(1.0, 2.0, 3.0));
        assert!((v[0].origin.transform_vector3(DVec3::X) - DVec3::Y).length() < 1e-12);
        // A top-level material by name; a link's own, later named by another link.
        assert_eq!(v[0].colour, Some([0.0, 0.0, 1.0, 1.0]));
        assert_eq!(v[1].colour, Some([1.0, 0.0, 0.0, 1.0]));
        assert_eq!(v[2].colour, Some([1.0, 0.0, 0.0, 1.0]));
        assert_eq!(v[3].colour, Some([0.5, 0.5, 0.5, 1.0]));
        assert_eq!(v[4].colour, None);
        assert_eq!(
            v[3].geometry,
            VisualGeometry::Cylinder {
                radius: 0.1,
                length: 0.5
            }
        );
    }

    #[test]
    fn a_top_level_material_wins_over_a_link_colour_of_the_same_name() {
        let urdf = URDF.replace(
            r#"<material name="red"><color rgba="1 0 0 1"/></material>"#,
            r#"<material name="blue"><color rgba="1 0 0 1"/></material>"#,
        );
        let model = RobotModel::from_urdf_str(&urdf).unwrap();
        assert_eq!(model.visuals()[1].colour, Some([0.0, 0.0, 1.0, 1.0]));
    }

    #[test]
    fn bad_visual_numbers_are_named() {
        for (from, to) in [
            (r#"radius="0.05""#, r#"radius="-0.05""#),
            (r#"size="1 2 3""#, r#"size="1 2 1e9""#),
            (r#"rgba="0 0 1 1""#, r#"rgba="0 0 2 1""#),
            (r#"xyz="1 2 3""#, r#"xyz="1 2 1e300""#),
        ] {
            let e = RobotModel::from_urdf_str(&URDF.replacen(from, to, 1)).unwrap_err();
            assert!(matches!(e, ModelError::BadNumber { .. }), "{to}: {e}");
        }
    }
}
