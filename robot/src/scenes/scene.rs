//! [`Scene`]: the obstacles around a robot, read from MoveIt's planning-scene YAML.

use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

use glam::{DAffine3, DQuat, DVec3};
use serde::Deserialize;
use serde::de::IgnoredAny;

use crate::{CloudObstacle, Obstacle, SceneError, Shape};

/// The obstacles of a planning scene, in the robot's base frame, and the robot link pairs the
/// scene allows to touch (its allowed-collision matrix); and point clouds
/// ([`CloudObstacle`], added with [`with_cloud`](Self::with_cloud)), checked and certified
/// as the primitives are.
///
/// Reads the MoveIt `PlanningScene` YAML of MotionBenchMaker: `world.collision_objects[]` with
/// `primitives[]` (`type: box` with full side lengths, `cylinder` with `[height, radius]` along
/// the local z axis, `sphere` with `[radius]`) and `primitive_poses[]` (`position` x, y, z,
/// `orientation` quaternion x, y, z, w), each relative to the object's optional `pose`.
///
/// What is accepted, and what is refused with an error naming the file, the field and the value:
/// - The file must have a `world` field: a file without one (an empty file, a request, a typo)
///   is not a planning scene. A world without objects (`world: {collision_objects: []}`,
///   `world: {}`) is an empty scene, as in MoveIt, and so is an explicit `world: null`.
/// - Every coordinate of a position is finite and within ±[`MAX_LENGTH`](Self::MAX_LENGTH)
///   (10⁶ m); every size (box sides, cylinder height and radius, sphere radius) is in
///   (0, [`MAX_LENGTH`](Self::MAX_LENGTH)].
/// - A quaternion has finite components and a norm, computed without overflow, that is finite
///   and at least [`MIN_QUATERNION_NORM`](Self::MIN_QUATERNION_NORM); it is normalised (so
///   `[0, 0, 0, 2]` is the identity).
/// - Object ids are unique (MoveIt would replace the first object by the second), and objects
///   hold only primitives: `meshes` or `planes` are refused rather than dropped.
/// - The allowed-collision matrix is square, symmetric, and names each link once.
///
/// ```
/// let scene = mit_star_robot::Scene::from_yaml_str(
///     "world:\n  collision_objects:\n    - id: table\n      primitives:\n        - type: box\n          dimensions: [1, 1, 0.1]\n      primitive_poses:\n        - position: [0.5, 0, -0.05]\n          orientation: [0, 0, 0, 1]\n",
///     "table.yaml",
/// )?;
/// assert_eq!(scene.obstacles().len(), 1);
/// assert_eq!(scene.ids(), ["table"]);
/// assert!(mit_star_robot::Scene::from_yaml_str("world: null", "empty.yaml")?.obstacles().is_empty());
/// assert!(mit_star_robot::Scene::from_yaml_str("name: not a scene", "request.yaml").is_err());
/// # Ok::<(), mit_star_robot::SceneError>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scene {
    obstacles: Vec<Obstacle>,
    ids: Vec<String>,
    allowed: Vec<(String, String)>,
    clouds: Vec<Arc<CloudObstacle>>,
}

#[derive(Deserialize)]
struct SceneFile {
    /// `None`: no `world` field; `Some(None)`: `world: null`.
    #[serde(default, deserialize_with = "present")]
    world: Option<Option<WorldMessage>>,
    #[serde(default)]
    allowed_collision_matrix: Option<AcmMessage>,
}

/// Deserialises a field that is present (perhaps as `null`), so that `Option<Option<T>>` tells
/// a missing field from a null one.
fn present<'de, D, T>(deserializer: D) -> Result<Option<T>, D::Error>
where
    D: serde::Deserializer<'de>,
    T: Deserialize<'de>,
{
    T::deserialize(deserializer).map(Some)
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
    #[serde(default)]
    meshes: Vec<IgnoredAny>,
    #[serde(default)]
    planes: Vec<IgnoredAny>,
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

/// What a coordinate must be (the text of [`SceneError::Number`]).
const COORDINATE: &str = "a coordinate within ±1e6 m";
/// What a size must be.
const SIZE: &str = "a size in (0, 1e6] m";
/// What a quaternion component must be.
const COMPONENT: &str = "a finite quaternion component";

/// Builds the errors of one file.
struct Errors<'a> {
    origin: &'a str,
}

impl Errors<'_> {
    fn field(&self, field: impl Into<String>, message: String) -> SceneError {
        SceneError::Field {
            origin: self.origin.to_owned(),
            field: field.into(),
            message,
        }
    }

    fn number(&self, field: String, value: f64, allowed: &'static str) -> SceneError {
        SceneError::Number {
            origin: self.origin.to_owned(),
            field,
            value,
            allowed,
        }
    }
}

impl Scene {
    /// The largest magnitude, in metres, of a coordinate or a size a scene file may hold
    /// (10⁶ m). Anything larger is a mistake in a robot's workspace, and would lose all
    /// precision in the checker's `f32` arithmetic (or overflow to infinity).
    pub const MAX_LENGTH: f64 = 1e6;

    /// The smallest norm of a quaternion a scene file may hold before normalisation: a smaller
    /// one is taken for the zero quaternion, which is no rotation.
    pub const MIN_QUATERNION_NORM: f64 = 1e-9;

    /// A scene of these obstacles (ids `obstacle0`, …) allowing nothing.
    pub fn new(obstacles: Vec<Obstacle>) -> Self {
        let ids = (0..obstacles.len())
            .map(|i| format!("obstacle{i}"))
            .collect();
        Self {
            obstacles,
            ids,
            allowed: Vec::new(),
            clouds: Vec::new(),
        }
    }

    /// Reads a scene file.
    ///
    /// # Errors
    /// [`SceneError::Io`] if it cannot be read, else as [`from_yaml_str`](Self::from_yaml_str).
    pub fn from_yaml_file(path: &Path) -> Result<Self, SceneError> {
        let text = mit_star_problems::read_bounded(
            path,
            mit_star_problems::TEXT_INPUT_LIMIT,
            "scene file",
        )
        .map_err(std::io::Error::from)
        .map_err(|source| SceneError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::from_yaml_str(&text, &path.display().to_string())
    }

    /// Reads a scene from YAML text; `origin` names it in errors (a file name).
    ///
    /// # Errors
    /// [`SceneError::Yaml`] for text that is not YAML of a planning scene's shape;
    /// [`SceneError::Number`] naming the field and the value for a coordinate, size or
    /// quaternion component out of range (see the type's documentation);
    /// [`SceneError::Field`] naming the field for a missing `world`, unknown primitive types,
    /// meshes and planes, wrong value counts, zero quaternions, repeated object ids,
    /// mismatched primitive and pose counts, and a malformed allowed-collision matrix.
    pub fn from_yaml_str(text: &str, origin: &str) -> Result<Self, SceneError> {
        let errors = Errors { origin };
        let file: SceneFile = crate::scenes::yaml_text::read_yaml(text, origin)?;
        let objects = match file.world {
            None => {
                return Err(errors.field(
                    "world",
                    "missing: this is not a MoveIt planning scene (a scene without obstacles \
                     says `world: {collision_objects: []}`)"
                        .into(),
                ));
            }
            Some(world) => world.map(|w| w.collision_objects).unwrap_or_default(),
        };
        let mut scene = Self::default();
        let mut ids = HashMap::new();
        for (o, object) in objects.iter().enumerate() {
            if let Some(first) = ids.insert(object.id.as_str(), o)
                && !object.id.is_empty()
            {
                return Err(errors.field(
                    format!("world.collision_objects[{o}].id"),
                    format!(
                        "`{}` is also the id of world.collision_objects[{first}] (ids must be \
                         unique: MoveIt would keep only the last)",
                        object.id
                    ),
                ));
            }
            scene.add_object(object, &format!("world.collision_objects[{o}]"), &errors)?;
        }
        if let Some(acm) = file.allowed_collision_matrix {
            scene.allowed = allowed_pairs(&acm, &errors)?;
        }
        Ok(scene)
    }

    /// Appends the obstacles of one collision object (`at` is its field path).
    fn add_object(
        &mut self,
        object: &ObjectMessage,
        at: &str,
        errors: &Errors<'_>,
    ) -> Result<(), SceneError> {
        for (kind, count) in [
            ("meshes", object.meshes.len()),
            ("planes", object.planes.len()),
        ] {
            if count > 0 {
                return Err(errors.field(
                    format!("{at}.{kind}"),
                    format!("{kind} are not supported (only primitives: box, cylinder, sphere)"),
                ));
            }
        }
        if object.primitives.len() != object.primitive_poses.len() {
            return Err(errors.field(
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
            Some(p) => pose(p, &format!("{at}.pose"), errors)?,
        };
        for (p, (primitive, placed)) in object
            .primitives
            .iter()
            .zip(&object.primitive_poses)
            .enumerate()
        {
            let shape = shape(primitive, &format!("{at}.primitives[{p}]"), errors)?;
            let local = pose(placed, &format!("{at}.primitive_poses[{p}]"), errors)?;
            let (_, rotation, position) = (base * local).to_scale_rotation_translation();
            self.obstacles
                .push(Obstacle::new(shape, position, rotation));
            self.ids.push(object.id.clone());
        }
        Ok(())
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

    /// The scene with `cloud` added to its obstacles (its tree was built with it; clones of
    /// the scene share it).
    pub fn with_cloud(mut self, cloud: CloudObstacle) -> Self {
        self.add_cloud(cloud);
        self
    }

    /// Adds `cloud` to the obstacles.
    pub fn add_cloud(&mut self, cloud: CloudObstacle) {
        self.clouds.push(Arc::new(cloud));
    }

    /// Adds `cloud`, shared with other scenes (its tree is not copied): the snapshots of a
    /// [`MovingScene`](crate::MovingScene) share its static cloud.
    pub fn add_shared_cloud(&mut self, cloud: Arc<CloudObstacle>) {
        self.clouds.push(cloud);
    }

    /// The point clouds, in the order they were added.
    pub fn clouds(&self) -> &[Arc<CloudObstacle>] {
        &self.clouds
    }

    /// The scene without its primitives (boxes, cylinders, spheres): its clouds and allowed
    /// collisions stay. A scene seen only through a camera: sample a cloud on the primitives
    /// first (`mit_star_robot::sample_surfaces`), then add it to this.
    #[must_use]
    pub fn without_primitives(mut self) -> Self {
        self.obstacles.clear();
        self.ids.clear();
        self
    }
}

/// The pairs an allowed-collision matrix allows, once a matrix that is square, symmetric and
/// names each link once.
fn allowed_pairs(
    acm: &AcmMessage,
    errors: &Errors<'_>,
) -> Result<Vec<(String, String)>, SceneError> {
    let names = &acm.entry_names;
    for (j, name) in names.iter().enumerate() {
        if let Some(i) = names[..j].iter().position(|n| n == name) {
            return Err(errors.field(
                format!("allowed_collision_matrix.entry_names[{j}]"),
                format!("`{name}` is also entry_names[{i}]"),
            ));
        }
    }
    let n = names.len();
    if acm.entry_values.len() != n {
        return Err(errors.field(
            "allowed_collision_matrix.entry_values",
            format!("{} rows for {n} entry_names", acm.entry_values.len()),
        ));
    }
    // Every row's length first, so that reading the mirror entry never goes out of bounds.
    if let Some((i, row)) = acm
        .entry_values
        .iter()
        .enumerate()
        .find(|(_, r)| r.len() != n)
    {
        return Err(errors.field(
            format!("allowed_collision_matrix.entry_values[{i}]"),
            format!("{} values for {n} entry_names", row.len()),
        ));
    }
    let mut allowed = Vec::new();
    for (i, row) in acm.entry_values.iter().enumerate() {
        for (j, (&value, mirror)) in row.iter().zip(&acm.entry_values).enumerate().skip(i + 1) {
            if value != mirror[i] {
                return Err(errors.field(
                    format!("allowed_collision_matrix.entry_values[{i}][{j}]"),
                    "the matrix is not symmetric".into(),
                ));
            }
            if value {
                allowed.push((names[i].clone(), names[j].clone()));
            }
        }
    }
    Ok(allowed)
}

/// The shape of a primitive (`at` is its field path).
fn shape(p: &PrimitiveMessage, at: &str, errors: &Errors<'_>) -> Result<Shape, SceneError> {
    let d = &p.dimensions;
    let (count, names) = match p.kind.as_str() {
        "box" => (3, "[x, y, z] side lengths"),
        "cylinder" => (2, "[height, radius]"),
        "sphere" => (1, "[radius]"),
        other => {
            return Err(errors.field(
                format!("{at}.type"),
                format!("`{other}` is not a supported primitive (box, cylinder, sphere)"),
            ));
        }
    };
    if d.len() != count {
        return Err(errors.field(
            format!("{at}.dimensions"),
            format!("a {} needs {count} values {names}, got {}", p.kind, d.len()),
        ));
    }
    if let Some((i, &v)) = d
        .iter()
        .enumerate()
        .find(|(_, v)| !(**v > 0.0 && **v <= Scene::MAX_LENGTH))
    {
        return Err(errors.number(format!("{at}.dimensions[{i}]"), v, SIZE));
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

/// A pose as a rigid transform, its quaternion normalised (`at` is its field path).
fn pose(p: &PoseMessage, at: &str, errors: &Errors<'_>) -> Result<DAffine3, SceneError> {
    let [x, y, z] = p.position[..] else {
        return Err(errors.field(
            format!("{at}.position"),
            format!("needs 3 values [x, y, z], got {}", p.position.len()),
        ));
    };
    let [qx, qy, qz, qw] = p.orientation[..] else {
        return Err(errors.field(
            format!("{at}.orientation"),
            format!("needs 4 values [x, y, z, w], got {}", p.orientation.len()),
        ));
    };
    for (i, v) in [x, y, z].into_iter().enumerate() {
        if !(-Scene::MAX_LENGTH..=Scene::MAX_LENGTH).contains(&v) {
            return Err(errors.number(format!("{at}.position[{i}]"), v, COORDINATE));
        }
    }
    let rotation = unit_quaternion([qx, qy, qz, qw]).map_err(|e| match e {
        Unusable::Component(i, v) => errors.number(format!("{at}.orientation[{i}]"), v, COMPONENT),
        Unusable::Norm(norm) => errors.field(
            format!("{at}.orientation"),
            if norm.is_finite() {
                format!(
                    "not a rotation: its norm {norm:e} is below {:e}",
                    Scene::MIN_QUATERNION_NORM
                )
            } else {
                "not a rotation: its norm overflows (beyond 1.8e308)".to_owned()
            },
        ),
    })?;
    Ok(DAffine3::from_rotation_translation(
        rotation,
        DVec3::new(x, y, z),
    ))
}

/// Why a quaternion is no rotation.
#[derive(Debug, PartialEq)]
enum Unusable {
    /// Component `.0` has the non-finite value `.1`.
    Component(usize, f64),
    /// The norm is below [`Scene::MIN_QUATERNION_NORM`], or beyond `f64::MAX` (infinite).
    Norm(f64),
}

/// The unit quaternion of `[x, y, z, w]`, its norm computed without overflow or underflow
/// (the components are first divided by the largest magnitude).
fn unit_quaternion(q: [f64; 4]) -> Result<DQuat, Unusable> {
    if let Some((i, &v)) = q.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(Unusable::Component(i, v));
    }
    let largest = q.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
    if largest == 0.0 {
        return Err(Unusable::Norm(0.0));
    }
    let scaled = DQuat::from_array(q.map(|v| v / largest));
    let length = scaled.length(); // in [1, 2]
    let norm = largest * length;
    if !(norm >= Scene::MIN_QUATERNION_NORM && norm.is_finite()) {
        return Err(Unusable::Norm(norm));
    }
    Ok(scaled / length)
}
