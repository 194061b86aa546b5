//! [`SamplerPart`] and [`CheckerPart`]: how the builder makes a configuration's parts from
//! [`Parameters`].

use mit_star_samplers::{
    AdaptiveSampler, BridgeSampler, Estimated, GaussianSampler, InformedSampler, NearTerminals,
    UniformSampler,
};
use mit_star_spaces::StateSpace;
use mit_star_validity::{
    DenseChecker, FixedSparseChecker, LengthAdaptiveChecker, step_from_resolution,
};

use crate::{BuildError, Parameters};

/// A sampler the [`Builder`](crate::Builder) can make from [`Parameters`] and the query.
///
/// Implemented for every sampler of the `samplers` crate; implement it for your own sampler to
/// use it with the builder (or pass a ready sampler to [`Eit::with_parts`](crate::Eit::with_parts)).
pub trait SamplerPart<S: StateSpace>: Sized {
    /// Short name used in planner names (`"informed"`, `"estimated(adaptive)"`, …).
    fn part_name() -> String;

    /// Builds the sampler for `start` and `goals` in `space`, seeded with `parameters.seed`.
    ///
    /// # Errors
    /// [`BuildError::Sampler`] if the sampler refuses the query or a parameter.
    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        parameters: &Parameters,
    ) -> Result<Self, BuildError>;
}

/// An edge checker the [`Builder`](crate::Builder) can make from [`Parameters`].
pub trait CheckerPart<S: StateSpace>: Sized {
    /// Short name used in planner names (`"fixed-sparse"`, `"length-adaptive"`, …).
    const NAME: &'static str;

    /// Builds the checker for `space` at `parameters.resolution`.
    ///
    /// # Errors
    /// [`BuildError::Validity`] if the checker refuses a parameter.
    fn build_part(space: &S, parameters: &Parameters) -> Result<Self, BuildError>;
}

impl<S: StateSpace> SamplerPart<S> for UniformSampler {
    fn part_name() -> String {
        "uniform".into()
    }
    fn build_part(_: &S, _: &[f64], _: &[Vec<f64>], p: &Parameters) -> Result<Self, BuildError> {
        Ok(UniformSampler::new(p.seed))
    }
}

impl<S: StateSpace> SamplerPart<S> for InformedSampler {
    fn part_name() -> String {
        "informed".into()
    }
    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        p: &Parameters,
    ) -> Result<Self, BuildError> {
        Ok(InformedSampler::new(space, start, goals, p.seed)?)
    }
}

impl<S: StateSpace> SamplerPart<S> for AdaptiveSampler {
    fn part_name() -> String {
        "adaptive".into()
    }
    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        p: &Parameters,
    ) -> Result<Self, BuildError> {
        Ok(AdaptiveSampler::new(space, start, goals, p.seed)?
            .with_std_dev(p.gaussian_std_fraction * space.maximum_extent())?
            .with_bridge_checks(
                p.bridge_checks
                    .unwrap_or(mit_star_problems::DEFAULT_BRIDGE_CHECKS),
            )?)
    }
}

// A planner built without a problem repairs as the sampler does on its own.
const _: () =
    assert!(AdaptiveSampler::DEFAULT_BRIDGE_CHECKS == mit_star_problems::DEFAULT_BRIDGE_CHECKS);

impl<S: StateSpace> SamplerPart<S> for GaussianSampler {
    fn part_name() -> String {
        "gaussian".into()
    }
    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        p: &Parameters,
    ) -> Result<Self, BuildError> {
        Ok(GaussianSampler::new(space, start, goals, p.seed)?
            .with_std_dev(p.gaussian_std_fraction * space.maximum_extent())?)
    }
}

impl<S: StateSpace> SamplerPart<S> for BridgeSampler {
    fn part_name() -> String {
        "bridge".into()
    }
    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        p: &Parameters,
    ) -> Result<Self, BuildError> {
        Ok(BridgeSampler::new(space, start, goals, p.seed)?
            .with_std_dev(p.gaussian_std_fraction * space.maximum_extent())?)
    }
}

/// MIT*'s estimated informed set around any sampler the builder can make.
impl<S: StateSpace, T: SamplerPart<S>> SamplerPart<S> for Estimated<T> {
    fn part_name() -> String {
        format!("estimated({})", T::part_name())
    }
    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        p: &Parameters,
    ) -> Result<Self, BuildError> {
        Ok(Estimated::new(T::build_part(space, start, goals, p)?)
            .with_form(p.eis_expansion_form)
            .with_rule(p.eis_expansion_rule)
            .with_immediate_batch(p.eis_immediate_batch))
    }
}

/// States near the start and the goals around any sampler the builder can make, at the
/// fraction `parameters.near_terminals` (`None`: the default,
/// [`NearTerminals::DEFAULT_FRACTION`]).
impl<S: StateSpace, T: SamplerPart<S>> SamplerPart<S> for NearTerminals<T> {
    fn part_name() -> String {
        format!("near-terminals({})", T::part_name())
    }
    fn build_part(
        space: &S,
        start: &[f64],
        goals: &[Vec<f64>],
        p: &Parameters,
    ) -> Result<Self, BuildError> {
        let inner = T::build_part(space, start, goals, p)?;
        let fraction = p
            .near_terminals
            .unwrap_or(NearTerminals::<T>::DEFAULT_FRACTION);
        Ok(NearTerminals::new(inner, space, start, goals, p.seed)?
            .with_fraction(fraction)?
            .with_frontier_rays(p.frontier_rays))
    }
}

impl<S: StateSpace> CheckerPart<S> for FixedSparseChecker {
    const NAME: &'static str = "fixed-sparse";
    fn build_part(space: &S, p: &Parameters) -> Result<Self, BuildError> {
        Ok(FixedSparseChecker::from_resolution(space, p.resolution)?
            .with_acceleration(p.accelerated_checks))
    }
}

impl<S: StateSpace> CheckerPart<S> for LengthAdaptiveChecker {
    const NAME: &'static str = "length-adaptive";
    fn build_part(space: &S, p: &Parameters) -> Result<Self, BuildError> {
        let step = step_from_resolution(space, p.resolution)?;
        Ok(LengthAdaptiveChecker::with_parameters(
            step,
            p.sparse_initial_steps
                .unwrap_or(mit_star_problems::PAPER_SPARSE_SPACING.0)
                * step,
            p.sparse_factor,
            p.sparse_min_steps
                .unwrap_or(mit_star_problems::PAPER_SPARSE_SPACING.1)
                * step,
        )?
        .with_acceleration(p.accelerated_checks))
    }
}

impl<S: StateSpace> CheckerPart<S> for DenseChecker {
    const NAME: &'static str = "dense";
    fn build_part(space: &S, p: &Parameters) -> Result<Self, BuildError> {
        Ok(DenseChecker::from_resolution(space, p.resolution)?
            .with_acceleration(p.accelerated_checks))
    }
}

/// The paper's name of the configuration made of these parts, or a descriptive one.
pub(crate) fn configuration_name(guidance: &str, sampler: &str, checker: &str) -> String {
    match (guidance, sampler, checker) {
        ("effort-informed+suspending", "estimated(adaptive)", "length-adaptive") => "MIT*".into(),
        ("effort-informed+suspending", "informed", "fixed-sparse") => "MIT*-SR".into(),
        ("effort-informed", "informed", "fixed-sparse") => "EIT*".into(),
        ("effort-informed", "adaptive", "fixed-sparse") => "MIT*-AS".into(),
        ("effort-informed", "estimated(informed)", "fixed-sparse") => "MIT*-EIS".into(),
        ("effort-informed", "informed", "length-adaptive") => "MIT*-SC".into(),
        ("effort-informed", s, c) => format!("EIT*[{s} sampler, {c} checks]"),
        ("cost-informed", "informed", "dense") => "AIT*".into(),
        ("cost-informed", s, c) => format!("AIT*[{s} sampler, {c} checks]"),
        ("a-priori", "informed", "dense") => "BIT*".into(),
        ("a-priori", s, c) => format!("BIT*[{s} sampler, {c} checks]"),
        ("effort-informed+suspending", s, c) => {
            format!("EIT*[suspending, {s} sampler, {c} checks]")
        }
        (g, s, c) => format!("Eit[{g} guidance, {s} sampler, {c} checks]"),
    }
}

/// [`configuration_name`] on a graph whose neighbours the rule named `neighbours` decides
/// ([`NeighbourRule::part_name`](crate::NeighbourRule::part_name); empty for the random
/// geometric graph, whose names these are): FCIT*'s parts are `FCIT*`, others the name of
/// their random-geometric counterpart with the rule in brackets.
pub(crate) fn graph_configuration_name(
    guidance: &str,
    sampler: &str,
    checker: &str,
    neighbours: &str,
) -> String {
    match (guidance, sampler, checker, neighbours) {
        (g, s, c, "") => configuration_name(g, s, c),
        ("a-priori", "informed", "dense", "fully connected") => "FCIT*".into(),
        (g, s, c, n) => format!("{}[{n}]", configuration_name(g, s, c)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mit_star_spaces::RealVectorSpace;

    #[test]
    fn parts_follow_the_parameters() {
        let space = RealVectorSpace::cube(4, -0.5, 0.5).unwrap();
        let p = Parameters::default();
        let checker = <LengthAdaptiveChecker as CheckerPart<_>>::build_part(&space, &p).unwrap();
        // Δ₀ = 2000 L with L = 5e-6 · 2.
        assert!((checker.spacing() - 2000.0 * 1e-5).abs() < 1e-12);
        let sampler = <AdaptiveSampler as SamplerPart<_>>::build_part(
            &space,
            &[-0.45, 0.0, 0.0, 0.0],
            &[vec![0.45, 0.0, 0.0, 0.0]],
            &p,
        )
        .unwrap();
        assert!((sampler.std_dev() - 0.2).abs() < 1e-12);
        assert_eq!(sampler.bridge_checks(), 8);
        let bad = Parameters {
            sparse_factor: 1.5,
            ..Parameters::default()
        };
        assert!(matches!(
            <LengthAdaptiveChecker as CheckerPart<_>>::build_part(&space, &bad),
            Err(BuildError::Validity(_))
        ));
        assert_eq!(
            configuration_name("effort-informed", "informed", "fixed-sparse"),
            "EIT*"
        );
        assert_eq!(
            configuration_name("cost-informed", "informed", "dense"),
            "AIT*"
        );
        assert_eq!(configuration_name("a-priori", "informed", "dense"), "BIT*");
        assert_eq!(
            graph_configuration_name("a-priori", "informed", "dense", ""),
            "BIT*"
        );
        assert_eq!(
            graph_configuration_name("a-priori", "informed", "dense", "fully connected"),
            "FCIT*"
        );
        assert_eq!(
            graph_configuration_name("cost-informed", "informed", "dense", "fully connected"),
            "AIT*[fully connected]"
        );
        type Mit = Estimated<AdaptiveSampler>;
        assert_eq!(
            configuration_name(
                "effort-informed+suspending",
                &<Mit as SamplerPart<RealVectorSpace>>::part_name(),
                "length-adaptive"
            ),
            "MIT*"
        );
        assert_eq!(
            configuration_name(
                "effort-informed",
                &<Mit as SamplerPart<RealVectorSpace>>::part_name(),
                "length-adaptive"
            ),
            "EIT*[estimated(adaptive) sampler, length-adaptive checks]"
        );
        assert_eq!(
            configuration_name("effort-informed+suspending", "informed", "fixed-sparse"),
            "MIT*-SR"
        );
        assert_eq!(
            configuration_name("effort-informed", "gaussian", "dense"),
            "EIT*[gaussian sampler, dense checks]"
        );
    }
}
