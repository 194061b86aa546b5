//! Helpers for unit tests: polyline lengths and dense validity checks.

use mit_star_spaces::euclidean_distance;
use mit_star_validity::{StateValidity, World};

/// Total length of a polyline.
pub(crate) fn polyline_length(points: &[Vec<f64>]) -> f64 {
    points
        .windows(2)
        .map(|w| euclidean_distance(&w[0], &w[1]))
        .sum()
}

/// `true` if every point of the polyline, sampled every `1e-4` along each segment (and at
/// every vertex), is valid in the world.
pub(crate) fn polyline_is_valid(world: &World, points: &[Vec<f64>]) -> bool {
    points.windows(2).all(|w| {
        let (a, b) = (&w[0], &w[1]);
        let steps = (euclidean_distance(a, b) / 1e-4).ceil().max(1.0) as usize;
        (0..=steps).all(|i| {
            let t = i as f64 / steps as f64;
            let p: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + (y - x) * t).collect();
            world.is_valid(&p)
        })
    })
}
