//! [`GoalSource`]: goal states drawn while planning, one at a time (OMPL's `GoalLazySamples`).

use mit_star_spaces::Stop;

/// A goal region that yields its goal states one at a time, while a planner plans: a pose of a
/// robot's hand reached through inverse kinematics, a set of grasps, any goal a planner cannot
/// be given as a finite list up front. [`LazyGoals`](crate::LazyGoals) asks it for goals
/// between stretches of planning.
///
/// A source gives valid states only (in bounds, collision-free), each new: a state it gave
/// before is not given again. Object safe: `Box<dyn GoalSource + Send>` works.
///
/// ```
/// use mit_star::GoalSource;
/// use mit_star_spaces::Stop;
///
/// /// The goals of a list, in order.
/// struct Listed(Vec<Vec<f64>>, usize);
///
/// impl GoalSource for Listed {
///     fn next_goal(&mut self, _stop: &dyn Stop) -> Option<Vec<f64>> {
///         let goal = self.0.get(self.1).cloned();
///         self.1 += 1;
///         goal
///     }
///     fn exhausted(&self) -> bool {
///         self.1 >= self.0.len()
///     }
///     fn reset(&mut self) {
///         self.1 = 0;
///     }
/// }
/// let mut source = Listed(vec![vec![0.9, 0.9]], 0);
/// assert_eq!(source.next_goal(&mit_star_spaces::Never), Some(vec![0.9, 0.9]));
/// assert!(source.exhausted());
/// ```
pub trait GoalSource {
    /// Draws a goal state not given before, or `None` if none was found before `stop` fired
    /// or the source ran out. Polls `stop` in every loop.
    fn next_goal(&mut self, stop: &dyn Stop) -> Option<Vec<f64>>;

    /// `true` once the source has no goal left to give (a finite set, every member given).
    /// The default: never.
    fn exhausted(&self) -> bool {
        false
    }

    /// Forgets the goals given and rewinds any random state, so the next draws repeat the
    /// first ones (a planner's `clear`).
    fn reset(&mut self);
}

impl<G: GoalSource + ?Sized> GoalSource for Box<G> {
    fn next_goal(&mut self, stop: &dyn Stop) -> Option<Vec<f64>> {
        (**self).next_goal(stop)
    }

    fn exhausted(&self) -> bool {
        (**self).exhausted()
    }

    fn reset(&mut self) {
        (**self).reset();
    }
}
