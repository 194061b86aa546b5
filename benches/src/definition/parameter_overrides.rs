//! [`ParameterOverrides`]: changes to the planners' [`Parameters`], from experiment files
//! (`[parameters]` tables) and the command line (`--set key=value`).

use mit_star::Parameters;
use serde::{Deserialize, Serialize};

use crate::error::HarnessError;

/// Parameters the harness sets itself, which overrides may not touch.
const RESERVED: [(&str, &str); 2] = [
    (
        "seed",
        "is set by the harness (run i on instance k uses base seed + k·100000 + i); use `--seed` or the experiment's `seed`",
    ),
    (
        "resolution",
        "comes from the problem; use `--resolution` or the problem entry's `resolution`",
    ),
];

/// An ordered list of `key = value` changes to [`Parameters`]; later entries win.
///
/// Keys are the field names of [`Parameters`] (`batch_size`, `rewire_factor`, `connection`,
/// …). Values are TOML values; integers are accepted where a float is expected, and enum
/// values are their kebab-case names (`connection = "r-disc"`). Unknown keys and values of the
/// wrong type are refused with a message naming the key; values out of range are refused by
/// [`Parameters::validate`].
///
/// ```
/// use mit_star_benches::ParameterOverrides;
/// let mut o = ParameterOverrides::default();
/// o.push_assignment("batch_size=200")?;
/// o.push_assignment("connection=r-disc")?;
/// let p = o.apply(&mit_star::Parameters::default())?;
/// assert_eq!(p.batch_size, Some(200));
/// assert_eq!(p.connection, Some(mit_star::Connection::RDisc));
/// assert!(o.clone().with_assignment("batch_sise=3").is_err());
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct ParameterOverrides {
    entries: toml::Table,
}

impl ParameterOverrides {
    /// Overrides from a TOML table (an experiment file's `[parameters]`).
    ///
    /// # Errors
    /// [`HarnessError::Parameter`] for an unknown or reserved key or a value of the wrong type.
    pub fn from_table(table: toml::Table) -> Result<Self, HarnessError> {
        let mut overrides = Self::default();
        for (key, value) in table {
            overrides.push(key, value)?;
        }
        Ok(overrides)
    }

    /// Adds `key = value`, checking the key and the value's type.
    ///
    /// # Errors
    /// [`HarnessError::Parameter`] for an unknown or reserved key or a value of the wrong type.
    pub fn push(&mut self, key: String, value: toml::Value) -> Result<(), HarnessError> {
        let value = checked(&key, value)?;
        self.entries.insert(key, value);
        Ok(())
    }

    /// Adds a `key=value` assignment from the command line. The value is read as TOML
    /// (`200`, `0.5`, `true`, `"r-disc"`), or as a bare string when it is not TOML (`r-disc`).
    ///
    /// # Errors
    /// [`HarnessError::Parameter`] when there is no `=`, the key is unknown or reserved, or the
    /// value has the wrong type.
    pub fn push_assignment(&mut self, assignment: &str) -> Result<(), HarnessError> {
        let Some((key, value)) = assignment.split_once('=') else {
            return Err(HarnessError::Parameter {
                key: assignment.trim().to_owned(),
                message: "expected `key=value`".to_owned(),
            });
        };
        let (key, value) = (key.trim(), value.trim());
        let parsed = format!("v = {value}")
            .parse::<toml::Table>()
            .ok()
            .and_then(|mut t| t.remove("v"))
            .unwrap_or_else(|| toml::Value::String(value.to_owned()));
        self.push(key.to_owned(), parsed)
    }

    /// `self` with an assignment added (builder form of [`push_assignment`](Self::push_assignment)).
    ///
    /// # Errors
    /// As [`push_assignment`](Self::push_assignment).
    pub fn with_assignment(mut self, assignment: &str) -> Result<Self, HarnessError> {
        self.push_assignment(assignment)?;
        Ok(self)
    }

    /// `self` followed by `later` (whose entries win).
    pub fn then(&self, later: &Self) -> Self {
        let mut merged = self.clone();
        for (k, v) in &later.entries {
            merged.entries.insert(k.clone(), v.clone());
        }
        merged
    }

    /// `true` if there is nothing to change.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The overrides as `(key, value)` pairs, in key order.
    pub fn entries(&self) -> impl Iterator<Item = (&str, &toml::Value)> {
        self.entries.iter().map(|(k, v)| (k.as_str(), v))
    }

    /// `base` with the overrides applied, validated.
    ///
    /// # Errors
    /// [`HarnessError::Parameter`] naming the first parameter that is refused.
    pub fn apply(&self, base: &Parameters) -> Result<Parameters, HarnessError> {
        let mut table = defaults_table(base);
        for (key, value) in &self.entries {
            table.insert(key.clone(), value.clone());
        }
        let parameters: Parameters =
            table
                .try_into()
                .map_err(|e: toml::de::Error| HarnessError::Parameter {
                    key: self
                        .entries
                        .keys()
                        .next()
                        .cloned()
                        .unwrap_or_else(|| "?".into()),
                    message: e.message().trim().to_owned(),
                })?;
        parameters.validate().map_err(|e| match e {
            // The key is named once: `parameter `x`: is 0; it must be at least 1`.
            mit_star::BuildError::Parameter {
                name,
                value,
                requirement,
            } => HarnessError::Parameter {
                key: name.to_owned(),
                message: format!("is {}; {requirement}", mit_star_spaces::short_number(value)),
            },
            other => HarnessError::Parameter {
                key: "parameters".to_owned(),
                message: other.to_string(),
            },
        })?;
        Ok(parameters)
    }
}

/// What a parameter's default says its values are, in words.
fn kind(default: &toml::Value) -> &'static str {
    match default {
        toml::Value::Integer(_) => "a whole number, 0 or more",
        toml::Value::Float(_) => "a number",
        toml::Value::Boolean(_) => "`true` or `false`",
        toml::Value::String(_) => "a name",
        _ => "a value",
    }
}

/// A value as the user wrote it, short.
fn shown(value: &toml::Value) -> String {
    let text = match value {
        toml::Value::String(s) => format!("`{s}`"),
        toml::Value::Float(f) => mit_star_spaces::short_number(*f),
        other => other.to_string(),
    };
    if text.chars().count() > 40 {
        format!("{}…", text.chars().take(40).collect::<String>())
    } else {
        text
    }
}

/// The parameters as a TOML table (every field present).
fn defaults_table(parameters: &Parameters) -> toml::Table {
    toml::Table::try_from(parameters).unwrap_or_default()
}

/// Checks a key against [`Parameters`]' fields and the value against the default's type.
fn checked(key: &str, value: toml::Value) -> Result<toml::Value, HarnessError> {
    if let Some((_, why)) = RESERVED.iter().find(|(k, _)| *k == key) {
        return Err(HarnessError::Parameter {
            key: key.to_owned(),
            message: (*why).to_owned(),
        });
    }
    // Optional parameters (absent from the default table) are named with a sample value.
    let defaults = defaults_table(&Parameters {
        certification: Some(1),
        near_terminals: Some(0.0),
        suspend_reverse_when_forward_empty: Some(true),
        repair_reverse_search: Some(false),
        eis_batch_size: Some(100),
        sparse_initial_steps: Some(2000.0),
        sparse_min_steps: Some(10.0),
        range: Some(1.0),
        initial_inflation: Some(1.0),
        inflation_scaling: Some(0.0),
        truncation_scaling: Some(0.0),
        cascading_rewirings: Some(false),
        connection: Some(mit_star::Connection::KNearest),
        batch_size: Some(mit_star_problems::PAPER_BATCH_SIZE),
        batch_growth: Some(0.0),
        solution_samples: Some(0.0),
        neighbour_cap: Some(1.0),
        bridge_checks: Some(mit_star_problems::DEFAULT_BRIDGE_CHECKS),
        ..Parameters::default()
    });
    let Some(default) = defaults.get(key) else {
        let known: Vec<&str> = defaults
            .keys()
            .map(String::as_str)
            .filter(|k| !RESERVED.iter().any(|(r, _)| r == k))
            .collect();
        return Err(HarnessError::Parameter {
            key: key.to_owned(),
            message: format!("unknown parameter; valid parameters: {}", known.join(", ")),
        });
    };
    let value = match (default, value) {
        (toml::Value::Float(_), toml::Value::Integer(i)) => toml::Value::Float(i as f64),
        (_, value) => value,
    };
    if default.type_str() != value.type_str() {
        return Err(HarnessError::Parameter {
            key: key.to_owned(),
            message: format!(
                "expects {} (default {default}), got {}",
                kind(default),
                shown(&value)
            ),
        });
    }
    if let toml::Value::Integer(i) = value
        && i < 0
    {
        return Err(HarnessError::Parameter {
            key: key.to_owned(),
            message: format!("expects {} (default {default}), got {i}", kind(default)),
        });
    }
    if let (toml::Value::String(_), toml::Value::String(_)) = (default, &value) {
        // Enum values: check by deserialising the defaults with this one value changed.
        let mut table = defaults;
        table.insert(key.to_owned(), value.clone());
        if let Err(e) = table.try_into::<Parameters>() {
            return Err(HarnessError::Parameter {
                key: key.to_owned(),
                message: e.message().trim().to_owned(),
            });
        }
    }
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(result: Result<ParameterOverrides, HarnessError>) -> String {
        result.unwrap_err().to_string()
    }

    #[test]
    fn values_are_typed_and_coerced() {
        let o = ParameterOverrides::default()
            .with_assignment("rewire_factor=2")
            .unwrap()
            .with_assignment("pruning = false")
            .unwrap()
            .with_assignment("eis_expansion_form=\"authors\"")
            .unwrap();
        let p = o.apply(&Parameters::default()).unwrap();
        assert_eq!(p.rewire_factor, 2.0);
        assert!(!p.pruning);
        assert_eq!(p.eis_expansion_form, mit_star::EisExpansionForm::Authors);
        assert_eq!(o.entries().count(), 3);
    }

    /// Every parameter `mit-star planners` lists (the settings of the defaults) can be set,
    /// optional ones included: the sample values above must name each of them.
    #[test]
    fn every_listed_parameter_can_be_overridden() {
        let defaults = defaults_table(&Parameters::default());
        for (key, _) in Parameters::default().settings() {
            if RESERVED.iter().any(|(k, _)| *k == key) {
                continue;
            }
            let sample = checked(&key, toml::Value::Boolean(true));
            // A known key with a boolean of the wrong type is refused for its type, never as
            // unknown.
            if let Err(e) = sample {
                assert!(!e.to_string().contains("unknown parameter"), "{key}: {e}");
            }
            if let Some(default) = defaults.get(&key) {
                assert!(checked(&key, default.clone()).is_ok(), "{key}");
            }
        }
        let p = ParameterOverrides::default()
            .with_assignment("connection=k-nearest")
            .unwrap()
            .apply(&Parameters::default())
            .unwrap();
        assert_eq!(p.connection, Some(mit_star::Connection::KNearest));
    }

    #[test]
    fn bad_overrides_name_the_key() {
        let o = ParameterOverrides::default();
        let m = message(o.clone().with_assignment("batch_sise=3"));
        assert!(
            m.starts_with(
                "parameter `batch_sise`: unknown parameter; valid parameters: accelerated_checks, aorrtc_resamples, aorrtc_simplify, batch_growth, batch_size"
            ),
            "{m}"
        );
        assert!(!m.contains("seed,"), "{m}");
        let m = message(o.clone().with_assignment("batch_size=many"));
        assert!(
            m.contains("`batch_size`: expects a whole number, 0 or more (default 100), got `many`"),
            "{m}"
        );
        for bad in ["-1", "18446744073709551616", "1e308", "nan"] {
            let m = message(o.clone().with_assignment(&format!("batch_size={bad}")));
            assert!(m.contains("expects a whole number"), "{bad}: {m}");
            assert!(!m.contains("usize") && m.len() < 120, "{bad}: {m}");
        }
        let m = message(o.clone().with_assignment("connection=r-disk"));
        assert!(m.contains("`connection`") && m.contains("r-disk"), "{m}");
        let m = message(o.clone().with_assignment("seed=3"));
        assert!(m.contains("set by the harness"), "{m}");
        let m = message(o.clone().with_assignment("batch_size"));
        assert!(m.contains("expected `key=value`"), "{m}");
        // Range errors come from Parameters::validate, naming the parameter.
        let zero = o.clone().with_assignment("batch_size=0").unwrap();
        let m = zero.apply(&Parameters::default()).unwrap_err().to_string();
        assert_eq!(m, "parameter `batch_size`: is 0; it must be at least 1");
        let twice = o.with_assignment("batch_growth=2").unwrap();
        let m = twice.apply(&Parameters::default()).unwrap_err().to_string();
        assert_eq!(
            m,
            "parameter `batch_growth`: is 2; it must lie in [0, 1] (a fraction of the graph's vertices)"
        );
    }

    #[test]
    fn optional_parameters_can_be_set() {
        let p = ParameterOverrides::default()
            .with_assignment("range=0.5")
            .unwrap()
            .with_assignment("certification=4")
            .unwrap()
            .apply(&Parameters::default())
            .unwrap();
        assert_eq!((p.range, p.certification), (Some(0.5), Some(4)));
        // Unset, they stay absent: the planner's or the problem's default applies.
        let p = ParameterOverrides::default()
            .apply(&Parameters::default())
            .unwrap();
        assert_eq!((p.range, p.certification), (None, None));
        for (assignment, key) in [("range=-1", "range"), ("certification=0", "certification")] {
            let o = ParameterOverrides::default()
                .with_assignment(assignment)
                .unwrap();
            let m = o.apply(&Parameters::default()).unwrap_err().to_string();
            assert!(m.contains(key), "{m}");
        }
    }

    #[test]
    fn later_overrides_win() {
        let a = ParameterOverrides::default()
            .with_assignment("batch_size=10")
            .unwrap();
        let b = ParameterOverrides::default()
            .with_assignment("batch_size=20")
            .unwrap();
        let p = a.then(&b).apply(&Parameters::default()).unwrap();
        assert_eq!(p.batch_size, Some(20));
        assert!(ParameterOverrides::default().is_empty());
        let t: toml::Table = "batch_size = 7".parse().unwrap();
        let c = ParameterOverrides::from_table(t).unwrap();
        assert_eq!(c.apply(&Parameters::default()).unwrap().batch_size, Some(7));
    }
}
