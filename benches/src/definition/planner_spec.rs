//! [`PlannerSpec`]: one planner of an experiment.

use mit_star::{Configuration, Parameters};

use crate::definition::parameter_overrides::ParameterOverrides;
use crate::error::HarnessError;

/// The valid configuration names, comma separated.
pub(crate) fn configuration_names() -> String {
    Configuration::ALL
        .iter()
        .map(|c| c.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Parses a configuration name (`mit-star`, `eit-star`, `mit-star-as`, `mit-star-eis`,
/// `mit-star-sc`).
///
/// # Errors
/// [`HarnessError::UnknownPlanner`], listing the valid names.
///
/// ```
/// use mit_star_benches::parse_configuration;
/// assert_eq!(parse_configuration("eit-star")?, mit_star::Configuration::EitStar);
/// let e = parse_configuration("rrt-star").unwrap_err().to_string();
/// assert!(e.contains("valid planners: mit-star, eit-star"));
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
pub fn parse_configuration(name: &str) -> Result<Configuration, HarnessError> {
    name.trim()
        .parse()
        .map_err(|_| HarnessError::UnknownPlanner {
            name: name.trim().to_owned(),
            known: configuration_names(),
        })
}

/// One planner of an experiment: a [`Configuration`], the name reports print, and its
/// parameters (the defaults with the experiment's overrides applied, validated once).
///
/// ```
/// use mit_star_benches::{ParameterOverrides, PlannerSpec};
/// let overrides = ParameterOverrides::default().with_assignment("batch_size=50")?;
/// let spec = PlannerSpec::new(mit_star::Configuration::MitStar, None, &overrides)?;
/// assert_eq!(spec.name(), "MIT*");
/// assert_eq!(spec.parameters_for_seed(7).seed, 7);
/// assert_eq!(spec.parameters_for_seed(7).batch_size, Some(50));
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PlannerSpec {
    name: String,
    configuration: Configuration,
    overrides: ParameterOverrides,
    parameters: Parameters,
}

impl PlannerSpec {
    /// A planner of `configuration`, named `name` (default: the paper's label, e.g. `MIT*`),
    /// with `overrides` applied to the default parameters.
    ///
    /// # Errors
    /// [`HarnessError::Parameter`] if an override is refused, [`HarnessError::Usage`] for an
    /// empty name or one with a line break.
    pub fn new(
        configuration: Configuration,
        name: Option<String>,
        overrides: &ParameterOverrides,
    ) -> Result<Self, HarnessError> {
        let name = name.unwrap_or_else(|| configuration.label().to_owned());
        if name.trim().is_empty() || name.contains(['\n', '\r']) {
            return Err(HarnessError::Usage(format!(
                "planner name {name:?} must be non-empty and on one line"
            )));
        }
        let parameters = overrides.apply(&Parameters::default())?;
        Ok(Self {
            name,
            configuration,
            overrides: overrides.clone(),
            parameters,
        })
    }

    /// The name reports print.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The configuration.
    pub fn configuration(&self) -> Configuration {
        self.configuration
    }

    /// The overrides applied to the defaults.
    pub fn overrides(&self) -> &ParameterOverrides {
        &self.overrides
    }

    /// Refuses an override of a parameter this planner does not read (`range` for MIT*,
    /// `batch_size` for RRT-Connect: [`Configuration::reads`]), naming the planners that read
    /// it. Where one planner runs (`plan`, Python's `Planner`) such an override changes
    /// nothing and is a mistake; an experiment's `--set` applies to all its planners, each
    /// reading what it uses, and is not checked this way.
    ///
    /// # Errors
    /// [`HarnessError::Usage`] naming the first such parameter.
    pub fn refuse_unread(&self) -> Result<(), HarnessError> {
        let Some((key, _)) = self
            .overrides
            .entries()
            .find(|(key, _)| !self.configuration.reads(key))
        else {
            return Ok(());
        };
        let readers: Vec<&str> = Configuration::ALL
            .into_iter()
            .filter(|c| c.reads(key))
            .map(Configuration::label)
            .collect();
        Err(HarnessError::Usage(format!(
            "{} does not read the parameter `{key}`, so setting it would change nothing{}",
            self.configuration.label(),
            if readers.is_empty() {
                String::new()
            } else {
                format!(" (it is read by {})", readers.join(", "))
            }
        )))
    }

    /// The parameters with the seed of one run (the problem sets the resolution when the
    /// planner is built).
    pub fn parameters_for_seed(&self, seed: u64) -> Parameters {
        Parameters {
            seed,
            ..self.parameters.clone()
        }
    }
}
