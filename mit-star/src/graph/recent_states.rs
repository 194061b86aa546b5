//! [`RecentStates`]: the coordinates of the last committed samples, column by column in commit
//! order, so that bringing a cached neighbour list up to date is a vectorised pass.

/// A ring of the states of the last `capacity` entries of the graph's commit log, stored by
/// coordinate (all first coordinates, then all second ones, …) within pages of a few states.
///
/// Under a weighted Euclidean metric ([`with_scales`](Self::with_scales)) the ring holds the
/// scaled coordinates, as the kd-trees do, so the same column pass measures the weighted
/// distance (a Fetch's prismatic torso among its revolute joints).
///
/// Every reverse-search restart brings the neighbour list of each vertex it expands up to date
/// by measuring its distance to each sample committed since the list was made (at most
/// `capacity` of them; beyond that a fresh tree query is made instead). That is most of the
/// planner's own work in the anytime phase: a vertex meets the samples of the batches since
/// its last expansion at each update, and tree pruning cannot cut that down in high
/// dimensions. Read through vertex ids those states are scattered over the graph's storage;
/// here one coordinate of the recent samples of a page is a contiguous run, so the squared
/// distances of a query to all of them are accumulated column by column in loops the compiler
/// vectorises.
///
/// The ring is a list of pages of at most [`PAGE_BYTES`](Self::PAGE_BYTES) each (between
/// [`MIN_PAGE_SLOTS`](Self::MIN_PAGE_SLOTS) and [`MAX_PAGE_SLOTS`](Self::MAX_PAGE_SLOTS)
/// states), allocated as the log first reaches them and never moved: a search solved within a
/// few batches never allocates (and zeroes) the full ring, and growing costs one page's fresh
/// memory, not a copy of everything held. In R^1000 a ring of columns doubled by copying put
/// a megabyte of page faults between two polls of the deadline.
#[derive(Debug, Clone)]
pub(crate) struct RecentStates {
    dimension: usize,
    capacity: usize,
    /// States per page; position `p` is in slot `p % (page_slots · page_count)`.
    page_slots: usize,
    page_count: usize,
    /// Log positions `end - held .. end` are held.
    end: usize,
    held: usize,
    /// Page `i` (allocated once the log reaches it) holds slots `i · page_slots ..`; column `d`
    /// of a page is `page[d * page_slots..(d + 1) * page_slots]`.
    pages: Vec<Vec<f64>>,
    /// Per-coordinate weights of the metric; empty for the plain Euclidean one.
    scales: Vec<f64>,
    /// The largest magnitude of a scaled coordinate pushed so far (0 without scales).
    magnitude: f64,
}

/// A run of neighbouring slots within one page: page, first slot in the page, length.
type Run = (usize, usize, usize);

impl RecentStates {
    /// The most bytes a page takes (fewer states per page in high dimensions).
    pub(crate) const PAGE_BYTES: usize = 64 * 1024;

    /// The most states a page holds, whatever the dimension.
    pub(crate) const MAX_PAGE_SLOTS: usize = 512;

    /// The fewest states a page holds, whatever the dimension (a cache line of each column).
    pub(crate) const MIN_PAGE_SLOTS: usize = 8;

    /// States written per column pass in [`extend`](Self::extend): a cache line of `f64`s.
    pub(crate) const BLOCK: usize = 8;

    /// An empty ring for the last `capacity` states of `dimension` coordinates.
    pub(crate) fn new(dimension: usize, capacity: usize) -> Self {
        let bytes_per_state = dimension.max(1) * size_of::<f64>();
        let page_slots = (Self::PAGE_BYTES / bytes_per_state)
            .clamp(Self::MIN_PAGE_SLOTS, Self::MAX_PAGE_SLOTS)
            .min(capacity)
            .max(1);
        Self {
            dimension,
            capacity,
            page_slots,
            page_count: capacity.div_ceil(page_slots),
            end: 0,
            held: 0,
            pages: Vec::new(),
            scales: Vec::new(),
            magnitude: 0.0,
        }
    }

    /// An empty ring for the last `capacity` states under the metric
    /// `√Σ (scales[d] · Δ_d)²`.
    pub(crate) fn with_scales(scales: &[f64], capacity: usize) -> Self {
        Self {
            scales: scales.to_vec(),
            ..Self::new(scales.len(), capacity)
        }
    }

    /// Appends the state of the next log entry (the oldest held one falls out when full): the
    /// one-by-one reference that [`extend`](Self::extend) is tested against.
    #[cfg(test)]
    pub(crate) fn push(&mut self, state: &[f64]) {
        self.push_block(&[state]);
    }

    /// Appends the states of the next log entries in order, as pushing them one by one would,
    /// but a block of [`BLOCK`](Self::BLOCK) states at a time: each column then receives a run
    /// of neighbouring slots (a cache line) per block instead of one scattered write per state.
    pub(crate) fn extend<'a>(&mut self, states: impl IntoIterator<Item = &'a [f64]>) {
        let mut block: [&[f64]; Self::BLOCK] = [&[]; Self::BLOCK];
        let mut filled = 0;
        for state in states {
            block[filled] = state;
            filled += 1;
            if filled == Self::BLOCK {
                self.push_block(&block);
                filled = 0;
            }
        }
        self.push_block(&block[..filled]);
    }

    /// The runs of slots of log positions `from..from + count`, in log order (a page boundary
    /// or the ring's end starts a new run), passed to `each` with the offset of the run's first
    /// position from `from`.
    fn runs(&self, from: usize, count: usize, mut each: impl FnMut(Run, usize)) {
        let slots = self.page_slots * self.page_count;
        let mut done = 0;
        while done < count {
            let slot = (from + done) % slots;
            let (page, offset) = (slot / self.page_slots, slot % self.page_slots);
            let len = (count - done).min(self.page_slots - offset);
            each((page, offset, len), done);
            done += len;
        }
    }

    /// Appends `block` (at most [`BLOCK`](Self::BLOCK) states) column by column.
    fn push_block(&mut self, block: &[&[f64]]) {
        debug_assert!(block.len() <= Self::BLOCK);
        debug_assert!(block.iter().all(|s| s.len() == self.dimension));
        if self.capacity == 0 || block.is_empty() {
            self.end += block.len();
            return;
        }
        let mut runs = [(0, 0, 0, 0); Self::BLOCK];
        let mut count = 0;
        self.runs(self.end, block.len(), |(page, offset, len), at| {
            runs[count] = (page, offset, len, at);
            count += 1;
        });
        // Runs in log order: where a tiny ring wraps within the block, the later state wins.
        let stride = self.page_slots;
        for &(page, offset, len, at) in &runs[..count] {
            while self.pages.len() <= page {
                self.pages.push(vec![0.0; self.dimension * stride]);
            }
            let page = &mut self.pages[page];
            let states = &block[at..at + len];
            for d in 0..self.dimension {
                let column = &mut page[d * stride + offset..d * stride + offset + len];
                match self.scales.get(d) {
                    Some(&s) => {
                        for (slot, state) in column.iter_mut().zip(states) {
                            let x = s * state[d];
                            self.magnitude = self.magnitude.max(x.abs());
                            *slot = x;
                        }
                    }
                    None => {
                        for (slot, state) in column.iter_mut().zip(states) {
                            *slot = state[d];
                        }
                    }
                }
            }
        }
        self.end += block.len();
        self.held = (self.held + block.len()).min(self.capacity);
    }

    /// Skips `count` log entries without their states (the head of a batch larger than the
    /// ring, which the batch's own tail pushes out anyway). A run of held states must reach the
    /// end of the log, so nothing before the skipped entries can be read any more.
    pub(crate) fn skip(&mut self, count: usize) {
        if count > 0 {
            self.end += count;
            self.held = 0;
        }
    }

    /// Bytes the ring has allocated for states.
    #[cfg(test)]
    fn allocated_bytes(&self) -> usize {
        self.pages.len() * self.dimension * self.page_slots * size_of::<f64>()
    }

    /// Writes to `out` the squared (weighted) Euclidean distances from `query` to the states of
    /// log positions `from..` (the newest entries), in log order, and returns how far the root
    /// of any of them may lie from the exact distance beyond a relative rounding of
    /// `dimension · 2⁻⁵²`: 0 for the plain metric (each difference is rounded once), a bound
    /// from the largest scaled coordinate under weights (each coordinate is scaled, rounded,
    /// then subtracted). `None` (and `out` untouched) if `from` is older than the ring holds.
    /// Callers filter with both margins, so a state the space's own metric puts within a bound
    /// always passes.
    pub(crate) fn squared_distances(
        &self,
        from: usize,
        query: &[f64],
        out: &mut Vec<f64>,
    ) -> Option<f64> {
        if from > self.end || from < self.end - self.held {
            return None;
        }
        let count = self.end - from;
        out.clear();
        out.resize(count, 0.0);
        let mut magnitude = self.magnitude;
        for (q, s) in query.iter().zip(&self.scales) {
            magnitude = magnitude.max((s * q).abs());
        }
        let stride = self.page_slots;
        self.runs(from, count, |(page, offset, len), at| {
            let page = &self.pages[page];
            let sums = &mut out[at..at + len];
            for (d, &q) in query.iter().enumerate() {
                let q = self.scales.get(d).map_or(q, |s| s * q);
                let column = &page[d * stride + offset..d * stride + offset + len];
                for (sum, &y) in sums.iter_mut().zip(column) {
                    let t = q - y;
                    *sum += t * t;
                }
            }
        });
        // Each scaled difference is off by at most 2⁻⁵² · 2 · magnitude (two scalings and a
        // subtraction, each rounded to half an ulp), so the root by at most √n times that;
        // 1e-12 · magnitude covers it for any dimension up to millions.
        Some(1e-12 * magnitude)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn distances(r: &RecentStates, from: usize, query: &[f64]) -> Option<Vec<f64>> {
        let mut out = vec![-1.0];
        r.squared_distances(from, query, &mut out).map(|_| out)
    }

    #[test]
    fn measures_the_newest_entries_in_log_order_across_the_wrap() {
        let mut r = RecentStates::new(2, 3);
        assert_eq!(distances(&r, 0, &[0.0, 0.0]), Some(vec![]));
        let states: Vec<[f64; 2]> = (0..5_u8)
            .map(|p| [f64::from(p), 0.5 - f64::from(p)])
            .collect();
        for s in &states {
            r.push(s);
        }
        let q = [0.25, -1.0];
        // Positions 2, 3, 4 are held; 0 and 1 fell out.
        assert_eq!(distances(&r, 1, &q), None);
        for from in 2..=5 {
            let want: Vec<f64> = states[from..]
                .iter()
                .map(|s| s.iter().zip(&q).map(|(x, y)| (x - y) * (x - y)).sum())
                .collect();
            assert_eq!(distances(&r, from, &q), Some(want), "from {from}");
        }
        assert_eq!(distances(&r, 6, &q), None);
    }

    #[test]
    fn skipped_entries_hide_everything_before_them() {
        let mut r = RecentStates::new(1, 4);
        for p in 0..3_u8 {
            r.push(&[f64::from(p)]);
        }
        r.skip(2);
        // Log positions 0..5 exist; 3 and 4 have no states, so nothing before 5 can be read.
        assert_eq!(distances(&r, 2, &[0.0]), None);
        assert_eq!(distances(&r, 5, &[0.0]), Some(vec![]));
        r.push(&[5.0]);
        assert_eq!(distances(&r, 5, &[1.0]), Some(vec![16.0]));
    }

    #[test]
    fn weighted_rings_measure_the_weighted_metric_within_their_slack() {
        let scales = [2.0, 0.3, 1.0];
        let mut r = RecentStates::with_scales(&scales, 8);
        let states = [[0.1, 3.0, -2.0], [1e6, -0.7, 0.25], [0.1 + 1e-9, 3.0, -2.0]];
        for s in &states {
            r.push(s);
        }
        let q = [0.1, 3.0 - 1e-12, -2.0];
        let mut out = Vec::new();
        let slack = r.squared_distances(0, &q, &mut out).unwrap();
        assert!(
            slack >= 1e-12 * 2e6,
            "slack {slack} covers the largest scaled coordinate"
        );
        for (s, got) in states.iter().zip(&out) {
            let exact: f64 = s
                .iter()
                .zip(&q)
                .zip(&scales)
                .map(|((a, b), w)| (w * (a - b)) * (w * (a - b)))
                .sum::<f64>()
                .sqrt();
            let tolerance = exact * 3.0 * f64::EPSILON + slack;
            assert!(
                (got.sqrt() - exact).abs() <= tolerance,
                "{got} against {exact}"
            );
        }
        // The plain ring adds no slack.
        let mut plain = RecentStates::new(3, 8);
        plain.push(&states[1]);
        assert_eq!(plain.squared_distances(0, &q, &mut out), Some(0.0));
    }

    #[test]
    fn a_growing_ring_keeps_every_held_state_in_log_order() {
        // A page of 512, then two (the capacity), then the oldest fall out.
        let capacity = 2 * RecentStates::MAX_PAGE_SLOTS;
        let mut r = RecentStates::new(2, capacity);
        let states: Vec<[f64; 2]> = (0..1_300_u32)
            .map(|p| [f64::from(p), f64::from(p % 7) - 3.0])
            .collect();
        let q = [10.5, 1.0];
        let squared =
            |s: &[f64; 2]| -> f64 { s.iter().zip(&q).map(|(x, y)| (x - y) * (x - y)).sum() };
        for (p, s) in states.iter().enumerate() {
            r.push(s);
            let end = p + 1;
            let oldest = end.saturating_sub(capacity);
            for from in [oldest, (oldest + end) / 2, end - 1] {
                let want: Vec<f64> = states[from..end].iter().map(squared).collect();
                assert_eq!(
                    distances(&r, from, &q),
                    Some(want),
                    "end {end}, from {from}"
                );
            }
            if oldest > 0 {
                assert_eq!(distances(&r, oldest - 1, &q), None, "end {end}");
            }
        }
        assert_eq!(r.allocated_bytes(), capacity * 2 * size_of::<f64>());
    }

    #[test]
    fn pages_are_small_allocated_as_reached_and_never_moved() {
        // Before: one block of columns, 512 states whatever the dimension (4 MB in R^1000),
        // later doubled by copying everything held.
        let mut r = RecentStates::new(1000, 16_384);
        r.push(&[0.5; 1000]);
        assert_eq!(r.page_slots, RecentStates::MIN_PAGE_SLOTS);
        assert!(r.allocated_bytes() <= RecentStates::PAGE_BYTES);
        let first = r.pages[0].as_ptr();
        let state: Vec<f64> = (0..1000).map(f64::from).collect();
        for _ in 0..100 {
            r.push(&state);
        }
        assert_eq!(r.pages.len(), 101_usize.div_ceil(8), "a page per 8 states");
        assert_eq!(r.pages[0].as_ptr(), first, "the first page never moved");
        let low = RecentStates::new(7, 16_384);
        assert_eq!(
            low.page_slots,
            RecentStates::MAX_PAGE_SLOTS,
            "low dimensions keep 512 states a page"
        );
    }

    #[test]
    fn extending_by_blocks_measures_every_held_state_exactly() {
        // Dimensions (one state a page up to 512), capacities (tiny rings wrap within a
        // block) and scales, with runs of every length around the block size, against the
        // distances measured directly from every state pushed.
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for dimension in [1, 3, 9, 1000, 9000] {
            for capacity in [0, 1, 3, 8, 13, 64, 600] {
                let scales: Vec<f64> = (0..dimension).map(|d| 0.5 + d as f64 * 0.25).collect();
                for scaled in [false, true] {
                    let mut ring = if scaled {
                        RecentStates::with_scales(&scales, capacity)
                    } else {
                        RecentStates::new(dimension, capacity)
                    };
                    let weight = |d: usize| if scaled { scales[d] } else { 1.0 };
                    let mut all: Vec<Vec<f64>> = Vec::new();
                    for _ in 0..12 {
                        let run = (next() % 20) as usize;
                        let first = all.len();
                        for _ in 0..run {
                            let label = all.len() as f64 + 1.0;
                            all.push((0..dimension).map(|d| label * 10.0 - d as f64).collect());
                        }
                        ring.extend(all[first..].iter().map(Vec::as_slice));
                        let context = format!("dimension {dimension}, capacity {capacity}");
                        let end = all.len();
                        let oldest = end.saturating_sub(capacity);
                        let query = vec![0.25; dimension];
                        for from in [oldest, (oldest + end) / 2, end.saturating_sub(1), end] {
                            let from = from.max(oldest);
                            let want: Vec<f64> = all[from..]
                                .iter()
                                .map(|s| {
                                    (0..dimension)
                                        .map(|d| {
                                            let t = weight(d) * 0.25 - weight(d) * s[d];
                                            t * t
                                        })
                                        .sum()
                                })
                                .collect();
                            assert_eq!(
                                distances(&ring, from, &query),
                                Some(want),
                                "{context}, from {from}"
                            );
                        }
                        if oldest > 0 {
                            assert_eq!(distances(&ring, oldest - 1, &query), None, "{context}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn a_ring_without_room_holds_nothing() {
        let mut r = RecentStates::new(2, 0);
        r.push(&[1.0, 2.0]);
        assert_eq!(distances(&r, 0, &[0.0, 0.0]), None);
        assert_eq!(distances(&r, 1, &[0.0, 0.0]), Some(vec![]));
    }
}
