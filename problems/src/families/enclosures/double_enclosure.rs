//! [`DoubleEnclosure`]: start and goal each sit in a hollow cube opening away from the other.

use crate::families::enclosures::enclosure::{EnclosedEnds, Enclosure, Ends};

/// PDT's **double enclosure** in `[-0.5, 0.5]^n`: [`StartEnclosure`](crate::StartEnclosure)
/// and [`GoalEnclosure`](crate::GoalEnclosure) together. Both cubes have the same sizes; the
/// start's opens to `−x`, the goal's to `+x`.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.2, 0, …) / (0.2, 0, …) |
/// | `outside` / `inside` / `gap` | 0.25 / 0.2 / 0.2 |
///
/// **Optimum.** When start and goal lie on the x-axis, the cubes are disjoint and clear of the
/// bounds and the openings no wider than the hollows, the shortest path leaves the start's cube,
/// runs along the tops of both cubes and enters the goal's:
/// `2(√(h² + g²) + (h − g) + 2h) + d` with `h = outside/2`, `g = gap/2` and `d` the distance
/// between the cubes (≈ 1.0202 by default). Otherwise unknown.
pub type DoubleEnclosure = Enclosure<BothEnclosed>;

/// The [`EnclosedEnds`](crate::EnclosedEnds) of [`DoubleEnclosure`]: start and goal are both
/// enclosed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct BothEnclosed;

impl EnclosedEnds for BothEnclosed {}

impl Ends for BothEnclosed {
    const NAME: &'static str = "double-enclosure";
    const START: bool = true;
    const GOAL: bool = true;

    fn optimum(sx: f64, gx: f64, h: f64, escape: f64) -> Option<f64> {
        let applies = sx + h < gx - h && sx - h > -0.5 && gx + h < 0.5;
        applies.then_some(2.0 * escape + (gx - h) - (sx + h))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use mit_star_validity::StateValidity;

    #[test]
    fn both_ends_are_enclosed() {
        let p = DoubleEnclosure::new(4).build().unwrap();
        let w = p.world();
        assert_eq!(w.obstacles().len(), 2);
        assert!(w.is_valid(&[-0.31, 0.0, 0.0, 0.0]));
        assert!(!w.is_valid(&[-0.09, 0.0, 0.0, 0.0]));
        assert!(w.is_valid(&[0.31, 0.0, 0.0, 0.0]));
        assert!(!w.is_valid(&[0.09, 0.0, 0.0, 0.0]));
        assert!(w.is_valid(&[0.0, 0.0, 0.0, 0.0]));
    }

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        let p = DoubleEnclosure::new(2).build().unwrap();
        let d = 1e-9;
        let (top, edge) = (0.125 + d, 0.1 - d);
        let path = [
            vec![-0.2, 0.0],
            vec![-0.325 - d, edge],
            vec![-0.325 - d, top],
            vec![0.325 + d, top],
            vec![0.325 + d, edge],
            vec![0.2, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        let optimum = p.optimum().unwrap();
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
        assert!((optimum - 1.02016).abs() < 1e-5, "{optimum}");
    }

    #[test]
    fn overlapping_cubes_have_no_closed_form() {
        let p = DoubleEnclosure::new(2)
            .start(vec![-0.1, 0.0])
            .goal(vec![0.1, 0.0])
            .build()
            .unwrap();
        assert_eq!(p.optimum(), None);
    }
}
