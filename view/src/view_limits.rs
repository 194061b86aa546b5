//! [`ViewLimits`]: how much one page draws at most, and the decimation that keeps a document
//! within them, saying in the page's notes what was dropped.

use crate::{CloudView, MotionView, SearchOverlay, ShapeView, SolidView, ViewDocument};

/// Caps on what one page draws, so that it opens in a few seconds whatever the plan.
///
/// With the defaults, a page holding all at once a 10⁶-frame motion, 10⁵ boxes, a 10⁶-point
/// cloud and 10⁶ search edges is 15 MB and opens in under 3 s in headless Chromium with
/// software WebGL on one core; each alone gives about 4 MB and 1–2 s
/// (`view/examples/sample_views.rs` makes such pages, `view/web/browser_check.mjs` times them).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ViewLimits {
    /// Frames kept of each motion (at least 2: the first and the last are always kept).
    pub frames_per_motion: usize,
    /// Cloud points kept over all clouds.
    pub cloud_points: usize,
    /// Solids kept (the largest).
    pub solids: usize,
    /// Search segments kept.
    pub search_segments: usize,
    /// Mesh triangles over all links; past it the robot is drawn as its spheres.
    pub mesh_triangles: usize,
}

impl Default for ViewLimits {
    fn default() -> Self {
        Self {
            frames_per_motion: 20_000,
            cloud_points: 250_000,
            solids: 20_000,
            search_segments: 100_000,
            mesh_triangles: 300_000,
        }
    }
}

/// `n` with thin groups of three digits: `1 000 000`.
pub(crate) fn grouped(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(' ');
        }
        out.push(c);
    }
    out
}

/// "every 5th", "every 2nd", "every 21st".
fn every(stride: usize) -> String {
    let suffix = match (stride % 10, stride % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("every {}{suffix}", grouped(stride))
}

/// The indices kept of `n` frames, at most `cap` (≥ 2), evenly, the first and the last kept.
fn kept_frames(n: usize, cap: usize) -> (Vec<usize>, usize) {
    let cap = cap.max(2);
    if n <= cap {
        return ((0..n).collect(), 1);
    }
    let stride = (n - 1).div_ceil(cap - 1);
    let mut kept: Vec<usize> = (0..n).step_by(stride).collect();
    if kept.last() != Some(&(n - 1)) {
        kept.push(n - 1);
    }
    (kept, stride)
}

/// `frames` (indices into the original) moved to the nearest kept frame, ascending, unique.
fn remap(frames: &[usize], stride: usize, kept: usize) -> Vec<usize> {
    let mut out: Vec<usize> = frames
        .iter()
        .map(|&f| ((f + stride / 2) / stride).min(kept - 1))
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

fn decimate_motion(motion: &MotionView, cap: usize, pose_width: usize) -> (MotionView, String) {
    let (kept, stride) = kept_frames(motion.frames, cap);
    let dof = motion.joint_names.len();
    let take = |values: &[f32], width: usize| -> Vec<f32> {
        kept.iter()
            .flat_map(|&f| &values[f * width..(f + 1) * width])
            .copied()
            .collect()
    };
    let decimated = MotionView {
        label: motion.label.clone(),
        joint_names: motion.joint_names.clone(),
        frames: kept.len(),
        joints: take(&motion.joints, dof),
        poses: take(&motion.poses, pose_width),
        times: motion
            .times
            .as_ref()
            .map(|t| kept.iter().map(|&f| t[f]).collect()),
        waypoints: remap(&motion.waypoints, stride, kept.len()),
        colliding: remap(&motion.colliding, stride, kept.len()),
        mover_positions: take(
            &motion.mover_positions,
            motion
                .mover_positions
                .len()
                .checked_div(motion.frames)
                .unwrap_or(0),
        ),
    };
    let note = format!(
        "motion \"{}\": {} frames, {} drawn ({}); waypoints and collisions shown at the nearest drawn frame",
        motion.label,
        grouped(motion.frames),
        grouped(kept.len()),
        every(stride)
    );
    (decimated, note)
}

fn decimate_clouds(clouds: &[CloudView], cap: usize) -> Option<(Vec<CloudView>, String)> {
    let total: usize = clouds.iter().map(|c| c.points.len() / 3).sum();
    if total <= cap {
        return None;
    }
    let stride = total.div_ceil(cap.max(1));
    let kept: Vec<CloudView> = clouds
        .iter()
        .map(|c| CloudView {
            name: c.name.clone(),
            points: c
                .points
                .chunks_exact(3)
                .step_by(stride)
                .flatten()
                .copied()
                .collect(),
            radius: c.radius,
        })
        .collect();
    let drawn: usize = kept.iter().map(|c| c.points.len() / 3).sum();
    let note = format!(
        "cloud: {} points, {} drawn ({})",
        grouped(total),
        grouped(drawn),
        every(stride)
    );
    Some((kept, note))
}

fn volume(solid: &SolidView) -> f32 {
    match solid.shape {
        ShapeView::Cuboid {
            half_extents: [x, y, z],
        } => 8.0 * x * y * z,
        ShapeView::Sphere { radius } => 4.0 / 3.0 * std::f32::consts::PI * radius.powi(3),
        ShapeView::Cylinder {
            radius,
            half_height,
        } => std::f32::consts::TAU * radius * radius * half_height,
    }
}

fn decimate_solids(solids: &[SolidView], cap: usize) -> Option<(Vec<SolidView>, String)> {
    if solids.len() <= cap {
        return None;
    }
    let mut order: Vec<usize> = (0..solids.len()).collect();
    order.sort_by(|&a, &b| volume(&solids[b]).total_cmp(&volume(&solids[a])));
    order.truncate(cap);
    order.sort_unstable();
    let note = format!(
        "solids: {}, {} drawn (the largest)",
        grouped(solids.len()),
        grouped(cap)
    );
    Some((order.into_iter().map(|i| solids[i].clone()).collect(), note))
}

fn decimate_search(search: &SearchOverlay, cap: usize) -> Option<(SearchOverlay, String)> {
    let n = search.costs.len();
    if n <= cap {
        return None;
    }
    let stride = n.div_ceil(cap.max(1));
    let decimated = SearchOverlay {
        segments: search
            .segments
            .chunks_exact(6)
            .step_by(stride)
            .flatten()
            .copied()
            .collect(),
        costs: search.costs.iter().step_by(stride).copied().collect(),
        informed: search.informed,
        label: search.label.clone(),
    };
    let note = format!(
        "search: {} segments, {} drawn ({})",
        grouped(n),
        grouped(decimated.costs.len()),
        every(stride)
    );
    Some((decimated, note))
}

impl ViewLimits {
    /// No caps: every frame, point, solid, segment and triangle is drawn.
    pub fn unlimited() -> Self {
        Self {
            frames_per_motion: usize::MAX,
            cloud_points: usize::MAX,
            solids: usize::MAX,
            search_segments: usize::MAX,
            mesh_triangles: usize::MAX,
        }
    }

    /// `doc` within these limits: motions keep evenly spaced frames (the first and last among
    /// them; waypoints and collisions move to the nearest kept frame), clouds every k-th point,
    /// solids the largest, the search every k-th segment, and meshes past the triangle cap give
    /// way to spheres. Each cut adds a note saying what was dropped.
    ///
    /// `doc` must pass [`ViewDocument::check`] (lengths are trusted here).
    pub fn decimate(&self, doc: &ViewDocument) -> ViewDocument {
        let mut notes = doc.notes.clone();
        let pose_width = doc.robot.as_ref().map_or(3, |r| r.links.len() * 7);
        let motions = doc
            .motions
            .iter()
            .map(|m| {
                if m.frames <= self.frames_per_motion.max(2) {
                    return m.clone();
                }
                let (decimated, note) = decimate_motion(m, self.frames_per_motion, pose_width);
                notes.push(note);
                decimated
            })
            .collect();
        let mut scene = doc.scene.clone();
        if let Some((clouds, note)) = decimate_clouds(&doc.scene.clouds, self.cloud_points) {
            scene.clouds = clouds;
            notes.push(note);
        }
        if let Some((solids, note)) = decimate_solids(&doc.scene.solids, self.solids) {
            scene.solids = solids;
            notes.push(note);
        }
        let search = doc.search.as_ref().map(|s| {
            decimate_search(s, self.search_segments).map_or_else(
                || s.clone(),
                |(decimated, note)| {
                    notes.push(note);
                    decimated
                },
            )
        });
        let mut robot = doc.robot.clone();
        if let Some(robot) = &mut robot {
            let triangles: usize = robot
                .links
                .iter()
                .flat_map(|l| &l.meshes)
                .map(|m| m.indices.len() / 3)
                .sum();
            if triangles > self.mesh_triangles {
                for link in &mut robot.links {
                    link.meshes.clear();
                }
                notes.push(format!(
                    "meshes: {} triangles, over the cap of {}: spheres shown",
                    grouped(triangles),
                    grouped(self.mesh_triangles)
                ));
            }
        }
        ViewDocument {
            title: doc.title.clone(),
            subtitle: doc.subtitle.clone(),
            notes,
            kind: doc.kind,
            robot,
            scene,
            motions,
            search,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ViewKind;

    fn world(frames: usize) -> ViewDocument {
        let mut doc = ViewDocument::new(ViewKind::World3d, "w");
        doc.motions.push(MotionView {
            label: "plan".into(),
            joint_names: vec!["x".into()],
            frames,
            joints: (0..frames).map(|f| f as f32).collect(),
            poses: (0..frames * 3).map(|v| v as f32).collect(),
            times: Some((0..frames).map(|f| f as f64).collect()),
            waypoints: vec![0, 7, frames - 1],
            colliding: vec![3, 4, 5, frames - 2],
            mover_positions: Vec::new(),
        });
        doc
    }

    #[test]
    fn numbers_are_grouped_and_strides_ordinal() {
        assert_eq!(grouped(0), "0");
        assert_eq!(grouped(999), "999");
        assert_eq!(grouped(1_000_000), "1 000 000");
        assert_eq!(every(2), "every 2nd");
        assert_eq!(every(5), "every 5th");
        assert_eq!(every(11), "every 11th");
        assert_eq!(every(21), "every 21st");
        assert_eq!(every(103), "every 103rd");
    }

    #[test]
    fn a_long_motion_keeps_its_ends_and_marks_within_the_cap() {
        let limits = ViewLimits {
            frames_per_motion: 10,
            ..ViewLimits::default()
        };
        let doc = limits.decimate(&world(1001));
        let m = &doc.motions[0];
        // Stride ⌈1000 / 9⌉ = 112: frames 0, 112, …, 896, and 1000.
        assert_eq!(m.frames, 10);
        assert_eq!(m.joints.len(), 10);
        assert_eq!(m.poses.len(), 30);
        assert_eq!(m.joints[1], 112.0);
        assert_eq!(m.joints[9], 1000.0);
        assert_eq!(m.poses[27..30], [3000.0, 3001.0, 3002.0]);
        assert_eq!(m.times.as_ref().unwrap()[9], 1000.0);
        assert_eq!(m.waypoints, [0, 9]);
        assert_eq!(m.colliding, [0, 9]);
        assert_eq!(
            doc.notes,
            [
                "motion \"plan\": 1 001 frames, 10 drawn (every 112th); waypoints and collisions shown at the nearest drawn frame"
            ]
        );
        let untouched = limits.decimate(&world(10));
        assert_eq!(untouched, world(10));
    }

    #[test]
    fn clouds_solids_and_search_are_cut_to_their_caps() {
        let mut doc = ViewDocument::new(ViewKind::World3d, "w");
        doc.scene.clouds = vec![
            CloudView {
                name: "a".into(),
                points: (0..3 * 600).map(|v| v as f32).collect(),
                radius: 0.1,
            },
            CloudView {
                name: "b".into(),
                points: vec![0.0; 3 * 400],
                radius: 0.1,
            },
        ];
        doc.scene.solids = (0..50)
            .map(|i| SolidView {
                name: format!("s{i}"),
                shape: ShapeView::Sphere {
                    radius: (i % 10) as f32,
                },
                position: [0.0; 3],
                rotation: [0.0, 0.0, 0.0, 1.0],
            })
            .collect();
        doc.search = Some(SearchOverlay {
            segments: vec![0.0; 6 * 1000],
            costs: (0..1000).map(|c| c as f32).collect(),
            informed: None,
            label: "tree".into(),
        });
        let limits = ViewLimits {
            cloud_points: 200,
            solids: 10,
            search_segments: 300,
            ..ViewLimits::default()
        };
        let cut = limits.decimate(&doc);
        assert_eq!(cut.scene.clouds[0].points.len(), 3 * 120);
        assert_eq!(cut.scene.clouds[0].points[3..6], [15.0, 16.0, 17.0]);
        assert_eq!(cut.scene.clouds[1].points.len(), 3 * 80);
        assert_eq!(cut.scene.solids.len(), 10);
        assert!(
            cut.scene
                .solids
                .iter()
                .all(|s| s.shape == ShapeView::Sphere { radius: 9.0 }
                    || s.shape == ShapeView::Sphere { radius: 8.0 })
        );
        let search = cut.search.unwrap();
        assert_eq!(search.costs.len(), 250);
        assert_eq!(search.segments.len(), 6 * 250);
        assert_eq!(search.costs[1], 4.0);
        assert_eq!(
            cut.notes,
            [
                "cloud: 1 000 points, 200 drawn (every 5th)",
                "solids: 50, 10 drawn (the largest)",
                "search: 1 000 segments, 250 drawn (every 4th)",
            ]
        );
    }

    #[test]
    fn too_many_triangles_give_way_to_spheres() {
        let mut doc = ViewDocument::new(ViewKind::Arm, "a");
        doc.robot = Some(crate::RobotView {
            name: "r".into(),
            links: vec![crate::LinkView {
                name: "l".into(),
                spheres: vec![0.0, 0.0, 0.0, 0.1],
                meshes: vec![crate::MeshView {
                    positions: vec![0.0; 9],
                    indices: vec![0, 1, 2, 0, 2, 1],
                    colour: [1.0; 3],
                }],
            }],
            hand: 0,
        });
        let limits = ViewLimits {
            mesh_triangles: 1,
            ..ViewLimits::default()
        };
        let cut = limits.decimate(&doc);
        assert!(cut.robot.unwrap().links[0].meshes.is_empty());
        assert_eq!(
            cut.notes,
            ["meshes: 2 triangles, over the cap of 1: spheres shown"]
        );
        assert_eq!(ViewLimits::unlimited().decimate(&doc), doc);
    }
}
