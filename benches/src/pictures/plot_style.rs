//! The look shared by every figure: the embedded font, the planners' colours, and saving a
//! figure as SVG and PNG.

use std::path::Path;
use std::sync::Once;

use mit_star::Configuration;
use plotters::coord::Shift;
use plotters::prelude::{BLACK, DrawingAreaErrorKind, IntoFont, PathElement, Text};
use plotters::prelude::{BitMapBackend, DrawingArea, DrawingBackend, IntoDrawingArea, SVGBackend};
use plotters::style::{Color, FontStyle, RGBColor};

use crate::definition::planner_spec::PlannerSpec;
use crate::error::HarnessError;

/// A figure plotters can draw on any backend, saved by [`save_svg_and_png`].
pub(crate) trait Figure {
    /// Draws the whole figure on `root`; a failure is described in words.
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String>;
}

/// Draws a figure's header on `area`: `title`, `subtitle` under it, and a legend line of
/// `entries` (a coloured stroke and a name each, spaced `char_width` pixels per character of
/// the name).
///
/// # Errors
/// The backend's drawing error.
pub(crate) fn draw_header<'a, DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (title, subtitle): (&str, &str),
    entries: impl IntoIterator<Item = (&'a str, RGBColor)>,
    char_width: i32,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    area.draw(&Text::new(
        title.to_owned(),
        (20, 10),
        ("sans-serif", 26).into_font().color(&BLACK),
    ))?;
    area.draw(&Text::new(
        subtitle.to_owned(),
        (20, 42),
        ("sans-serif", 15).into_font().color(&RGBColor(80, 80, 80)),
    ))?;
    let mut x = 20;
    for (name, colour) in entries {
        area.draw(&PathElement::new(
            vec![(x, 70), (x + 28, 70)],
            colour.stroke_width(4),
        ))?;
        area.draw(&Text::new(
            name.to_owned(),
            (x + 34, 62),
            ("sans-serif", 16).into_font().color(&BLACK),
        ))?;
        x += 60 + char_width * name.chars().count() as i32;
    }
    Ok(())
}

/// Draws `figure` at `size` pixels into an SVG and a PNG file (the embedded font registered).
///
/// # Errors
/// [`HarnessError::Plot`] naming the file that could not be drawn or written.
pub(crate) fn save_svg_and_png(
    figure: &impl Figure,
    size: (u32, u32),
    svg: &Path,
    png: &Path,
) -> Result<(), HarnessError> {
    ensure_font();
    let fail = |path: &Path| {
        let path = path.to_path_buf();
        move |message: String| HarnessError::Plot { path, message }
    };
    {
        let root = SVGBackend::new(svg, size).into_drawing_area();
        figure.draw_on(&root).map_err(fail(svg))?;
        root.present().map_err(|e| fail(svg)(e.to_string()))?;
    }
    let root = BitMapBackend::new(png, size).into_drawing_area();
    figure.draw_on(&root).map_err(fail(png))?;
    root.present().map_err(|e| fail(png)(e.to_string()))
}

static FONT: Once = Once::new();

/// Registers the embedded font (Noto Sans Regular, SIL Open Font License, from the
/// `ttf-noto-sans` crate) as plotters' `sans-serif`, once per process. No system font is
/// needed, so PNG text renders the same everywhere.
pub(crate) fn ensure_font() {
    FONT.call_once(|| {
        let _ =
            plotters::style::register_font("sans-serif", FontStyle::Normal, ttf_noto_sans::REGULAR);
    });
}

/// Fixed colours for the paper's configurations, so MIT* and EIT* look the same in every
/// figure of every experiment.
fn configuration_colour(c: Configuration) -> RGBColor {
    match c {
        Configuration::MitStar => RGBColor(214, 39, 40),
        Configuration::EitStar => RGBColor(31, 119, 180),
        Configuration::MitStarAs => RGBColor(44, 160, 44),
        Configuration::MitStarEis => RGBColor(148, 103, 189),
        Configuration::MitStarSc => RGBColor(255, 127, 14),
        Configuration::MitStarSr => RGBColor(23, 100, 60),
        Configuration::RrtConnect => RGBColor(23, 190, 207),
        Configuration::Aorrtc => RGBColor(0, 90, 110),
        Configuration::BitStar => RGBColor(140, 86, 75),
        Configuration::AbitStar => RGBColor(227, 119, 194),
        Configuration::AitStar => RGBColor(188, 189, 34),
        Configuration::InformedRrtStar => RGBColor(127, 127, 127),
        Configuration::FcitStar => RGBColor(100, 60, 20),
    }
}

/// Colours for further planners of an already coloured configuration.
const EXTRA: [RGBColor; 5] = [
    RGBColor(82, 84, 163),
    RGBColor(0, 0, 0),
    RGBColor(57, 59, 121),
    RGBColor(140, 109, 49),
    RGBColor(99, 121, 57),
];

/// One colour per planner, in experiment order: the first planner of each configuration gets
/// that configuration's fixed colour (MIT* red, EIT* blue, MIT*-AS green, MIT*-EIS purple,
/// MIT*-SC orange, MIT*-SR dark green, RRT-Connect cyan, BIT* brown, ABIT* pink, AIT* olive, Informed RRT* grey); further planners of the same configuration get distinct extra colours.
///
/// ```
/// use mit_star_benches::{planner_colours, ParameterOverrides, PlannerSpec};
/// use mit_star::Configuration::{EitStar, MitStar};
/// let o = ParameterOverrides::default();
/// let planners = [PlannerSpec::new(EitStar, None, &o)?, PlannerSpec::new(MitStar, None, &o)?];
/// let colours = planner_colours(&planners);
/// assert_eq!(colours[1], plotters::style::RGBColor(214, 39, 40));
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
pub fn planner_colours(planners: &[PlannerSpec]) -> Vec<RGBColor> {
    let mut extra = EXTRA.iter().cycle();
    planners
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let first = !planners[..i]
                .iter()
                .any(|q| q.configuration() == p.configuration());
            if first {
                configuration_colour(p.configuration())
            } else {
                *extra.next().unwrap_or(&EXTRA[0])
            }
        })
        .collect()
}

/// Clips the segment `a → b` to the box `[lo, hi]` (Liang–Barsky); `None` if it lies outside.
pub(crate) fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    lo: (f64, f64),
    hi: (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - lo.0),
        (dx, hi.0 - a.0),
        (-dy, a.1 - lo.1),
        (dy, hi.1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping() {
        let (lo, hi) = ((0.0, 0.0), (1.0, 1.0));
        assert_eq!(
            clip_segment((0.2, 0.2), (0.4, 0.4), lo, hi),
            Some(((0.2, 0.2), (0.4, 0.4)))
        );
        let ((a, b), _) = clip_segment((-1.0, 0.5), (0.5, 0.5), lo, hi).unwrap();
        assert_eq!((a, b), (0.0, 0.5));
        assert_eq!(clip_segment((2.0, 2.0), (3.0, 3.0), lo, hi), None);
        assert_eq!(clip_segment((-1.0, 2.0), (2.0, 2.0), lo, hi), None);
    }

    #[test]
    fn colours_are_distinct_for_repeated_configurations() {
        let o = crate::ParameterOverrides::default();
        let a = PlannerSpec::new(Configuration::MitStar, None, &o).unwrap();
        let b = PlannerSpec::new(Configuration::MitStar, Some("MIT* b".into()), &o).unwrap();
        let c = planner_colours(&[a, b]);
        assert_ne!(c[0], c[1]);
        ensure_font();
        ensure_font();
    }
}
