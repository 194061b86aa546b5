//! The search overlay of a view: a planner's forward tree as segments in the workspace,
//! coloured by cost-to-come.

use mit_star::Snapshot;
use mit_star_view::{InformedView, SearchOverlay};

/// Each vertex's cost-to-come along the forward tree of `snapshot` (`∞` off the tree), the
/// edge from vertex `a` to `b` costing `distance(a, b)`.
pub(crate) fn costs_to_come(
    snapshot: &Snapshot,
    distance: impl Fn(usize, usize) -> f64,
) -> Vec<f64> {
    let n = snapshot.states.len();
    let mut children = vec![Vec::new(); n];
    let mut has_parent = vec![false; n];
    for &(parent, child) in &snapshot.forward_edges {
        if parent < n && child < n {
            children[parent].push(child);
            has_parent[child] = true;
        }
    }
    let mut cost = vec![f64::INFINITY; n];
    let mut stack: Vec<usize> = (0..n)
        .filter(|&v| !has_parent[v] && !children[v].is_empty())
        .collect();
    for &root in &stack {
        cost[root] = 0.0;
    }
    while let Some(v) = stack.pop() {
        for &c in &children[v] {
            // A tree: each child is reached once; the guard keeps a malformed snapshot finite.
            if cost[c].is_infinite() {
                cost[c] = cost[v] + distance(v, c);
                stack.push(c);
            }
        }
    }
    cost
}

/// The forward tree of `snapshot` drawn between `positions` (one per vertex), coloured by
/// `costs`; with the informed set `informed` where it can be drawn.
pub(crate) fn overlay(
    snapshot: &Snapshot,
    positions: &[glam::DVec3],
    costs: &[f64],
    informed: Option<InformedView>,
) -> SearchOverlay {
    let mut segments = Vec::with_capacity(snapshot.forward_edges.len() * 6);
    let mut edge_costs = Vec::with_capacity(snapshot.forward_edges.len());
    for &(parent, child) in &snapshot.forward_edges {
        let (Some(a), Some(b)) = (positions.get(parent), positions.get(child)) else {
            continue;
        };
        segments.extend([a.x, a.y, a.z, b.x, b.y, b.z].map(|v| v as f32));
        edge_costs.push(costs.get(child).copied().unwrap_or(f64::INFINITY) as f32);
    }
    SearchOverlay {
        label: format!(
            "forward tree: {} edges, {} vertices",
            edge_costs.len(),
            snapshot.states.len()
        ),
        segments,
        costs: edge_costs,
        informed,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star::{EitStar, IterationLimit, Planner};

    #[test]
    fn costs_add_up_along_the_tree() {
        let problem = mit_star_problems::ObstacleFree::new(2).build().unwrap();
        let mut planner = EitStar::for_problem(&problem).seed(1).build().unwrap();
        planner.solve(&IterationLimit::new(200)).unwrap();
        let snapshot = planner.snapshot().unwrap();
        let d = |a: usize, b: usize| {
            let (p, q) = (&snapshot.states[a], &snapshot.states[b]);
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt()
        };
        let costs = costs_to_come(&snapshot, d);
        assert_eq!(costs[0], 0.0, "the start is the root");
        for &(parent, child) in &snapshot.forward_edges {
            assert!((costs[child] - costs[parent] - d(parent, child)).abs() < 1e-12);
        }
        let positions: Vec<glam::DVec3> = (0..snapshot.states.len())
            .map(|i| glam::DVec3::new(snapshot.states[i][0], snapshot.states[i][1], 0.0))
            .collect();
        let overlay = overlay(&snapshot, &positions, &costs, None);
        assert_eq!(overlay.segments.len(), 6 * snapshot.forward_edges.len());
        assert_eq!(overlay.costs.len(), snapshot.forward_edges.len());
    }
}
