//! Tests of the frontier the EIT* family hands its sampler: the reverse tree's farthest
//! samples, and nothing once solved.

use mit_star_samplers::{CostBound, InformedSampler, SampleError, Sampler, SamplerCounters};
use mit_star_spaces::{StateSpace, Stop};
use mit_star_validity::{FixedSparseChecker, StateValidity, World};

use crate::termination::SolveStop;
use crate::{Eit, IterationLimit};

/// An informed sampler that records every frontier it is handed, and with a pocket puts every
/// third sample uniformly in the box of half-side `half` around its centre (the start's
/// hollow of `start_reach_tests`).
#[derive(Debug, Clone)]
pub(super) struct Recording {
    inner: InformedSampler,
    pub(super) sent: Vec<Vec<f64>>,
    pocket: Option<(Vec<f64>, f64)>,
    /// A xorshift state for the draws in the pocket.
    rng: u64,
    count: u64,
}

impl Recording {
    /// Records around `inner`, drawing nothing of its own.
    pub(super) fn new(inner: InformedSampler) -> Self {
        Self {
            inner,
            sent: Vec::new(),
            pocket: None,
            rng: 0x9e37_79b9_7f4a_7c15,
            count: 0,
        }
    }

    /// Every third sample in the box of half-side `half` around `centre`.
    pub(super) fn with_pocket(mut self, centre: &[f64], half: f64) -> Self {
        self.pocket = Some((centre.to_vec(), half));
        self
    }

    /// The next uniform number in `[-1, 1)`.
    fn unit(&mut self) -> f64 {
        self.rng ^= self.rng << 13;
        self.rng ^= self.rng >> 7;
        self.rng ^= self.rng << 17;
        2.0 * ((self.rng >> 11) as f64 / (1_u64 << 53) as f64) - 1.0
    }
}

impl<S, V> Sampler<S, V> for Recording
where
    S: StateSpace + ?Sized,
    V: StateValidity + ?Sized,
{
    fn sample(
        &mut self,
        space: &S,
        validity: &V,
        bound: CostBound,
        stop: &dyn Stop,
        out: &mut [f64],
    ) -> Result<(), SampleError> {
        self.count += 1;
        if self.count.is_multiple_of(3)
            && let Some((centre, half)) = self.pocket.take()
        {
            loop {
                for (x, c) in out.iter_mut().zip(&centre) {
                    *x = c + half * self.unit();
                }
                if validity.is_valid(out) {
                    break;
                }
            }
            self.pocket = Some((centre, half));
            return Ok(());
        }
        self.inner.sample(space, validity, bound, stop, out)
    }

    fn sampled_measure(&self, space: &S, bound: CostBound) -> f64 {
        Sampler::<S, V>::sampled_measure(&self.inner, space, bound)
    }

    fn reseed(&mut self, seed: u64) {
        Sampler::<S, V>::reseed(&mut self.inner, seed);
    }

    fn counters(&self) -> SamplerCounters {
        Sampler::<S, V>::counters(&self.inner)
    }

    fn observe_frontier(&mut self, states: &[f64]) {
        self.sent.push(states.to_vec());
    }
}

impl<S: StateSpace> crate::SamplerPart<S> for Recording {
    fn part_name() -> String {
        "recording".into()
    }

    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        parameters: &crate::Parameters,
    ) -> Result<Self, crate::BuildError> {
        Ok(Self::new(InformedSampler::new(
            space,
            start,
            goals,
            parameters.seed,
        )?))
    }
}

pub(super) type RecordingEit =
    Eit<mit_star_spaces::RealVectorSpace, World, Recording, FixedSparseChecker>;

/// The planner of these tests, with the whole reverse tree's frontier (the default).
fn make(frontier: usize) -> (RecordingEit, mit_star_problems::Problem) {
    make_with(frontier, false)
}

/// The planner of these tests; `validated` sets
/// [`validated_frontier`](crate::Parameters::validated_frontier).
fn make_with(frontier: usize, validated: bool) -> (RecordingEit, mit_star_problems::Problem) {
    let problem = mit_star_problems::DividingWalls::new(4)
        .build()
        .unwrap()
        .with_resolution(1e-3)
        .unwrap();
    let (space, start, goals) = (problem.space(), problem.start(), problem.goals());
    let sampler = Recording::new(InformedSampler::new(space, start, goals, 5).unwrap());
    let mut parameters = crate::Parameters {
        batch_size: Some(300),
        ..crate::Parameters::default()
    };
    parameters.near_frontier = frontier;
    parameters.validated_frontier = validated;
    let planner = RecordingEit::for_problem(&problem)
        .sampler(sampler)
        .parameters(parameters)
        .build()
        .unwrap();
    (planner, problem)
}

#[test]
fn the_frontier_is_the_reverse_trees_farthest_samples_farthest_first() {
    let (mut planner, problem) = make(7);
    let n = problem.space().dimension();
    send_after_one_batch(&mut planner);
    // Every sample the reverse search reached, farthest first, ties by id.
    let tag = planner.reverse_tag;
    let graph = &planner.graph;
    let mut reached: Vec<(f64, u32)> = graph
        .vertices()
        .map(|(id, _)| id.0)
        .filter(|&v| !graph.vertex(v).is_terminal())
        .map(|v| (graph.vertex(v).h(tag), v))
        .filter(|(h, _)| h.is_finite())
        .collect();
    reached.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    assert!(reached.len() > 7, "only {} samples reached", reached.len());
    let expected: Vec<f64> = reached[..7]
        .iter()
        .flat_map(|&(_, v)| graph.state(v).to_vec())
        .collect();
    let sent = planner.sampler.sent.last().unwrap();
    assert_eq!(sent.len(), 7 * n);
    assert_eq!(*sent, expected);
}

#[test]
fn a_solution_or_a_count_of_zero_sends_no_frontier() {
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    let (mut planner, _) = make(5);
    send_after_one_batch(&mut planner);
    assert!(!planner.sampler.sent.last().unwrap().is_empty());
    // Solved: one empty frontier, so the sampler drops the last one; then nothing more.
    planner.send_frontier(true, &stop);
    assert_eq!(planner.sampler.sent.last().unwrap(), &Vec::<f64>::new());
    let count = planner.sampler.sent.len();
    planner.send_frontier(true, &stop);
    assert_eq!(planner.sampler.sent.len(), count);
    // A count of 0 never sends one.
    let (mut off, _) = make(0);
    send_after_one_batch(&mut off);
    assert!(off.sampler.sent.is_empty());
}

/// Runs the planner of these tests through one batch and 300 iterations, then ends the batch
/// unsolved.
fn send_after_one_batch(planner: &mut RecordingEit) {
    let limit = IterationLimit::new(u64::MAX);
    let stop = SolveStop::new(&limit);
    planner.setup(&stop).unwrap();
    planner.add_batch(&stop);
    for _ in 0..300 {
        planner.iterate(&stop);
    }
    planner.send_frontier(false, &stop);
}

/// The id of the vertex at `state` (a state the planner sent).
fn vertex_at(planner: &RecordingEit, state: &[f64]) -> u32 {
    let found = planner.graph.vertices().find(|(_, s)| *s == state);
    found.expect("a sent state is a vertex").0.0
}

/// Whether every edge of the reverse tree from the vertex at `state` up to a goal is free,
/// decided exactly (segment against boxes, no grid).
fn confirmed(planner: &RecordingEit, problem: &mit_star_problems::Problem, state: &[f64]) -> bool {
    let graph = &planner.graph;
    let mut v = vertex_at(planner, state);
    while !graph.vertex(v).is_goal() {
        let parent = graph.vertex(v).reverse_parent;
        if !problem
            .world()
            .segment_verdict(graph.state(parent), graph.state(v))
            .is_valid()
        {
            return false;
        }
        v = parent;
    }
    true
}

#[test]
fn a_validated_frontier_lies_beyond_no_invalid_edge() {
    // The same seed and the same steps build the same reverse tree in both planners.
    let (mut whole, problem) = make_with(12, false);
    let (mut validated, _) = make_with(12, true);
    send_after_one_batch(&mut whole);
    send_after_one_batch(&mut validated);
    let n = problem.space().dimension();
    let sent = validated.sampler.sent.last().unwrap();
    assert!(!sent.is_empty());
    for state in sent.chunks_exact(n) {
        assert!(confirmed(&validated, &problem, state), "{state:?}");
    }
    // Farthest first.
    let tag = validated.reverse_tag;
    let h: Vec<f64> = sent
        .chunks_exact(n)
        .map(|s| validated.graph.vertex(vertex_at(&validated, s)).h(tag))
        .collect();
    assert!(h.windows(2).all(|w| w[0] >= w[1]), "{h:?}");
    // Not vacuous: the whole tree's farthest states include one beyond an invalid edge
    // (an edge whose midpoint alone was tested at the first sparse level).
    let beyond = whole.sampler.sent.last().unwrap();
    assert!(
        beyond
            .chunks_exact(n)
            .any(|state| !confirmed(&whole, &problem, state)),
        "every farthest state of the whole tree is confirmed: the test proves nothing"
    );
}
