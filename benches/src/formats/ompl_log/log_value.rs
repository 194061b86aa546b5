//! The pieces of an OMPL benchmark log: [`PropertyType`], [`LogValue`], [`Property`],
//! [`ExperimentProperty`] and [`EnumType`].

/// The type word of a property in an OMPL log (also its SQL column type).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PropertyType {
    /// `BOOLEAN`: 0 or 1.
    Boolean,
    /// `INTEGER`.
    Integer,
    /// `REAL`.
    Real,
    /// `ENUM`: an index into an enum type's values.
    Enum,
    /// `STRING`.
    String,
}

impl PropertyType {
    /// The type word.
    pub fn word(self) -> &'static str {
        match self {
            Self::Boolean => "BOOLEAN",
            Self::Integer => "INTEGER",
            Self::Real => "REAL",
            Self::Enum => "ENUM",
            Self::String => "STRING",
        }
    }

    /// The type of a type word.
    pub fn from_word(word: &str) -> Option<Self> {
        Some(match word {
            "BOOLEAN" => Self::Boolean,
            "INTEGER" => Self::Integer,
            "REAL" => Self::Real,
            "ENUM" => Self::Enum,
            "STRING" => Self::String,
            _ => return None,
        })
    }
}

/// A value in an OMPL log. Booleans and enums are integers; `∞` and NaN are written as empty
/// fields and read back as [`Null`](Self::Null), as OMPL's reader stores them.
#[derive(Debug, Clone, PartialEq)]
pub enum LogValue {
    /// No value (SQL `NULL`).
    Null,
    /// An integer (also booleans and enum indices).
    Integer(i64),
    /// A finite real.
    Real(f64),
    /// Text without separators.
    Text(String),
}

impl LogValue {
    /// A real, `Null` unless finite.
    pub fn real(value: f64) -> Self {
        if value.is_finite() {
            Self::Real(value)
        } else {
            Self::Null
        }
    }

    /// A real from an optional value.
    pub fn real_or_null(value: Option<f64>) -> Self {
        value.map_or(Self::Null, Self::real)
    }

    /// A boolean as 0 or 1.
    pub fn boolean(value: bool) -> Self {
        Self::Integer(i64::from(value))
    }

    /// An unsigned count (saturating at `i64::MAX`).
    pub fn count(value: u64) -> Self {
        Self::Integer(i64::try_from(value).unwrap_or(i64::MAX))
    }

    /// The value as log text (empty for `Null`; reals in shortest round-trip form).
    pub fn to_log_text(&self) -> String {
        match self {
            Self::Null => String::new(),
            Self::Integer(i) => i.to_string(),
            Self::Real(r) => r.to_string(),
            Self::Text(t) => t.clone(),
        }
    }
}

/// A named, typed property (a run property or a progress property).
#[derive(Debug, Clone, PartialEq)]
pub struct Property {
    /// The name; may contain spaces (`initial solution time`), which SQL columns replace by `_`.
    pub name: String,
    /// The type.
    pub kind: PropertyType,
}

impl Property {
    /// A property.
    pub fn new(name: &str, kind: PropertyType) -> Self {
        Self {
            name: name.to_owned(),
            kind,
        }
    }

    /// The SQL column name OMPL's reader derives: whitespace-separated words joined by `_`.
    pub fn column(&self) -> String {
        self.name.split_whitespace().collect::<Vec<_>>().join("_")
    }
}

/// An experiment property: a numeric parameter of the problem instance (Planner Arena offers
/// a selector for each).
#[derive(Debug, Clone, PartialEq)]
pub struct ExperimentProperty {
    /// One word.
    pub name: String,
    /// Its type.
    pub kind: PropertyType,
    /// Its value.
    pub value: LogValue,
}

/// An enum type: its name and its values' descriptions, in value order.
#[derive(Debug, Clone, PartialEq)]
pub struct EnumType {
    /// The name (`status`).
    pub name: String,
    /// The descriptions of values 0, 1, ….
    pub values: Vec<String>,
}
