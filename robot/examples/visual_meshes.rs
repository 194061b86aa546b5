//! `visual_meshes`: loads a robot's visual meshes as the 3-D view would and prints, per
//! visual element, what was loaded (triangles, colour) or why not; then the totals.
//!
//! ```text
//! cargo run -p mit-star-robot --example visual_meshes -- panda            # a shipped robot
//! cargo run -p mit-star-robot --example visual_meshes -- path/to/robot.urdf [PACKAGE_ROOT ...]
//! ```
//!
//! A URDF file must have spheres as its collision geometry (as `mit-star spherise` writes
//! it); its relative mesh names are looked up beside it, then under the package roots, and
//! `package://PKG/rest` names under each root as `ROOT/PKG/rest` or `ROOT/rest`. Exits with
//! status 1 if any visual mesh failed to load.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use mit_star_robot::{MeshResolver, RobotModel, ShippedRobot, VisualMeshes};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(what) = args.first() else {
        eprintln!("usage: visual_meshes ROBOT | URDF [PACKAGE_ROOT ...]");
        return ExitCode::from(2);
    };
    let loaded = match ShippedRobot::find(what) {
        Some(shipped) => shipped
            .model(false)
            .map(|model| (model, shipped.mesh_resolver())),
        None => {
            let path = Path::new(what);
            let roots = args[1..].iter().map(PathBuf::from).collect();
            RobotModel::from_urdf_file(path)
                .map(|model| (model, MeshResolver::for_urdf_file(path, roots)))
        }
    };
    let (model, resolver) = match loaded {
        Ok(loaded) => loaded,
        Err(e) => {
            eprintln!("{what}: {e}");
            return ExitCode::from(2);
        }
    };
    let started = std::time::Instant::now();
    let visuals = VisualMeshes::load(&model, &resolver);
    let seconds = started.elapsed().as_secs_f64();
    for mesh in &visuals.meshes {
        println!(
            "{:<28} {:>7} triangles  {:<60} colour {:?}",
            model.links()[mesh.link].name,
            mesh.triangle_count(),
            mesh.filename.as_deref().unwrap_or("(primitive)"),
            mesh.colour
        );
    }
    for failure in &visuals.failures {
        println!("FAILED {failure}");
    }
    println!(
        "{}: {} visual elements, {} loaded ({} triangles), {} failed, in {seconds:.2} s",
        model.name(),
        model.visuals().len(),
        visuals.meshes.len(),
        visuals.triangle_count(),
        visuals.failures.len()
    );
    if visuals.failures.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
