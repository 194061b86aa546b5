//! `mit-star spherise`: a sphere model from a URDF's collision meshes.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use clap::Args;

use crate::commands::CommandOutcome;
use crate::error::HarnessError;

/// Options of `mit-star spherise`.
#[derive(Debug, Args)]
pub struct SpheriseArgs {
    /// The URDF whose collision meshes (STL, OBJ, COLLADA .dae), boxes and cylinders are
    /// covered by spheres (its sphere elements are kept).
    pub urdf: PathBuf,
    /// Where `package://PKG/path` names are looked up, as `DIR/PKG/path` or `DIR/path`
    /// (repeatable).
    #[arg(long = "package-root", value_name = "DIR")]
    pub package_roots: Vec<PathBuf>,
    /// How far, at most, a sphere may reach beyond the mesh's solid, in metres (a tolerance
    /// so fine for a mesh's size that its grid would exceed 4 000 000 cells is refused before
    /// any work).
    #[arg(long, default_value_t = 0.01)]
    pub tolerance: f64,
    /// The most spheres in the whole model: the tolerance (the same for every link) is
    /// raised from --tolerance until the covers fit. Every mesh stays inside its spheres;
    /// what the budget costs is how far they reach beyond it (the table's bound and
    /// measured columns).
    #[arg(long, value_name = "N")]
    pub max_spheres: Option<usize>,
    /// The most spheres per collision element (mesh, box or cylinder): an element needing
    /// more is covered again with its tolerance raised by a quarter at a time.
    #[arg(long, value_name = "N")]
    pub max_mesh_spheres: Option<usize>,
    /// A spherised URDF whose spheres are copied for links whose mesh files are missing or
    /// unreadable (Git LFS pointers, corrupt files, unsupported formats), with a warning
    /// naming each file (without it, such meshes are an error naming every one).
    #[arg(long, value_name = "URDF")]
    pub fallback: Option<PathBuf>,
    /// Where the spheres are placed: `grid` (greedy over a grid's corners), `medial`
    /// (candidates on an approximate medial axis, a finer grid, pairs merged), `fewest`
    /// (both, keeping the cover with fewer spheres per mesh) or `searched` (the medial
    /// candidates, the greedy cover improved by a local search: fewest spheres, slowest).
    /// Default: `searched` under a sphere budget (--max-spheres, --max-mesh-spheres), `grid`
    /// otherwise.
    #[arg(long, value_name = "PLACEMENT", value_parser = parse_placement)]
    pub placement: Option<mit_star_robot::Placement>,
    /// Where to write the spherised URDF.
    #[arg(long, short)]
    pub output: PathBuf,
}

/// `grid`, `medial`, `fewest` or `searched`.
fn parse_placement(text: &str) -> Result<mit_star_robot::Placement, String> {
    match text {
        "grid" => Ok(mit_star_robot::Placement::Grid),
        "medial" => Ok(mit_star_robot::Placement::Medial),
        "fewest" => Ok(mit_star_robot::Placement::Fewest),
        "searched" => Ok(mit_star_robot::Placement::Searched),
        _ => Err(format!("`{text}`: one of grid, medial, fewest, searched")),
    }
}

impl SpheriseArgs {
    /// Covers every link's collision geometry, writes the URDF with spheres, checks that it
    /// loads as a robot model, and prints the table per link.
    ///
    /// The first SIGINT or SIGTERM (`interrupt` raised) stops the covers within a few
    /// seconds: nothing is written and the command ends as interrupted.
    ///
    /// # Errors
    /// An unreadable URDF or fallback, a `package://` name without a root, missing or
    /// unreadable meshes without fallback spheres, a bad tolerance or budget, a tolerance too
    /// fine (or a mesh too large) for the work cap, an unwritable output, or an output that
    /// does not load as a sphere model.
    pub fn run(&self, interrupt: &Arc<AtomicBool>) -> Result<CommandOutcome, HarnessError> {
        self.check_output()?;
        let fallback = match &self.fallback {
            Some(path) => Some(std::fs::read_to_string(path).map_err(|source| {
                mit_star_robot::SpheriseError::Io {
                    path: path.clone(),
                    source,
                }
            })?),
            None => None,
        };
        let options = mit_star_robot::SpheriseOptions {
            cover: mit_star_robot::CoverOptions {
                tolerance: self.tolerance,
                max_spheres: self.max_mesh_spheres,
            },
            package_roots: self.package_roots.clone(),
            fallback,
            max_spheres: self.max_spheres,
            placement: self.placement,
            stop: Some(Arc::clone(interrupt)),
        };
        let spherised = match mit_star_robot::SpherisedUrdf::from_file(&self.urdf, &options) {
            Err(mit_star_robot::SpheriseError::Stopped) => return Ok(CommandOutcome::Interrupted),
            result => result?,
        };
        let model =
            mit_star_robot::RobotModel::from_urdf_str(&spherised.text).map_err(|source| {
                HarnessError::Usage(format!(
                    "the spherised URDF does not load as a sphere model: {source}"
                ))
            })?;
        std::fs::write(&self.output, &spherised.text).map_err(|source| {
            mit_star_robot::SpheriseError::Io {
                path: self.output.clone(),
                source,
            }
        })?;
        for link in &spherised.links {
            for file in &link.unusable {
                eprintln!(
                    "warning: link `{}`: mesh {file}: its spheres are the fallback's",
                    link.link
                );
            }
        }
        print_table(&spherised.links);
        say!(
            "wrote {}: {} spheres on {} links ({} joints)",
            self.output.display(),
            model.spheres().len(),
            spherised.links.len(),
            model.joint_names().len()
        );
        for link in spherised.links.iter().filter(|l| !l.closed) {
            eprintln!(
                "warning: link `{}`: a mesh is not closed; only its surface is covered",
                link.link
            );
        }
        Ok(CommandOutcome::Success)
    }

    /// Refuses, before any mesh is read (a cover takes minutes), an output that is a folder
    /// or lies in a folder that does not exist.
    fn check_output(&self) -> Result<(), HarnessError> {
        if self.output.is_dir() {
            return Err(HarnessError::Usage(format!(
                "--output `{}` is a folder: name the URDF file to write",
                self.output.display()
            )));
        }
        let folder = match self.output.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => std::path::Path::new("."),
        };
        if !folder.is_dir() {
            return Err(HarnessError::Usage(format!(
                "--output `{}`: the folder `{}` does not exist (create it first, with the \
                 robot's SRDF beside the URDF)",
                self.output.display(),
                folder.display()
            )));
        }
        Ok(())
    }
}

fn print_table(links: &[mit_star_robot::LinkReport]) {
    let width = links.iter().map(|l| l.link.len()).max().unwrap_or(4).max(4);
    say!(
        "{:width$}  {:>9}  {:>6}  {:>7}  {:>9}  {:>9}  {:>13}  {:>12}",
        "link",
        "triangles",
        "closed",
        "spheres",
        "tolerance",
        "bound",
        "outward error",
        "measured mean"
    );
    let mm = |v: Option<f64>| v.map_or_else(|| "—".to_owned(), |v| format!("{:.1} mm", v * 1e3));
    for l in links {
        let (triangles, closed, tolerance) = match l.source {
            mit_star_robot::LinkSource::Covered => (
                l.triangles.to_string(),
                match (l.closed, l.filled) {
                    (true, true) => "filled",
                    (true, false) => "yes",
                    (false, _) => "no",
                }
                .to_owned(),
                mm(Some(l.tolerance)),
            ),
            mit_star_robot::LinkSource::Fallback => {
                ("fallback".to_owned(), "—".to_owned(), "—".to_owned())
            }
        };
        say!(
            "{:width$}  {triangles:>9}  {closed:>6}  {:>7}  {tolerance:>9}  {:>9}  {:>13}  {:>12}",
            l.link,
            l.spheres,
            mm(l.max_protrusion),
            mm(l.outward_error),
            mm(l.measured_mean)
        );
    }
    say!(
        "bound: no point of a link's spheres lies farther than this from its solid (guaranteed; a hollow mesh's inside counts as solid: closed `filled`); outward error: no point of the boundary of the spheres' union lies farther than this from the meshes (guaranteed, measured by branch and bound to 0.25 mm); measured mean: over points sampled on that boundary"
    );
    for l in links.iter().filter(|l| l.weld > 0.0) {
        say!(
            "link `{}`: vertices within {:.2} µm merged to close its mesh (its spheres grown by the move)",
            l.link,
            l.weld * 1e6
        );
    }
}
