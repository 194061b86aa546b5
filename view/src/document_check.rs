//! [`ViewDocument::check`]: the document agrees with itself — sizes, indices, finite numbers.

use crate::{MotionView, RobotView, SceneView, SearchOverlay, ViewDocument, ViewError, ViewKind};

type Checked = Result<(), ViewError>;

fn all_finite(field: &str, values: &[f32]) -> Checked {
    match values.iter().position(|v| !v.is_finite()) {
        None => Ok(()),
        Some(i) => Err(ViewError::invalid(
            field,
            format!("value {i} is {} (not finite)", values[i]),
        )),
    }
}

fn multiple_of(field: &str, len: usize, k: usize, what: &str) -> Checked {
    if len.is_multiple_of(k) {
        Ok(())
    } else {
        Err(ViewError::invalid(
            field,
            format!("has {len} values, not a multiple of {k} ({what})"),
        ))
    }
}

fn length(field: &str, len: usize, expected: usize, formula: &str) -> Checked {
    if len == expected {
        Ok(())
    } else {
        Err(ViewError::invalid(
            field,
            format!("has {len} values, expected {formula} = {expected}"),
        ))
    }
}

fn non_negative(field: &str, value: f32) -> Checked {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(ViewError::invalid(
            field,
            format!("is {value}, expected a finite number ≥ 0"),
        ))
    }
}

fn check_robot(robot: &RobotView) -> Checked {
    if robot.hand >= robot.links.len() {
        return Err(ViewError::invalid(
            "robot.hand",
            format!(
                "is {}, but the robot has {} links",
                robot.hand,
                robot.links.len()
            ),
        ));
    }
    for (l, link) in robot.links.iter().enumerate() {
        let field = format!("robot.links[{l}] ({}).spheres", link.name);
        multiple_of(&field, link.spheres.len(), 4, "x, y, z, radius each")?;
        all_finite(&field, &link.spheres)?;
        for (s, sphere) in link.spheres.chunks_exact(4).enumerate() {
            non_negative(&format!("{field}[{s}].radius"), sphere[3])?;
        }
        for (m, mesh) in link.meshes.iter().enumerate() {
            let field = format!("robot.links[{l}] ({}).meshes[{m}]", link.name);
            multiple_of(
                &format!("{field}.positions"),
                mesh.positions.len(),
                3,
                "x, y, z each",
            )?;
            all_finite(&format!("{field}.positions"), &mesh.positions)?;
            all_finite(&format!("{field}.colour"), &mesh.colour)?;
            multiple_of(
                &format!("{field}.indices"),
                mesh.indices.len(),
                3,
                "three a triangle",
            )?;
            let vertices = mesh.positions.len() / 3;
            if let Some(&i) = mesh.indices.iter().find(|&&i| i as usize >= vertices) {
                return Err(ViewError::invalid(
                    format!("{field}.indices"),
                    format!("index {i} ≥ {vertices} vertices"),
                ));
            }
        }
    }
    Ok(())
}

fn check_scene(scene: &SceneView) -> Checked {
    let solids = scene
        .solids
        .iter()
        .enumerate()
        .map(|(i, s)| ("solids", i, s));
    let movers = scene
        .movers
        .iter()
        .enumerate()
        .map(|(i, s)| ("movers", i, s));
    for (list, i, solid) in solids.chain(movers) {
        let field = format!("scene.{list}[{i}] ({})", solid.name);
        all_finite(&format!("{field}.position"), &solid.position)?;
        all_finite(&format!("{field}.rotation"), &solid.rotation)?;
        if solid.rotation.iter().map(|v| v * v).sum::<f32>() < 1e-12 {
            return Err(ViewError::invalid(
                format!("{field}.rotation"),
                "is the zero quaternion",
            ));
        }
        let sizes: &[f32] = match &solid.shape {
            crate::ShapeView::Cuboid { half_extents } => half_extents,
            crate::ShapeView::Sphere { radius } => std::slice::from_ref(radius),
            crate::ShapeView::Cylinder {
                radius,
                half_height,
            } => &[*radius, *half_height],
        };
        for &size in sizes {
            non_negative(&format!("{field}.shape"), size)?;
        }
    }
    for (i, cloud) in scene.clouds.iter().enumerate() {
        let field = format!("scene.clouds[{i}] ({})", cloud.name);
        multiple_of(
            &format!("{field}.points"),
            cloud.points.len(),
            3,
            "x, y, z each",
        )?;
        all_finite(&format!("{field}.points"), &cloud.points)?;
        non_negative(&format!("{field}.radius"), cloud.radius)?;
    }
    if let Some([lo, hi]) = &scene.bounds {
        all_finite("scene.bounds", &[lo.as_slice(), hi.as_slice()].concat())?;
        if lo.iter().zip(hi).any(|(a, b)| a > b) {
            return Err(ViewError::invalid(
                "scene.bounds",
                format!("lower corner {lo:?} is above the upper corner {hi:?}"),
            ));
        }
    }
    Ok(())
}

fn check_frames(field: &str, frames: &[usize], n: usize) -> Checked {
    match frames.iter().find(|&&f| f >= n) {
        None => Ok(()),
        Some(f) => Err(ViewError::invalid(field, format!("frame {f} ≥ {n} frames"))),
    }
}

fn check_motion(
    k: usize,
    motion: &MotionView,
    pose_width: usize,
    what: &str,
    movers: usize,
) -> Checked {
    let field = |name: &str| format!("motions[{k}] ({}).{name}", motion.label);
    let n = motion.frames;
    if n == 0 {
        return Err(ViewError::invalid(
            field("frames"),
            "is 0: a motion needs a frame",
        ));
    }
    let dof = motion.joint_names.len();
    length(
        &field("joints"),
        motion.joints.len(),
        n * dof,
        &format!("frames × joints = {n} × {dof}"),
    )?;
    all_finite(&field("joints"), &motion.joints)?;
    length(
        &field("poses"),
        motion.poses.len(),
        n * pose_width,
        &format!("frames × {what} = {n} × {pose_width}"),
    )?;
    all_finite(&field("poses"), &motion.poses)?;
    if let Some(times) = &motion.times {
        if times.len() != n {
            return Err(ViewError::invalid(
                field("times"),
                format!("has {} values for {n} frames", times.len()),
            ));
        }
        if let Some(i) = times.iter().position(|t| !t.is_finite()) {
            return Err(ViewError::invalid(
                field("times"),
                format!("time {i} is {} (not finite)", times[i]),
            ));
        }
        if let Some(i) = times.windows(2).position(|w| w[1] < w[0]) {
            return Err(ViewError::invalid(
                field("times"),
                format!("time {} is before time {i}", i + 1),
            ));
        }
    }
    length(
        &field("mover_positions"),
        motion.mover_positions.len(),
        if motion.mover_positions.is_empty() {
            0
        } else {
            n * movers * 3
        },
        &format!("frames × movers × 3 = {n} × {movers} × 3, or none"),
    )?;
    all_finite(&field("mover_positions"), &motion.mover_positions)?;
    check_frames(&field("waypoints"), &motion.waypoints, n)?;
    check_frames(&field("colliding"), &motion.colliding, n)
}

fn check_search(search: &SearchOverlay) -> Checked {
    multiple_of(
        "search.segments",
        search.segments.len(),
        6,
        "x0, y0, z0, x1, y1, z1 each",
    )?;
    all_finite("search.segments", &search.segments)?;
    let n = search.segments.len() / 6;
    length("search.costs", search.costs.len(), n, "one per segment")?;
    if let Some(i) = search.costs.iter().position(|c| c.is_nan()) {
        return Err(ViewError::invalid(
            "search.costs",
            format!("cost {i} is NaN"),
        ));
    }
    if let Some(informed) = &search.informed {
        all_finite("search.informed.start", &informed.start)?;
        all_finite("search.informed.goal", &informed.goal)?;
        non_negative("search.informed.cost", informed.cost)?;
    }
    Ok(())
}

impl ViewDocument {
    /// Checks that the document agrees with itself: an arm has a robot and a box world none,
    /// array lengths match their counts (`poses` = frames × links × 7 for an arm, frames × 3
    /// in a box world; `joints` = frames × joint names), frame indices and the hand are in
    /// range, every position is finite.
    ///
    /// # Errors
    /// [`ViewError::Invalid`] naming the first field found wrong and what is wrong with it.
    pub fn check(&self) -> Result<(), ViewError> {
        let (pose_width, what) = match (self.kind, &self.robot) {
            (ViewKind::Arm, Some(robot)) => (robot.links.len() * 7, "links × 7"),
            (ViewKind::Arm, None) => {
                return Err(ViewError::invalid("robot", "an arm view has no robot"));
            }
            (_, Some(_)) => {
                return Err(ViewError::invalid(
                    "robot",
                    "a box world draws a point, not a robot",
                ));
            }
            (_, None) => (3, "3"),
        };
        if let Some(robot) = &self.robot {
            check_robot(robot)?;
        }
        check_scene(&self.scene)?;
        for (k, motion) in self.motions.iter().enumerate() {
            check_motion(k, motion, pose_width, what, self.scene.movers.len())?;
        }
        if let Some(search) = &self.search {
            check_search(search)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{InformedView, LinkView, MeshView, ShapeView, SolidView};

    fn world(frames: usize) -> ViewDocument {
        let mut doc = ViewDocument::new(ViewKind::World2d, "w");
        doc.motions.push(MotionView {
            label: "plan".into(),
            joint_names: vec!["x".into(), "y".into()],
            frames,
            joints: vec![0.5; frames * 2],
            poses: vec![0.5; frames * 3],
            times: None,
            waypoints: vec![0],
            colliding: Vec::new(),
            mover_positions: Vec::new(),
        });
        doc
    }

    fn arm() -> ViewDocument {
        let mut doc = ViewDocument::new(ViewKind::Arm, "a");
        doc.robot = Some(RobotView {
            name: "r".into(),
            links: vec![LinkView {
                name: "l".into(),
                spheres: vec![0.0, 0.0, 0.0, 0.1],
                meshes: vec![MeshView {
                    positions: vec![0.0; 9],
                    indices: vec![0, 1, 2],
                    colour: [0.5; 3],
                }],
            }],
            hand: 0,
        });
        doc
    }

    fn problem(doc: &ViewDocument) -> String {
        doc.check().unwrap_err().to_string()
    }

    #[test]
    fn consistent_documents_pass() {
        world(4).check().unwrap();
        arm().check().unwrap();
    }

    #[test]
    fn lengths_that_do_not_match_their_counts_are_named() {
        let mut doc = world(4);
        doc.motions[0].poses.push(1.0);
        let text = problem(&doc);
        assert!(
            text.contains("motions[0] (plan).poses") && text.contains("= 12"),
            "{text}"
        );
        let mut doc = world(4);
        doc.motions[0].joints.pop();
        assert!(problem(&doc).contains("frames × joints = 4 × 2"));
        let mut doc = world(4);
        doc.motions[0].times = Some(vec![0.0, 1.0]);
        assert!(problem(&doc).contains("2 values for 4 frames"));
        let mut doc = world(3);
        doc.motions[0].times = Some(vec![0.0, 2.0, 1.0]);
        assert!(problem(&doc).contains("time 2 is before time 1"));
    }

    #[test]
    fn frame_indices_and_the_hand_must_be_in_range() {
        let mut doc = world(4);
        doc.motions[0].waypoints = vec![0, 4];
        assert!(problem(&doc).contains("waypoints: frame 4 ≥ 4 frames"));
        let mut doc = world(4);
        doc.motions[0].colliding = vec![9];
        assert!(problem(&doc).contains("colliding: frame 9"));
        assert!(problem(&world(0)).contains("frames: is 0"));
        let mut doc = arm();
        doc.robot.as_mut().unwrap().hand = 1;
        assert!(problem(&doc).contains("robot.hand: is 1, but the robot has 1 links"));
        let mut doc = arm();
        doc.robot.as_mut().unwrap().links[0].meshes[0].indices[2] = 3;
        assert!(problem(&doc).contains("index 3 ≥ 3 vertices"));
    }

    #[test]
    fn non_finite_numbers_are_refused() {
        let mut doc = world(2);
        doc.motions[0].poses[4] = f32::NAN;
        assert!(problem(&doc).contains("value 4 is NaN"));
        let mut doc = world(2);
        doc.scene.solids.push(SolidView {
            name: "b".into(),
            shape: ShapeView::Sphere { radius: 1.0 },
            position: [0.0, f32::INFINITY, 0.0],
            rotation: [0.0, 0.0, 0.0, 1.0],
        });
        assert!(problem(&doc).contains("scene.solids[0] (b).position"));
        let mut doc = world(2);
        doc.scene.bounds = Some([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
        assert!(problem(&doc).contains("is above the upper corner"));
        let mut doc = world(2);
        doc.search = Some(SearchOverlay {
            segments: vec![0.0; 6],
            costs: vec![f32::INFINITY],
            informed: Some(InformedView {
                start: [0.0; 3],
                goal: [1.0, 0.0, 0.0],
                cost: -1.0,
            }),
            label: "s".into(),
        });
        assert!(
            problem(&doc).contains("search.informed.cost"),
            "∞ costs are fine"
        );
    }

    #[test]
    fn the_kind_decides_whether_there_is_a_robot() {
        let mut doc = arm();
        doc.robot = None;
        assert!(problem(&doc).contains("an arm view has no robot"));
        let mut doc = world(1);
        doc.robot = arm().robot;
        assert!(problem(&doc).contains("a box world draws a point"));
    }
}
