//! [`MeshResolver`]: where a mesh file named in a URDF is on disk, for `spherise`'s
//! collision meshes and for visual meshes alike.

use std::path::{Path, PathBuf};

use thiserror::Error;

/// Finds the mesh files a URDF names: `package://PKG/rest` under each package root as
/// `ROOT/PKG/rest` or `ROOT/rest`, `file:///path` and absolute paths as they are, and a
/// relative name beside the URDF (its folder, if known) or under a package root.
///
/// An alias stands a URDF's file name for another name, resolved in its place: the shipped
/// robots use it to draw a link with a smaller mesh of the same link than the one the URDF
/// names ([`ShippedRobot::mesh_resolver`](crate::ShippedRobot::mesh_resolver)).
///
/// ```
/// use std::path::{Path, PathBuf};
/// let resolver = mit_star_robot::MeshResolver::new(None, vec![PathBuf::from(env!("CARGO_MANIFEST_DIR"))]);
/// let found = resolver.resolve("package://robot/Cargo.toml").unwrap();
/// assert_eq!(found, Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml"));
/// assert!(resolver.resolve("package://robot/missing.stl").is_err());
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshResolver {
    urdf_folder: Option<PathBuf>,
    package_roots: Vec<PathBuf>,
    aliases: Vec<(String, String)>,
}

/// Why a mesh file name did not lead to a file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ResolveError {
    /// A `package://` name, and no package root to look under.
    #[error("`{filename}`: a package:// address and no package root to look under")]
    NoPackageRoot {
        /// The name as the URDF gives it.
        filename: String,
    },
    /// No file at any of the places the name can mean.
    #[error("`{filename}`: no such file (tried {})", list(.tried))]
    NotFound {
        /// The name as the URDF gives it.
        filename: String,
        /// The paths tried, in order.
        tried: Vec<PathBuf>,
    },
}

fn list(paths: &[PathBuf]) -> String {
    if paths.is_empty() {
        return "nothing: no URDF folder or package root".into();
    }
    paths
        .iter()
        .map(|p| p.display().to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

impl MeshResolver {
    /// A resolver for a URDF in `urdf_folder` (`None` for URDF text from nowhere: relative
    /// names are then looked up under the package roots only) with these package roots.
    pub fn new(urdf_folder: Option<PathBuf>, package_roots: Vec<PathBuf>) -> Self {
        Self {
            urdf_folder,
            package_roots,
            aliases: Vec::new(),
        }
    }

    /// A resolver for the URDF file at `path`: relative names beside it.
    pub fn for_urdf_file(path: &Path, package_roots: Vec<PathBuf>) -> Self {
        let folder = path
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        Self::new(Some(folder.to_owned()), package_roots)
    }

    /// Resolves `filename` (exactly as the URDF writes it) as `instead` would be.
    #[must_use]
    pub fn with_alias(mut self, filename: impl Into<String>, instead: impl Into<String>) -> Self {
        self.aliases.push((filename.into(), instead.into()));
        self
    }

    /// The same resolver looking in `roots` too, after its own package roots (a user's
    /// description packages for a robot that ships without some of its meshes).
    #[must_use]
    pub fn with_package_roots(mut self, roots: impl IntoIterator<Item = PathBuf>) -> Self {
        self.package_roots.extend(roots);
        self
    }

    /// The folder relative names are looked up in first, if any.
    pub fn urdf_folder(&self) -> Option<&Path> {
        self.urdf_folder.as_deref()
    }

    /// The package roots.
    pub fn package_roots(&self) -> &[PathBuf] {
        &self.package_roots
    }

    /// The name `filename` is resolved as: its alias, else itself.
    pub fn alias_of<'a>(&'a self, filename: &'a str) -> &'a str {
        self.aliases
            .iter()
            .find(|(from, _)| from == filename)
            .map_or(filename, |(_, to)| to.as_str())
    }

    /// The places `filename` (after its alias) can mean, in the order they are tried.
    ///
    /// # Errors
    /// [`ResolveError::NoPackageRoot`] for a `package://` name without package roots.
    pub fn candidates(&self, filename: &str) -> Result<Vec<PathBuf>, ResolveError> {
        let name = self.alias_of(filename);
        Ok(if let Some(rest) = name.strip_prefix("package://") {
            if self.package_roots.is_empty() {
                return Err(ResolveError::NoPackageRoot {
                    filename: filename.to_owned(),
                });
            }
            let without_package = rest.split_once('/').map_or(rest, |(_, r)| r);
            self.package_roots
                .iter()
                .flat_map(|root| [root.join(rest), root.join(without_package)])
                .collect()
        } else if let Some(path) = name.strip_prefix("file://") {
            vec![PathBuf::from(path)]
        } else if Path::new(name).is_absolute() {
            vec![PathBuf::from(name)]
        } else {
            self.urdf_folder
                .iter()
                .chain(&self.package_roots)
                .map(|folder| folder.join(name))
                .collect()
        })
    }

    /// The file `filename` names: the first of its [`candidates`](Self::candidates) that is
    /// a file.
    ///
    /// # Errors
    /// [`ResolveError::NoPackageRoot`], or [`ResolveError::NotFound`] naming the paths tried.
    pub fn resolve(&self, filename: &str) -> Result<PathBuf, ResolveError> {
        let tried = self.candidates(filename)?;
        match tried.iter().find(|p| p.is_file()) {
            Some(found) => Ok(found.clone()),
            None => Err(ResolveError::NotFound {
                filename: filename.to_owned(),
                tried,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_names_look_beside_the_urdf_then_under_the_roots() {
        let resolver = MeshResolver::for_urdf_file(
            Path::new("/robots/arm/arm.urdf"),
            vec![PathBuf::from("/pkgs")],
        );
        assert_eq!(resolver.urdf_folder(), Some(Path::new("/robots/arm")));
        assert_eq!(
            resolver.candidates("meshes/a.stl").unwrap(),
            [
                PathBuf::from("/robots/arm/meshes/a.stl"),
                PathBuf::from("/pkgs/meshes/a.stl")
            ]
        );
        assert_eq!(
            resolver.candidates("file:///m/a.dae").unwrap(),
            [PathBuf::from("/m/a.dae")]
        );
        let e = resolver.resolve("meshes/a.stl").unwrap_err();
        assert!(e.to_string().contains("/pkgs/meshes/a.stl"), "{e}");
        assert_eq!(
            MeshResolver::for_urdf_file(Path::new("arm.urdf"), vec![]).urdf_folder(),
            Some(Path::new("."))
        );
    }

    #[test]
    fn an_alias_is_resolved_in_place_of_the_name_and_failures_name_the_urdf_name() {
        let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let resolver = MeshResolver::new(Some(manifest.clone()), vec![])
            .with_alias("package://meshes/big.dae", "Cargo.toml");
        assert_eq!(
            resolver.resolve("package://meshes/big.dae"),
            Ok(manifest.join("Cargo.toml"))
        );
        assert_eq!(
            resolver.resolve("package://meshes/other.dae"),
            Err(ResolveError::NoPackageRoot {
                filename: "package://meshes/other.dae".into()
            })
        );
        let none = MeshResolver::default().resolve("a.stl").unwrap_err();
        assert!(none.to_string().contains("no URDF folder"), "{none}");
    }
}
