//! [`Simplifying`]: a planner whose every new solution is simplified before it is reported.

use std::time::{Duration, Instant};

use mit_star_spaces::StateSpace;
use mit_star_validity::StateValidity;

use super::IdlePolish;
use crate::planner::keep_if_cheaper;
use crate::termination::Wrapped;
use crate::{
    Counters, Outcome, PathSimplifier, Planner, PlannerError, Progress, Snapshot, Solution,
    Termination, TerminationExt, Trace,
};

/// Wraps a planner so that each solution it finds is reported at once and then shortened by
/// a [`PathSimplifier`] (OMPL's anytime path shortening, for one planner): the reported cost
/// falls right after every improvement of the planner, and the first solution comes as soon
/// as without the wrapper. Removing the wrapper is the ablation (`simplify_solutions` in [`Parameters`]).
///
/// The inner planner runs until the caller's termination fires or it improves its own
/// solution; the simplification then runs under the same termination: the shortcuts first,
/// whose path is reported and offered at once, then, if the simplifier smooths
/// ([`PathSimplifier::smoothing_rounds`]), the smoothing rounds on that path, whose result is
/// reported and offered in turn. Every edge the
/// simplifier adds is checked and certified as the planner's are. The shorter path is then
/// offered to the inner planner ([`Planner::offer_solution`]): the asymptotically optimal
/// planners of the crate take it as their best solution, so their cost bound, informed set and
/// pruning follow the shorter cost; others ignore it. With
/// [`polish_when_idle`](Self::polish_when_idle), the best path is also polished whenever the
/// inner planner has found nothing cheaper for a while, and each shorter stage is offered in
/// the same way. Time limits
/// and cost thresholds apply to the whole call; an [`IterationLimit`](crate::IterationLimit) counts the iterations of
/// each stretch of planning between two of the inner planner's solutions.
///
/// [`Parameters`]: crate::Parameters
#[derive(Debug, Clone)]
pub struct Simplifying<P, S, V> {
    inner: P,
    space: S,
    validity: V,
    /// Check step and certification factor of the problem.
    checks: (f64, u32),
    simplifier: PathSimplifier,
    solution: Option<Solution>,
    trace: Trace,
    /// Planning time of the finished `solve` calls.
    elapsed: Duration,
    /// Simplifications run.
    runs: u64,
    /// Simplified paths the inner planner took as its best solution.
    taken: u64,
    /// States moved by smoothing.
    smoothing_moves: u64,
    /// Polishes of the best path while the inner planner finds nothing cheaper (`None`: off).
    polish: Option<IdlePolish>,
}

impl<P, S, V> Simplifying<P, S, V>
where
    P: Planner,
    S: StateSpace,
    V: StateValidity,
{
    /// `inner` with its solutions simplified in `space` with `validity`, edges checked at
    /// `step` and certified `certification` times finer (1: not at all), by `simplifier`.
    pub fn new(
        inner: P,
        (space, validity): (S, V),
        (step, certification): (f64, u32),
        simplifier: PathSimplifier,
    ) -> Self {
        Self {
            inner,
            space,
            validity,
            checks: (step, certification),
            simplifier,
            solution: None,
            trace: Trace::default(),
            elapsed: Duration::ZERO,
            runs: 0,
            taken: 0,
            smoothing_moves: 0,
            polish: None,
        }
    }

    /// Polishes the best path whenever the inner planner has found nothing cheaper for a
    /// while ([`polish_when_idle`](crate::Parameters::polish_when_idle)), with random draws
    /// seeded by `seed`; each polished path is offered to the inner planner as a simplified one
    /// is. `None` turns it off (the default).
    #[must_use]
    pub fn polish_when_idle(mut self, seed: Option<u64>) -> Self {
        self.polish = seed.map(IdlePolish::new);
        self
    }

    /// The wrapped planner.
    pub fn inner(&self) -> &P {
        &self.inner
    }

    /// Takes `solution` (the inner planner's newest) if it beats the best so far, at once,
    /// then simplifies it and takes the result if shorter: first the shortcuts, then, if the
    /// simplifier smooths, the smoothing rounds on the shortcut path, so the shortcut path is
    /// reported (and offered) while it is smoothed. The simplification stops when the
    /// caller's termination would have fired before this solution (so a first-solution
    /// condition still lets its first path be simplified).
    fn adopt(&mut self, solution: &Solution, termination: &dyn Termination, started: Instant) {
        let before = self.best_cost();
        self.keep(solution.clone(), started);
        let stop = || termination.should_terminate(&Progress::new(started.elapsed(), 0, before));
        let path: Vec<Vec<f64>> = solution.path.iter().map(<[f64]>::to_vec).collect();
        self.runs += 1;
        let simplifier = self.simplifier.clone();
        self.simplify_path(&simplifier, &path, &stop, started);
    }

    /// Runs `simplifier` on `path` in stages under `stop`: each stage is offered to the inner
    /// planner if shorter than the stage's start, and kept if cheaper than the best path.
    fn simplify_path(
        &mut self,
        simplifier: &PathSimplifier,
        path: &[Vec<f64>],
        stop: &dyn mit_star_spaces::Stop,
        started: Instant,
    ) {
        let Self {
            inner,
            space,
            validity,
            checks,
            solution: best,
            trace,
            elapsed,
            taken,
            smoothing_moves,
            ..
        } = self;
        let _ = simplifier.simplify_in_stages(space, validity, *checks, path, stop, &mut |stage| {
            *smoothing_moves += stage.smoothing_moves;
            let shorter = stage.solution(space.dimension());
            if shorter.cost < stage.original_cost && inner.offer_solution(&shorter) {
                *taken += 1;
            }
            keep_if_cheaper((best, trace), *elapsed + started.elapsed(), shorter);
        });
    }

    /// Polishes the best path with at most `budget` polls of the stop (about one per edge
    /// check), each stage kept and offered to the inner planner if cheaper.
    fn polish(&mut self, budget: u64, termination: &dyn Termination, started: Instant) {
        let (Some(polish), Some(best)) = (&mut self.polish, &self.solution) else {
            return;
        };
        let before = best.cost;
        let path: Vec<Vec<f64>> = best.path.iter().map(<[f64]>::to_vec).collect();
        let simplifier = polish.next_simplifier();
        let polls = std::cell::Cell::new(0_u64);
        let stop = || {
            polls.set(polls.get() + 1);
            let progress = Progress::new(started.elapsed(), 0, before);
            polls.get() > budget || termination.should_terminate(&progress)
        };
        self.simplify_path(&simplifier, &path, &stop, started);
        let paid = self.best_cost() < before;
        if let Some(polish) = &mut self.polish {
            polish.polished(paid);
        }
    }

    /// Makes `solution` the best one, with a trace point, if it is cheaper.
    fn keep(&mut self, solution: Solution, started: Instant) {
        let best = (&mut self.solution, &mut self.trace);
        keep_if_cheaper(best, self.elapsed + started.elapsed(), solution);
    }
}

/// Fires after `limit` iterations of the inner planner's call, and remembers that it did.
struct Waited {
    limit: u64,
    fired: std::cell::Cell<bool>,
}

impl Waited {
    fn new(limit: u64) -> Self {
        Self {
            limit,
            fired: std::cell::Cell::new(false),
        }
    }
}

impl Termination for Waited {
    fn should_terminate(&self, progress: &Progress) -> bool {
        let fired = progress.iterations >= self.limit;
        if fired {
            self.fired.set(true);
        }
        fired
    }
}

/// Fires once the inner planner's best cost is below the given one.
struct Improved(f64);

impl Termination for Improved {
    fn should_terminate(&self, progress: &Progress) -> bool {
        progress.best_cost < self.0
    }
}

impl<P, S, V> Planner for Simplifying<P, S, V>
where
    P: Planner,
    S: StateSpace,
    V: StateValidity,
{
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn solve(&mut self, termination: &dyn Termination) -> Result<Outcome, PlannerError> {
        let started = Instant::now();
        // Iterations of the inner planner since its last cheaper solution, over the stretches
        // that polishes cut.
        let mut idle = 0;
        loop {
            let before = self.inner.best_cost();
            let outer = Wrapped {
                termination,
                started,
                best: self.best_cost(),
            };
            // Back as soon as the inner planner improves on `before`, or, when polishing a
            // solution, once it has found nothing cheaper for the polish's wait.
            let wait = Waited::new(match (&self.polish, &self.solution) {
                (Some(polish), Some(_)) => polish.wait(),
                _ => u64::MAX,
            });
            let outcome = self.inner.solve(&(&outer).or(Improved(before)).or(&wait))?;
            let found = self.inner.best_cost() < before;
            if found && let Outcome::Solved(solution) = &outcome {
                idle = 0;
                if let Some(polish) = &mut self.polish {
                    polish.improved();
                }
                self.adopt(solution, termination, started);
            }
            let progress = Progress::new(started.elapsed(), idle, self.best_cost());
            if termination.should_terminate(&progress) {
                break;
            }
            if !found {
                // The inner planner stopped on its own, or waited long enough to polish.
                if !wait.fired.get() {
                    break;
                }
                idle += wait.limit;
                self.polish(wait.limit, termination, started);
            }
        }
        self.elapsed += started.elapsed();
        Ok(match &self.solution {
            Some(solution) => Outcome::Solved(solution.clone()),
            None => Outcome::NoSolution,
        })
    }

    fn clear(&mut self) {
        self.inner.clear();
        self.solution = None;
        self.trace.clear();
        self.elapsed = Duration::ZERO;
        self.runs = 0;
        self.taken = 0;
        self.smoothing_moves = 0;
        if let Some(polish) = &mut self.polish {
            polish.reset();
        }
    }

    fn best_cost(&self) -> f64 {
        self.solution.as_ref().map_or(f64::INFINITY, |s| s.cost)
    }

    fn trace(&self) -> &Trace {
        &self.trace
    }

    fn counters(&self) -> Counters {
        self.inner.counters()
    }

    fn settings(&self) -> Vec<(String, String)> {
        let mut settings = self.inner.settings();
        settings.push(("simplified_solutions".into(), self.runs.to_string()));
        settings.push(("simplified_taken_by_planner".into(), self.taken.to_string()));
        settings.push(("smoothing_moves".into(), self.smoothing_moves.to_string()));
        let polished = self.polish.as_ref().map_or(0, IdlePolish::count);
        settings.push(("polished_solutions".into(), polished.to_string()));
        settings
    }

    fn snapshot(&self) -> Option<Snapshot> {
        self.inner.snapshot()
    }

    fn offer_solution(&mut self, solution: &Solution) -> bool {
        if !self.inner.offer_solution(solution) {
            return false;
        }
        let time = self.elapsed.as_secs_f64();
        if solution.cost < self.best_cost() {
            self.trace.push(time, solution.cost);
            self.solution = Some(solution.clone());
        }
        true
    }
}
