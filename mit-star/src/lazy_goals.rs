//! [`LazyGoals`]: plan towards a goal region whose states a [`GoalSource`] keeps supplying.

use std::time::{Duration, Instant};

use mit_star_spaces::Stop;

use crate::termination::Wrapped;
use crate::{
    BuildError, Counters, GoalSource, Outcome, Planner, PlannerError, Progress, Snapshot, Solution,
    Termination, TerminationExt, TimeLimit, Trace,
};

/// Plans towards a goal region: a [`GoalSource`] supplies goal states while planning, and the
/// planner is rebuilt over the grown goal set with the best path so far offered to it
/// ([`Planner::offer_solution`]). This is how a pose of a robot's hand becomes a goal: the
/// source is inverse kinematics, each new solution a new goal (OMPL's `GoalLazySamples`
/// with a sampling thread; MoveIt's goal regions).
///
/// Planning alternates stretches of the planner (the first `first_stretch` long, each next
/// twice the last) with a draw of one goal (at most `goal_share` of the stretch before it).
/// It starts once `initial_goals` goals are drawn (or the source runs out after giving at
/// least one); once `max_goals` are drawn, or the source runs out, the planner plans on alone.
///
/// Why rebuilt rather than told: the EIT* family's informed sets, heuristics and reverse
/// search, AORRTC's cost-bounded sampling and RRT-Connect's goal tree are all built from the
/// goal set, so each planner is built over a set it knows whole, and each admissible bound
/// stays admissible **for the goals drawn so far**. A solution is optimal among paths to those
/// goals, not to the whole region: the region's best goal may never be drawn. The offered path
/// ends at a goal of the new set (sets only grow), so the rebuilt planner's cost bound and
/// pruning start from it (the EIT* family grafts it into its tree). The work of a discarded
/// planner is lost; stretches that double bound that loss to about half the planning time.
///
/// # Arguments
/// `build`, which builds the planner for a goal set (the same query otherwise, each time);
/// `source`, the goal region.
///
/// # Returns
/// From [`solve`](Planner::solve): the best path so far, to one of the goals drawn;
/// [`Outcome::NoSolution`] if the source gave no goal before the termination condition fired.
/// The trace holds every improvement at its time since the first `solve`. A build that fails
/// for a new goal (the source gave a state the query refuses) drops that goal and plans on
/// with the planner before it; the first build's failure is returned as the error.
///
/// # Complexity
/// The planner's own, plus one build per drawn goal (at most `max_goals`) and the source's
/// draws (at most `goal_share` of the planning time once planning started).
///
/// ```
/// use mit_star::{build_planner, Configuration, GoalSource, LazyGoals, Parameters, Planner, TimeLimit};
///
/// /// Three goals along the far side of the square `[-0.5, 0.5]²`.
/// struct Wall(usize);
/// impl GoalSource for Wall {
///     fn next_goal(&mut self, _: &dyn mit_star_spaces::Stop) -> Option<Vec<f64>> {
///         self.0 += 1;
///         (self.0 <= 3).then(|| vec![0.45, 0.6 - 0.3 * self.0 as f64])
///     }
///     fn exhausted(&self) -> bool { self.0 >= 3 }
///     fn reset(&mut self) { self.0 = 0 }
/// }
/// let world = mit_star_problems::DividingWalls::new(2).build()?.world().clone();
/// let build = move |goals: &[Vec<f64>]| {
///     let problem = mit_star_problems::Problem::new("wall", world.clone(), vec![-0.45, 0.0], goals.to_vec())?
///         .with_resolution(1e-3)?;
///     build_planner(Configuration::RrtConnect, &problem, &Parameters::default())
/// };
/// let mut planner = LazyGoals::new(build, Wall(0));
/// let outcome = planner.solve(&TimeLimit::seconds(0.5))?;
/// assert!(outcome.is_solved());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct LazyGoals<B, G, P> {
    build: B,
    source: G,
    goals: Vec<Vec<f64>>,
    /// The planner and the number of goals it was built with.
    planner: Option<(P, usize)>,
    name: String,
    solution: Option<Solution>,
    trace: Trace,
    /// Planning time of the finished `solve` calls.
    elapsed: Duration,
    /// Time the current planner planned, as this wrapper measured it.
    planner_time: Duration,
    /// Trace points of the current planner already merged.
    merged: usize,
    /// Counters of the planners discarded since the last `clear`.
    discarded: Counters,
    /// Time spent drawing goals, and goals the query refused.
    drawing: Duration,
    refused: usize,
    /// The next stretch of planning.
    stretch: Duration,
    initial_goals: usize,
    max_goals: usize,
    first_stretch: Duration,
    goal_share: f64,
}

impl<B, G, P> LazyGoals<B, G, P>
where
    B: FnMut(&[Vec<f64>]) -> Result<P, BuildError>,
    G: GoalSource,
    P: Planner,
{
    /// Plans with planners from `build` towards the goals `source` supplies, with the
    /// defaults: 1 initial goal, at most 8 goals, a first stretch of 5 ms, draws of at most
    /// a quarter of the stretch before them.
    pub fn new(build: B, source: G) -> Self {
        let first_stretch = Duration::from_millis(5);
        Self {
            build,
            source,
            goals: Vec::new(),
            planner: None,
            name: "lazy goals".into(),
            solution: None,
            trace: Trace::default(),
            elapsed: Duration::ZERO,
            planner_time: Duration::ZERO,
            merged: 0,
            discarded: Counters::default(),
            drawing: Duration::ZERO,
            refused: 0,
            stretch: first_stretch,
            initial_goals: 1,
            max_goals: 8,
            first_stretch,
            goal_share: 0.25,
        }
    }

    /// Goals drawn before planning starts (at least 1; more gives the first planner a choice
    /// of goals at the price of a later start).
    #[must_use]
    pub fn with_initial_goals(mut self, goals: usize) -> Self {
        self.initial_goals = goals.max(1);
        self.max_goals = self.max_goals.max(self.initial_goals);
        self
    }

    /// The most goals drawn (at least the initial ones); the planner plans on alone after.
    #[must_use]
    pub fn with_max_goals(mut self, goals: usize) -> Self {
        self.max_goals = goals.max(self.initial_goals);
        self
    }

    /// The first stretch of planning between draws (each next is twice the last).
    #[must_use]
    pub fn with_first_stretch(mut self, stretch: Duration) -> Self {
        self.first_stretch = stretch.max(Duration::from_micros(100));
        self.stretch = self.first_stretch;
        self
    }

    /// The most time a draw takes, as a fraction of the stretch before it (clamped to
    /// `[0.01, 10]`; NaN keeps the default).
    #[must_use]
    pub fn with_goal_share(mut self, share: f64) -> Self {
        if !share.is_nan() {
            self.goal_share = share.clamp(0.01, 10.0);
        }
        self
    }

    /// The goals drawn so far, oldest first.
    pub fn goals(&self) -> &[Vec<f64>] {
        &self.goals
    }

    /// The goal source.
    pub fn source(&self) -> &G {
        &self.source
    }

    /// Whether the source may still give goals this wrapper would use.
    fn drawing_on(&self) -> bool {
        self.goals.len() < self.max_goals && !self.source.exhausted()
    }

    /// Draws one goal, stopping when `termination` fires or after `budget`.
    fn draw(&mut self, termination: &dyn Termination, started: Instant, budget: Option<Duration>) {
        let began = Instant::now();
        let stop = DrawStop {
            termination: Wrapped {
                termination,
                started,
                best: self.best_cost(),
            },
            deadline: budget.map(|b| began + b),
        };
        if let Some(goal) = self.source.next_goal(&stop) {
            self.goals.push(goal);
        }
        self.drawing += began.elapsed();
    }

    /// Builds a planner over the goals if they grew since the last build, offering it the best
    /// path. A new goal the query refuses is dropped.
    fn rebuild(&mut self) -> Result<(), PlannerError> {
        if self
            .planner
            .as_ref()
            .is_some_and(|(_, n)| *n == self.goals.len())
        {
            return Ok(());
        }
        match (self.build)(&self.goals) {
            Ok(mut planner) => {
                if let Some(best) = &self.solution {
                    planner.offer_solution(best);
                }
                if let Some((old, _)) = self.planner.take() {
                    self.discarded = self.discarded.merged(&old.counters());
                }
                self.name = planner.name().to_owned();
                self.planner = Some((planner, self.goals.len()));
                self.planner_time = Duration::ZERO;
                self.merged = 0;
                Ok(())
            }
            Err(_) if self.planner.is_some() => {
                self.goals.pop();
                self.refused += 1;
                Ok(())
            }
            Err(BuildError::Query(error)) => Err(error),
            Err(error) => Err(PlannerError::GoalSet(Box::new(error))),
        }
    }

    /// Runs the planner for one stretch (to the end of planning once no goal will come).
    fn run_stretch(
        &mut self,
        termination: &dyn Termination,
        started: Instant,
    ) -> Result<(), PlannerError> {
        let best = self.best_cost();
        let shift = (self.elapsed + started.elapsed()).as_secs_f64();
        let bounded = self.drawing_on();
        let stretch = self.stretch;
        let Some((planner, _)) = self.planner.as_mut() else {
            return Ok(());
        };
        let outer = Wrapped {
            termination,
            started,
            best,
        };
        let shift = shift - self.planner_time.as_secs_f64();
        let began = Instant::now();
        let outcome = if bounded {
            planner.solve(&outer.or(TimeLimit::until(began + stretch)))?
        } else {
            planner.solve(&outer)?
        };
        self.planner_time += began.elapsed();
        while let Some(&point) = planner.trace().points().get(self.merged) {
            self.merged += 1;
            if point.cost < self.solution.as_ref().map_or(f64::INFINITY, |s| s.cost) {
                self.trace.push(point.time + shift, point.cost);
            }
        }
        if let Outcome::Solved(solution) = outcome
            && solution.cost < self.best_cost()
        {
            self.solution = Some(solution);
        }
        self.stretch = self.stretch.saturating_mul(2);
        Ok(())
    }
}

impl<B, G, P> Planner for LazyGoals<B, G, P>
where
    B: FnMut(&[Vec<f64>]) -> Result<P, BuildError>,
    G: GoalSource,
    P: Planner,
{
    fn name(&self) -> &str {
        &self.name
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        let started = Instant::now();
        let fired =
            |best: f64| termination.should_terminate(&Progress::new(started.elapsed(), 0, best));
        let result = loop {
            if fired(self.best_cost()) {
                break Ok(());
            }
            let waiting = self.planner.is_none()
                && self.goals.len() < self.initial_goals
                && !self.source.exhausted();
            if waiting {
                self.draw(termination, started, None);
                continue;
            }
            if self.goals.is_empty() {
                break Ok(());
            }
            if let Err(error) = self.rebuild() {
                break Err(error);
            }
            let drawing_on = self.drawing_on();
            if let Err(error) = self.run_stretch(termination, started) {
                break Err(error);
            }
            if !drawing_on {
                break Ok(());
            }
            if !fired(self.best_cost()) {
                let budget = self.stretch.mul_f64(self.goal_share / 2.0);
                self.draw(termination, started, Some(budget));
            }
        };
        self.elapsed += started.elapsed();
        result?;
        Ok(match &self.solution {
            Some(solution) => Outcome::Solved(solution.clone()),
            None => Outcome::NoSolution,
        })
    }

    fn clear(&mut self) {
        self.source.reset();
        self.goals.clear();
        self.planner = None;
        self.solution = None;
        self.trace.clear();
        self.elapsed = Duration::ZERO;
        self.planner_time = Duration::ZERO;
        self.merged = 0;
        self.discarded = Counters::default();
        self.drawing = Duration::ZERO;
        self.refused = 0;
        self.stretch = self.first_stretch;
    }

    fn best_cost(&self) -> f64 {
        self.solution.as_ref().map_or(f64::INFINITY, |s| s.cost)
    }

    fn trace(&self) -> &Trace {
        &self.trace
    }

    /// The work of every planner built since the last `clear`, summed.
    fn counters(&self) -> Counters {
        match &self.planner {
            Some((planner, _)) => planner.counters().merged(&self.discarded),
            None => self.discarded,
        }
    }

    fn settings(&self) -> Vec<(String, String)> {
        let mut settings = self
            .planner
            .as_ref()
            .map_or_else(Vec::new, |(p, _)| p.settings());
        settings.extend([
            ("goal_states".to_owned(), self.goals.len().to_string()),
            ("goal_states_refused".to_owned(), self.refused.to_string()),
            (
                "goal_drawing_time".to_owned(),
                self.drawing.as_secs_f64().to_string(),
            ),
            ("initial_goals".to_owned(), self.initial_goals.to_string()),
            ("max_goals".to_owned(), self.max_goals.to_string()),
        ]);
        settings
    }

    fn snapshot(&self) -> Option<Snapshot> {
        self.planner.as_ref().and_then(|(p, _)| p.snapshot())
    }

    /// Passed on to the current planner (none before the first goal is drawn).
    fn offer_solution(&mut self, solution: &Solution) -> bool {
        let Some((planner, _)) = self.planner.as_mut() else {
            return false;
        };
        if !planner.offer_solution(solution) {
            return false;
        }
        self.merged = planner.trace().len();
        if solution.cost < self.best_cost() {
            self.trace.push(self.elapsed.as_secs_f64(), solution.cost);
            self.solution = Some(solution.clone());
        }
        true
    }
}

impl<B, G: std::fmt::Debug, P: std::fmt::Debug> std::fmt::Debug for LazyGoals<B, G, P> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LazyGoals")
            .field("source", &self.source)
            .field("goals", &self.goals.len())
            .field("planner", &self.planner.as_ref().map(|(p, _)| p))
            .field("best_cost", &self.solution.as_ref().map(|s| s.cost))
            .finish_non_exhaustive()
    }
}

/// The stop of a draw: the caller's termination, or the draw's own deadline.
struct DrawStop<'a> {
    termination: Wrapped<'a>,
    deadline: Option<Instant>,
}

impl Stop for DrawStop<'_> {
    fn should_stop(&self) -> bool {
        let now = Instant::now();
        if self.deadline.is_some_and(|d| now >= d) {
            return true;
        }
        self.termination.should_terminate(&Progress {
            now,
            elapsed: now.saturating_duration_since(self.termination.started),
            iterations: 0,
            best_cost: f64::INFINITY,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Configuration, FirstSolution, Parameters, build_planner};

    /// The goals of a list, in order; a `None` entry is a draw that finds nothing.
    #[derive(Debug)]
    struct Listed {
        goals: Vec<Option<Vec<f64>>>,
        next: usize,
        draws: usize,
    }

    impl Listed {
        fn new(goals: Vec<Option<Vec<f64>>>) -> Self {
            Self {
                goals,
                next: 0,
                draws: 0,
            }
        }
    }

    impl GoalSource for Listed {
        fn next_goal(&mut self, _: &dyn Stop) -> Option<Vec<f64>> {
            self.draws += 1;
            let goal = self.goals.get(self.next).cloned().flatten();
            self.next += 1;
            goal
        }
        fn exhausted(&self) -> bool {
            self.next >= self.goals.len()
        }
        fn reset(&mut self) {
            self.next = 0;
        }
    }

    type Built = Box<dyn Planner + Send>;

    fn builder(
        configuration: Configuration,
    ) -> impl FnMut(&[Vec<f64>]) -> Result<Built, BuildError> {
        let world = mit_star_problems::DividingWalls::new(2)
            .build()
            .expect("a world")
            .world()
            .clone();
        move |goals: &[Vec<f64>]| {
            let problem = mit_star_problems::Problem::new(
                "walls",
                world.clone(),
                vec![-0.45, 0.0],
                goals.to_vec(),
            )?
            .with_resolution(1e-4)?;
            let parameters = Parameters {
                seed: 5,
                ..Parameters::default()
            };
            build_planner(configuration, &problem, &parameters)
        }
    }

    #[test]
    fn a_later_nearer_goal_improves_the_solution() {
        // The far corner first, then a goal just beside the start.
        let source = Listed::new(vec![Some(vec![0.45, 0.0]), Some(vec![-0.4, 0.0])]);
        let mut planner = LazyGoals::new(builder(Configuration::EitStar), source)
            .with_first_stretch(Duration::from_millis(2));
        let outcome = planner.solve(&TimeLimit::seconds(0.3)).expect("solves");
        assert_eq!(planner.goals().len(), 2);
        // The straight segment to the near goal: 0.05 long.
        assert!(outcome.cost() < 0.051, "cost {}", outcome.cost());
        let path = &outcome.solution().expect("a path").path;
        assert_eq!(path.get(path.len() - 1), Some(&[-0.4, 0.0][..]));
        let points = planner.trace().points();
        assert!(points.len() >= 2);
        for pair in points.windows(2) {
            assert!(pair[1].time >= pair[0].time && pair[1].cost < pair[0].cost);
        }
        let settings = planner.settings();
        assert!(settings.contains(&("goal_states".to_owned(), "2".to_owned())));
    }

    #[test]
    fn a_refused_goal_is_dropped_and_planning_goes_on() {
        // The second goal is out of bounds: the query refuses it.
        let source = Listed::new(vec![Some(vec![0.45, 0.0]), Some(vec![2.0, 0.0])]);
        let mut planner = LazyGoals::new(builder(Configuration::RrtConnect), source)
            .with_first_stretch(Duration::from_millis(1));
        let outcome = planner.solve(&TimeLimit::seconds(0.2)).expect("solves");
        assert!(outcome.is_solved());
        assert_eq!(planner.goals(), &[vec![0.45, 0.0]]);
        let settings = planner.settings();
        assert!(settings.contains(&("goal_states_refused".to_owned(), "1".to_owned())));
    }

    #[test]
    fn no_goal_is_no_solution_and_a_bad_first_goal_is_the_error() {
        let mut planner = LazyGoals::new(
            builder(Configuration::RrtConnect),
            Listed::new(vec![None, None]),
        );
        let outcome = planner.solve(&FirstSolution).expect("no error");
        assert_eq!(outcome, Outcome::NoSolution);
        assert_eq!(planner.source().draws, 2);
        let mut planner = LazyGoals::new(
            builder(Configuration::RrtConnect),
            Listed::new(vec![Some(vec![0.5, 0.5, 0.5])]),
        );
        let error = planner
            .solve(&FirstSolution)
            .expect_err("a goal of the wrong dimension");
        assert!(error.to_string().contains("goal"), "{error}");
    }

    #[test]
    fn clear_forgets_goals_solutions_and_counters() {
        let source = Listed::new(vec![Some(vec![0.45, 0.0]), Some(vec![-0.4, 0.0])]);
        let mut planner = LazyGoals::new(builder(Configuration::RrtConnect), source);
        let first = planner.solve(&FirstSolution).expect("solves");
        assert!(first.is_solved());
        assert!(planner.counters().iterations > 0);
        planner.clear();
        assert!(planner.goals().is_empty());
        assert!(planner.trace().is_empty());
        assert_eq!(planner.best_cost(), f64::INFINITY);
        assert_eq!(planner.counters(), Counters::default());
        assert_eq!(planner.solve(&FirstSolution).expect("solves"), first);
    }
}
