//! [`NeighbourRule`]: which vertices a vertex of the implicit graph is joined to in a batch —
//! the part that tells the random geometric graph of EIT*, MIT*, AIT* and BIT*
//! ([`RandomGeometric`]) from the fully connected graph of FCIT* ([`FullyConnected`]).

use crate::{Connection, k_nearest, r_disc};

/// What a batch's graph looks like, as a [`NeighbourRule`] reads it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatchDensity {
    /// Vertices that stand for the sampler's coverage of its set (start and goals included;
    /// samples drawn near the terminals left out).
    pub vertices: usize,
    /// The state space's dimension.
    pub dimension: usize,
    /// The RGG constant `η` ([`Parameters::rewire_factor`](crate::Parameters)).
    pub rewire_factor: f64,
    /// k-nearest or r-disc ([`Parameters::connection`](crate::Parameters); k-nearest if unset).
    pub connection: Connection,
    /// Under r-disc, the most neighbours as a multiple of the k-nearest rule's `k`
    /// ([`Parameters::neighbour_cap`](crate::Parameters); none if unset).
    pub neighbour_cap: Option<f64>,
}

/// Which vertices a vertex is joined to in the current batch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Connectivity {
    /// Its `k` nearest vertices.
    Nearest(usize),
    /// Every vertex within `radius`, the nearest `cap` of them at most (`usize::MAX`: all).
    Radius {
        /// The connection radius.
        radius: f64,
        /// The most neighbours kept, nearest first.
        cap: usize,
    },
    /// Every other vertex: a fully connected graph.
    Complete,
}

/// The neighbourhood part of the informed-trees skeleton ([`Eit`](crate::Eit)'s `N`): after
/// each batch it decides which vertices each vertex is joined to. Its methods are object safe
/// (`&dyn NeighbourRule` works); the planner holds one by value (static dispatch).
pub trait NeighbourRule {
    /// The rule's name in a configuration's name (`""` for the default rule, which the names
    /// of EIT*'s configurations leave out).
    fn part_name(&self) -> &'static str;

    /// The connectivity of a batch of `density`; `measure` gives the Lebesgue measure of the
    /// set samples are drawn from (asked for only by rules that need it: it may cost a
    /// sampler's estimate).
    fn connectivity(&self, density: &BatchDensity, measure: &dyn Fn() -> f64) -> Connectivity;

    /// `true` if a forward expansion should queue its vertex's edges one at a time, best
    /// `ĉ + ĥ` first, rather than all at once (FCIT*'s rule for a graph whose every vertex has
    /// `q − 1` neighbours). Applied only with the a-priori heuristic, where edges leave the
    /// queue in the order they would if all were queued, but for one rule: without cascading
    /// rewirings a vertex then queues at most one edge into the tree (other than to its
    /// children), the first it meets. Default `false`.
    fn queues_successors_lazily(&self) -> bool {
        false
    }
}

/// The random geometric graph of BIT*, AIT*, EIT* and MIT*: each vertex joined to its `k`
/// nearest vertices or to those within the radius `r` of the RGG theory (Karaman and Frazzoli
/// 2011, as the informed trees scale it), as [`BatchDensity::connection`] says.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RandomGeometric;

impl NeighbourRule for RandomGeometric {
    fn part_name(&self) -> &'static str {
        ""
    }

    fn connectivity(&self, density: &BatchDensity, measure: &dyn Fn() -> f64) -> Connectivity {
        let (q, n, eta) = (density.vertices, density.dimension, density.rewire_factor);
        match density.connection {
            Connection::KNearest => Connectivity::Nearest(k_nearest(q, n, eta)),
            Connection::RDisc => {
                let radius = r_disc(q, n, eta, measure());
                let cap = density.neighbour_cap.map_or(usize::MAX, |c| {
                    (c * k_nearest(q, n, eta) as f64).ceil() as usize
                });
                Connectivity::Radius { radius, cap }
            }
        }
    }
}

/// FCIT*'s fully connected graph (Wilson, Thomason, Kingston, Kavraki and Gammell, ICRA 2025):
/// every vertex is a neighbour of every other, whatever the batch's density — no radius, no
/// `k`, and so no nearest-neighbour structure needed to find them. The search's order
/// (admissible keys, lazy checks) decides which of the `O(q²)` edges are ever looked at.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct FullyConnected;

impl NeighbourRule for FullyConnected {
    fn part_name(&self) -> &'static str {
        "fully connected"
    }

    fn connectivity(&self, _: &BatchDensity, _: &dyn Fn() -> f64) -> Connectivity {
        Connectivity::Complete
    }

    fn queues_successors_lazily(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn density(connection: Connection, neighbour_cap: Option<f64>) -> BatchDensity {
        BatchDensity {
            vertices: 1000,
            dimension: 7,
            rewire_factor: 1.001,
            connection,
            neighbour_cap,
        }
    }

    #[test]
    fn the_random_geometric_rule_is_the_rgg_of_its_connection() {
        let rule: &dyn NeighbourRule = &RandomGeometric;
        let k = k_nearest(1000, 7, 1.001);
        let nearest = rule.connectivity(&density(Connection::KNearest, None), &|| {
            panic!("k-nearest needs no measure")
        });
        assert_eq!(nearest, Connectivity::Nearest(k));
        let disc = rule.connectivity(&density(Connection::RDisc, Some(2.0)), &|| 3.0);
        let radius = r_disc(1000, 7, 1.001, 3.0);
        assert_eq!(disc, Connectivity::Radius { radius, cap: 2 * k });
        let uncapped = rule.connectivity(&density(Connection::RDisc, None), &|| 3.0);
        assert_eq!(
            uncapped,
            Connectivity::Radius {
                radius,
                cap: usize::MAX
            }
        );
    }

    #[test]
    fn the_fully_connected_rule_joins_every_vertex_at_any_density() {
        let rule: &dyn NeighbourRule = &FullyConnected;
        for connection in [Connection::KNearest, Connection::RDisc] {
            let c = rule.connectivity(&density(connection, Some(1.0)), &|| {
                panic!("a complete graph needs no measure")
            });
            assert_eq!(c, Connectivity::Complete);
        }
        assert_eq!(rule.part_name(), "fully connected");
        assert_eq!(RandomGeometric.part_name(), "");
        assert!(rule.queues_successors_lazily());
        assert!(!RandomGeometric.queues_successors_lazily());
    }
}
