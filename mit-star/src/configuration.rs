//! [`Configuration`]: the paper's configurations and comparison planners chosen at run time,
//! and [`build_planner`].

use std::fmt;
use std::str::FromStr;

use mit_star_problems::PlanningProblem;
use mit_star_validity::StateValidity;
use serde::{Deserialize, Serialize};

use mit_star_heuristics::Heuristic;
use mit_star_samplers::{NearTerminals, Sampler};
use mit_star_spaces::StateSpace;
use mit_star_validity::{Counted, EdgeChecker};

use crate::{
    AitStar, Aorrtc, BitStar, BuildError, CheckerPart, Eit, EitStar, FcitStar, Guidance,
    InformedRrtStar, MitStar, MitStarAs, MitStarEis, MitStarSc, MitStarSr, NeighbourRule,
    Parameters, Planner, RrtConnect, SamplerPart,
};

/// A configuration of the MIT*/EIT* family, or a comparison planner, for choosing one at run
/// time (command lines, benchmark files). The names are `mit-star`, `eit-star`, `mit-star-as`,
/// `mit-star-eis`, `mit-star-sc`, `mit-star-sr`, `rrt-connect`, `aorrtc`, `bit-star`, `abit-star`,
/// `ait-star`, `informed-rrt-star` and `fcit-star`.
///
/// ```
/// use mit_star::Configuration;
/// let c: Configuration = "mit-star-sc".parse()?;
/// assert_eq!(c, Configuration::MitStarSc);
/// assert_eq!(c.to_string(), "mit-star-sc");
/// assert_eq!(c.label(), "MIT*-SC");
/// assert!("rrt".parse::<Configuration>().is_err());
/// # Ok::<(), mit_star::BuildError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Configuration {
    /// Adaptive sampler, estimated informed set, length-related sparse checks.
    MitStar,
    /// Informed sampler, fixed sparse levels.
    EitStar,
    /// EIT* with the adaptive sampler.
    MitStarAs,
    /// EIT* with the estimated informed set.
    MitStarEis,
    /// EIT* with length-related sparse checks.
    MitStarSc,
    /// EIT* with the MIT* authors' suspension rule (an ablation the paper does not run).
    MitStarSr,
    /// RRT-Connect (Kuffner & LaValle 2000): bidirectional trees, first solution.
    RrtConnect,
    /// AORRTC (Wilson et al. 2025): RRT-Connect, then repeated cost-bounded searches under the
    /// best cost, each solution simplified.
    Aorrtc,
    /// BIT* (Gammell et al. 2020): the forward search alone, ordered by the a-priori heuristic.
    BitStar,
    /// ABIT* (Strub & Gammell 2020): BIT* with an inflated, then truncated search per batch.
    AbitStar,
    /// AIT* (Strub & Gammell 2020/2022): an unchecked lazy reverse search guides the forward
    /// search.
    AitStar,
    /// Informed RRT* (Gammell et al. 2014): RRT* with k-nearest rewiring, goal bias, direct
    /// informed sampling and pruning.
    InformedRrtStar,
    /// FCIT* (Wilson et al. 2025): BIT*'s search on a fully connected graph, each vertex's
    /// edges queued one at a time.
    FcitStar,
}

impl Configuration {
    /// Every configuration, MIT* first.
    pub const ALL: [Self; 13] = [
        Self::MitStar,
        Self::EitStar,
        Self::MitStarAs,
        Self::MitStarEis,
        Self::MitStarSc,
        Self::MitStarSr,
        Self::RrtConnect,
        Self::Aorrtc,
        Self::BitStar,
        Self::AbitStar,
        Self::AitStar,
        Self::InformedRrtStar,
        Self::FcitStar,
    ];

    /// The command-line name (`mit-star`, …).
    pub fn name(self) -> &'static str {
        match self {
            Self::MitStar => "mit-star",
            Self::EitStar => "eit-star",
            Self::MitStarAs => "mit-star-as",
            Self::MitStarEis => "mit-star-eis",
            Self::MitStarSc => "mit-star-sc",
            Self::MitStarSr => "mit-star-sr",
            Self::RrtConnect => "rrt-connect",
            Self::Aorrtc => "aorrtc",
            Self::BitStar => "bit-star",
            Self::AbitStar => "abit-star",
            Self::AitStar => "ait-star",
            Self::InformedRrtStar => "informed-rrt-star",
            Self::FcitStar => "fcit-star",
        }
    }

    /// `true` for the asymptotically optimal planners (all but RRT-Connect, which returns its
    /// first solution).
    pub fn is_asymptotically_optimal(self) -> bool {
        self != Self::RrtConnect
    }

    /// `true` for the planners of the EIT* family — MIT*, EIT*, their ablations, BIT*, ABIT*
    /// and AIT*, the [`Eit`] skeleton's batches and searches — and `false` for the tree
    /// planners RRT-Connect, AORRTC and Informed RRT*.
    pub fn is_informed_tree(self) -> bool {
        !matches!(
            self,
            Self::RrtConnect | Self::Aorrtc | Self::InformedRrtStar
        )
    }

    /// The paper's label (`MIT*`, `EIT*`, `MIT*-AS`, …).
    pub fn label(self) -> &'static str {
        match self {
            Self::MitStar => "MIT*",
            Self::EitStar => "EIT*",
            Self::MitStarAs => "MIT*-AS",
            Self::MitStarEis => "MIT*-EIS",
            Self::MitStarSc => "MIT*-SC",
            Self::MitStarSr => "MIT*-SR",
            Self::RrtConnect => "RRT-Connect",
            Self::Aorrtc => "AORRTC",
            Self::BitStar => "BIT*",
            Self::AbitStar => "ABIT*",
            Self::AitStar => "AIT*",
            Self::InformedRrtStar => "Informed RRT*",
            Self::FcitStar => "FCIT*",
        }
    }
}

impl fmt::Display for Configuration {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Configuration {
    type Err = BuildError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|c| c.name() == s)
            .ok_or_else(|| BuildError::UnknownConfiguration {
                name: s.to_string(),
                expected: "mit-star, eit-star, mit-star-as, mit-star-eis, mit-star-sc, mit-star-sr, \
                           rrt-connect, aorrtc, \
                           bit-star, abit-star, ait-star, informed-rrt-star, fcit-star",
            })
    }
}

/// Builds the planner of `configuration` for `problem` — a box-world [`mit_star_problems::Problem`], a
/// robot-arm problem, or any other [`PlanningProblem`] — with `parameters` (the problem's
/// resolution replaces `parameters.resolution`).
///
/// # Errors
/// [`BuildError::Problem`] if the problem refuses its check step, else as
/// [`Builder::build`](crate::Builder::build).
///
/// ```
/// use mit_star::{build_planner, Configuration, IterationLimit, Parameters};
/// let problem = mit_star_problems::ObstacleFree::new(3).build()?;
/// let mut planner = build_planner(Configuration::EitStar, &problem, &Parameters::default())?;
/// let outcome = planner.solve(&IterationLimit::new(50))?;
/// assert_eq!(planner.name(), "EIT*");
/// assert!((outcome.cost() - problem.straight_line_cost()).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn build_planner<P: PlanningProblem>(
    configuration: Configuration,
    problem: &P,
    parameters: &Parameters,
) -> Result<Box<dyn Planner + Send>, BuildError> {
    let mut planner = build_planner_with(
        configuration,
        problem,
        parameters,
        problem.validity().clone(),
    )?;
    if parameters.warm_start
        && configuration.is_asymptotically_optimal()
        && configuration != Configuration::Aorrtc
    {
        let front = build_planner_with(
            Configuration::RrtConnect,
            problem,
            parameters,
            problem.validity().clone(),
        )?;
        planner = Box::new(crate::WarmStarted::new(planner, front));
    }
    if !parameters.simplify_solutions {
        return Ok(planner);
    }
    let certification = parameters.for_problem(problem)?.certification.unwrap_or(1);
    Ok(Box::new(
        crate::Simplifying::new(
            planner,
            (problem.space().clone(), problem.validity().clone()),
            (problem.check_step()?, certification),
            crate::PathSimplifier::new()
                .seed(parameters.seed)
                .smoothing_rounds(if parameters.simplify_smoothing {
                    crate::PathSimplifier::DEFAULT_SMOOTHING_ROUNDS
                } else {
                    0
                }),
        )
        .polish_when_idle(parameters.polish_when_idle.then_some(parameters.seed)),
    ))
}

/// [`build_planner`] with another validity checker than the problem's own — a wrapper that
/// times or logs checks, or a different collision model over the problem's space, start, goals
/// and resolution.
///
/// # Errors
/// As [`build_planner`].
///
/// ```
/// use mit_star::{build_planner_with, Configuration, FirstSolution, Parameters};
/// use mit_star_validity::Counted;
/// let problem = mit_star_problems::DividingWalls::new(2).build()?.with_resolution(1e-4)?;
/// let counted = Counted::new(problem.world().clone());
/// let mut planner = build_planner_with(Configuration::MitStar, &problem, &Parameters::default(), counted)?;
/// assert!(planner.solve(&FirstSolution)?.is_solved());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn build_planner_with<P, V>(
    configuration: Configuration,
    problem: &P,
    parameters: &Parameters,
    validity: V,
) -> Result<Box<dyn Planner + Send>, BuildError>
where
    P: PlanningProblem,
    V: StateValidity + Send + 'static,
{
    let parameters = configuration.effective_parameters(problem, parameters)?;
    let space = problem.space().clone();
    let (start, goals) = (problem.start().to_vec(), problem.goals().to_vec());
    let label = configuration.label();
    let query = (space, validity, start, goals);
    Ok(match configuration {
        Configuration::MitStar => MitStar::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::EitStar => EitStar::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::MitStarAs => MitStarAs::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::MitStarEis => MitStarEis::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::MitStarSc => MitStarSc::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::MitStarSr => MitStarSr::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::BitStar => BitStar::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::AbitStar => BitStar::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::AitStar => AitStar::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::FcitStar => FcitStar::<P::Space, V>::boxed(query, parameters, label)?,
        Configuration::RrtConnect => {
            let (space, validity, start, goals) = query;
            let mut planner = RrtConnect::new(space, validity, (start, goals), parameters)?;
            planner.set_name(label);
            Box::new(planner)
        }
        Configuration::Aorrtc => {
            let (space, validity, start, goals) = query;
            let mut planner = Aorrtc::new(space, validity, (start, goals), parameters)?;
            planner.set_name(label);
            Box::new(planner)
        }
        Configuration::InformedRrtStar => {
            let (space, validity, start, goals) = query;
            let mut planner = InformedRrtStar::new(space, validity, (start, goals), parameters)?;
            planner.set_name(label);
            Box::new(planner)
        }
    })
}

/// What a planner of the EIT* family is built from: space, validity checker, start, goals.
type Parts<S, V> = (S, V, Vec<f64>, Vec<Vec<f64>>);

/// A planner type of the EIT* family (as its alias names it), built for `build_planner`.
trait FamilyMember<S, V> {
    /// The planner for `parts`, with its sampler in the [`NearTerminals`] wrapper when
    /// `parameters.near_terminals` is above 0.
    fn boxed(
        parts: Parts<S, V>,
        parameters: Parameters,
        label: &str,
    ) -> Result<Box<dyn Planner + Send>, BuildError>;
}

impl<S, V, Smp, E, H, G, N> FamilyMember<S, V> for Eit<S, V, Smp, E, H, G, N>
where
    S: StateSpace + Send + 'static,
    V: StateValidity + Send + 'static,
    Smp: Sampler<S, Counted<V>> + SamplerPart<S> + Clone + Send + 'static,
    E: EdgeChecker<S, Counted<V>> + CheckerPart<S> + Clone + Send + 'static,
    H: Heuristic<S> + Default + Send + 'static,
    G: Guidance + Send + 'static,
    N: NeighbourRule + Default + Send + 'static,
{
    fn boxed(
        parts: Parts<S, V>,
        parameters: Parameters,
        label: &str,
    ) -> Result<Box<dyn Planner + Send>, BuildError> {
        if parameters.near_terminals.unwrap_or(0.0) > 0.0 {
            built::<S, V, NearTerminals<Smp>, E, H, G, N>(parts, parameters, label)
        } else {
            built::<S, V, Smp, E, H, G, N>(parts, parameters, label)
        }
    }
}

/// `Eit` with exactly these parts, named `label`.
fn built<S, V, Smp, E, H, G, N>(
    (space, validity, start, goals): Parts<S, V>,
    parameters: Parameters,
    label: &str,
) -> Result<Box<dyn Planner + Send>, BuildError>
where
    S: StateSpace + Send + 'static,
    V: StateValidity + Send + 'static,
    Smp: Sampler<S, Counted<V>> + SamplerPart<S> + Clone + Send + 'static,
    E: EdgeChecker<S, Counted<V>> + CheckerPart<S> + Clone + Send + 'static,
    H: Heuristic<S> + Default + Send + 'static,
    G: Guidance + Send + 'static,
    N: NeighbourRule + Default + Send + 'static,
{
    Ok(Box::new(
        Eit::<S, V, Smp, E, H, G, N>::builder(space, validity, start, goals)
            .parameters(parameters)
            .name(label)
            .build()?,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{FirstSolution, IterationLimit, TerminationExt};

    fn near_terminal_draws(configuration: Configuration, parameters: &Parameters) -> u64 {
        let problem = mit_star_problems::DividingWalls::new(4).build().unwrap();
        let mut planner = build_planner(configuration, &problem, parameters).unwrap();
        assert_eq!(planner.name(), configuration.label());
        planner
            .solve(&FirstSolution.or(IterationLimit::new(2000)))
            .unwrap();
        planner.counters().sampler_near_terminals
    }

    #[test]
    fn samples_near_the_terminals_only_where_asked() {
        // Box worlds ask for none: the paper's sampling, no wrapper.
        let none = Parameters::default();
        let some = Parameters {
            near_terminals: Some(0.3),
            ..Parameters::default()
        };
        for configuration in [Configuration::MitStar, Configuration::BitStar] {
            assert_eq!(near_terminal_draws(configuration, &none), 0);
            assert!(near_terminal_draws(configuration, &some) > 0);
        }
        // RRT-Connect has no such sampler.
        assert_eq!(near_terminal_draws(Configuration::RrtConnect, &some), 0);
        // Out of range is a typed error naming the parameter.
        let bad = Parameters {
            near_terminals: Some(1.0),
            ..Parameters::default()
        };
        let problem = mit_star_problems::DividingWalls::new(2).build().unwrap();
        let error = build_planner(Configuration::MitStar, &problem, &bad)
            .err()
            .unwrap();
        assert!(error.to_string().contains("near_terminals"), "{error}");
    }
}
