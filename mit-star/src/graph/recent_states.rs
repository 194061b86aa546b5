//! [`RecentStates`]: the coordinates of the last committed samples, column by column in commit
//! order, so that bringing a cached neighbour list up to date is a vectorised pass.

/// A ring of the states of the last `capacity` entries of the graph's commit log, stored by
/// coordinate (all first coordinates, then all second ones, …).
///
/// Under a weighted Euclidean metric ([`with_scales`](Self::with_scales)) the ring holds the
/// scaled coordinates, as the kd-trees do, so the same column pass measures the weighted
/// distance (a Fetch's prismatic torso among its revolute joints).
///
/// Every reverse-search restart brings the neighbour list of each vertex it expands up to date
/// by measuring its distance to each sample committed since the list was made (at most
/// `capacity` of them; beyond that a fresh tree query is made instead). That is most of the
/// planner's own work in the anytime phase: a vertex meets the samples of the batches since
/// its last expansion at each update, and tree pruning cannot cut that down in high dimensions. Read through vertex ids
/// those states are scattered over the graph's storage; here one coordinate of every recent
/// sample is a contiguous column, so the squared distances of a query to all of them are
/// accumulated column by column in loops the compiler vectorises. The ring starts with room for
/// [`FIRST_ROOM`](Self::FIRST_ROOM) states and doubles while the log outgrows it, up to its
/// capacity: a search solved within a few batches never allocates (and zeroes) the full ring.
/// The first room is also held to [`FIRST_BYTES`](Self::FIRST_BYTES): in R^1000, 512 states
/// would be a 4 MB allocation whose pages the very first push touches one per column (a
/// millisecond of page faults inside the planner's construction, past a 1 ms budget).
#[derive(Debug, Clone)]
pub(crate) struct RecentStates {
    dimension: usize,
    capacity: usize,
    /// Slots allocated per column (at most `capacity`); position `p` is in slot `p % room`.
    room: usize,
    /// Log positions `end - held .. end` are held.
    end: usize,
    held: usize,
    /// Column `d` is `columns[d * room..(d + 1) * room]`.
    columns: Vec<f64>,
    /// Per-coordinate weights of the metric; empty for the plain Euclidean one.
    scales: Vec<f64>,
    /// The largest magnitude of a scaled coordinate pushed so far (0 without scales).
    magnitude: f64,
}

impl RecentStates {
    /// The states a ring first makes room for (or its capacity, if smaller).
    pub(crate) const FIRST_ROOM: usize = 512;

    /// The most bytes the first room may take (a smaller room in high dimensions, at least
    /// [`MIN_FIRST_ROOM`](Self::MIN_FIRST_ROOM) states).
    pub(crate) const FIRST_BYTES: usize = 64 * 1024;

    /// The fewest states a first room holds, whatever the dimension.
    pub(crate) const MIN_FIRST_ROOM: usize = 8;

    /// The room of the first allocation: [`FIRST_ROOM`](Self::FIRST_ROOM) states, fewer when
    /// they would take more than [`FIRST_BYTES`](Self::FIRST_BYTES), never beyond the capacity.
    fn first_room(&self) -> usize {
        let bytes_per_state = self.dimension.max(1) * size_of::<f64>();
        (Self::FIRST_BYTES / bytes_per_state)
            .clamp(Self::MIN_FIRST_ROOM, Self::FIRST_ROOM)
            .min(self.capacity)
    }

    /// An empty ring for the last `capacity` states of `dimension` coordinates.
    pub(crate) fn new(dimension: usize, capacity: usize) -> Self {
        Self {
            dimension,
            capacity,
            room: 0,
            end: 0,
            held: 0,
            columns: Vec::new(),
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

    /// Appends the state of the next log entry (the oldest held one falls out when full).
    pub(crate) fn push(&mut self, state: &[f64]) {
        debug_assert_eq!(state.len(), self.dimension);
        if self.capacity == 0 {
            self.end += 1;
            return;
        }
        if self.held == self.room && self.room < self.capacity {
            self.grow();
        }
        let slot = self.end % self.room;
        for (d, &x) in state.iter().enumerate() {
            let x = match self.scales.get(d) {
                Some(&s) => {
                    let x = s * x;
                    self.magnitude = self.magnitude.max(x.abs());
                    x
                }
                None => x,
            };
            self.columns[d * self.room + slot] = x;
        }
        self.end += 1;
        self.held = (self.held + 1).min(self.room);
    }

    /// Doubles the room (to its [first room](Self::first_room) at first, never beyond the
    /// capacity), moving the held states to their slots in the larger columns.
    fn grow(&mut self) {
        let room = (2 * self.room).clamp(self.first_room(), self.capacity);
        let mut columns = vec![0.0; room * self.dimension];
        for p in self.end - self.held..self.end {
            let (from, to) = (p % self.room, p % room);
            for d in 0..self.dimension {
                columns[d * room + to] = self.columns[d * self.room + from];
            }
        }
        self.columns = columns;
        self.room = room;
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
        if count == 0 {
            return Some(0.0);
        }
        // At most two runs of slots: up to the end of the ring, then from its start.
        let first = from % self.room;
        let head = count.min(self.room - first);
        let runs = [(first, 0, head), (0, head, count - head)];
        for (d, &q) in query.iter().enumerate() {
            let q = match self.scales.get(d) {
                Some(&s) => {
                    magnitude = magnitude.max((s * q).abs());
                    s * q
                }
                None => q,
            };
            let column = &self.columns[d * self.room..(d + 1) * self.room];
            for &(slot, at, len) in &runs {
                for (sum, &y) in out[at..at + len].iter_mut().zip(&column[slot..slot + len]) {
                    let t = q - y;
                    *sum += t * t;
                }
            }
        }
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
        // Room for 512, then 1 024 (the capacity), then the oldest fall out.
        let capacity = 2 * RecentStates::FIRST_ROOM;
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
        assert_eq!(r.room, capacity);
    }

    #[test]
    fn the_first_room_of_a_high_dimensional_ring_is_small() {
        // Before: 512 states whatever the dimension, 4 MB in R^1000.
        let mut r = RecentStates::new(1000, 16_384);
        r.push(&[0.5; 1000]);
        assert_eq!(r.room, RecentStates::MIN_FIRST_ROOM);
        assert!(r.columns.len() * size_of::<f64>() <= RecentStates::FIRST_BYTES);
        let state: Vec<f64> = (0..1000).map(f64::from).collect();
        for _ in 0..100 {
            r.push(&state);
        }
        assert_eq!(r.room, 128, "the room doubles from its first size");
        let mut low = RecentStates::new(7, 16_384);
        low.push(&[0.0; 7]);
        assert_eq!(
            low.room,
            RecentStates::FIRST_ROOM,
            "low dimensions keep 512"
        );
    }

    #[test]
    fn a_ring_without_room_holds_nothing() {
        let mut r = RecentStates::new(2, 0);
        r.push(&[1.0, 2.0]);
        assert_eq!(distances(&r, 0, &[0.0, 0.0]), None);
        assert_eq!(distances(&r, 1, &[0.0, 0.0]), Some(vec![]));
    }
}
