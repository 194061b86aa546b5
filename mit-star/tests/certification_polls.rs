//! Every planner's certifications in a world of many boxes poll the termination condition in
//! proportion to the boxes they examine (issue 28: with a coarse step, a 0.05 s budget slipped
//! while exact certifications went through every box without a poll), and a planner driven
//! in slices of a few polls still solves: a stopped certification goes on where it stopped.

use std::cell::Cell;
use std::sync::{Arc, Mutex};

use mit_star::{
    Configuration, FirstSolution, IterationLimit, Parameters, Progress, Termination,
    TerminationExt, build_planner_with,
};
use mit_star_problems::Problem;
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{
    AxisBox, EdgeStatus, MotionProgress, Preparation, Segment, StateValidity, World,
};

/// Obstacles of the world besides the wall: small cubes, none near the corridor the paths
/// take, so that certifications examine them all and find the edges valid.
const BOXES: usize = 20_000;

/// What the probe saw of certifications begun afresh and finished: (polls, status).
type Seen = Arc<Mutex<Vec<(u64, EdgeStatus)>>>;

/// A world that records how often each of its motion certifications polled.
struct Probe {
    world: World,
    seen: Seen,
}

/// Counts the polls of the stop it wraps.
struct Counting<'a> {
    inner: &'a dyn Stop,
    polls: Cell<u64>,
}

impl Stop for Counting<'_> {
    fn should_stop(&self) -> bool {
        self.polls.set(self.polls.get() + 1);
        self.inner.should_stop()
    }
}

impl StateValidity for Probe {
    fn is_valid(&self, state: &[f64]) -> bool {
        self.world.is_valid(state)
    }

    fn certify_motion(
        &self,
        space: &dyn StateSpace,
        a: &[f64],
        b: &[f64],
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        self.world.certify_motion(space, a, b, progress, stop)
    }

    fn certify_motion_in(
        &self,
        space: &dyn StateSpace,
        ends: (&[f64], &[f64]),
        scratch: &mut Segment,
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        let fresh = progress.cursor() == 0.0 && !progress.is_complete();
        let counting = Counting {
            inner: stop,
            polls: Cell::new(0),
        };
        let status = self
            .world
            .certify_motion_in(space, ends, scratch, progress, &counting)?;
        if fresh && status != EdgeStatus::Unknown {
            self.seen
                .lock()
                .unwrap()
                .push((counting.polls.get(), status));
        }
        Some(status)
    }

    fn prepare_segment(&self, segment: &mut Segment) -> Preparation {
        self.world.prepare_segment(segment)
    }

    fn first_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        self.world.first_invalid_on(segment, fractions)
    }
}

/// `[-0.5, 0.5]^4` with a cube between the start and the goal, and [`BOXES`] small cubes away
/// from the corridor `|x₁|, |x₂|, |x₃| ≤ 0.3` the paths take; planned at a step of 0.05 of the
/// extent (coarser than the small cubes: allowed explicitly).
fn problem() -> Problem {
    let mut world = World::new(vec![-0.5; 4], vec![0.5; 4])
        .with_obstacle(AxisBox::cube(vec![0.0; 4], 0.2))
        .unwrap();
    let mut seed = 5_u64;
    let mut next = || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1_u64 << 53) as f64 - 0.5
    };
    while world.obstacles().len() < BOXES + 1 {
        let c = vec![next(), next(), next(), next()];
        if c[1..].iter().any(|x| x.abs() > 0.35) {
            world.add_obstacle(AxisBox::cube(c, 0.01)).unwrap();
        }
    }
    let start = vec![-0.3, 0.0, 0.0, 0.0];
    let goal = vec![0.3, 0.0, 0.0, 0.0];
    Problem::new("many-boxes", world, start, vec![goal])
        .unwrap()
        .with_resolution(0.05)
        .unwrap()
        .allowing_coarse_step(true)
}

/// Fires from its `polls`-th poll of a slice on, or once a solution is found.
struct Slice {
    seen: Cell<u64>,
    polls: u64,
}

impl Termination for Slice {
    fn should_terminate(&self, progress: &Progress) -> bool {
        self.seen.set(self.seen.get() + 1);
        progress.best_cost.is_finite() || self.seen.get() >= self.polls
    }
}

#[test]
fn certifications_of_a_large_world_poll_in_proportion_to_its_boxes() {
    let problem = problem();
    for configuration in Configuration::ALL {
        let seen = Seen::default();
        let probe = Probe {
            world: problem.world().clone(),
            seen: Arc::clone(&seen),
        };
        let parameters = Parameters {
            seed: 1,
            ..Parameters::default()
        };
        let mut planner = build_planner_with(configuration, &problem, &parameters, probe).unwrap();
        let outcome = planner
            .solve(&FirstSolution.or(IterationLimit::new(100_000)))
            .unwrap();
        assert!(outcome.is_solved(), "{}", configuration.label());
        let seen = seen.lock().unwrap();
        let valid: Vec<u64> = seen
            .iter()
            .filter(|(_, status)| *status == EdgeStatus::Valid)
            .map(|(polls, _)| *polls)
            .collect();
        assert!(
            !valid.is_empty(),
            "{}: nothing certified",
            configuration.label()
        );
        // A valid edge's certification examines every box twice (once per parametrization),
        // and polled at least once per 1024 of them (before issue 28's fix: once in all).
        let least = 2 * BOXES as u64 / 1024;
        assert!(
            valid.iter().all(|&polls| polls >= least),
            "{}: {valid:?} polls, at least {least} expected",
            configuration.label()
        );
    }
}

#[test]
fn every_planner_solves_a_large_world_in_slices_of_a_few_polls() {
    // A certification here takes about 80 poll periods; a slice is 12 polls. Each is stopped
    // many times, and the planners still solve: they go on where they stopped.
    let problem = problem();
    for configuration in Configuration::ALL {
        let parameters = Parameters {
            seed: 2,
            ..Parameters::default()
        };
        let mut planner = build_planner_with(
            configuration,
            &problem,
            &parameters,
            problem.world().clone(),
        )
        .unwrap();
        let slice = Slice {
            seen: Cell::new(0),
            polls: 12,
        };
        let mut calls = 0_u32;
        while !planner.solve(&slice).unwrap().is_solved() {
            calls += 1;
            slice.seen.set(0);
            assert!(calls < 200_000, "{}: no solution", configuration.label());
        }
        assert!(
            calls > 10,
            "{}: solved in {calls} slices",
            configuration.label()
        );
        assert!(
            planner.counters().certifications > 0,
            "{}",
            configuration.label()
        );
    }
}
