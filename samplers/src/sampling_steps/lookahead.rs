//! [`Lookahead`]: candidates drawn ahead of need and checked together, one batch of the
//! checker at a time.

use mit_star_validity::StateValidity;

use crate::SampleError;

/// The most states a sampler hands a checker in one batch (candidates drawn ahead, points of
/// a segment search), whatever batch width the checker asks for: eight, so that a sampler
/// draws the same random sequence whether the arm checker runs eight lanes or sixteen (with
/// AVX-512). Sixteen gained nothing on the Panda: MIT*'s pooled median time to a first solution
/// was 109–114 µs either way (`arm_profile target 20 mit-star 10`, two runs each), and its median
/// iterations on cage rose from 2 136 to 2 288.
pub(crate) const MOST_BATCHED: usize = 8;

/// Candidates a sampler drew ahead of need, with their validity, decided together by one
/// batched call ([`StateValidity::are_valid`]) of up to the checker's
/// [`batch_width`](StateValidity::batch_width): an arm checked in eight SIMD lanes decides
/// eight candidates for about the price of one.
///
/// The candidates are independent draws, handed out in the order they were drawn, so a
/// sampler sees the same sequence of (candidate, validity) pairs in law as if it drew and
/// checked each when needed. Candidates drawn under another cost bound are dropped unseen,
/// and a checker of batch width 1 draws exactly when asked — the same random sequence as no
/// lookahead at all. The validity answers belong to the checker of the call that drew them:
/// [`clear`](Self::clear) before asking with another one (a sampler does on `reseed`).
#[derive(Debug, Clone, Default)]
pub(crate) struct Lookahead {
    /// Candidates drawn, `dimension` coordinates each.
    states: Vec<f64>,
    /// Whether each is valid.
    valid: [bool; MOST_BATCHED],
    /// How many are held; the next to hand out.
    held: usize,
    next: usize,
    /// The cost bound they were drawn under, as bits (`None`: unbounded).
    drawn_under: Option<u64>,
    /// How many batches have been drawn: names the batch held, for what a sampler keeps
    /// about its candidates (their Gaussian partners).
    generation: u64,
}

impl Lookahead {
    /// Drops the candidates held.
    pub(crate) fn clear(&mut self) {
        self.held = 0;
        self.next = 0;
    }

    /// Writes the next candidate drawn under `cost` into `out` and returns whether it is
    /// valid. When none is left (or those left were drawn under another bound or dimension),
    /// first draws up to `validity`'s batch width of them with `draw` and decides them in one
    /// call, adding the states decided to `checks`.
    ///
    /// # Errors
    /// The first error of `draw` when it could not draw a single candidate (a draw that fails
    /// after others succeeded ends the batch early; the next call meets the error again).
    pub(crate) fn next<V: StateValidity + ?Sized>(
        &mut self,
        validity: &V,
        cost: Option<f64>,
        checks: &mut u64,
        out: &mut [f64],
        mut draw: impl FnMut(&mut [f64]) -> Result<(), SampleError>,
    ) -> Result<bool, SampleError> {
        let dimension = out.len();
        if dimension == 0 {
            draw(out)?;
            *checks += 1;
            return Ok(validity.is_valid(out));
        }
        let under = cost.map(f64::to_bits);
        if self.next == self.held
            || self.drawn_under != under
            || self.states.len() != MOST_BATCHED * dimension
        {
            self.clear();
            self.generation += 1;
            self.states.resize(MOST_BATCHED * dimension, 0.0);
            self.drawn_under = under;
            let width = validity.batch_width().clamp(1, MOST_BATCHED);
            for candidate in self.states.chunks_exact_mut(dimension).take(width) {
                match draw(candidate) {
                    Ok(()) => self.held += 1,
                    Err(error) if self.held == 0 => return Err(error),
                    Err(_) => break,
                }
            }
            let drawn = &self.states[..self.held * dimension];
            validity.are_valid(drawn, dimension, &mut self.valid[..self.held]);
            *checks += self.held as u64;
        }
        let i = self.next;
        self.next += 1;
        out.copy_from_slice(&self.states[i * dimension..(i + 1) * dimension]);
        Ok(self.valid[i])
    }

    /// Where the candidate [`next`](Self::next) handed out last was in the order of its batch's
    /// draws (0 for the first drawn): a sampler that keeps something about each draw (where it
    /// was centred) finds it there.
    pub(crate) fn last_index(&self) -> usize {
        self.next.saturating_sub(1)
    }

    /// The batch held: its [generation](Self::generation) and its candidates in drawn order
    /// (`dimension` coordinates each) with their validity. Empty without a batch (a dimension
    /// of 0 draws none ahead).
    pub(crate) fn batch(&self, dimension: usize) -> (u64, &[f64], &[bool]) {
        let held = if self.states.len() == MOST_BATCHED * dimension && dimension > 0 {
            self.held
        } else {
            0
        };
        (
            self.generation,
            &self.states[..held * dimension],
            &self.valid[..held],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling_steps::test_checkers::RightHalf;

    #[test]
    fn hands_out_candidates_in_drawn_order_a_batch_at_a_time() {
        let checker = RightHalf::new(4);
        let mut ahead = Lookahead::default();
        let mut counter = 0.0;
        let mut draw = |x: &mut [f64]| {
            counter += 0.25;
            x[0] = counter % 1.0;
            x[1] = counter;
            Ok(())
        };
        let (mut checks, mut out) = (0, [0.0; 2]);
        let mut seen = Vec::new();
        for _ in 0..6 {
            let valid = ahead
                .next(&checker, None, &mut checks, &mut out, &mut draw)
                .unwrap();
            seen.push((out[1], valid));
        }
        let expected = [0.25, 0.5, 0.75, 1.0, 1.25, 1.5];
        let want: Vec<_> = expected.iter().map(|&c| (c, c % 1.0 >= 0.5)).collect();
        assert_eq!(seen, want);
        assert_eq!(checker.batches(), [4, 4]);
        assert_eq!(checks, 8);
        // The sixth candidate handed out was the second of the second batch's draws.
        assert_eq!(ahead.last_index(), 1);
    }

    #[test]
    fn another_bound_drops_what_was_drawn_under_the_last() {
        let checker = RightHalf::new(4);
        let mut ahead = Lookahead::default();
        let (mut checks, mut out) = (0, [0.0]);
        let mut draws = 0;
        let mut draw = |x: &mut [f64]| {
            draws += 1;
            x[0] = 1.0;
            Ok(())
        };
        ahead
            .next(&checker, Some(2.0), &mut checks, &mut out, &mut draw)
            .unwrap();
        ahead
            .next(&checker, Some(1.5), &mut checks, &mut out, &mut draw)
            .unwrap();
        assert_eq!((draws, checks), (8, 8));
    }

    #[test]
    fn a_failed_draw_ends_the_batch_and_is_met_again() {
        let checker = RightHalf::new(4);
        let mut ahead = Lookahead::default();
        let (mut checks, mut out) = (0, [0.0]);
        let mut left = 2;
        let mut draw = |x: &mut [f64]| {
            if left == 0 {
                return Err(SampleError::Stopped);
            }
            left -= 1;
            x[0] = 1.0;
            Ok(())
        };
        for _ in 0..2 {
            assert_eq!(
                ahead.next(&checker, None, &mut checks, &mut out, &mut draw),
                Ok(true)
            );
        }
        assert_eq!(
            ahead.next(&checker, None, &mut checks, &mut out, &mut draw),
            Err(SampleError::Stopped)
        );
        assert_eq!(checks, 2);
    }
}
