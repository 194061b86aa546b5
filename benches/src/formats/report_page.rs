//! [`ReportPage`]: `report.html`, an experiment's results on one page — the KPI tables, each
//! scene's figure (cost and success over time per planner, first solutions; each problem
//! instance's too with `--per-problem`) and links to the 3-D views of best and worst runs.

use std::fmt::Write as _;

use mit_star_view::escape_html as escape;

/// One problem instance on the report: its figure and its view, as paths relative to the
/// results folder.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ReportInstance {
    /// The instance's title.
    pub(crate) title: String,
    /// Its figure (`plots/<id>.svg`), if drawn.
    pub(crate) figure: Option<String>,
    /// Its 3-D view (`views/<id>.html`) and what the view shows, if written.
    pub(crate) view: Option<(String, String)>,
}

/// The report page of an experiment.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ReportPage {
    /// The page's title (the experiment's name).
    pub(crate) title: String,
    /// `kpi.md`, shown as HTML.
    pub(crate) kpi_markdown: String,
    /// The instances, in the experiment's order.
    pub(crate) instances: Vec<ReportInstance>,
}

const STYLE: &str = "body{font-family:system-ui,sans-serif;margin:2em auto;max-width:72em;\
padding:0 1em;color:#222}table{border-collapse:collapse;margin:1em 0;font-size:.9em}\
th,td{border:1px solid #ccc;padding:.25em .6em;text-align:right}th{background:#f2f2f2}\
td:first-child,th:first-child{text-align:left}code{background:#f4f4f4;padding:0 .2em}\
figure{margin:1.5em 0;border-top:1px solid #ddd;padding-top:1em}figure img{max-width:100%}\
nav a{margin-right:1em}";

impl ReportPage {
    /// The page as HTML (no script, no external resource but the figures and views beside it).
    pub(crate) fn to_html(&self) -> String {
        let mut s = String::new();
        let _ = write!(
            s,
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
             <meta name=\"viewport\" content=\"width=device-width\"><title>{}</title>\
             <style>{STYLE}</style></head><body>\n",
            escape(&self.title)
        );
        let _ = writeln!(
            s,
            "<nav><a href=\"#tables\">Tables</a><a href=\"#instances\">Figures</a></nav>"
        );
        let _ = writeln!(s, "<section id=\"tables\">");
        s.push_str(&markdown_html(&self.kpi_markdown));
        let _ = writeln!(s, "</section>\n<section id=\"instances\"><h2>Figures</h2>");
        if self.instances.iter().all(|i| i.figure.is_none()) {
            let _ = writeln!(
                s,
                "<p>No figures: the experiment ran with <code>--no-plots</code>.</p>"
            );
        }
        for (k, instance) in self.instances.iter().enumerate() {
            let _ = write!(
                s,
                "<figure id=\"instance-{k}\"><figcaption><strong>{}</strong>",
                escape(&instance.title)
            );
            if let Some((link, what)) = &instance.view {
                let _ = write!(
                    s,
                    " · <a href=\"{}\">3-D view</a> ({})",
                    escape(link),
                    escape(what)
                );
            }
            s.push_str("</figcaption>");
            if let Some(figure) = &instance.figure {
                let _ = write!(
                    s,
                    "<img src=\"{}\" alt=\"median cost and success over time of {}\" loading=\"lazy\">",
                    escape(figure),
                    escape(&instance.title)
                );
            }
            s.push_str("</figure>\n");
        }
        s.push_str("</section></body></html>\n");
        s
    }
}

/// The Markdown that `kpi.md` uses as HTML: `#` headings, paragraphs, pipe tables (the
/// separator row dropped), `code` and **bold** spans. Everything else is text, escaped.
pub(crate) fn markdown_html(markdown: &str) -> String {
    let mut out = String::new();
    let mut paragraph: Vec<&str> = Vec::new();
    let mut table: Vec<Vec<String>> = Vec::new();
    let flush = |out: &mut String, paragraph: &mut Vec<&str>, table: &mut Vec<Vec<String>>| {
        if !paragraph.is_empty() {
            let _ = writeln!(out, "<p>{}</p>", inline(&paragraph.join(" ")));
            paragraph.clear();
        }
        if !table.is_empty() {
            out.push_str("<table>");
            for (r, row) in table.iter().enumerate() {
                let cell = if r == 0 { "th" } else { "td" };
                out.push_str("<tr>");
                for c in row {
                    let _ = write!(out, "<{cell}>{}</{cell}>", inline(c));
                }
                out.push_str("</tr>");
            }
            out.push_str("</table>\n");
            table.clear();
        }
    };
    for line in markdown.lines() {
        let trimmed = line.trim();
        if trimmed.starts_with('|') {
            if !paragraph.is_empty() {
                flush(&mut out, &mut paragraph, &mut Vec::new());
            }
            let cells: Vec<String> = trimmed
                .trim_matches('|')
                .split('|')
                .map(|c| c.trim().to_owned())
                .collect();
            let separator = cells
                .iter()
                .all(|c| !c.is_empty() && c.chars().all(|ch| matches!(ch, '-' | ':')));
            if !separator {
                table.push(cells);
            }
            continue;
        }
        let level = trimmed.chars().take_while(|&c| c == '#').count();
        let heading = (1..=6).contains(&level) && trimmed[level..].starts_with(' ');
        // A paragraph runs on until a blank line, a heading or a table.
        if !table.is_empty() || trimmed.is_empty() || heading {
            flush(&mut out, &mut paragraph, &mut table);
        }
        if trimmed.is_empty() {
            continue;
        }
        if heading {
            let _ = writeln!(
                out,
                "<h{level}>{}</h{level}>",
                inline(trimmed[level..].trim())
            );
        } else {
            paragraph.push(trimmed);
        }
    }
    flush(&mut out, &mut paragraph, &mut table);
    out
}

/// Inline Markdown: `code` and **bold**; the rest escaped.
fn inline(text: &str) -> String {
    let mut out = String::new();
    let mut code = false;
    let mut bold = false;
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if c == '`' {
            out.push_str(if code { "</code>" } else { "<code>" });
            code = !code;
            rest = &rest[1..];
        } else if !code && rest.starts_with("**") {
            out.push_str(if bold { "</strong>" } else { "<strong>" });
            bold = !bold;
            rest = &rest[2..];
        } else {
            out.push_str(&escape(&rest[..c.len_utf8()]));
            rest = &rest[c.len_utf8()..];
        }
    }
    if code {
        out.push_str("</code>");
    }
    if bold {
        out.push_str("</strong>");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kpi_markdown_becomes_headings_paragraphs_and_tables() {
        let md = "# Run <1>\n\nStarted on `box` with **2 runs**\nconcurrently.\n\n\
                  | planner | cost |\n|---|---:|\n| MIT* | 1.5 |\n\n## Next\n";
        let html = markdown_html(md);
        assert!(html.contains("<h1>Run &lt;1&gt;</h1>"), "{html}");
        assert!(
            html.contains(
                "<p>Started on <code>box</code> with <strong>2 runs</strong> concurrently.</p>"
            ),
            "{html}"
        );
        assert!(
            html.contains("<table><tr><th>planner</th><th>cost</th></tr><tr><td>MIT*</td><td>1.5</td></tr></table>"),
            "{html}"
        );
        assert!(html.contains("<h2>Next</h2>"));
        assert!(!html.contains("---"));
    }

    #[test]
    fn the_page_links_figures_and_views() {
        let page = ReportPage {
            title: "demo".into(),
            kpi_markdown: "# demo\n".into(),
            instances: vec![
                ReportInstance {
                    title: "box #1".into(),
                    figure: Some("plots/box-1.svg".into()),
                    view: Some(("views/box-1.html".into(), "best and worst run".into())),
                },
                ReportInstance {
                    title: "walls R^8".into(),
                    figure: None,
                    view: None,
                },
            ],
        };
        let html = page.to_html();
        assert!(html.contains("<img src=\"plots/box-1.svg\""));
        assert!(html.contains("<a href=\"views/box-1.html\">3-D view</a> (best and worst run)"));
        assert!(html.contains("<strong>walls R^8</strong></figcaption></figure>"));
        assert!(html.starts_with("<!DOCTYPE html>"));
    }
}
