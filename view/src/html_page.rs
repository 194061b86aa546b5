//! The page itself: one self-contained HTML file holding the viewer (three.js and the page's
//! own code, bundled at build time) and the document as JSON.

use std::fs;
use std::path::Path;

use crate::{ViewDocument, ViewError, ViewLimits};

/// The viewer: view/web/src bundled with three.js by esbuild (see build.rs).
const VIEWER: &str = include_str!(concat!(env!("OUT_DIR"), "/viewer.js"));
/// three.js's MIT licence, whose notice must travel with the bundle.
const THREE_LICENSE: &str = include_str!(concat!(env!("OUT_DIR"), "/three-license.txt"));

const STYLE: &str = "
html, body { margin: 0; height: 100%; overflow: hidden; font: 13px/1.4 system-ui, sans-serif; color: #1f2937; }
#stage { position: fixed; inset: 0; }
#panel { position: fixed; top: 8px; left: 8px; width: 330px; max-height: calc(100% - 16px); overflow: auto;
  background: rgba(255,255,255,0.92); border-radius: 6px; padding: 8px 12px; box-shadow: 0 1px 4px rgba(0,0,0,0.2); }
#panel h1 { font-size: 16px; margin: 0 0 4px; }
#panel p { margin: 2px 0; }
.subtitle { color: #4b5563; }
.notes { margin: 4px 0; padding-left: 18px; color: #92400e; overflow-wrap: anywhere; }
.note { color: #6b7280; font-style: italic; }
.row { display: flex; gap: 6px; align-items: center; flex-wrap: wrap; margin: 4px 0; }
.spread { justify-content: space-between; }
.toggle { display: block; margin: 2px 0; }
#frame-slider { width: 100%; }
.bad { color: #dc2626; font-weight: bold; }
.legend .bar { height: 10px; border-radius: 2px; }
#joints { border-collapse: collapse; margin-top: 6px; font-variant-numeric: tabular-nums; }
#joints td { padding: 0 8px 0 0; }
#joints td.value { text-align: right; }
#message { position: fixed; top: 40%; left: 50%; transform: translateX(-50%); max-width: 520px; padding: 16px;
  background: #fff7ed; border: 1px solid #f59e0b; border-radius: 6px; font-size: 15px; }
#tooltip { position: fixed; pointer-events: none; background: #111827; color: #f9fafb; padding: 2px 6px;
  border-radius: 3px; font-size: 12px; }
#about { margin-top: 8px; color: #6b7280; }
#about pre { white-space: pre-wrap; font-size: 11px; }
";

/// `text` with `&`, `<`, `>` and `"` escaped for HTML text and attributes.
pub fn escape_html(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            c => out.push(c),
        }
    }
    out
}

/// JSON safe inside a `<script>` element: every `<` (which only occurs inside JSON strings)
/// becomes `\u003c`, so neither `</script` nor `<!--` can appear.
fn script_safe_json(json: &str) -> String {
    json.replace('<', "\\u003c")
}

/// Where a page finds its viewer (three.js and the page's code, about 590 KB).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Viewer<'a> {
    /// Inside the page: one file that opens anywhere.
    Embedded,
    /// In the file of this name beside the page (write [`viewer_script`] there): a folder of
    /// many pages, such as an experiment's views, holds one copy.
    Beside(&'a str),
}

/// The viewer as a script file for pages written with [`Viewer::Beside`], three.js's licence
/// at its head.
pub fn viewer_script() -> String {
    format!(
        "/* Drawn with three.js (https://threejs.org), under this licence:\n{}\n*/\n{VIEWER}",
        THREE_LICENSE.trim().replace("*/", "* /")
    )
}

impl ViewDocument {
    /// The page: the document [checked](Self::check), cut down to `limits` (with notes saying
    /// what was dropped), as one self-contained UTF-8 HTML file.
    ///
    /// # Errors
    /// [`ViewError::Invalid`] when the document contradicts itself; [`ViewError::Json`] if it
    /// cannot be serialised.
    pub fn to_html(&self, limits: ViewLimits) -> Result<String, ViewError> {
        self.to_html_with(limits, Viewer::Embedded)
    }

    /// As [`to_html`](Self::to_html), the viewer embedded or loaded from a file beside the
    /// page ([`Viewer::Beside`]: many pages of one folder share one copy of
    /// [`viewer_script`]).
    ///
    /// # Errors
    /// As [`to_html`](Self::to_html).
    pub fn to_html_with(
        &self,
        limits: ViewLimits,
        viewer: Viewer<'_>,
    ) -> Result<String, ViewError> {
        self.check()?;
        let decimated = limits.decimate(self);
        let json = script_safe_json(&serde_json::to_string(&decimated)?);
        let title = escape_html(&self.title);
        let licence = escape_html(THREE_LICENSE.trim());
        let comment = THREE_LICENSE.trim().replace("--", "- -");
        let mut page = String::with_capacity(json.len() + VIEWER.len() + 8192);
        page.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
        page.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
        page.push_str(&format!("<title>{title}</title>\n"));
        page.push_str(&format!(
            "<!-- Drawn with three.js (https://threejs.org), under this licence:\n{comment}\n-->\n"
        ));
        page.push_str(&format!("<style>{STYLE}</style>\n</head>\n<body>\n"));
        page.push_str(
            "<div id=\"stage\"></div>\n<aside id=\"panel\"><div id=\"panel-body\"></div>\n",
        );
        page.push_str(&format!(
            "<details id=\"about\"><summary>about</summary><p>Drawn with three.js {} \
             (MIT licence):</p><pre>{licence}</pre></details></aside>\n",
            env!("VIEW_THREE_VERSION")
        ));
        page.push_str("<div id=\"message\" hidden></div>\n<div id=\"tooltip\" hidden></div>\n");
        page.push_str("<script type=\"application/json\" id=\"mit-star-view-data\">");
        page.push_str(&json);
        match viewer {
            Viewer::Embedded => {
                page.push_str("</script>\n<script>");
                page.push_str(VIEWER);
                page.push_str("</script>\n</body>\n</html>\n");
            }
            Viewer::Beside(name) => {
                page.push_str(&format!(
                    "</script>\n<script src=\"{}\"></script>\n</body>\n</html>\n",
                    escape_html(name)
                ));
            }
        }
        Ok(page)
    }

    /// Writes [`to_html`](Self::to_html) to `path`; returns the bytes written.
    ///
    /// # Errors
    /// As `to_html`, and [`ViewError::Io`] naming `path` when it cannot be written.
    pub fn write_html(&self, path: impl AsRef<Path>, limits: ViewLimits) -> Result<u64, ViewError> {
        self.write_html_with(path, limits, Viewer::Embedded)
    }

    /// Writes [`to_html_with`](Self::to_html_with) to `path`; returns the bytes written.
    ///
    /// # Errors
    /// As [`write_html`](Self::write_html).
    pub fn write_html_with(
        &self,
        path: impl AsRef<Path>,
        limits: ViewLimits,
        viewer: Viewer<'_>,
    ) -> Result<u64, ViewError> {
        let path = path.as_ref();
        let page = self.to_html_with(limits, viewer)?;
        fs::write(path, &page).map_err(|source| ViewError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Ok(page.len() as u64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ViewKind;

    #[test]
    fn a_page_may_load_its_viewer_from_beside_it() {
        let doc = ViewDocument::new(ViewKind::World2d, "shared");
        let page = doc
            .to_html_with(ViewLimits::default(), Viewer::Beside("viewer.js"))
            .unwrap();
        let embedded = doc.to_html(ViewLimits::default()).unwrap();
        assert!(page.contains("<script src=\"viewer.js\"></script>"));
        assert!(page.len() + VIEWER.len() / 2 < embedded.len());
        let script = viewer_script();
        assert!(script.starts_with("/* Drawn with three.js") && script.ends_with(VIEWER));
    }

    #[test]
    fn nothing_in_the_json_can_close_the_script_or_open_a_comment() {
        let mut doc = ViewDocument::new(ViewKind::World2d, "a </script><script>alert(1)</script>");
        doc.notes.push("<!-- and </SCRIPT > too".into());
        let html = doc.to_html(ViewLimits::default()).unwrap();
        let data = html
            .split("id=\"mit-star-view-data\">")
            .nth(1)
            .and_then(|rest| rest.split("</script>").next())
            .unwrap();
        assert!(!data.contains('<'), "{data}");
        let json: serde_json::Value = serde_json::from_str(data).unwrap();
        assert_eq!(json["title"], "a </script><script>alert(1)</script>");
        assert_eq!(json["notes"][0], "<!-- and </SCRIPT > too");
        assert!(
            html.contains("<title>a &lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;</title>")
        );
        assert_eq!(
            html.matches("<script").count(),
            2,
            "only the data and the viewer"
        );
    }

    #[test]
    fn the_page_carries_the_viewer_and_the_licence() {
        let html = ViewDocument::new(ViewKind::World3d, "w")
            .to_html(ViewLimits::default())
            .unwrap();
        assert!(html.starts_with("<!DOCTYPE html>"));
        assert!(html.contains("<meta charset=\"utf-8\">"));
        assert!(html.contains("mitStarView"), "the bundle is embedded");
        assert!(html.contains("Permission is hereby granted"));
        assert!(html.contains(&format!("three.js {}", env!("VIEW_THREE_VERSION"))));
    }

    #[test]
    fn an_invalid_document_gives_no_page() {
        let mut doc = ViewDocument::new(ViewKind::Arm, "no robot");
        doc.subtitle.push("x".into());
        assert!(matches!(
            doc.to_html(ViewLimits::default()),
            Err(ViewError::Invalid { .. })
        ));
    }
}
