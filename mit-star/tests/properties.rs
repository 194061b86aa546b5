//! Property tests: exact nearest neighbours against brute force in 2–32 dimensions, and
//! pruning never keeps a vertex outside the informed set once a solution exists.

use std::sync::{Arc, Mutex};

use mit_star::{
    BatchEvent, EitStar, IterationLimit, KdTree, MitStar, NearestNeighbors, Neighbours, Observer,
    Planner, VertexKind,
};
use mit_star_samplers::CostBound;
use mit_star_spaces::euclidean_distance;
use proptest::prelude::*;

fn brute_force(points: &[Vec<f64>], query: &[f64], k: usize) -> Vec<u32> {
    let mut all: Vec<(f64, u32)> = points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let d: f64 = p.iter().zip(query).map(|(a, b)| (a - b) * (a - b)).sum();
            (d, i as u32)
        })
        .collect();
    all.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    all.into_iter().take(k).map(|(_, i)| i).collect()
}

/// Up to 3 000 points: past the 1 024 a forest keeps in its linear buffer, so its trees are
/// exercised too.
fn cloud() -> impl Strategy<Value = (Vec<Vec<f64>>, Vec<f64>, usize)> {
    (2usize..=32).prop_flat_map(|n| {
        (
            prop::collection::vec(prop::collection::vec(-1.0f64..1.0, n), 1..3000),
            prop::collection::vec(-1.2f64..1.2, n),
            1usize..40,
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn kd_tree_k_nearest_equals_brute_force((points, query, k) in cloud()) {
        let n = query.len();
        let tree = KdTree::build(n, points.iter().enumerate().map(|(i, p)| (i as u32, p.as_slice())));
        let mut found = Neighbours::new();
        tree.nearest(&query, k, &mut found);
        let got: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
        prop_assert_eq!(got, brute_force(&points, &query, k));
    }

    #[test]
    fn batched_forest_equals_brute_force((points, query, k) in cloud(), batch in 1usize..150) {
        let n = query.len();
        let mut nn = NearestNeighbors::new(n);
        for (b, chunk) in points.chunks(batch).enumerate() {
            nn.insert(chunk.iter().enumerate().map(|(i, p)| ((b * batch + i) as u32, p.as_slice())));
        }
        let mut found = Neighbours::new();
        nn.nearest(&query, k, &mut found);
        let got: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
        prop_assert_eq!(got, brute_force(&points, &query, k));
        // Radius queries return exactly the points within the radius.
        let radius = 0.8;
        nn.within(&query, radius, &mut found);
        let mut expected: Vec<u32> = brute_force(&points, &query, points.len())
            .into_iter()
            .filter(|&i| {
                let d: f64 = points[i as usize].iter().zip(&query).map(|(a, b)| (a - b) * (a - b)).sum();
                d <= radius * radius
            })
            .collect();
        let mut got: Vec<u32> = found.iter().map(|&(_, id)| id).collect();
        got.sort_unstable();
        expected.sort_unstable();
        prop_assert_eq!(got, expected);
    }
}

/// Records the bound of every batch.
#[derive(Clone, Default)]
struct Bounds(Arc<Mutex<Vec<CostBound>>>);

impl Observer for Bounds {
    fn on_batch(&mut self, event: &BatchEvent) {
        self.0.lock().unwrap().push(event.bound);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// With `c_best` finite, a batch prunes every sample whose admissible solution cost
    /// `ĉ(start, x) + ĉ(x, goal)` exceeds it and draws new samples inside it, so after the last
    /// batch no vertex lies outside the informed set of that batch's bound.
    #[test]
    fn no_vertex_outside_the_informed_set_survives_pruning(seed in 0u64..1000, mit in any::<bool>()) {
        let problem = mit_star_problems::DividingWalls::new(2).build().unwrap().with_resolution(1e-4).unwrap();
        let bounds = Bounds::default();
        let iterations = IterationLimit::new(6_000);
        let graph_check = |graph: &mit_star::RandomGeometricGraph, bound: f64| -> Result<(), TestCaseError> {
            let goal = &problem.goals()[0];
            let mut samples = 0;
            for (id, x) in graph.vertices() {
                if graph.kind(id) != Some(VertexKind::Sample) {
                    continue;
                }
                samples += 1;
                let f = euclidean_distance(problem.start(), x) + euclidean_distance(x, goal);
                prop_assert!(f <= bound * (1.0 + 1e-12), "vertex {id:?} has f̂ = {f} > {bound}");
            }
            prop_assert!(samples > 0);
            Ok(())
        };
        let last_bound = |bounds: &Bounds| bounds.0.lock().unwrap().last().copied();
        if mit {
            let mut planner = MitStar::for_problem(&problem).seed(seed).observer(Box::new(bounds.clone())).build().unwrap();
            planner.solve(&iterations).unwrap();
            prop_assume!(planner.best_cost().is_finite());
            if let Some(CostBound::Solution(c)) = last_bound(&bounds) {
                graph_check(planner.graph(), c)?;
            }
        } else {
            let mut planner = EitStar::for_problem(&problem).seed(seed).observer(Box::new(bounds.clone())).build().unwrap();
            planner.solve(&iterations).unwrap();
            prop_assume!(planner.best_cost().is_finite());
            if let Some(CostBound::Solution(c)) = last_bound(&bounds) {
                graph_check(planner.graph(), c)?;
            }
        }
    }
}
