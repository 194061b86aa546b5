//! [`CoverSearch`]: a local search for a set cover with fewer spheres than the greedy's,
//! over the same candidates and the same elements (so with the same guarantee).
//!
//! The greedy set cover picks the candidate that covers most elements still uncovered; its
//! last picks are small spheres mopping up slivers between the large ones, which is where it
//! spends most of its count on a link-like solid. The search starts from the greedy's cover
//! and looks for one with a sphere fewer, over and over:
//!
//! - **Covered**: the cover is kept as the best so far, and the sphere whose removal uncovers
//!   the least (weighted) is removed.
//! - **Otherwise**: one sphere is swapped. The sphere of the cover whose removal uncovers
//!   least (not the one just added) goes; then an uncovered element is drawn at random, and
//!   of the candidates that contain it, the one covering the most weight still uncovered
//!   comes in (not the one just removed; ties to the one changed longest ago). The weight of
//!   every element left uncovered grows by one, so elements that stay uncovered pull the
//!   spheres towards them.
//!
//! This is row-weighting local search for unicost set cover, as in the literature (Gao,
//! Weise and Li, 2015), written here from that description. It ends after a number of steps
//! proportional to the elements (at least [`MIN_STEPS`]), or when the cover reaches one sphere. Each candidate's
//! elements are kept as a bitset over the span of element indices it reaches.

use std::sync::atomic::AtomicBool;

use super::cell_grid::{CellGrid, check};
use super::medial_cover::medial_grid;
use super::solid::Solid;
use super::sphere_cover::{Candidate, CoverSphere, candidate, shrink_and_prune};
use super::spherise_error::SpheriseError;

/// Elements per step of the search after the greedy cover (at least [`MIN_STEPS`] steps).
/// On the Panda's links at 15 mm (7 000 to 47 000 elements) this gave 136 spheres (23 s of
/// CPU for the whole model, measuring included), 5 000 steps per link 139, and one step per
/// element 136 again in several times the time.
pub(super) const ELEMENTS_PER_STEP: usize = 4;

/// The fewest steps of the search.
pub(super) const MIN_STEPS: usize = 5_000;

/// The elements one candidate contains: a bitset over word `first` onwards.
#[derive(Debug, Clone, Default)]
struct Coverage {
    first: usize,
    words: Vec<u64>,
}

impl Coverage {
    fn contains(&self, e: usize) -> bool {
        let w = e / 64;
        w >= self.first
            && self
                .words
                .get(w - self.first)
                .is_some_and(|word| word >> (e % 64) & 1 == 1)
    }

    fn elements(&self) -> impl Iterator<Item = usize> + '_ {
        self.words.iter().enumerate().flat_map(move |(i, &word)| {
            let base = (self.first + i) * 64;
            let mut left = word;
            std::iter::from_fn(move || {
                (left != 0).then(|| {
                    let bit = left.trailing_zeros() as usize;
                    left &= left - 1;
                    base + bit
                })
            })
        })
    }
}

/// The local search's state: which candidates are in the cover, how many cover each element,
/// and the elements' weights.
pub(super) struct CoverSearch {
    coverage: Vec<Coverage>,
    chosen: Vec<bool>,
    count: Vec<u32>,
    weight: Vec<u64>,
    /// Per candidate of the cover: the weight of the elements only it covers.
    loss: Vec<u64>,
    /// The step at which each candidate last entered or left the cover.
    changed: Vec<usize>,
    /// The cover's candidates.
    cover: Vec<usize>,
    /// Elements no candidate of the cover contains.
    uncovered: Vec<usize>,
    /// Elements no candidate contains at all (left to the caller).
    orphans: Vec<usize>,
    rng: u64,
}

impl CoverSearch {
    /// The search over `candidates` for `grid`'s elements, started from a greedy cover.
    ///
    /// # Errors
    /// [`SpheriseError::Stopped`] once `stop` is raised.
    pub(super) fn new(
        grid: &CellGrid,
        candidates: &[Candidate],
        stop: &AtomicBool,
    ) -> Result<Self, SpheriseError> {
        let elements = grid.elements.len();
        let mut coverage = Vec::with_capacity(candidates.len());
        let mut count = vec![0_u32; elements];
        let mut mine = Vec::new();
        for (i, c) in candidates.iter().enumerate() {
            if i % 64 == 0 {
                check(stop)?;
            }
            mine.clear();
            contained(grid, c, &mut mine);
            coverage.push(bitset(&mine));
            for &e in &mine {
                count[e] += 1;
            }
        }
        let orphans = (0..elements).filter(|&e| count[e] == 0).collect();
        let mut search = Self {
            chosen: vec![false; coverage.len()],
            loss: vec![0; coverage.len()],
            changed: vec![0; coverage.len()],
            coverage,
            count: vec![0; elements],
            weight: vec![1; elements],
            cover: Vec::new(),
            uncovered: Vec::new(),
            orphans,
            rng: 0x9e37_79b9_7f4a_7c15,
        };
        search.greedy(stop)?;
        Ok(search)
    }

    /// Elements no candidate contains.
    pub(super) fn orphans(&self) -> &[usize] {
        &self.orphans
    }

    /// The lazy greedy cover, then its redundant candidates dropped (fewest elements first).
    fn greedy(&mut self, stop: &AtomicBool) -> Result<(), SpheriseError> {
        use std::cmp::Reverse;
        use std::collections::BinaryHeap;
        let mut covered = vec![false; self.count.len()];
        for &e in &self.orphans {
            covered[e] = true;
        }
        let gain = |c: &Coverage, covered: &[bool]| c.elements().filter(|&e| !covered[e]).count();
        let mut heap: BinaryHeap<(usize, Reverse<usize>)> = self
            .coverage
            .iter()
            .enumerate()
            .map(|(i, c)| (gain(c, &covered), Reverse(i)))
            .collect();
        while let Some((stale, Reverse(i))) = heap.pop() {
            check(stop)?;
            let fresh = gain(&self.coverage[i], &covered);
            if fresh == 0 {
                continue;
            }
            if fresh < stale && heap.peek().is_some_and(|&(top, _)| top > fresh) {
                heap.push((fresh, Reverse(i)));
                continue;
            }
            for e in self.coverage[i].elements() {
                covered[e] = true;
            }
            self.add(i, 0);
        }
        let mut order = self.cover.clone();
        order.sort_by_key(|&i| self.coverage[i].elements().count());
        for i in order {
            if self.coverage[i].elements().all(|e| self.count[e] >= 2) {
                self.remove(i, 0);
            }
        }
        Ok(())
    }

    fn add(&mut self, i: usize, step: usize) {
        self.chosen[i] = true;
        self.changed[i] = step;
        self.cover.push(i);
        self.loss[i] = 0;
        for k in 0..self.coverage[i].words.len() {
            let mut word = self.coverage[i].words[k];
            while word != 0 {
                let e = (self.coverage[i].first + k) * 64 + word.trailing_zeros() as usize;
                word &= word - 1;
                self.count[e] += 1;
                match self.count[e] {
                    1 => self.loss[i] += self.weight[e],
                    2 => {
                        if let Some(j) = self.holder(e, i) {
                            self.loss[j] -= self.weight[e];
                        }
                    }
                    _ => {}
                }
            }
        }
        let count = &self.count;
        self.uncovered.retain(|&e| count[e] == 0);
    }

    fn remove(&mut self, i: usize, step: usize) {
        self.chosen[i] = false;
        self.changed[i] = step;
        self.cover.retain(|&c| c != i);
        for k in 0..self.coverage[i].words.len() {
            let mut word = self.coverage[i].words[k];
            while word != 0 {
                let e = (self.coverage[i].first + k) * 64 + word.trailing_zeros() as usize;
                word &= word - 1;
                self.count[e] -= 1;
                match self.count[e] {
                    0 => self.uncovered.push(e),
                    1 => {
                        if let Some(j) = self.holder(e, i) {
                            self.loss[j] += self.weight[e];
                        }
                    }
                    _ => {}
                }
            }
        }
    }

    /// The candidate of the cover other than `not` that contains `e`.
    fn holder(&self, e: usize, not: usize) -> Option<usize> {
        self.cover
            .iter()
            .copied()
            .find(|&j| j != not && self.coverage[j].contains(e))
    }

    /// The uncovered weight candidate `i` would cover.
    fn gain(&self, i: usize) -> u64 {
        let c = &self.coverage[i];
        self.uncovered
            .iter()
            .filter(|&&e| c.contains(e))
            .map(|&e| self.weight[e])
            .sum()
    }

    /// The cover's candidate whose removal costs least (not `keep`), ties to the oldest.
    fn cheapest(&self, keep: Option<usize>) -> Option<usize> {
        self.cover
            .iter()
            .copied()
            .filter(|&i| Some(i) != keep)
            .min_by_key(|&i| (self.loss[i], self.changed[i]))
    }

    fn random(&mut self, n: usize) -> usize {
        // xorshift64*: deterministic, so that covers repeat.
        self.rng ^= self.rng >> 12;
        self.rng ^= self.rng << 25;
        self.rng ^= self.rng >> 27;
        let r = self.rng.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (r >> 32) as usize % n
    }

    /// Runs the search for `steps` steps and returns the smallest cover found (candidate
    /// indices; every element but the orphans lies in one of them).
    ///
    /// # Errors
    /// [`SpheriseError::Stopped`] once `stop` is raised.
    pub(super) fn run(
        &mut self,
        steps: usize,
        stop: &AtomicBool,
    ) -> Result<Vec<usize>, SpheriseError> {
        let mut best = self.cover.clone();
        let (mut added, mut removed) = (None, None);
        for step in 1..=steps {
            if step % 64 == 0 {
                check(stop)?;
            }
            while self.uncovered.is_empty() {
                if self.cover.len() < best.len() {
                    best.clone_from(&self.cover);
                }
                if self.cover.len() <= 1 {
                    return Ok(best);
                }
                let Some(i) = self.cheapest(None) else {
                    return Ok(best);
                };
                self.remove(i, step);
            }
            if let Some(i) = self.cheapest(added) {
                self.remove(i, step);
                removed = Some(i);
            }
            let at = self.random(self.uncovered.len());
            let e = self.uncovered[at];
            let pick = (0..self.coverage.len())
                .filter(|&i| !self.chosen[i] && Some(i) != removed && self.coverage[i].contains(e))
                .max_by_key(|&i| (self.gain(i), std::cmp::Reverse(self.changed[i])));
            // The removed candidate is the only one containing `e` when no other is.
            let pick = pick.or(removed.filter(|&i| self.coverage[i].contains(e)));
            let Some(i) = pick else {
                return Ok(best);
            };
            self.add(i, step);
            added = Some(i);
            for k in 0..self.uncovered.len() {
                let e = self.uncovered[k];
                self.weight[e] += 1;
            }
        }
        if self.uncovered.is_empty() && self.cover.len() < best.len() {
            best.clone_from(&self.cover);
        }
        Ok(best)
    }

    /// Whether candidate `i` contains element `e`.
    pub(super) fn contains(&self, i: usize, e: usize) -> bool {
        self.coverage[i].contains(e)
    }
}

/// The searched placement's spheres covering `solid` with protrusion at most `tolerance`,
/// and the tolerance they keep: the medial placement's grid and candidates
/// (`medial_cover.rs`), the greedy cover improved by [`CoverSearch`]; each element then goes
/// to the sphere of the cover it makes protrude least, and the grid placement's pruning and
/// shrinking end it.
///
/// # Errors
/// [`SpheriseError::Stopped`] once `stop` is raised.
pub(super) fn searched_cover(
    solid: &Solid,
    tolerance: f64,
    stop: &AtomicBool,
) -> Result<(Vec<CoverSphere>, f64), SpheriseError> {
    let (grid, candidates, tolerance) = medial_grid(solid, tolerance, stop)?;
    let mut search = CoverSearch::new(&grid, &candidates, stop)?;
    let steps = (grid.elements.len() / ELEMENTS_PER_STEP).max(MIN_STEPS);
    let cover = search.run(steps, stop)?;
    let mut picked: Vec<(Candidate, Vec<usize>)> =
        cover.iter().map(|&i| (candidates[i], Vec::new())).collect();
    for (e, element) in grid.elements.iter().enumerate() {
        if e % 256 == 0 {
            check(stop)?;
        }
        let best = cover
            .iter()
            .enumerate()
            .filter(|&(_, &i)| search.contains(i, e))
            .map(|(k, &i)| {
                (
                    k,
                    element.reach_from(candidates[i].centre) - candidates[i].depth,
                )
            })
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((k, _)) = best {
            picked[k].1.push(e);
        }
    }
    // Elements no candidate contains (none, by the cell size; kept as a safety net): each
    // gets a sphere of its own, with its true protrusion.
    for &e in search.orphans() {
        let c = grid.elements[e].centre();
        let mut own = candidate(solid, c, tolerance);
        own.reach = grid.elements[e].reach_from(c);
        picked.push((own, vec![e]));
    }
    picked.retain(|(_, mine)| !mine.is_empty());
    Ok((shrink_and_prune(solid, &grid, &picked, stop)?, tolerance))
}

/// The elements of `grid` candidate `c` contains whole, in increasing order.
fn contained(grid: &CellGrid, c: &Candidate, out: &mut Vec<usize>) {
    let r = glam::DVec3::splat(c.reach);
    let [ri, rj, rk] = grid.cell_range(c.centre - r, c.centre + r);
    for i in ri {
        for j in rj.clone() {
            for k in rk.clone() {
                let e = grid.element_of[grid.cell_index([i, j, k])];
                if e != u32::MAX && grid.elements[e as usize].within(c.centre, c.reach) {
                    out.push(e as usize);
                }
            }
        }
    }
    out.sort_unstable();
}

/// The bitset of sorted element indices.
fn bitset(elements: &[usize]) -> Coverage {
    let (Some(&lo), Some(&hi)) = (elements.first(), elements.last()) else {
        return Coverage::default();
    };
    let first = lo / 64;
    let mut words = vec![0_u64; hi / 64 - first + 1];
    for &e in elements {
        words[e / 64 - first] |= 1 << (e % 64);
    }
    Coverage { first, words }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bitset_lists_and_tests_its_elements() {
        let elements = [3, 64, 65, 200];
        let c = bitset(&elements);
        assert_eq!(c.elements().collect::<Vec<_>>(), elements);
        for e in 0..300 {
            assert_eq!(c.contains(e), elements.contains(&e), "{e}");
        }
        assert_eq!(bitset(&[]).elements().count(), 0);
        assert!(!bitset(&[]).contains(0));
    }

    #[test]
    fn the_search_keeps_every_element_covered_with_no_more_candidates() {
        let mesh = crate::spherise::triangle_mesh::TriangleMesh::cylinder(0.05, 0.3, 16).unwrap();
        let solid = Solid::new(mesh).unwrap();
        let stop = AtomicBool::new(false);
        let (grid, candidates, _) = medial_grid(&solid, 0.015, &stop).unwrap();
        let mut search = CoverSearch::new(&grid, &candidates, &stop).unwrap();
        let greedy = search.cover.clone();
        assert!(search.orphans().is_empty());
        let best = search.run(2_000, &stop).unwrap();
        assert!(
            best.len() <= greedy.len(),
            "{} {}",
            best.len(),
            greedy.len()
        );
        for e in 0..grid.elements.len() {
            // Each element lies whole in a chosen candidate, by the containment test itself.
            assert!(
                best.iter()
                    .any(|&i| grid.elements[e].within(candidates[i].centre, candidates[i].reach)),
                "element {e}"
            );
        }
        // The counts the search keeps are those of its cover.
        for e in 0..grid.elements.len() {
            let holders = search
                .cover
                .iter()
                .filter(|&&i| search.contains(i, e))
                .count();
            assert_eq!(search.count[e] as usize, holders);
        }
    }
}
