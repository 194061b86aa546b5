//! [`GoalEnclosure`]: PDT's goal enclosure — the goal sits in a hollow cube opening away from
//! the start.

use crate::families::enclosures::enclosure::{EnclosedEnds, Enclosure, Ends};

/// PDT's **goal enclosure** in `[-0.5, 0.5]^n`: the goal lies inside a hollow cube whose only
/// opening is in the face pointing to `+x`, away from the start, so a planner must go around.
///
/// The obstacle is a cube of side `outside` centred on the goal; the hollow is an anti-obstacle
/// cube of side `inside` centred on the goal; the opening is an anti-obstacle centred at
/// `x = goal_x + inside/2 + (outside − inside)/4` (other coordinates those of the goal),
/// `(outside − inside)/2` wide in `x` and `gap` wide in every other coordinate.
///
/// | parameter | default (every n) |
/// |---|---|
/// | `start` / `goal` | (−0.2, 0, …) / (0.2, 0, …) |
/// | `outside` / `inside` / `gap` | 0.25 / 0.2 / 0.2 |
///
/// The paper's figure variant is `start (−0.4, 0)`, `goal (0.1, 0)` (its unit-square
/// `(0.1, 0.5)` / `(0.6, 0.5)`).
///
/// **Optimum.** When start and goal lie on the x-axis, the start left of the cube, the opening
/// no wider than the hollow and the cube clear of the bounds, the shortest path runs to the
/// cube's near top corner, along its top, down its `+x` face to the opening's edge and in to the
/// goal: `√(a² + h²) + 2h + (h − g) + √(h² + g²)` with `h = outside/2`, `g = gap/2` and `a` the
/// start's distance to the cube (≈ 0.7372 by default, in every dimension). Otherwise unknown.
///
/// ```
/// use mit_star_problems::GoalEnclosure;
/// use mit_star_validity::StateValidity;
///
/// let problem = GoalEnclosure::new(2).start(vec![-0.4, 0.0]).goal(vec![0.1, 0.0]).build()?;
/// assert!(!problem.world().is_valid(&[0.1, 0.11])); // the shell
/// assert!(problem.world().is_valid(&[0.21, 0.0])); // the opening
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
pub type GoalEnclosure = Enclosure<GoalEnclosed>;

/// The [`EnclosedEnds`](crate::EnclosedEnds) of [`GoalEnclosure`]: only the goal is enclosed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct GoalEnclosed;

impl EnclosedEnds for GoalEnclosed {}

impl Ends for GoalEnclosed {
    const NAME: &'static str = "goal-enclosure";
    const START: bool = false;
    const GOAL: bool = true;

    fn optimum(sx: f64, gx: f64, h: f64, escape: f64) -> Option<f64> {
        (sx < gx - h && gx + h < 0.5).then(|| (gx - h - sx).hypot(h) + escape)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ProblemError;
    use crate::test_support::{polyline_is_valid, polyline_length};
    use mit_star_validity::StateValidity;

    #[test]
    fn goal_is_enclosed_with_an_opening_away_from_the_start() {
        let p = GoalEnclosure::new(3).build().unwrap();
        let w = p.world();
        // Shell x ∈ [0.075, 0.1] ∪ [0.3, 0.325], |y|, |z| ∈ [0.1, 0.125].
        assert!(!w.is_valid(&[0.09, 0.0, 0.0]));
        assert!(!w.is_valid(&[0.2, 0.11, 0.0]));
        assert!(!w.is_valid(&[0.2, 0.0, -0.11]));
        assert!(w.is_valid(&[0.31, 0.05, -0.05]));
        assert!(!w.is_valid(&[0.31, 0.05, -0.11]));
    }

    #[test]
    fn optimum_is_attained_by_a_valid_path() {
        let p = GoalEnclosure::new(2).build().unwrap();
        let d = 1e-9;
        let path = [
            vec![-0.2, 0.0],
            vec![0.075 - d, 0.125 + d],
            vec![0.325 + d, 0.125 + d],
            vec![0.325 + d, 0.1 - d],
            vec![0.2, 0.0],
        ];
        assert!(polyline_is_valid(p.world(), &path));
        let optimum = p.optimum().unwrap();
        assert!((polyline_length(&path) - optimum).abs() < 1e-8);
        assert!((optimum - 0.73715).abs() < 1e-5, "{optimum}");
        // The optimum of the 2-D problem holds in every dimension.
        let p8 = GoalEnclosure::new(8).build().unwrap();
        assert_eq!(p8.optimum(), Some(optimum));
    }

    #[test]
    fn parameters_are_checked() {
        assert!(matches!(
            GoalEnclosure::new(2).gap(f64::NAN).build(),
            Err(ProblemError::Parameter {
                parameter: "gap",
                ..
            })
        ));
        // The start inside the shell.
        assert!(matches!(
            GoalEnclosure::new(2).start(vec![0.09, 0.0]).build(),
            Err(ProblemError::InCollision { .. })
        ));
        // A goal near the bound: no room to reach the opening, no closed form.
        let p = GoalEnclosure::new(2).goal(vec![0.4, 0.0]).build().unwrap();
        assert_eq!(p.optimum(), None);
    }
}
