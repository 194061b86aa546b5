//! Taking a path offered from outside ([`Planner::offer_solution`](crate::Planner)) into the
//! forward tree, so the searches can improve on it locally.

use mit_star_heuristics::Heuristic;
use mit_star_samplers::{SampleOrigin, Sampler};
use mit_star_spaces::{StateSpace, States};
use mit_star_validity::{Counted, EdgeChecker, EdgeProgress, EdgeStatus, StateValidity};

use crate::VertexKind;
use crate::graph::EdgeRecord;
use crate::informed_trees::NeighbourRule;
use crate::informed_trees::eit::Eit;
use crate::informed_trees::guidance::Guidance;

impl<S, V, Smp, E, H, G, N> Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace,
    V: StateValidity,
    Smp: Sampler<S, Counted<V>> + Clone,
    E: EdgeChecker<S, Counted<V>> + Clone,
    H: Heuristic<S>,
    G: Guidance,
    N: NeighbourRule,
{
    /// Grafts `path` — checked at full resolution and certified, from the start to a goal,
    /// `progress[i]` the checking progress of its edge `i` — into the forward tree as the
    /// best solution: its interior states become vertices ([`SampleOrigin::Offered`], left
    /// out of the connection rules' sample count) unless they are vertices of the current
    /// solution already, its edges are stored as valid (and certified when the planner
    /// certifies), and each state's forward parent is its predecessor on the path. Both
    /// searches restart at the next iteration.
    ///
    /// Without the graft an offered path would only set the cost bound: every better path
    /// would have to be found again from scratch among the samples, which in 7 dimensions,
    /// inside an informed set that tight, the searches rarely manage. With it, a new sample
    /// near the path that shortcuts part of it is one reverse and one forward expansion away
    /// (the searches follow forward-tree links besides the neighbour lists).
    ///
    /// # Complexity
    /// `O(m·s)` for a path of `m` states and a current solution of `s` vertices, plus one pass
    /// over the forward tree to bring its costs-to-come up to date.
    pub(crate) fn adopt_offer(&mut self, path: &States, progress: &[EdgeProgress]) {
        let last = &path[path.len() - 1];
        let Some(goal) = (self.goals.iter())
            .position(|g| g.as_slice() == last)
            .map(|i| self.goal_ids[i])
        else {
            return;
        };
        // Vertices of the current solution that the path passes through again keep their id
        // (a simplified path keeps some of the corners it was made from).
        let reusable: Vec<u32> = (self.solution_vertices().iter())
            .map(|v| v.0)
            .filter(|&v| !self.graph.vertex(v).is_terminal())
            .collect();
        let mut chain = Vec::with_capacity(path.len());
        let mut added = Vec::with_capacity(path.len());
        chain.push(self.start_id);
        for x in path.iter().take(path.len() - 1).skip(1) {
            let known = (reusable.iter().copied())
                .find(|&v| self.graph.state(v) == x && !chain.contains(&v));
            let id = known.unwrap_or_else(|| {
                let mut vertex = self.new_vertex(VertexKind::Sample, x);
                vertex.origin = SampleOrigin::Offered;
                let id = self.graph.add_vertex(x, vertex);
                added.push(id);
                id
            });
            chain.push(id);
        }
        chain.push(goal);
        self.graph.commit(&added);
        let certified = self.parameters.certification.unwrap_or(1) > 1;
        // In path order, each vertex's new parent is already linked to the start through the
        // path's earlier vertices only, none of which is the vertex itself: no cycle forms.
        for (pair, &tested) in chain.windows(2).zip(progress) {
            let (u, v) = (pair[0], pair[1]);
            let cost = self
                .space
                .distance(self.graph.state(u), self.graph.state(v));
            let record = EdgeRecord {
                progress: tested,
                status: EdgeStatus::Valid,
                certified,
            };
            self.graph.store_edge(u, v, record);
            self.graph.set_forward_parent(v, u, cost);
        }
        let mut stack = std::mem::take(&mut self.scratch);
        self.graph.refresh_costs_below(self.start_id, &mut stack);
        self.scratch = stack;
        self.best_goal = goal;
        self.best_cost = self.graph.vertex(goal).g;
        self.restart_pending = true;
    }
}

#[cfg(test)]
mod tests {
    use mit_star_samplers::SampleOrigin;
    use mit_star_spaces::States;

    use crate::{
        Configuration, EitStar, FirstSolution, IterationLimit, MitStar, Parameters, Planner,
        Solution, build_planner,
    };

    fn problem() -> mit_star_problems::Problem {
        mit_star_problems::DividingWalls::new(2)
            .build()
            .expect("builds")
            .with_resolution(1e-4)
            .expect("resolution")
    }

    /// A valid path for `problem` found by RRT-Connect (many corners: room to improve).
    fn donated(problem: &mit_star_problems::Problem, seed: u64) -> Solution {
        let parameters = Parameters {
            seed,
            ..Parameters::default()
        };
        let mut donor = build_planner(Configuration::RrtConnect, problem, &parameters).unwrap();
        let outcome = donor.solve(&FirstSolution).expect("solves");
        outcome.solution().expect("a path").clone()
    }

    #[test]
    fn an_offered_path_becomes_the_forward_trees_solution() {
        let problem = problem();
        let offer = donated(&problem, 5);
        let mut planner = MitStar::for_problem(&problem)
            .seed(1)
            .build()
            .expect("builds");
        planner.solve(&IterationLimit::new(1)).expect("solves");
        let vertices_before = planner.graph().vertex_count();
        assert!(planner.offer_solution(&offer));
        let vertices = planner.solution_vertices();
        assert_eq!(vertices.len(), offer.path.len());
        for (v, x) in vertices.iter().zip(offer.path.iter()) {
            assert_eq!(planner.graph().state_of(*v), Some(x));
        }
        let interior = &vertices[1..vertices.len() - 1];
        assert!((interior.iter()).all(|&v| planner.graph().origin(v) == SampleOrigin::Offered));
        assert_eq!(
            planner.graph().vertex_count(),
            vertices_before + interior.len()
        );
        let goal = vertices[vertices.len() - 1];
        assert_eq!(planner.graph().cost_to_come(goal), planner.best_cost());
        assert_eq!(planner.best_cost(), offer.cost);
        // The grafted edges count as checked and certified: the planner returns the path
        // (extracting it checks every edge's record) and goes on from it.
        let outcome = planner.solve(&IterationLimit::new(0)).expect("solves");
        assert_eq!(outcome.cost(), offer.cost);
        let later = planner.solve(&IterationLimit::new(3000)).expect("solves");
        assert!(
            later.cost() < offer.cost,
            "{} !< {}",
            later.cost(),
            offer.cost
        );
    }

    #[test]
    fn an_offer_before_the_first_solve_is_grafted_when_the_graph_is_built() {
        let problem = problem();
        let offer = donated(&problem, 2);
        let mut planner = EitStar::for_problem(&problem)
            .seed(4)
            .build()
            .expect("builds");
        assert!(planner.offer_solution(&offer));
        assert!(planner.solution_vertices().is_empty());
        let outcome = planner.solve(&IterationLimit::new(0)).expect("solves");
        assert_eq!(outcome.cost(), offer.cost);
        let vertices = planner.solution_vertices();
        let states: Vec<&[f64]> = (vertices.iter())
            .map(|&v| planner.graph().state_of(v).expect("alive"))
            .collect();
        let offered: Vec<&[f64]> = offer.path.iter().collect();
        assert_eq!(states, offered);
    }

    #[test]
    fn corners_of_the_current_solution_are_reused_not_duplicated() {
        let problem = problem();
        let mut planner = MitStar::for_problem(&problem)
            .seed(9)
            .build()
            .expect("builds");
        let first = planner.solve(&FirstSolution).expect("solves");
        let first = first.solution().expect("a path").clone();
        // Vertex reduction only (no shortcuts, no smoothing): the shorter path keeps a subset
        // of the corners.
        let rows: Vec<Vec<f64>> = first.path.iter().map(<[f64]>::to_vec).collect();
        let simplified = crate::PathSimplifier::new()
            .attempts(0)
            .smoothing_rounds(0)
            .simplify(&problem, &rows, &mit_star_spaces::Never)
            .expect("simplifies");
        assert!(
            simplified.cost < first.cost,
            "seed 9's first path has a corner to drop"
        );
        let mut path = States::new(2);
        for row in &simplified.path {
            path.push(row);
        }
        let before = planner.graph().vertex_count();
        let offer = Solution {
            path,
            cost: simplified.cost,
        };
        assert!(planner.offer_solution(&offer));
        // Vertex reduction keeps a subset of the corners: every one is a vertex already.
        assert_eq!(planner.graph().vertex_count(), before);
        assert_eq!(planner.solution_vertices().len(), simplified.path.len());
    }
}
