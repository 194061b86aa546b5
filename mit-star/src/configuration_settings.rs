//! [`Configuration::reads`] and [`Configuration::settings`]: the parameters a configuration's
//! planner uses, as OMPL lists each planner's own properties in its benchmark logs.

use crate::{Configuration, Parameters};

/// Read by every planner [`build_planner`](crate::build_planner) builds: the check grid, the
/// seed, certification, the prepared edge checks and the simplification wrapper's switches.
const EVERY_PLANNER: &[&str] = &[
    "resolution",
    "seed",
    "certification",
    "accelerated_checks",
    "simplify_solutions",
    "simplify_smoothing",
    "polish_when_idle",
];

/// Read by every planner of the EIT* family (MIT*, EIT*, their ablations, BIT*, ABIT*, AIT*,
/// FCIT*): batches, pruning, samples near the terminals and the frontier, certification of
/// solutions, and the inflated and truncated searches.
const INFORMED_TREES: &[&str] = &[
    "batch_size",
    "batch_growth",
    "solution_samples",
    "solution_corner_pulls",
    "solution_corner_weights",
    "pruning",
    "lazy_certification",
    "near_terminals",
    "near_frontier",
    "frontier_rays",
    "start_frontier",
    "validated_frontier",
    "initial_inflation",
    "inflation_scaling",
    "truncation_scaling",
    "cascading_rewirings",
];

/// Read by the informed trees on a random geometric graph (all but FCIT*, whose graph is
/// fully connected): its connections.
const RANDOM_GEOMETRIC_GRAPH: &[&str] = &["rewire_factor", "connection", "neighbour_cap"];

/// Read by the informed trees with a reverse search (all but BIT* and ABIT*).
const REVERSE_SEARCH: &[&str] = &[
    "suspend_reverse_when_forward_empty",
    "repair_reverse_search",
];

/// Read by MIT*'s adaptive sampler (MIT* and MIT*-AS).
const ADAPTIVE_SAMPLER: &[&str] = &["gaussian_std_fraction", "bridge_checks"];

/// Read by the estimated informed set (MIT* and MIT*-EIS).
const ESTIMATED_SET: &[&str] = &[
    "eis_expansion_form",
    "eis_expansion_rule",
    "eis_batch_size",
    "eis_immediate_batch",
];

/// Read by the length-related sparse checks (MIT* and MIT*-SC).
const LENGTH_SPARSE_CHECKS: &[&str] =
    &["sparse_initial_steps", "sparse_factor", "sparse_min_steps"];

/// Read by RRT-Connect, and by AORRTC, whose first path is RRT-Connect's.
const RRT_CONNECT: &[&str] = &[
    "range",
    "rrt_valid_samples",
    "rrt_dynamic_domain",
    "rrt_forced_redraws",
    "rrt_balance",
    "rrt_halton",
    "rrt_halton_shift",
];

/// AORRTC's own.
const AORRTC: &[&str] = &["aorrtc_simplify", "aorrtc_resamples"];

/// Informed RRT*'s own.
const INFORMED_RRT_STAR: &[&str] = &["range", "goal_bias", "rrt_rewire_factor", "pruning"];

impl Configuration {
    /// The groups of parameter names the planner of this configuration reads.
    fn parameter_groups(self) -> Vec<&'static [&'static str]> {
        let mut groups = vec![EVERY_PLANNER];
        // `build_planner` warm-starts every asymptotically optimal planner but AORRTC.
        if self.is_asymptotically_optimal() && self != Self::Aorrtc {
            groups.push(&["warm_start"]);
        }
        match self {
            Self::RrtConnect => groups.push(RRT_CONNECT),
            Self::Aorrtc => groups.extend([RRT_CONNECT, AORRTC]),
            Self::InformedRrtStar => groups.push(INFORMED_RRT_STAR),
            Self::FcitStar => groups.push(INFORMED_TREES),
            _ => groups.extend([INFORMED_TREES, RANDOM_GEOMETRIC_GRAPH]),
        }
        if self.is_informed_tree() && !matches!(self, Self::BitStar | Self::AbitStar) {
            groups.push(REVERSE_SEARCH);
        }
        if matches!(self, Self::MitStar | Self::MitStarAs) {
            groups.push(ADAPTIVE_SAMPLER);
        }
        if matches!(self, Self::MitStar | Self::MitStarEis) {
            groups.push(ESTIMATED_SET);
        }
        if matches!(self, Self::MitStar | Self::MitStarSc) {
            groups.push(LENGTH_SPARSE_CHECKS);
        }
        groups
    }

    /// `true` if the planner of this configuration, as [`build_planner`](crate::build_planner)
    /// builds it (with its warm start and simplification when asked for), reads the parameter
    /// `name` (a name of [`Parameters::settings`]). RRT-Connect reads its range and its
    /// `rrt_*` switches but no batch size; MIT* reads the estimated informed set's parameters,
    /// EIT* does not.
    ///
    /// ```
    /// use mit_star::Configuration;
    /// assert!(Configuration::RrtConnect.reads("rrt_balance"));
    /// assert!(!Configuration::RrtConnect.reads("batch_size"));
    /// assert!(Configuration::MitStar.reads("eis_expansion_rule"));
    /// assert!(!Configuration::EitStar.reads("eis_expansion_rule"));
    /// assert!(Configuration::EitStar.reads("seed"));
    /// assert!(!Configuration::FcitStar.reads("rewire_factor"));
    /// ```
    pub fn reads(self, name: &str) -> bool {
        self.parameter_groups()
            .iter()
            .any(|group| group.contains(&name))
    }

    /// The parameters this configuration's planner reads, as `(name, value)` text pairs in the
    /// order of [`Parameters::settings`]: what a benchmark log lists as the planner's
    /// properties (OMPL lists each planner's own, not every planner's).
    ///
    /// ```
    /// use mit_star::{Configuration, Parameters};
    /// let rrt = Configuration::RrtConnect.settings(&Parameters::default());
    /// assert!(rrt.iter().any(|(k, _)| k == "range"));
    /// assert!(rrt.iter().all(|(k, _)| k != "batch_size"));
    /// ```
    pub fn settings(self, parameters: &Parameters) -> Vec<(String, String)> {
        parameters
            .settings()
            .into_iter()
            .filter(|(name, _)| self.reads(name))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every parameter's name.
    fn parameter_names() -> Vec<String> {
        Parameters::default()
            .settings()
            .into_iter()
            .map(|(k, _)| k)
            .collect()
    }

    #[test]
    fn every_name_is_a_parameter_and_every_parameter_is_read() {
        let names = parameter_names();
        for c in Configuration::ALL {
            for group in c.parameter_groups() {
                for name in group {
                    assert!(
                        names.iter().any(|n| n == name),
                        "{c}: {name} is no parameter"
                    );
                }
            }
        }
        // Each parameter is read by some configuration: a new one must be placed.
        for name in &names {
            assert!(
                Configuration::ALL.iter().any(|c| c.reads(name)),
                "{name} is read by no configuration"
            );
        }
    }

    #[test]
    fn planners_report_only_parameters_they_read() {
        let problem = mit_star_problems::ObstacleFree::new(2).build().unwrap();
        let names = parameter_names();
        for c in Configuration::ALL {
            let planner = crate::build_planner(c, &problem, &Parameters::default()).unwrap();
            let reported = planner.settings();
            for (key, _) in &reported {
                if names.contains(key) {
                    assert!(c.reads(key), "{c} reports {key}, which it does not read");
                }
            }
            // And the parameters that shape its search are there.
            let expected = match c {
                Configuration::RrtConnect => "rrt_dynamic_domain",
                Configuration::Aorrtc => "aorrtc_resamples",
                Configuration::InformedRrtStar => "goal_bias",
                _ => "batch_size",
            };
            assert!(
                reported.iter().any(|(k, _)| k == expected),
                "{c}: {expected}"
            );
        }
    }

    #[test]
    fn the_families_keep_to_their_own_parameters() {
        let rrt = Configuration::RrtConnect.settings(&Parameters::default());
        let has = |s: &[(String, String)], k: &str| s.iter().any(|(n, _)| n == k);
        assert!(has(&rrt, "rrt_dynamic_domain") && has(&rrt, "range"));
        for other in [
            "batch_size",
            "rewire_factor",
            "eis_expansion_form",
            "warm_start",
        ] {
            assert!(!has(&rrt, other), "{other}");
        }
        let mit = Configuration::MitStar.settings(&Parameters::default());
        for own in [
            "batch_size",
            "eis_batch_size",
            "sparse_factor",
            "bridge_checks",
        ] {
            assert!(has(&mit, own), "{own}");
        }
        assert!(!has(&mit, "range") && !has(&mit, "rrt_balance"));
        let bit = Configuration::BitStar.settings(&Parameters::default());
        assert!(!has(&bit, "repair_reverse_search") && has(&bit, "initial_inflation"));
        let aorrtc = Configuration::Aorrtc.settings(&Parameters::default());
        assert!(has(&aorrtc, "aorrtc_resamples") && has(&aorrtc, "rrt_balance"));
        assert!(!has(&aorrtc, "warm_start"));
        let rrt_star = Configuration::InformedRrtStar.settings(&Parameters::default());
        assert!(has(&rrt_star, "goal_bias") && !has(&rrt_star, "rrt_halton"));
    }
}
