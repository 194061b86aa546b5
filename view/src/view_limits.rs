//! [`ViewLimits`]: how much one page draws at most, and the decimation that keeps a document
//! within them, saying in the page's notes what was dropped.

use crate::{CloudView, MotionView, SearchOverlay, ShapeView, SolidView, ViewDocument};

/// Caps on what one page draws, so that it opens in a few seconds whatever the plan.
///
/// The defaults keep a page under about 10 MB and opening in under 2 s in headless Chromium
/// (software WebGL) on the project's machines, even for 10⁶-frame motions, 10⁵ boxes and
/// 10⁶-point clouds (`view/examples/sample_views.rs` makes such pages).
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
        if i > 0 && (digits.len() - i) % 3 == 0 {
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
        ShapeView::Sphere { radius } => 4.19 * radius.powi(3),
        ShapeView::Cylinder {
            radius,
            half_height,
        } => 6.28 * radius * radius * half_height,
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
