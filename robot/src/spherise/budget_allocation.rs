//! Splitting a whole model's sphere budget among its links: each link has covers at a few
//! tolerances (a *ladder*), each with its sphere count and its measured outward error; one
//! cover per link is chosen so that the counts fit the budget and the worst link's error is
//! the least possible, then the spheres left over go where they cut a link's error most per
//! sphere (the marginal error reduction).
//!
//! Why not one common tolerance: a link's measured error is not its tolerance (a seal's lid,
//! a coarse grid, the greedy's luck make it 0 to 10 % more or less), and its count does not
//! fall steadily with the tolerance. Choosing per link among measured covers minimises the
//! quantity reported, the worst measured outward error.

/// One cover of a link (a rung of its ladder): its sphere count and its measured outward
/// error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Rung {
    /// Spheres.
    pub(super) spheres: usize,
    /// The measured outward error (metres).
    pub(super) error: f64,
}

/// For each link, the index of the chosen option: the spheres fit `budget` and the largest
/// error is the least any choice gives; then, while spheres are left, the change of one
/// link's option that lowers its error most per added sphere (a change that adds none or
/// removes some first). `None` if even the fewest spheres per link exceed the budget, or a
/// link has no option.
pub(super) fn allocate(links: &[Vec<Rung>], budget: usize) -> Option<Vec<usize>> {
    if links.iter().any(Vec::is_empty) {
        return None;
    }
    if links.is_empty() {
        return Some(Vec::new());
    }
    // The fewest spheres of a link among its options within error `e`, and which.
    let cheapest = |options: &[Rung], e: f64| {
        options
            .iter()
            .enumerate()
            .filter(|(_, o)| o.error <= e)
            .min_by(|(_, a), (_, b)| a.spheres.cmp(&b.spheres).then(a.error.total_cmp(&b.error)))
            .map(|(i, _)| i)
    };
    let fits = |e: f64| -> Option<Vec<usize>> {
        let picks: Option<Vec<usize>> = links.iter().map(|options| cheapest(options, e)).collect();
        let picks = picks?;
        let total: usize = picks.iter().zip(links).map(|(&i, o)| o[i].spheres).sum();
        (total <= budget).then_some(picks)
    };
    let mut levels: Vec<f64> = links.iter().flatten().map(|o| o.error).collect();
    levels.sort_by(f64::total_cmp);
    levels.dedup();
    // Feasibility only grows with the level: the first that fits, by bisection.
    let (mut lo, mut hi) = (0, levels.len());
    while lo < hi {
        let mid = (lo + hi) / 2;
        if fits(levels[mid]).is_some() {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    let mut picks = fits(*levels.get(lo)?)?;
    let used =
        |picks: &[usize]| -> usize { picks.iter().zip(links).map(|(&i, o)| o[i].spheres).sum() };
    loop {
        let left = budget - used(&picks);
        // The best change: the largest error cut per added sphere (a change adding none
        // counts as cutting per a hundredth of a sphere, so it comes first).
        let mut best: Option<(f64, usize, usize)> = None;
        for (l, options) in links.iter().enumerate() {
            let now = options[picks[l]];
            for (i, o) in options.iter().enumerate() {
                if o.error >= now.error || o.spheres > now.spheres + left {
                    continue;
                }
                let added = o.spheres.saturating_sub(now.spheres) as f64;
                let rate = (now.error - o.error) / added.max(0.01);
                if best.is_none_or(|(r, _, _)| rate > r) {
                    best = Some((rate, l, i));
                }
            }
        }
        let Some((_, l, i)) = best else {
            return Some(picks);
        };
        picks[l] = i;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn o(spheres: usize, error: f64) -> Rung {
        Rung { spheres, error }
    }

    #[test]
    fn the_worst_error_is_the_least_that_fits_and_leftovers_cut_errors() {
        let links = vec![
            vec![o(10, 0.010), o(6, 0.015), o(4, 0.020)],
            vec![o(20, 0.012), o(12, 0.016), o(8, 0.025)],
        ];
        // 18 spheres: (6, 12) at 16 mm is the best worst error; nothing is left.
        assert_eq!(allocate(&links, 18), Some(vec![1, 1]));
        // 22: (6, 12) leaves 4, which buy link 0's 10 mm cover (5 mm for 4 spheres).
        assert_eq!(allocate(&links, 22), Some(vec![0, 1]));
        // 12: (4, 8) at 25 mm is all that fits.
        assert_eq!(allocate(&links, 12), Some(vec![2, 2]));
        assert_eq!(allocate(&links, 11), None);
        // A finer cover with fewer spheres (counts do not fall steadily) is taken for free.
        let uneven = vec![vec![o(9, 0.010), o(7, 0.012), o(8, 0.015)]];
        assert_eq!(allocate(&uneven, 8), Some(vec![1]));
        assert_eq!(allocate(&[], 5), Some(vec![]));
        assert_eq!(allocate(&[vec![]], 5), None);
    }

    #[test]
    fn no_choice_within_the_budget_has_a_smaller_worst_error() {
        // Every choice of three links with three options each, against the allocation.
        let links = vec![
            vec![o(3, 0.03), o(5, 0.02), o(9, 0.01)],
            vec![o(2, 0.04), o(4, 0.018), o(7, 0.012)],
            vec![o(4, 0.025), o(6, 0.015), o(8, 0.011)],
        ];
        for budget in 9..=24 {
            let picks = allocate(&links, budget).unwrap();
            let worst = |p: &[usize]| {
                p.iter()
                    .zip(&links)
                    .map(|(&i, l)| l[i].error)
                    .fold(0.0, f64::max)
            };
            let count = |p: &[usize]| {
                p.iter()
                    .zip(&links)
                    .map(|(&i, l)| l[i].spheres)
                    .sum::<usize>()
            };
            assert!(count(&picks) <= budget);
            for a in 0..3 {
                for b in 0..3 {
                    for c in 0..3 {
                        let other = [a, b, c];
                        if count(&other) <= budget {
                            assert!(
                                worst(&picks) <= worst(&other),
                                "{budget}: {picks:?} {other:?}"
                            );
                        }
                    }
                }
            }
        }
    }
}
