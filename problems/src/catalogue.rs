//! The catalogue of built-in problem families: [`catalogue`], [`builtin`], [`Family`] and
//! [`Parameter`].

use std::fmt::Display;

use mit_star_spaces::MemoryBudget;

use crate::{
    CenterSquare, DividingWalls, DoubleEnclosure, FlankingGap, GoalEnclosure, NarrowPassage,
    ObstacleFree, Problem, ProblemError, RandomRectangles, RepeatingRectangles, StartEnclosure,
    WallGap,
};

/// One parameter of a problem family and its value, for listings.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Parameter {
    /// The parameter's name (its setter's name).
    pub name: &'static str,
    /// Its value, formatted (`0.1`, `(-0.2, 0)`, `35`, …).
    pub value: String,
    /// What it is.
    pub meaning: &'static str,
}

impl Parameter {
    /// A real-valued parameter.
    pub(crate) fn number(name: &'static str, value: f64, meaning: &'static str) -> Self {
        Self {
            name,
            value: value.to_string(),
            meaning,
        }
    }

    /// An integer parameter (a count or a seed).
    pub(crate) fn integer(name: &'static str, value: impl Display, meaning: &'static str) -> Self {
        Self {
            name,
            value: value.to_string(),
            meaning,
        }
    }

    /// A point: `(-0.2, 0, 0)`.
    pub(crate) fn point(name: &'static str, point: &[f64], meaning: &'static str) -> Self {
        let coordinates: Vec<String> = point.iter().map(f64::to_string).collect();
        Self {
            name,
            value: format!("({})", coordinates.join(", ")),
            meaning,
        }
    }

    /// A list of pairs: `(-0.25, 0.05), (0, 0.1)`.
    pub(crate) fn pairs(name: &'static str, pairs: &[(f64, f64)], meaning: &'static str) -> Self {
        let pairs: Vec<String> = pairs.iter().map(|(a, b)| format!("({a}, {b})")).collect();
        Self {
            name,
            value: pairs.join(", "),
            meaning,
        }
    }
}

/// A built-in problem family: its name, a one-line description, and how to build it with its
/// defaults.
#[derive(Debug, Clone, Copy)]
pub struct Family {
    name: &'static str,
    description: &'static str,
    seeded: bool,
    build: fn(usize, u64) -> Result<Problem, ProblemError>,
    parameters: fn(usize) -> Vec<Parameter>,
}

impl Family {
    /// The family's name, as [`builtin`] takes it (`flanking-gap`, …).
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// A one-line description.
    pub fn description(&self) -> &'static str {
        self.description
    }

    /// `true` if the layout depends on the seed (random rectangles); the others ignore it.
    pub fn is_seeded(&self) -> bool {
        self.seeded
    }

    /// Builds the family's problem with its defaults in `n` dimensions.
    ///
    /// # Errors
    /// As the family's `build`: [`ProblemError::Dimension`] if `n < 2`;
    /// [`ProblemError::TooLarge`] if the problem could not fit in this machine's memory (no
    /// family holds more than `4n` boxes of `n` dimensions, so `n²` sets the size: `R^100000`
    /// would need over a terabyte; the bound allows `4·max(n, 64)` boxes).
    pub fn build(&self, n: usize, seed: u64) -> Result<Problem, ProblemError> {
        let bytes = Self::estimated_bytes(n);
        if let Err(budget) = MemoryBudget::check_on_machine(bytes) {
            return Err(ProblemError::TooLarge {
                what: format!("{} in {n} dimensions", self.name),
                needed: bytes.map_or_else(|| "more than 16 EiB".to_owned(), MemoryBudget::describe),
                available: MemoryBudget::describe(budget.bytes()),
            });
        }
        (self.build)(n, seed)
    }

    /// A generous upper bound on the memory a built-in problem takes in `n` dimensions (at most
    /// `4n` boxes, each stored three times as `n` centres, `n` widths and `2n` bounds), `None`
    /// if it overflows.
    pub fn estimated_bytes(n: usize) -> Option<u64> {
        let n = n as u64;
        MemoryBudget::bytes_for(&[4, n.max(64), n, 4 * 8])
    }

    /// The family's parameters with their defaults in `n` dimensions (some defaults depend on
    /// `n`).
    pub fn parameters(&self, n: usize) -> Vec<Parameter> {
        (self.parameters)(n)
    }
}

/// The built-in families, in a fixed order.
static FAMILIES: [Family; 12] = [
    Family {
        name: FlankingGap::NAME,
        description: "a wall short of the bounds with a small square hole; through the hole \
                      beats going around",
        seeded: false,
        build: |n, _| FlankingGap::new(n).build(),
        parameters: |n| FlankingGap::new(n).parameters(),
    },
    Family {
        name: DividingWalls::NAME,
        description: "three walls spanning the bounds, crossed only through six slots",
        seeded: false,
        build: |n, _| DividingWalls::new(n).build(),
        parameters: |n| DividingWalls::new(n).parameters(),
    },
    Family {
        name: GoalEnclosure::NAME,
        description: "the goal inside a hollow cube that opens away from the start",
        seeded: false,
        build: |n, _| GoalEnclosure::new(n).build(),
        parameters: |n| GoalEnclosure::new(n).parameters(),
    },
    Family {
        name: RandomRectangles::NAME,
        description: "35 random boxes, the layout fixed by the seed",
        seeded: true,
        build: |n, seed| RandomRectangles::new(n).seed(seed).build(),
        parameters: |n| RandomRectangles::new(n).parameters(),
    },
    Family {
        name: RandomRectangles::CLUTTERED,
        description: "random rectangles with teeth: more and larger boxes, calibrated per \
                      dimension so that the straight line is blocked",
        seeded: true,
        build: |n, seed| RandomRectangles::cluttered(n).seed(seed).build(),
        parameters: |n| RandomRectangles::cluttered(n).parameters(),
    },
    Family {
        name: ObstacleFree::NAME,
        description: "the empty unit cube",
        seeded: false,
        build: |n, _| ObstacleFree::new(n).build(),
        parameters: |n| ObstacleFree::new(n).parameters(),
    },
    Family {
        name: CenterSquare::NAME,
        description: "one cube between start and goal",
        seeded: false,
        build: |n, _| CenterSquare::new(n).build(),
        parameters: |n| CenterSquare::new(n).parameters(),
    },
    Family {
        name: WallGap::NAME,
        description: "a wall with a slot, and a corridor past the wall's end",
        seeded: false,
        build: |n, _| WallGap::new(n).build(),
        parameters: |n| WallGap::new(n).parameters(),
    },
    Family {
        name: NarrowPassage::NAME,
        description: "a wall spanning the bounds with one slot",
        seeded: false,
        build: |n, _| NarrowPassage::new(n).build(),
        parameters: |n| NarrowPassage::new(n).parameters(),
    },
    Family {
        name: StartEnclosure::NAME,
        description: "the start inside a hollow cube that opens away from the goal",
        seeded: false,
        build: |n, _| StartEnclosure::new(n).build(),
        parameters: |n| StartEnclosure::new(n).parameters(),
    },
    Family {
        name: DoubleEnclosure::NAME,
        description: "start and goal each inside a hollow cube opening away from the other",
        seeded: false,
        build: |n, _| DoubleEnclosure::new(n).build(),
        parameters: |n| DoubleEnclosure::new(n).parameters(),
    },
    Family {
        name: RepeatingRectangles::NAME,
        description: "a regular lattice of 49^n small cubes",
        seeded: false,
        build: |n, _| RepeatingRectangles::new(n).build(),
        parameters: |n| RepeatingRectangles::new(n).parameters(),
    },
];

/// Every built-in problem family, in a fixed order (PDT's four benchmark problems first).
///
/// ```
/// for family in mit_star_problems::catalogue() {
///     let problem = family.build(2, 0)?;
///     assert!(problem.validate().is_ok(), "{}", family.name());
/// }
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
pub fn catalogue() -> &'static [Family] {
    &FAMILIES
}

/// The built-in problem `name` in `n` dimensions with its defaults; `seed` fixes the layout of
/// seeded families (random rectangles) and is ignored by the others.
///
/// # Errors
/// [`ProblemError::UnknownProblem`] for a name not in the [`catalogue`] (the message lists the
/// known names); otherwise as the family's `build` ([`ProblemError::Dimension`] if `n < 2`).
///
/// ```
/// let problem = mit_star_problems::builtin("dividing-walls", 4, 0)?;
/// assert_eq!(problem.dimension(), 4);
/// assert!(mit_star_problems::builtin("dividing-wall", 4, 0).is_err());
/// # Ok::<(), mit_star_problems::ProblemError>(())
/// ```
pub fn builtin(name: &str, n: usize, seed: u64) -> Result<Problem, ProblemError> {
    match FAMILIES.iter().find(|family| family.name == name) {
        Some(family) => family.build(n, seed),
        None => Err(ProblemError::UnknownProblem {
            name: name.to_owned(),
            known: FAMILIES
                .iter()
                .map(|family| family.name)
                .collect::<Vec<_>>()
                .join(", "),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dimensions_beyond_the_machine_are_refused_before_building() {
        let err = builtin("goal-enclosure", 100_000, 0).unwrap_err();
        assert!(matches!(err, ProblemError::TooLarge { .. }), "{err:?}");
        let text = err.to_string();
        assert!(
            text.contains("goal-enclosure in 100000 dimensions"),
            "{text}"
        );
        assert!(builtin("goal-enclosure", usize::MAX, 0).is_err());
        assert!(builtin("goal-enclosure", 64, 0).is_ok());
    }

    #[test]
    fn names_are_the_documented_ones() {
        let names: Vec<&str> = catalogue().iter().map(Family::name).collect();
        assert_eq!(
            names,
            [
                "flanking-gap",
                "dividing-walls",
                "goal-enclosure",
                "random-rectangles",
                "cluttered-rectangles",
                "obstacle-free",
                "center-square",
                "wall-gap",
                "narrow-passage",
                "start-enclosure",
                "double-enclosure",
                "repeating-rectangles",
            ]
        );
        let only_seeded: Vec<&str> = catalogue()
            .iter()
            .filter(|f| f.is_seeded())
            .map(Family::name)
            .collect();
        assert_eq!(only_seeded, ["random-rectangles", "cluttered-rectangles"]);
    }

    #[test]
    fn unknown_names_list_the_known_ones() {
        let err = builtin("flanking-gaps", 2, 0).unwrap_err();
        let message = err.to_string();
        assert!(message.starts_with("unknown problem `flanking-gaps`; known problems: "));
        assert!(message.contains("flanking-gap, dividing-walls"));
        assert!(matches!(
            builtin("wall-gap", 1, 0),
            Err(ProblemError::Dimension {
                problem: "wall-gap",
                n: 1
            })
        ));
    }

    #[test]
    fn listings_show_dimension_dependent_defaults() {
        let fg = &catalogue()[0];
        let value = |n: usize, name: &str| {
            fg.parameters(n)
                .into_iter()
                .find(|p| p.name == name)
                .map(|p| p.value)
        };
        assert_eq!(value(2, "wall_width").as_deref(), Some("0.7"));
        assert_eq!(value(3, "wall_width").as_deref(), Some("0.8"));
        assert_eq!(value(3, "start").as_deref(), Some("(-0.2, 0, 0)"));
        let dw = catalogue()[1].parameters(2);
        assert_eq!(dw[2].value, "(-0.25, 0.05), (0, 0.1), (0.25, 0.05)");
    }

    #[test]
    fn seeds_only_change_seeded_families() {
        for family in catalogue() {
            let a = family.build(3, 1).unwrap();
            let b = family.build(3, 2).unwrap();
            assert_eq!(
                a.world() == b.world(),
                !family.is_seeded(),
                "{}",
                family.name()
            );
        }
    }
}
