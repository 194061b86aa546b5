//! [`Enclosure`]: the builder shared by goal, start and double enclosure — start and goal, and
//! hollow cubes with an opening around the ends that [`EnclosedEnds`] names.

use std::marker::PhantomData;

use mit_star_validity::{AxisBox, World};

use crate::families::optimum::enclosure_escape;
use crate::families::shared::{axis_point, check_endpoints, check_positive, on_axis, unit_world};
use crate::{Parameter, Problem, ProblemError};

/// PDT's enclosure families in `[-0.5, 0.5]^n`: `E` says which ends sit at the centre of a
/// hollow cube whose only opening faces away from the other end. Used through its aliases
/// [`GoalEnclosure`](crate::GoalEnclosure), [`StartEnclosure`](crate::StartEnclosure) and
/// [`DoubleEnclosure`](crate::DoubleEnclosure), whose docs give the geometry, the defaults and
/// the optimum.
///
/// Every enclosure has the same sizes: an obstacle cube of side `outside` centred on the
/// enclosed end, an anti-obstacle hollow of side `inside` centred on it, and an anti-obstacle
/// opening through the face pointing away from the other end, `(outside − inside)/2` wide in
/// `x` and `gap` wide in every other coordinate.
#[derive(Debug, Clone, PartialEq)]
pub struct Enclosure<E> {
    n: usize,
    start: Vec<f64>,
    goal: Vec<f64>,
    sizes: Sizes,
    ends: PhantomData<E>,
}

/// Which ends of an [`Enclosure`] are enclosed, with the family's name and closed-form optimum:
/// [`GoalEnclosed`](crate::GoalEnclosed), [`StartEnclosed`](crate::StartEnclosed) or
/// [`BothEnclosed`](crate::BothEnclosed). Sealed: no other type implements it.
pub trait EnclosedEnds: Ends {}

/// The crate-private part of [`EnclosedEnds`] (its seal).
pub trait Ends {
    /// The family's name in the [catalogue](crate::catalogue).
    const NAME: &'static str;
    /// The start is enclosed (its opening faces `−x`).
    const START: bool;
    /// The goal is enclosed (its opening faces `+x`).
    const GOAL: bool;

    /// The closed-form optimum from the x-coordinates `sx` of the start and `gx` of the goal,
    /// the outer half-side `h` and the cost `escape` of leaving one enclosure; called only when
    /// both ends lie on the x-axis and the sizes admit a closed form. `None` when the family's
    /// own conditions fail.
    fn optimum(sx: f64, gx: f64, h: f64, escape: f64) -> Option<f64>;
}

impl<E: EnclosedEnds> Enclosure<E> {
    /// The family's name in the [catalogue](crate::catalogue).
    pub const NAME: &'static str = E::NAME;

    /// PDT's defaults in `n` dimensions (checked by [`build`](Self::build): `n ≥ 2`).
    pub fn new(n: usize) -> Self {
        Self {
            n,
            start: axis_point(n, -0.2),
            goal: axis_point(n, 0.2),
            sizes: Sizes::PDT,
            ends: PhantomData,
        }
    }

    /// Sets the start state (an enclosure's centre if the start is enclosed).
    pub fn start(mut self, start: Vec<f64>) -> Self {
        self.start = start;
        self
    }

    /// Sets the goal state (an enclosure's centre if the goal is enclosed).
    pub fn goal(mut self, goal: Vec<f64>) -> Self {
        self.goal = goal;
        self
    }

    /// Sets the side of the enclosing cubes.
    pub fn outside(mut self, outside: f64) -> Self {
        self.sizes.outside = outside;
        self
    }

    /// Sets the side of the hollows (less than `outside`).
    pub fn inside(mut self, inside: f64) -> Self {
        self.sizes.inside = inside;
        self
    }

    /// Sets the width of the openings in every coordinate but `x`.
    pub fn gap(mut self, gap: f64) -> Self {
        self.sizes.gap = gap;
        self
    }

    /// The current parameter values, for listings.
    pub fn parameters(&self) -> Vec<Parameter> {
        vec![
            Parameter::point("start", &self.start, "start state"),
            Parameter::point("goal", &self.goal, "goal state"),
            Parameter::number("outside", self.sizes.outside, "side of the enclosing cube"),
            Parameter::number("inside", self.sizes.inside, "side of the hollow"),
            Parameter::number("gap", self.sizes.gap, "width of the opening"),
        ]
    }

    /// Builds the problem.
    ///
    /// # Errors
    /// [`ProblemError::Dimension`] if `n < 2`; [`ProblemError::Parameter`] for a size that is
    /// not finite and positive, `inside ≥ outside`, or a start or goal of the wrong length;
    /// [`ProblemError::State`] or [`ProblemError::InCollision`] for a start or goal out of
    /// bounds or in the shell.
    pub fn build(&self) -> Result<Problem, ProblemError> {
        let (name, n) = (Self::NAME, self.n);
        check_endpoints(name, n, &self.start, &self.goal)?;
        self.sizes.check(name)?;
        let mut world = unit_world(n);
        if E::START {
            self.sizes.add_to(&mut world, &self.start, -1.0)?;
        }
        if E::GOAL {
            self.sizes.add_to(&mut world, &self.goal, 1.0)?;
        }
        Problem::new(name, world, self.start.clone(), vec![self.goal.clone()])?
            .with_optimum(self.optimum())
    }

    /// The closed-form optimum (the aliases' docs).
    fn optimum(&self) -> Option<f64> {
        let applies = on_axis(&self.start) && on_axis(&self.goal) && self.sizes.has_closed_form();
        let escape = enclosure_escape(self.sizes.outside, self.sizes.gap);
        applies
            .then(|| E::optimum(self.start[0], self.goal[0], self.sizes.half(), escape))
            .flatten()
    }
}

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
    ) -> Result<(), mit_star_validity::ValidityError> {
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
    use mit_star_validity::StateValidity;

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
