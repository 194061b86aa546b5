//! [`StartEnclosure`]: goal enclosure mirrored — the start sits in a hollow cube opening away
//! from the goal.

use crate::families::enclosures::enclosure::{EnclosedEnds, Enclosure, Ends};

/// PDT's **start enclosure** in `[-0.5, 0.5]^n`: the mirror image of
/// [`GoalEnclosure`](crate::GoalEnclosure). The start lies inside a hollow cube whose only
/// opening is in the face pointing to `−x`, away from the goal.
///
/// The obstacle is a cube of side `outside` centred on the start, the hollow a cube of side
/// `inside`, the opening centred at `x = start_x − inside/2 − (outside − inside)/4`,
/// `(outside − inside)/2` wide in `x` and `gap` wide in every other coordinate.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.2, 0, …) / (0.2, 0, …) |
/// | `outside` / `inside` / `gap` | 0.25 / 0.2 / 0.2 |
///
/// **Optimum.** The goal enclosure's, mirrored: `√(h² + g²) + (h − g) + 2h + √(b² + h²)` with
/// `h = outside/2`, `g = gap/2` and `b` the goal's distance to the cube, under the mirrored
/// conditions (≈ 0.7372 by default). Otherwise unknown.
pub type StartEnclosure = Enclosure<StartEnclosed>;

/// The [`EnclosedEnds`](crate::EnclosedEnds) of [`StartEnclosure`]: only the start is enclosed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct StartEnclosed;

impl EnclosedEnds for StartEnclosed {}

impl Ends for StartEnclosed {
    const NAME: &'static str = "start-enclosure";
    const START: bool = true;
    const GOAL: bool = false;

    fn optimum(sx: f64, gx: f64, h: f64, escape: f64) -> Option<f64> {
        (gx > sx + h && sx - h > -0.5).then(|| escape + (gx - sx - h).hypot(h))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::GoalEnclosure;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use mit_star_validity::StateValidity;

    #[test]
    fn start_is_enclosed_with_an_opening_away_from_the_goal() {
        let p = StartEnclosure::new(2).build().unwrap();
        let w = p.world();
        assert!(w.is_valid(&[-0.31, 0.0]));
        assert!(!w.is_valid(&[-0.09, 0.0]));
        assert!(!w.is_valid(&[-0.2, 0.11]));
    }

    #[test]
    fn optimum_mirrors_the_goal_enclosure() {
        let p = StartEnclosure::new(2).build().unwrap();
        let optimum = p.optimum().unwrap();
        let mirrored = GoalEnclosure::new(2).build().unwrap().optimum().unwrap();
        assert!((optimum - mirrored).abs() < 1e-12);
        let d = 1e-9;
        let path = [
            vec![-0.2, 0.0],
            vec![-0.325 - d, 0.1 - d],
            vec![-0.325 - d, 0.125 + d],
            vec![-0.075 + d, 0.125 + d],
            vec![0.2, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
    }
}
