//! [`GaussianPartners`]: the Gaussian neighbours of a batch's invalid candidates, drawn and
//! checked together.

use mit_star_spaces::{SeededRng, StateSpace};
use mit_star_validity::StateValidity;

use super::MOST_BATCHED;
use crate::{GaussianStep, InformedSet, SamplerCounters};

/// What became of a candidate's partner.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) enum Partner {
    /// None drawn (the candidate is valid, or was handed out before the partners were drawn).
    #[default]
    None,
    /// Outside the informed set of the batch's bound: turned down unchecked.
    Outside,
    /// Inside the set, and valid or not.
    Checked(bool),
}

/// The adaptive sampler's step 3 for a whole batch of candidates at once: when the first
/// invalid candidate of a batch ([`Lookahead`](super::Lookahead)) needs its Gaussian
/// neighbour `x_temp`, every invalid candidate from it on gets one, and those inside the
/// informed set are decided by one batched call of the checker instead of one call each (an
/// arm checked in sixteen SIMD lanes decides them for about the price of one).
///
/// Each partner is drawn from its own candidate alone, so a sampler that takes the partners in
/// the candidates' order sees the same sequence of states in law as if it drew and checked
/// each when needed; partners of candidates the sampler never reaches (a batch dropped when
/// the bound changes) are drawn for nothing.
#[derive(Debug, Clone, Default)]
pub(crate) struct GaussianPartners {
    /// The batch the partners belong to (its [`Lookahead`](super::Lookahead) generation).
    generation: Option<u64>,
    /// One partner per candidate, `dimension` coordinates each.
    states: Vec<f64>,
    verdicts: [Partner; MOST_BATCHED],
    /// The partners inside the set, packed for the checker, and their candidates' indices.
    packed: Vec<f64>,
    packed_of: Vec<usize>,
    packed_valid: [bool; MOST_BATCHED],
}

/// What drawing a batch's partners takes: the step, the space, the checker, the set and its
/// bound, the generator and the counters to charge.
pub(crate) struct PartnerDraw<'a, S: ?Sized, V: ?Sized> {
    pub(crate) step: &'a GaussianStep,
    pub(crate) space: &'a S,
    pub(crate) validity: &'a V,
    pub(crate) set: &'a InformedSet,
    pub(crate) cost: Option<f64>,
    pub(crate) rng: &'a mut SeededRng,
    pub(crate) counters: &'a mut SamplerCounters,
}

impl GaussianPartners {
    /// The partner of candidate `index` of the batch `(generation, candidates, valid)` (as
    /// [`Lookahead::batch`](super::Lookahead::batch) gives it), written into `out` unless it
    /// is [`Partner::None`]. The first call for a batch draws the partners of its invalid
    /// candidates from `index` on (each counted as drawn) and checks those inside the set in
    /// one call (each counted as a check); `None` for an index the batch does not hold.
    pub(crate) fn partner<S, V>(
        &mut self,
        (generation, candidates, valid): (u64, &[f64], &[bool]),
        index: usize,
        mut draw: PartnerDraw<'_, S, V>,
        out: &mut [f64],
    ) -> Option<Partner>
    where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        let dimension = out.len();
        if index >= valid.len() || dimension == 0 {
            return None;
        }
        if self.generation != Some(generation) {
            self.generation = Some(generation);
            self.draw_all((candidates, valid), index, &mut draw, dimension);
        }
        let verdict = self.verdicts[index];
        if verdict != Partner::None {
            out.copy_from_slice(&self.states[index * dimension..(index + 1) * dimension]);
        }
        Some(verdict)
    }

    /// The segments `candidate → partner` of batch `generation`'s candidates from `first` on
    /// whose partner failed (invalid, or outside the set): those the adaptive sampler will
    /// search ([`SegmentsAhead`](super::SegmentsAhead)), with their candidates' indices. Empty
    /// unless the partners held are that batch's.
    pub(crate) fn failed<'a>(
        &'a self,
        (generation, candidates): (u64, &'a [f64]),
        first: usize,
        dimension: usize,
    ) -> impl Iterator<Item = (usize, &'a [f64], &'a [f64])> + 'a {
        let held = if self.generation == Some(generation) && dimension > 0 {
            candidates.len() / dimension
        } else {
            0
        };
        (first..held)
            .filter(|&i| matches!(self.verdicts[i], Partner::Outside | Partner::Checked(false)))
            .map(move |i| {
                let span = i * dimension..(i + 1) * dimension;
                (i, &candidates[span.clone()], &self.states[span])
            })
    }

    /// Draws the partners of the invalid candidates from `first` on and checks those inside
    /// the set together.
    fn draw_all<S, V>(
        &mut self,
        (candidates, valid): (&[f64], &[bool]),
        first: usize,
        draw: &mut PartnerDraw<'_, S, V>,
        dimension: usize,
    ) where
        S: StateSpace + ?Sized,
        V: StateValidity + ?Sized,
    {
        self.states.resize(MOST_BATCHED * dimension, 0.0);
        self.verdicts = [Partner::None; MOST_BATCHED];
        self.packed.clear();
        self.packed_of.clear();
        for (i, candidate) in candidates.chunks_exact(dimension).enumerate().skip(first) {
            if valid[i] {
                continue;
            }
            let partner = &mut self.states[i * dimension..(i + 1) * dimension];
            draw.step.perturb(draw.space, draw.rng, candidate, partner);
            draw.counters.drawn += 1;
            if draw.set.contains(draw.space, draw.cost, partner) {
                self.packed.extend_from_slice(partner);
                self.packed_of.push(i);
            } else {
                self.verdicts[i] = Partner::Outside;
            }
        }
        let count = self.packed_of.len();
        if count == 0 {
            return;
        }
        draw.validity
            .are_valid(&self.packed, dimension, &mut self.packed_valid[..count]);
        draw.counters.validity_checks += count as u64;
        for (&i, &ok) in self.packed_of.iter().zip(&self.packed_valid) {
            self.verdicts[i] = Partner::Checked(ok);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling_steps::test_checkers::RightHalf;
    use mit_star_spaces::RealVectorSpace;
    use rand::SeedableRng;

    #[test]
    fn the_invalid_candidates_from_the_first_asked_get_partners_checked_together() {
        let space = RealVectorSpace::cube(2, 0.0, 1.0).unwrap();
        let set = InformedSet::new(&space, &[0.1, 0.5], &[[0.9, 0.5]]).unwrap();
        let step = GaussianStep::new(0.3).unwrap();
        let checker = RightHalf::new(8);
        let mut rng = SeededRng::seed_from_u64(7);
        let mut counters = SamplerCounters::default();
        // Five candidates: valid, invalid, invalid, valid, invalid.
        let candidates = [0.7, 0.5, 0.2, 0.5, 0.3, 0.5, 0.6, 0.5, 0.1, 0.5];
        let valid = [true, false, false, true, false];
        let mut partners = GaussianPartners::default();
        let mut out = [0.0; 2];
        let ask = |partners: &mut GaussianPartners,
                   rng: &mut SeededRng,
                   counters: &mut SamplerCounters,
                   generation: u64,
                   index: usize,
                   out: &mut [f64]| {
            let draw = PartnerDraw {
                step: &step,
                space: &space,
                validity: &checker,
                set: &set,
                cost: None,
                rng,
                counters,
            };
            partners.partner((generation, &candidates, &valid), index, draw, out)
        };
        // The first asked is candidate 2: candidates 2 and 4 get partners, in one call.
        let second = ask(&mut partners, &mut rng, &mut counters, 1, 2, &mut out).unwrap();
        assert_eq!(second, Partner::Checked(checker.is_valid(&out)));
        let fifth = ask(&mut partners, &mut rng, &mut counters, 1, 4, &mut out).unwrap();
        assert_eq!(fifth, Partner::Checked(checker.is_valid(&out)));
        // Candidate 1 was invalid but handed out before: none drawn for it, nor for the
        // valid ones; an index beyond the batch has none either.
        assert_eq!(
            ask(&mut partners, &mut rng, &mut counters, 1, 1, &mut out),
            Some(Partner::None)
        );
        assert_eq!(
            ask(&mut partners, &mut rng, &mut counters, 1, 3, &mut out),
            Some(Partner::None)
        );
        assert_eq!(
            ask(&mut partners, &mut rng, &mut counters, 1, 5, &mut out),
            None
        );
        assert_eq!(checker.batches(), [2]);
        assert_eq!((counters.drawn, counters.validity_checks), (2, 2));
        // A new batch draws again.
        ask(&mut partners, &mut rng, &mut counters, 2, 0, &mut out).unwrap();
        assert_eq!(checker.batches(), [2, 3]);
        assert_eq!((counters.drawn, counters.validity_checks), (5, 5));
    }
}
