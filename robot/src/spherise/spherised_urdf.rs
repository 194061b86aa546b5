//! [`SpherisedUrdf`]: a URDF's collision meshes and primitives covered by spheres, link by
//! link, and the URDF rewritten with the spheres as its collision geometry, in the form of
//! VAMP's `*_spherized.urdf` (one `<collision>` with a `<sphere>` per sphere).

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use glam::DVec3;

use super::budget_allocation::{Rung, allocate};
use super::mesh_file::read_mesh;
use super::sphere_budget::fit_budget;
use super::sphere_cover::{CoverOptions, CoverSphere, Placement, SphereCover, check_work};
use super::spherise_error::SpheriseError;
use super::triangle_mesh::TriangleMesh;
use super::urdf_collisions::{Geometry, LinkCollisions, read_collisions, resolve};

/// The tolerances, as factors of the common one a budget found, at which every link is
/// covered again for the per-link choice (`budget_allocation.rs`).
const LADDER: [f64; 6] = [0.85, 0.92, 1.08, 1.17, 1.27, 1.4];

/// Sides of the prism a cylinder is covered as (circumscribed, so it contains the cylinder).
const CYLINDER_SIDES: u32 = 32;

/// How to spherise a URDF.
#[derive(Debug, Clone, Default)]
pub struct SpheriseOptions {
    /// How each collision mesh is covered.
    pub cover: CoverOptions,
    /// Where `package://` addresses are looked up.
    pub package_roots: Vec<PathBuf>,
    /// The text of a spherised URDF whose spheres stand in for links whose mesh files are
    /// missing or unreadable (VAMP's hand-made model for a gripper whose meshes are not at
    /// hand, or are Git LFS pointers).
    pub fallback: Option<String>,
    /// The most spheres in the whole model (`--max-spheres`): the tolerance is raised, the
    /// same for every link, until the covers together fit (kept sphere elements and fallback
    /// spheres count too); then every link is covered again at a few tolerances about that
    /// one, and each link's cover is chosen among them so that the worst measured outward
    /// error is the least that fits, the spheres left over going where they cut a link's
    /// error most. Each link's report gives the tolerance used and what it measured.
    pub max_spheres: Option<usize>,
    /// Where the spheres are placed; `None` takes [`Placement::Searched`] under a sphere
    /// budget (`max_spheres` or the cover's own) and [`Placement::Grid`] otherwise.
    pub placement: Option<Placement>,
    /// Raised to stop (a SIGINT/SIGTERM handler): covers poll it in every long loop and
    /// return [`SpheriseError::Stopped`].
    pub stop: Option<Arc<AtomicBool>>,
}

/// Where a link's spheres came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LinkSource {
    /// Covers of its collision meshes or primitives (spheres kept as they are).
    Covered,
    /// Its mesh files are missing or unreadable; the fallback model's spheres for it were
    /// copied.
    Fallback,
}

/// What was done for one link with collision geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkReport {
    /// The link.
    pub link: String,
    /// Where its spheres came from.
    pub source: LinkSource,
    /// Its collision elements.
    pub elements: usize,
    /// Triangles of its meshes (primitives count as the meshes they are covered as).
    pub triangles: usize,
    /// Whether every mesh is closed (an open one has only its surface covered).
    pub closed: bool,
    /// Its spheres.
    pub spheres: usize,
    /// The largest tolerance a cover used (above the one asked when a budget raised it).
    pub tolerance: f64,
    /// The guaranteed bound on how far any sphere reaches beyond the link's geometry
    /// (`None` for fallback spheres).
    pub max_protrusion: Option<f64>,
    /// The outward error, guaranteed: no point of the boundary of the link's spheres' union
    /// lies farther than this from its meshes' surfaces (the largest of its covers'
    /// [`SphereCover::outward_error`]; `None` for fallback spheres).
    pub outward_error: Option<f64>,
    /// The largest distance from the meshes reached by a point of that boundary.
    pub measured_max: Option<f64>,
    /// Whether a mesh of the link walls in space (a hollow housing) that its cover fills.
    pub filled: bool,
    /// The largest distance within which a mesh's vertices were merged to close it (0 if
    /// none was).
    pub weld: f64,
    /// The mean protrusion measured there.
    pub measured_mean: Option<f64>,
    /// For a [`LinkSource::Fallback`] link: its mesh files that are missing (the name) or
    /// unreadable (`name (why)`: a Git LFS pointer, a corrupt file, an unsupported format).
    pub unusable: Vec<String>,
}

/// A spherised URDF: its text and the report per link.
#[derive(Debug, Clone)]
pub struct SpherisedUrdf {
    /// The URDF with every link's collision elements replaced by spheres.
    pub text: String,
    /// One report per link with collision geometry, in document order.
    pub links: Vec<LinkReport>,
}

impl SpherisedUrdf {
    /// Spherises the URDF file at `path` (relative mesh names are looked up beside it).
    ///
    /// # Errors
    /// As [`from_text`](Self::from_text), and [`SpheriseError::Io`] if the file cannot be read.
    pub fn from_file(path: &Path, options: &SpheriseOptions) -> Result<Self, SpheriseError> {
        let text = std::fs::read_to_string(path).map_err(|source| SpheriseError::Io {
            path: path.to_owned(),
            source,
        })?;
        let folder = path.parent().unwrap_or(Path::new("."));
        Self::from_text(&text, folder, &path.display().to_string(), options)
    }

    /// Spherises URDF text whose relative mesh names are relative to `folder`; `origin` names
    /// it in errors.
    ///
    /// # Errors
    /// [`SpheriseError::Urdf`] or [`SpheriseError::BadNumber`] for a malformed URDF or
    /// fallback, [`SpheriseError::UnknownPackage`] for a `package://` name without a package
    /// root, [`SpheriseError::MissingMeshes`] naming every missing or unreadable mesh (and
    /// why) of links the fallback lacks, [`SphereCover::stoppable`]'s errors (a
    /// [`TooMuchWork`](SpheriseError::TooMuchWork) names the link), and
    /// [`SpheriseError::BadOption`] for a sphere budget below the spheres no tolerance
    /// changes (kept sphere elements and fallback spheres).
    pub fn from_text(
        text: &str,
        folder: &Path,
        origin: &str,
        options: &SpheriseOptions,
    ) -> Result<Self, SpheriseError> {
        let document = parse(text, origin)?;
        let links = read_collisions(&document, origin)?;
        let fallback = match &options.fallback {
            Some(f) => fallback_collisions(f)?,
            None => HashMap::new(),
        };
        let stop = options.stop.clone().unwrap_or_default();
        // Every link's geometry, read once (a budget covers it at several tolerances).
        let mut missing = Vec::new();
        let mut sources = Vec::new();
        for link in links.iter().filter(|l| !l.collisions.is_empty()) {
            let source = match meshes(link, folder, &options.package_roots)? {
                Ok(placed) => Source::Geometry(placed),
                Err(unusable) => match fallback.get(link.name.as_str()) {
                    Some(elements) => Source::Fallback(elements, unusable),
                    None => {
                        missing.extend(unusable.into_iter().map(|f| (link.name.clone(), f)));
                        continue;
                    }
                },
            };
            sources.push((link, source));
        }
        if !missing.is_empty() {
            return Err(SpheriseError::MissingMeshes {
                missing,
                fallback_given: options.fallback.is_some(),
            });
        }
        // The work cap, for every mesh before any cover (a tolerance check comes first).
        SphereCover::check_options(&options.cover)?;
        for (link, source) in &sources {
            if let Source::Geometry(placed) = source {
                for p in placed {
                    if let Placed::Mesh(mesh) = p {
                        check_work(
                            mesh,
                            options.cover.tolerance,
                            &format!("link `{}`", link.name),
                        )?;
                    }
                }
            }
        }
        let placement = options.placement.unwrap_or(
            if options.max_spheres.is_some() || options.cover.max_spheres.is_some() {
                Placement::Searched
            } else {
                Placement::Grid
            },
        );
        let cover_all = |tolerance: f64| -> Result<Vec<(String, LinkReport)>, SpheriseError> {
            let cover = CoverOptions {
                tolerance,
                ..options.cover
            };
            sources
                .iter()
                .map(|(link, source)| {
                    let indent = indentation(text, link.collisions[0].range.start);
                    match source {
                        Source::Geometry(placed) => {
                            covered(link, placed, &cover, placement, &indent, &stop)
                        }
                        Source::Fallback(elements, unusable) => {
                            Ok(fallen_back(link, elements, unusable, &indent))
                        }
                    }
                })
                .collect()
        };
        let covers = match options.max_spheres {
            None => cover_all(options.cover.tolerance)?,
            Some(budget) => {
                let minimum = sources.iter().map(|(_, s)| s.least_spheres()).sum();
                let (found, covers) =
                    fit_budget(budget, minimum, options.cover.tolerance, |tolerance| {
                        let covers = cover_all(tolerance)?;
                        let total = covers.iter().map(|(_, r)| r.spheres).sum();
                        Ok((total, (tolerance, covers)))
                    })?;
                // Each link's cover chosen among a ladder of tolerances about the common
                // one, by measured outward error (`budget_allocation.rs`).
                let mut ladder = vec![covers];
                for factor in LADDER {
                    let tolerance = found * factor;
                    if tolerance >= options.cover.tolerance {
                        ladder.push(cover_all(tolerance)?);
                    }
                }
                let rungs: Vec<Vec<Rung>> = (0..sources.len())
                    .map(|l| {
                        ladder
                            .iter()
                            .map(|covers| Rung {
                                spheres: covers[l].1.spheres,
                                error: covers[l].1.outward_error.unwrap_or(0.0),
                            })
                            .collect()
                    })
                    .collect();
                let picks = allocate(&rungs, budget).unwrap_or_else(|| vec![0; sources.len()]);
                picks
                    .iter()
                    .enumerate()
                    .map(|(l, &k)| ladder[k][l].clone())
                    .collect()
            }
        };
        let mut edits: Vec<(std::ops::Range<usize>, String)> = Vec::new();
        let mut reports = Vec::new();
        for ((link, _), (block, report)) in sources.iter().zip(covers) {
            let indent = indentation(text, link.collisions[0].range.start);
            for (i, c) in link.collisions.iter().enumerate() {
                let start = line_start(text, c.range.start);
                if i == 0 {
                    edits.push((start..c.range.end, format!("{indent}{block}")));
                } else {
                    // The element and its line go.
                    let end = c.range.end + usize::from(text[c.range.end..].starts_with('\n'));
                    edits.push((start..end, String::new()));
                }
            }
            reports.push(report);
        }
        let mut out = text.to_owned();
        for (range, replacement) in edits.into_iter().rev() {
            out.replace_range(range, &replacement);
        }
        Ok(Self {
            text: out,
            links: reports,
        })
    }
}

fn parse<'a>(text: &'a str, origin: &str) -> Result<roxmltree::Document<'a>, SpheriseError> {
    roxmltree::Document::parse(text).map_err(|e| SpheriseError::Urdf {
        origin: origin.to_owned(),
        message: e.to_string(),
    })
}

/// A geometry placed in the link frame: a mesh to cover, or a sphere to keep.
enum Placed {
    Mesh(TriangleMesh),
    Sphere(DVec3, f64),
}

/// Where a link's spheres come from: its geometry, or the fallback's collision elements
/// (with why its meshes could not be used).
enum Source<'a> {
    Geometry(Vec<Placed>),
    Fallback(&'a [String], Vec<String>),
}

impl Source<'_> {
    /// The fewest spheres any tolerance gives: kept sphere elements and fallback spheres,
    /// and one per mesh.
    fn least_spheres(&self) -> usize {
        match self {
            Self::Geometry(placed) => placed.len(),
            Self::Fallback(elements, _) => elements.len(),
        }
    }
}

/// The link's geometry in its frame, or its mesh names whose files are missing or unreadable
/// (`name` alone when missing, `name (why)` when unreadable: a Git LFS pointer, a corrupt
/// file, an unsupported format).
fn meshes(
    link: &LinkCollisions,
    folder: &Path,
    roots: &[PathBuf],
) -> Result<Result<Vec<Placed>, Vec<String>>, SpheriseError> {
    let mut placed = Vec::new();
    let mut missing = Vec::new();
    for c in &link.collisions {
        let place =
            |mesh: TriangleMesh, scale: DVec3| mesh.transformed(c.rotation, c.translation, scale);
        match &c.geometry {
            Geometry::Mesh { filename, scale } => {
                match resolve(&link.name, filename, folder, roots)? {
                    Ok(path) => match read_mesh(&path) {
                        Ok(mesh) => placed.push(Placed::Mesh(place(mesh, *scale))),
                        Err(why) => missing.push(format!("{filename} ({why})")),
                    },
                    Err(_) => missing.push(filename.clone()),
                }
            }
            Geometry::Cuboid(size) => placed.push(Placed::Mesh(place(
                TriangleMesh::cuboid(*size / 2.0)?,
                DVec3::ONE,
            ))),
            Geometry::Cylinder { radius, length } => placed.push(Placed::Mesh(place(
                TriangleMesh::cylinder(*radius, *length, CYLINDER_SIDES)?,
                DVec3::ONE,
            ))),
            Geometry::Sphere(r) => placed.push(Placed::Sphere(c.translation, *r)),
        }
    }
    Ok(if missing.is_empty() {
        Ok(placed)
    } else {
        Err(missing)
    })
}

fn covered(
    link: &LinkCollisions,
    placed: &[Placed],
    options: &CoverOptions,
    placement: Placement,
    indent: &str,
    stop: &AtomicBool,
) -> Result<(String, LinkReport), SpheriseError> {
    let mut spheres: Vec<CoverSphere> = Vec::new();
    let mut report = LinkReport {
        link: link.name.clone(),
        source: LinkSource::Covered,
        elements: link.collisions.len(),
        triangles: 0,
        closed: true,
        spheres: 0,
        tolerance: 0.0,
        max_protrusion: Some(0.0),
        outward_error: Some(0.0),
        measured_max: Some(0.0),
        filled: false,
        weld: 0.0,
        measured_mean: None,
        unusable: Vec::new(),
    };
    let (mut weighted_mean, mut weight) = (0.0, 0.0);
    for p in placed {
        match p {
            Placed::Mesh(mesh) => {
                let cover = SphereCover::placed(mesh, options, placement, stop)?;
                report.triangles += cover.triangles;
                report.closed &= cover.closed;
                report.tolerance = report.tolerance.max(cover.tolerance);
                report.max_protrusion = report.max_protrusion.map(|m| m.max(cover.max_protrusion));
                report.measured_max = report.measured_max.map(|m| m.max(cover.measured_max));
                report.outward_error = report.outward_error.map(|m| m.max(cover.outward_error));
                report.filled |= cover.filled;
                report.weld = report.weld.max(cover.weld);
                weighted_mean += cover.measured_mean * cover.spheres.len() as f64;
                weight += cover.spheres.len() as f64;
                spheres.extend(cover.spheres);
            }
            Placed::Sphere(centre, radius) => spheres.push(CoverSphere {
                centre: *centre,
                radius: *radius,
                protrusion: 0.0,
            }),
        }
    }
    report.spheres = spheres.len();
    report.measured_mean = Some(if weight > 0.0 {
        weighted_mean / weight
    } else {
        0.0
    });
    let mut block = String::new();
    for (i, s) in spheres.iter().enumerate() {
        let lead = if i == 0 { "" } else { indent };
        let _ = write!(block, "{lead}{}", sphere_element(s, indent));
        if i + 1 < spheres.len() {
            block.push('\n');
        }
    }
    Ok((block, report))
}

/// One `<collision>` element for a sphere, in VAMP's form; its numbers are written to
/// micrometres, the radius rounded up and grown by the centre's rounding, so the written
/// sphere contains the computed one.
fn sphere_element(s: &CoverSphere, indent: &str) -> String {
    let micro = |v: f64| (v * 1e6).round() / 1e6;
    let radius = ((s.radius + 1e-6) * 1e6).ceil() / 1e6;
    let c = s.centre;
    format!(
        "<collision>\n{indent}\t<geometry>\n{indent}\t\t<sphere radius=\"{radius}\"></sphere>\n{indent}\t</geometry>\n{indent}\t<origin xyz=\"{} {} {}\" rpy=\"0 0 0\"></origin>\n{indent}</collision>",
        micro(c.x) + 0.0,
        micro(c.y) + 0.0,
        micro(c.z) + 0.0,
    )
}

/// The collision elements of each link of a spherised URDF, as text.
fn fallback_collisions(text: &str) -> Result<HashMap<String, Vec<String>>, SpheriseError> {
    let document = parse(text, "the fallback URDF")?;
    Ok(read_collisions(&document, "the fallback URDF")?
        .into_iter()
        .filter(|l| !l.collisions.is_empty())
        .map(|l| {
            let elements = l
                .collisions
                .iter()
                .map(|c| text[c.range.clone()].to_owned())
                .collect();
            (l.name, elements)
        })
        .collect())
}

fn fallen_back(
    link: &LinkCollisions,
    elements: &[String],
    unusable: &[String],
    indent: &str,
) -> (String, LinkReport) {
    let block = elements.join(&format!("\n{indent}"));
    let report = LinkReport {
        link: link.name.clone(),
        source: LinkSource::Fallback,
        elements: link.collisions.len(),
        triangles: 0,
        closed: true,
        spheres: elements.len(),
        tolerance: 0.0,
        max_protrusion: None,
        outward_error: None,
        measured_max: None,
        filled: false,
        weld: 0.0,
        measured_mean: None,
        unusable: unusable.to_vec(),
    };
    (block, report)
}

/// The white space before position `at` on its line.
fn indentation(text: &str, at: usize) -> String {
    let start = line_start(text, at);
    text[start..at].to_owned()
}

/// The start of `at`'s line if only white space precedes it there, else `at`.
fn line_start(text: &str, at: usize) -> usize {
    let start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    if text[start..at].chars().all(char::is_whitespace) {
        start
    } else {
        at
    }
}
