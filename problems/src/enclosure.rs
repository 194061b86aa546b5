//! The hollow cube with an opening shared by goal, start and double enclosure.

use validity::{AxisBox, World};

use crate::ProblemError;
use crate::family::check_positive;

/// Extra thickness in `x` given to an opening so that rounding in its centre cannot leave a
/// sliver of wall between it and the hollow (PDT's "plus epsilon"). Harmless: the opening only
/// reaches further into the hollow and into the free space outside, both free anyway.
const SEAM: f64 = 1e-9;

/// Sizes of an enclosure: full side lengths of the outer cube and of the hollow, and the width
/// of the opening.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sizes {
    pub(crate) outside: f64,
    pub(crate) inside: f64,
    pub(crate) gap: f64,
}

impl Sizes {
    /// PDT's defaults: outside 0.25, inside 0.2, gap 0.2.
    pub(crate) const PDT: Self = Self {
        outside: 0.25,
        inside: 0.2,
        gap: 0.2,
    };

    /// Checks that all three are finite and positive and that the hollow fits inside.
    pub(crate) fn check(&self, problem: &'static str) -> Result<(), ProblemError> {
        check_positive(problem, "outside", self.outside)?;
        check_positive(problem, "inside", self.inside)?;
        check_positive(problem, "gap", self.gap)?;
        if self.inside >= self.outside {
            return Err(ProblemError::Parameter {
                problem,
                parameter: "inside",
                reason: format!(
                    "is {}; it must be less than `outside` ({})",
                    self.inside, self.outside
                ),
            });
        }
        Ok(())
    }

    /// Adds the enclosure around `center` to the world, with its opening in the face pointing
    /// to `+x` (`facing = 1.0`) or `−x` (`facing = -1.0`).
    ///
    /// The outer cube is an obstacle; the hollow and the opening are anti-obstacles. The opening
    /// spans the shell's thickness in `x` and `gap` in every other coordinate.
    pub(crate) fn add_to(
        &self,
        world: &mut World,
        center: &[f64],
        facing: f64,
    ) -> Result<(), validity::ValidityError> {
        world.add_obstacle(AxisBox::cube(center.to_vec(), self.outside))?;
        world.add_anti_obstacle(AxisBox::cube(center.to_vec(), self.inside))?;
        let shell = 0.5 * (self.outside - self.inside);
        let mut opening_center = center.to_vec();
        opening_center[0] += facing * (0.5 * self.inside + 0.5 * shell);
        let mut widths = vec![self.gap; center.len()];
        widths[0] = shell + SEAM;
        world.add_anti_obstacle(AxisBox::new(opening_center, widths))
    }

    /// `true` when the closed-form optima apply: the opening is no wider than the hollow and
    /// the cube leaves room around it in every coordinate but `x` (`x` is the caller's check).
    pub(crate) fn has_closed_form(&self) -> bool {
        self.gap <= self.inside && self.outside < 1.0
    }

    /// Half the outer side.
    pub(crate) fn half(&self) -> f64 {
        0.5 * self.outside
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use validity::StateValidity;

    #[test]
    fn opening_faces_the_requested_side() {
        for facing in [1.0, -1.0] {
            let mut world = World::new(vec![-0.5; 2], vec![0.5; 2]);
            Sizes::PDT.add_to(&mut world, &[0.0, 0.0], facing).unwrap();
            // Shell x ∈ [0.1, 0.125] on the opening side, |y| ≤ 0.1 open.
            assert!(world.is_valid(&[facing * 0.11, 0.09]));
            assert!(!world.is_valid(&[facing * 0.11, 0.11]));
            assert!(!world.is_valid(&[-facing * 0.11, 0.0]));
            assert!(world.is_valid(&[0.0, 0.0]));
            assert!(!world.is_valid(&[0.0, 0.11]));
        }
    }

    #[test]
    fn hollow_must_fit() {
        let sizes = Sizes {
            inside: 0.3,
            ..Sizes::PDT
        };
        assert_eq!(
            sizes.check("goal-enclosure").unwrap_err().to_string(),
            "goal-enclosure: `inside` is 0.3; it must be less than `outside` (0.25)"
        );
        assert!(Sizes::PDT.check("goal-enclosure").is_ok());
    }
}
