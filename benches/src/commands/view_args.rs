//! The 3-D view options shared by `plan`, `replan` and `check-path`: `--view FILE.html` writes
//! one self-contained page (the robot or the box world, the scene, the motion, a time slider),
//! `--view-search` adds the planner's search.

use std::path::{Path, PathBuf};

use clap::Args;

use crate::error::HarnessError;

/// Options that write a 3-D view of the run.
#[derive(Debug, Args, Clone, Default)]
pub struct ViewArgs {
    /// Write an interactive 3-D view of the result to this HTML file: one file that opens
    /// offline in a browser (arms and 2-D/3-D box worlds).
    #[arg(long, value_name = "FILE.html")]
    pub view: Option<PathBuf>,
    /// Draw the planner's search in the view: its forward tree (through the hand's position
    /// on an arm), coloured by cost-to-come, and the informed set in a box world. Planners
    /// without a graph (the RRTs) have none to show.
    #[arg(long, requires = "view")]
    pub view_search: bool,
    /// A folder `package://NAME/…` mesh paths are also looked up in (as `NAME/…`; repeatable):
    /// meshes the robot's files do not ship (the Fetch's, whose licence keeps them out).
    #[arg(long, value_name = "DIR", requires = "view")]
    pub view_package_root: Vec<PathBuf>,
}

impl ViewArgs {
    /// Checks the page's name and that its folder can be written, before any planning.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] for a name that does not end in `.html`;
    /// [`HarnessError::OutputFolder`] if the folder cannot be made or written.
    pub fn prepare(&self) -> Result<Option<&Path>, HarnessError> {
        let Some(file) = &self.view else {
            return Ok(None);
        };
        if !matches!(
            file.extension().and_then(|e| e.to_str()),
            Some("html" | "htm")
        ) {
            return Err(HarnessError::Usage(format!(
                "--view {}: the page is an .html file",
                file.display()
            )));
        }
        if file.is_dir() {
            return Err(HarnessError::Usage(format!(
                "--view {}: a folder, not a file",
                file.display()
            )));
        }
        let folder = file
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        crate::writable_folder(folder)?;
        Ok(Some(file))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_html_pages_in_writable_folders() {
        let wrong = ViewArgs {
            view: Some("plan.png".into()),
            ..ViewArgs::default()
        };
        assert!(matches!(wrong.prepare(), Err(HarnessError::Usage(m)) if m.contains(".html")));
        let folder = std::env::temp_dir().join(format!("view-args-{}", std::process::id()));
        let right = ViewArgs {
            view: Some(folder.join("a/plan.html")),
            view_search: true,
            view_package_root: Vec::new(),
        };
        assert_eq!(
            right.prepare().unwrap(),
            Some(folder.join("a/plan.html").as_path())
        );
        assert!(folder.join("a").is_dir());
        std::fs::remove_dir_all(&folder).unwrap();
        assert_eq!(ViewArgs::default().prepare().unwrap(), None);
    }
}
