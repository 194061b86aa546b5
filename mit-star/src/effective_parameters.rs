//! [`Configuration::effective_parameters`]: the parameters a planner built by
//! [`build_planner`](crate::build_planner) runs with, every default decided.

use mit_star_problems::PlanningProblem;
use mit_star_spaces::StateSpace;

use crate::{
    APriori, BuildError, Configuration, CostInformed, EffortInformed, Guidance, Parameters,
    Suspending, default_range,
};

impl Configuration {
    /// The parameters the planner of this configuration, built by
    /// [`build_planner`](crate::build_planner) for `problem` with `parameters`, runs with:
    /// those set in `parameters` as they are, and every default decided — the problem's
    /// resolution, certification, near-terminal fraction, sparse spacing, reverse-search
    /// repair, connection rule, batch size and batch growth wherever unset ([`PlanningProblem`]); the planner's suspension rule, inflation,
    /// truncation and cascading rewirings (ABIT*'s for `abit-star`, none for the rest of the
    /// EIT* family); RRT-Connect's, AORRTC's and Informed RRT*'s range
    /// ([`default_range`]). Parameters a configuration does not use stay as they are.
    ///
    /// A benchmark log or a results folder records these, so a reader sees the values that
    /// ran, not "the problem's" (OMPL's logs list each planner's effective properties the same
    /// way).
    ///
    /// # Errors
    /// [`BuildError::Problem`] if the problem refuses its check step or certification.
    ///
    /// ```
    /// use mit_star::{Configuration, Parameters};
    /// let problem = mit_star_problems::DividingWalls::new(2).build()?;
    /// let defaults = Parameters::default();
    /// assert_eq!(defaults.sparse_initial_steps, None);
    /// let mit = Configuration::MitStar.effective_parameters(&problem, &defaults)?;
    /// assert_eq!(mit.sparse_initial_steps, Some(mit_star_problems::PAPER_SPARSE_SPACING.0));
    /// assert_eq!(mit.suspend_reverse_when_forward_empty, Some(true));
    /// let eit = Configuration::EitStar.effective_parameters(&problem, &defaults)?;
    /// assert_eq!(eit.suspend_reverse_when_forward_empty, Some(false));
    /// let abit = Configuration::AbitStar.effective_parameters(&problem, &defaults)?;
    /// assert_eq!(abit.initial_inflation, Some(1e6));
    /// let rrt = Configuration::RrtConnect.effective_parameters(&problem, &defaults)?;
    /// assert!(rrt.range.is_some());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn effective_parameters<P: PlanningProblem>(
        self,
        problem: &P,
        parameters: &Parameters,
    ) -> Result<Parameters, BuildError> {
        // FCIT*'s batches are larger than the problem's default for the RGG planners.
        let parameters = match (self, parameters.batch_size) {
            (Self::FcitStar, None) => &Parameters {
                batch_size: Some(FCIT_BATCH_SIZE),
                ..parameters.clone()
            },
            _ => parameters,
        };
        let parameters = parameters.for_problem(problem)?;
        Ok(match self {
            Self::MitStar | Self::MitStarSr => guided::<Suspending>(parameters),
            Self::EitStar | Self::MitStarAs | Self::MitStarEis | Self::MitStarSc => {
                guided::<EffortInformed>(parameters)
            }
            Self::AitStar => guided::<CostInformed>(parameters),
            Self::FcitStar => guided::<APriori>(parameters),
            Self::BitStar => guided::<APriori>(parameters),
            Self::AbitStar => guided::<APriori>(parameters.abit_star()),
            Self::RrtConnect | Self::Aorrtc | Self::InformedRrtStar => {
                let space = problem.space();
                let range = parameters
                    .range
                    .unwrap_or_else(|| default_range(space.dimension(), space.maximum_extent()));
                Parameters {
                    range: Some(range),
                    ..parameters
                }
            }
        })
    }
}

/// FCIT*'s samples per batch unless set. Each batch restarts the search, and every vertex
/// it expands sorts its `q − 1` edges, so a batch costs `O(q² log q)`: the arms' 50 spends the
/// budget on restarts, VAMP's 1000 delays the first path. On the first 5 Panda problems of
/// each of the five `panda-mbm` scenes at 1 s (`anytime_arm`), 200 solved 24 of 25 against 23
/// with 50 and 24 with 1000, with a pooled median cost at 100 ms of 4.34 against 4.41 and 4.71.
pub(crate) const FCIT_BATCH_SIZE: usize = 200;

/// `parameters` with the unset choices of a planner of the EIT* family guided by `G` decided:
/// `G`'s suspension rule, no inflation or truncation, no cascading rewirings (the values the
/// planner falls back to).
fn guided<G: Guidance>(mut parameters: Parameters) -> Parameters {
    parameters
        .suspend_reverse_when_forward_empty
        .get_or_insert(G::SUSPEND_WHEN_FORWARD_EMPTY);
    parameters.initial_inflation.get_or_insert(1.0);
    parameters.inflation_scaling.get_or_insert(0.0);
    parameters.truncation_scaling.get_or_insert(0.0);
    parameters.cascading_rewirings.get_or_insert(false);
    parameters
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{
        AitStar, BitStar, EitStar, FcitStar, MitStar, MitStarAs, MitStarEis, MitStarSc, MitStarSr,
    };
    use mit_star_spaces::RealVectorSpace;
    use mit_star_validity::World;

    /// The suspension rule the planner type behind each configuration of the EIT* family
    /// falls back to, read from the type (not from a table kept by hand).
    fn type_suspends(c: Configuration) -> Option<bool> {
        type S = RealVectorSpace;
        Some(match c {
            Configuration::MitStar => MitStar::<S, World>::SUSPENDS,
            Configuration::EitStar => EitStar::<S, World>::SUSPENDS,
            Configuration::MitStarAs => MitStarAs::<S, World>::SUSPENDS,
            Configuration::MitStarEis => MitStarEis::<S, World>::SUSPENDS,
            Configuration::MitStarSc => MitStarSc::<S, World>::SUSPENDS,
            Configuration::MitStarSr => MitStarSr::<S, World>::SUSPENDS,
            Configuration::AitStar => AitStar::<S, World>::SUSPENDS,
            Configuration::FcitStar => FcitStar::<S, World>::SUSPENDS,
            Configuration::BitStar | Configuration::AbitStar => BitStar::<S, World>::SUSPENDS,
            _ => return None,
        })
    }

    #[test]
    fn effective_parameters_decide_every_default_as_the_planner_would() {
        let problem = mit_star_problems::DividingWalls::new(2).build().unwrap();
        let defaults = Parameters::default();
        for c in Configuration::ALL {
            let effective = c.effective_parameters(&problem, &defaults).unwrap();
            let undecided: Vec<(String, String)> = effective
                .settings()
                .into_iter()
                .filter(|(_, v)| v == "problem's")
                .collect();
            assert!(undecided.is_empty(), "{c}: {undecided:?}");
            match type_suspends(c) {
                Some(suspends) => {
                    assert_eq!(
                        effective.suspend_reverse_when_forward_empty,
                        Some(suspends),
                        "{c}"
                    );
                    assert!(effective.initial_inflation.is_some(), "{c}");
                    assert!(effective.cascading_rewirings.is_some(), "{c}");
                }
                None => {
                    let space = problem.space();
                    let range = default_range(space.dimension(), space.maximum_extent());
                    assert_eq!(effective.range, Some(range), "{c}");
                }
            }
            // Deciding twice changes nothing, and a planner built from the decided values
            // reports what one built from the defaults reports.
            assert_eq!(
                c.effective_parameters(&problem, &effective).unwrap(),
                effective
            );
            let built = crate::build_planner(c, &problem, &effective).unwrap();
            let from_defaults = crate::build_planner(c, &problem, &defaults).unwrap();
            assert_eq!(built.settings(), from_defaults.settings(), "{c}");
        }
        // A value set by the caller stays.
        let set = Parameters {
            suspend_reverse_when_forward_empty: Some(false),
            ..defaults
        };
        let mit = Configuration::MitStar
            .effective_parameters(&problem, &set)
            .unwrap();
        assert_eq!(mit.suspend_reverse_when_forward_empty, Some(false));
    }
}
