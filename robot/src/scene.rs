//! [`Scene`]: the obstacles around a robot, read from MoveIt's planning-scene YAML.

use std::path::Path;

use glam::{DAffine3, DQuat, DVec3};
use serde::Deserialize;

use crate::{Obstacle, SceneError, Shape};

/// The obstacles of a planning scene, in the robot's base frame, and the robot link pairs the
/// scene allows to touch (its allowed-collision matrix).
///
/// Reads the MoveIt `PlanningScene` YAML of MotionBenchMaker: `world.collision_objects[]` with
/// `primitives[]` (`type: box` with full side lengths, `cylinder` with `[height, radius]` along
/// the local z axis, `sphere` with `[radius]`) and `primitive_poses[]` (`position` x, y, z,
/// `orientation` quaternion x, y, z, w), each relative to the object's optional `pose`.
///
/// ```
/// let scene = robot::Scene::from_yaml_str(
///     "world:\n  collision_objects:\n    - id: table\n      primitives:\n        - type: box\n          dimensions: [1, 1, 0.1]\n      primitive_poses:\n        - position: [0.5, 0, -0.05]\n          orientation: [0, 0, 0, 1]\n",
///     "table.yaml",
/// )?;
/// assert_eq!(scene.obstacles().len(), 1);
/// assert_eq!(scene.ids(), ["table"]);
/// # Ok::<(), robot::SceneError>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scene {
    obstacles: Vec<Obstacle>,
    ids: Vec<String>,
    allowed: Vec<(String, String)>,
}

#[derive(Deserialize)]
struct SceneFile {
    #[serde(default)]
    world: Option<WorldMessage>,
    #[serde(default)]
    allowed_collision_matrix: Option<AcmMessage>,
}

#[derive(Deserialize)]
struct WorldMessage {
    #[serde(default)]
    collision_objects: Vec<ObjectMessage>,
}

#[derive(Deserialize)]
struct ObjectMessage {
    #[serde(default)]
    id: String,
    #[serde(default)]
    pose: Option<PoseMessage>,
    #[serde(default)]
    primitives: Vec<PrimitiveMessage>,
    #[serde(default)]
    primitive_poses: Vec<PoseMessage>,
}

#[derive(Deserialize)]
struct PrimitiveMessage {
    #[serde(rename = "type")]
    kind: String,
    #[serde(default)]
    dimensions: Vec<f64>,
}

#[derive(Deserialize)]
struct PoseMessage {
    position: Vec<f64>,
    orientation: Vec<f64>,
}

#[derive(Deserialize)]
struct AcmMessage {
    #[serde(default)]
    entry_names: Vec<String>,
    #[serde(default)]
    entry_values: Vec<Vec<bool>>,
}

impl Scene {
    /// A scene of these obstacles (ids `obstacle0`, …) allowing nothing.
    pub fn new(obstacles: Vec<Obstacle>) -> Self {
        let ids = (0..obstacles.len())
            .map(|i| format!("obstacle{i}"))
            .collect();
        Self {
            obstacles,
            ids,
            allowed: Vec::new(),
        }
    }

    /// Reads a scene file.
    ///
    /// # Errors
    /// [`SceneError::Io`] if it cannot be read, else as [`from_yaml_str`](Self::from_yaml_str).
    pub fn from_yaml_file(path: &Path) -> Result<Self, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::from_yaml_str(&text, &path.display().to_string())
    }

    /// Reads a scene from YAML text; `origin` names it in errors (a file name).
    ///
    /// # Errors
    /// [`SceneError::Yaml`] for text that is not YAML of a planning scene's shape,
    /// [`SceneError::Field`] naming the field for unknown primitive types, wrong dimension
    /// counts, non-positive or non-finite sizes, bad positions or quaternions, mismatched
    /// primitive and pose counts, and a malformed allowed-collision matrix.
    pub fn from_yaml_str(text: &str, origin: &str) -> Result<Self, SceneError> {
        let file: SceneFile = serde_saphyr::from_str(text).map_err(|e| SceneError::Yaml {
            origin: origin.to_owned(),
            message: e.to_string(),
        })?;
        let field = |field: String, message: String| SceneError::Field {
            origin: origin.to_owned(),
            field,
            message,
        };
        let mut scene = Self::default();
        let objects = file.world.map(|w| w.collision_objects).unwrap_or_default();
        for (o, object) in objects.iter().enumerate() {
            let at = format!("world.collision_objects[{o}]");
            if object.primitives.len() != object.primitive_poses.len() {
                return Err(field(
                    at,
                    format!(
                        "{} primitives but {} primitive_poses",
                        object.primitives.len(),
                        object.primitive_poses.len()
                    ),
                ));
            }
            let base = match &object.pose {
                None => DAffine3::IDENTITY,
                Some(p) => {
                    let (t, r) = pose(p).map_err(|m| field(format!("{at}.pose"), m))?;
                    DAffine3::from_rotation_translation(r, t)
                }
            };
            for (p, (primitive, placed)) in object
                .primitives
                .iter()
                .zip(&object.primitive_poses)
                .enumerate()
            {
                let shape = shape(primitive)
                    .map_err(|m| field(format!("{at}.primitives[{p}]{}", m.0), m.1))?;
                let (t, r) =
                    pose(placed).map_err(|m| field(format!("{at}.primitive_poses[{p}]"), m))?;
                let world = base * DAffine3::from_rotation_translation(r, t);
                let (_, rotation, position) = world.to_scale_rotation_translation();
                scene
                    .obstacles
                    .push(Obstacle::new(shape, position, rotation));
                scene.ids.push(object.id.clone());
            }
        }
        if let Some(acm) = file.allowed_collision_matrix {
            let n = acm.entry_names.len();
            if acm.entry_values.len() != n {
                return Err(field(
                    "allowed_collision_matrix.entry_values".into(),
                    format!("{} rows for {n} entry_names", acm.entry_values.len()),
                ));
            }
            // Every row's length first, so that reading the mirror entry never goes out of
            // bounds.
            if let Some((i, row)) = acm
                .entry_values
                .iter()
                .enumerate()
                .find(|(_, r)| r.len() != n)
            {
                return Err(field(
                    format!("allowed_collision_matrix.entry_values[{i}]"),
                    format!("{} values for {n} entry_names", row.len()),
                ));
            }
            for (i, row) in acm.entry_values.iter().enumerate() {
                for (j, (&value, mirror)) in
                    row.iter().zip(&acm.entry_values).enumerate().skip(i + 1)
                {
                    if value != mirror[i] {
                        return Err(field(
                            format!("allowed_collision_matrix.entry_values[{i}][{j}]"),
                            "the matrix is not symmetric".into(),
                        ));
                    }
                    if value {
                        let (a, b) = (&acm.entry_names[i], &acm.entry_names[j]);
                        scene.allowed.push((a.clone(), b.clone()));
                    }
                }
            }
        }
        Ok(scene)
    }

    /// The obstacles, one per primitive.
    pub fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }

    /// The id of the object each obstacle belongs to.
    pub fn ids(&self) -> &[String] {
        &self.ids
    }

    /// The link pairs the allowed-collision matrix allows to touch (each unordered pair once).
    pub fn allowed_pairs(&self) -> &[(String, String)] {
        &self.allowed
    }
}

/// The shape of a primitive, or the field suffix and message of what is wrong.
fn shape(p: &PrimitiveMessage) -> Result<Shape, (&'static str, String)> {
    let d = &p.dimensions;
    let (count, names) = match p.kind.as_str() {
        "box" => (3, "[x, y, z] side lengths"),
        "cylinder" => (2, "[height, radius]"),
        "sphere" => (1, "[radius]"),
        other => {
            return Err((
                ".type",
                format!("`{other}` is not a supported primitive (box, cylinder, sphere)"),
            ));
        }
    };
    if d.len() != count {
        return Err((
            ".dimensions",
            format!("a {} needs {count} values {names}, got {}", p.kind, d.len()),
        ));
    }
    if let Some(v) = d.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
        return Err((
            ".dimensions",
            format!("{v} is not a positive size ({names})"),
        ));
    }
    Ok(match count {
        3 => Shape::Cuboid {
            half_extents: DVec3::new(d[0], d[1], d[2]) / 2.0,
        },
        2 => Shape::Cylinder {
            half_height: d[0] / 2.0,
            radius: d[1],
        },
        _ => Shape::Sphere { radius: d[0] },
    })
}

/// A pose's translation and (normalised) rotation, or what is wrong with it.
fn pose(p: &PoseMessage) -> Result<(DVec3, DQuat), String> {
    let [x, y, z] = p.position[..] else {
        return Err(format!(
            "position needs 3 values [x, y, z], got {}",
            p.position.len()
        ));
    };
    let [qx, qy, qz, qw] = p.orientation[..] else {
        return Err(format!(
            "orientation needs 4 values [x, y, z, w], got {}",
            p.orientation.len()
        ));
    };
    if let Some(v) = [x, y, z, qx, qy, qz, qw]
        .into_iter()
        .find(|v| !v.is_finite())
    {
        return Err(format!("{v} is not a finite number"));
    }
    let q = DQuat::from_xyzw(qx, qy, qz, qw);
    let norm = q.length();
    if norm <= 1e-9 {
        return Err("orientation is the zero quaternion".into());
    }
    Ok((DVec3::new(x, y, z), q / norm))
}
