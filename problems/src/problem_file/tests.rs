//! Unit tests of the problem file format: every malformed input gets its own variant and a
//! message naming the field.

use super::writer::{array, number, quote};
use super::*;

/// A valid 2-D file: a wall with a slot.
const BASE: &str = r#"
name = "wall"
start = [-0.3, 0.0]
goal = [0.3, 0.0]

[bounds]
lower = [-0.5, -0.5]
upper = [0.5, 0.5]

[[obstacles]]
center = [0.0, -0.1]
widths = [0.2, 0.8]

[[anti_obstacles]]
center = [0.0, 0.1]
widths = [0.2, 0.04]
"#;

fn load(text: &str) -> Result<Problem, ProblemFileError> {
    Problem::from_toml_str(text)
}

fn error(text: &str) -> ProblemFileError {
    match load(text) {
        Ok(p) => panic!("expected an error, loaded {p:?}"),
        Err(e) => e,
    }
}

#[test]
fn base_file_loads() {
    let p = load(BASE).unwrap();
    assert_eq!(p.name(), "wall");
    assert_eq!(p.resolution(), Problem::DEFAULT_RESOLUTION);
    assert_eq!(p.world().obstacles().len(), 1);
    assert_eq!(p.world().anti_obstacles().len(), 1);
    assert_eq!(p.optimum(), None);
}

#[test]
fn empty_file() {
    assert!(matches!(error(""), ProblemFileError::Empty));
    let err = error("# only a comment\n\n");
    assert!(matches!(err, ProblemFileError::Empty));
    assert!(err.to_string().starts_with("the problem file is empty"));
}

#[test]
fn syntax_error_gives_the_line() {
    let text = BASE.replace("goal = [0.3, 0.0]", "goal = [0.3 0.0]");
    let err = error(&text);
    let ProblemFileError::Syntax { location, message } = &err else {
        panic!("{err:?}");
    };
    assert_eq!(*location, Some(Location { line: 4, column: 9 }));
    assert!(message.contains("must be quoted"), "{message}");
    assert!(
        err.to_string()
            .starts_with("TOML syntax error: line 4, column 9: "),
        "{err}"
    );
    // An unclosed array is noticed where the next table starts.
    let err = error(&BASE.replace("goal = [0.3, 0.0]", "goal = [0.3, 0.0"));
    assert!(matches!(
        err,
        ProblemFileError::Syntax {
            location: Some(Location { line: 6, .. }),
            ..
        }
    ));
}

#[test]
fn missing_field() {
    let err = error(&BASE.replace("start = [-0.3, 0.0]\n", ""));
    assert!(matches!(err, ProblemFileError::Schema { .. }), "{err:?}");
    assert!(err.to_string().contains("missing field `start`"), "{err}");
    // A field missing from a repeated table points at that table.
    let err = error(&BASE.replace("widths = [0.2, 0.8]\n", ""));
    let message = err.to_string();
    assert!(message.contains("missing field `widths`"), "{message}");
    assert!(message.contains("in `[[obstacles]]`"), "{message}");
}

#[test]
fn unknown_field() {
    let err = error(&BASE.replace("name = \"wall\"", "name = \"wall\"\ncolour = \"red\""));
    let ProblemFileError::Schema { location, message } = &err else {
        panic!("{err:?}");
    };
    assert_eq!(location.map(|l| l.line), Some(3));
    assert!(message.starts_with("unknown field `colour`"), "{message}");
    let err = error(&BASE.replace("center = [0.0, 0.1]", "centre = [0.0, 0.1]"));
    assert!(err.to_string().contains("unknown field `centre`"), "{err}");
}

#[test]
fn wrong_type_quotes_the_line() {
    let err = error(&BASE.replace("start = [-0.3, 0.0]", "start = [-0.3, \"zero\"]"));
    assert!(matches!(err, ProblemFileError::Schema { .. }));
    let message = err.to_string();
    assert!(message.contains("invalid type"), "{message}");
    assert!(
        message.contains("in `start = [-0.3, \"zero\"]`"),
        "{message}"
    );
}

#[test]
fn wrong_dimension() {
    let text = format!("{BASE}\n[[obstacles]]\ncenter = [0.3, 0.3]\nwidths = [0.1, 0.1]\n")
        + "\n[[obstacles]]\ncenter = [0.3, 0.3]\nwidths = [0.1, 0.1, 0.1]\n";
    let err = error(&text);
    assert!(matches!(
        &err,
        ProblemFileError::Dimension { field, got: 3, expected: 2 } if field == "obstacles[2].widths"
    ));
    assert_eq!(
        err.to_string(),
        "`obstacles[2].widths` has 3 values, but the bounds have 2"
    );
    let err = error(&BASE.replace("start = [-0.3, 0.0]", "start = [-0.3, 0.0, 0.0]"));
    assert_eq!(
        err.to_string(),
        "`start` has 3 values, but the bounds have 2"
    );
}

#[test]
fn start_in_collision() {
    let err = error(&BASE.replace("start = [-0.3, 0.0]", "start = [0.0, 0.0]"));
    assert!(matches!(&err, ProblemFileError::InCollision { field, .. } if field == "start"));
    assert_eq!(
        err.to_string(),
        "`start` = [0.0, 0.0] is in collision with an obstacle"
    );
    let text = BASE.replace("goal = [0.3, 0.0]", "goals = [[0.3, 0.0], [0.0, -0.2]]");
    let err = error(&text);
    assert!(matches!(&err, ProblemFileError::InCollision { field, .. } if field == "goals[1]"));
}

#[test]
fn goal_out_of_bounds() {
    let err = error(&BASE.replace("goal = [0.3, 0.0]", "goal = [0.3, 0.7]"));
    assert!(matches!(
        &err,
        ProblemFileError::OutOfBounds { field, index: 1, .. } if field == "goal"
    ));
    assert_eq!(
        err.to_string(),
        "`goal` is outside the bounds: coordinate 1 is 0.7, not in [-0.5, 0.5]"
    );
}

#[test]
fn nan_and_infinity_are_refused() {
    let err = error(&BASE.replace("start = [-0.3, 0.0]", "start = [nan, 0.0]"));
    assert!(matches!(&err, ProblemFileError::BadValue { field, .. } if field == "start[0]"));
    assert_eq!(err.to_string(), "`start[0]` is NaN; values must be finite");
    let err = error(&BASE.replace("upper = [0.5, 0.5]", "upper = [0.5, inf]"));
    assert_eq!(
        err.to_string(),
        "`bounds.upper[1]` is inf; values must be finite"
    );
    let err = error(&BASE.replace("center = [0.0, 0.1]", "center = [0.0, -inf]"));
    assert_eq!(
        err.to_string(),
        "`anti_obstacles[0].center[1]` is -inf; values must be finite"
    );
}

#[test]
fn negative_width() {
    let err = error(&BASE.replace("widths = [0.2, 0.8]", "widths = [0.2, -0.8]"));
    assert!(matches!(
        &err,
        ProblemFileError::BadValue { field, value, .. }
            if field == "obstacles[0].widths[1]" && *value == -0.8
    ));
    assert_eq!(
        err.to_string(),
        "`obstacles[0].widths[1]` is -0.8; widths are full side lengths and must not be negative"
    );
}

#[test]
fn lower_not_below_upper() {
    let err = error(&BASE.replace("lower = [-0.5, -0.5]", "lower = [-0.5, 0.5]"));
    assert!(matches!(
        err,
        ProblemFileError::EmptyInterval { index: 1, .. }
    ));
    assert_eq!(
        err.to_string(),
        "`bounds.lower[1]` = 0.5 is not below `bounds.upper[1]` = 0.5"
    );
    let err = error(&BASE.replace("lower = [-0.5, -0.5]", "lower = [-0.5]"));
    assert!(matches!(
        err,
        ProblemFileError::BoundsLength { lower: 1, upper: 2 }
    ));
    let text = BASE
        .replace("lower = [-0.5, -0.5]", "lower = []")
        .replace("upper = [0.5, 0.5]", "upper = []");
    assert!(matches!(error(&text), ProblemFileError::NoDimensions));
}

#[test]
fn goal_and_goals() {
    let both = BASE.replace(
        "goal = [0.3, 0.0]",
        "goal = [0.3, 0.0]\ngoals = [[0.3, 0.0]]",
    );
    let err = error(&both);
    assert!(matches!(err, ProblemFileError::GoalAndGoals));
    assert_eq!(err.to_string(), "give either `goal` or `goals`, not both");
    let neither = BASE.replace("goal = [0.3, 0.0]\n", "");
    assert!(matches!(error(&neither), ProblemFileError::NoGoal));
    let empty = BASE.replace("goal = [0.3, 0.0]", "goals = []");
    assert!(matches!(error(&empty), ProblemFileError::NoGoal));
}

#[test]
fn resolution_must_lie_between_zero_and_one() {
    for bad in ["0.0", "-0.0", "-1e-3", "nan", "inf", "1.0", "1e300", "-inf"] {
        let err = error(&BASE.replace(
            "name = \"wall\"",
            &format!("name = \"wall\"\nresolution = {bad}"),
        ));
        assert!(
            matches!(&err, ProblemFileError::BadValue { field, .. } if field == "resolution"),
            "{bad}: {err:?}"
        );
        assert!(
            err.to_string().ends_with(
                "it must lie strictly between 0 and 1 (a fraction of the maximum extent)"
            ),
            "{err}"
        );
    }
    let p = load(&BASE.replace("name = \"wall\"", "name = \"wall\"\nresolution = 1e-3")).unwrap();
    assert!((p.step() - 1e-3 * 2f64.sqrt()).abs() < 1e-15);
}

#[test]
fn lattices_are_checked() {
    let lattice = "\n[[lattices]]\ncount = 0\nspacing = 0.02\nside = 0.01\n";
    let err = error(&format!("{BASE}{lattice}"));
    assert!(
        matches!(&err, ProblemFileError::EmptyLattice { field } if field == "lattices[0].count")
    );
    let lattice = "\n[[lattices]]\ncount = 3\nspacing = 0.25\nside = -0.01\n";
    let err = error(&format!("{BASE}{lattice}"));
    assert_eq!(
        err.to_string(),
        "`lattices[0].side` is -0.01; it must be finite and positive"
    );
    let lattice = "\n[[lattices]]\ncount = -3\nspacing = 0.25\nside = 0.01\n";
    assert!(matches!(
        error(&format!("{BASE}{lattice}")),
        ProblemFileError::Schema { .. }
    ));
}

#[test]
fn impossible_optimum() {
    let text = BASE.replace("name = \"wall\"", "name = \"wall\"\noptimum = 0.5");
    let err = error(&text);
    assert!(matches!(
        err,
        ProblemFileError::Problem(ProblemError::Optimum { value: 0.5, .. })
    ));
    let text = BASE.replace("name = \"wall\"", "name = \"wall\"\noptimum = -1");
    assert!(matches!(error(&text), ProblemFileError::BadValue { .. }));
}

#[test]
fn integers_are_numbers() {
    let text = BASE
        .replace("lower = [-0.5, -0.5]", "lower = [-1, -1]")
        .replace("upper = [0.5, 0.5]", "upper = [1, 1]");
    let p = load(&text).unwrap();
    assert_eq!(p.space().upper(), &[1.0, 1.0]);
}

#[test]
fn round_trip_keeps_everything() {
    let text = format!(
        "{}\n[[lattices]]\ncount = 4\nspacing = 0.2\nside = 0.013\n",
        BASE.replace("goal = [0.3, 0.0]", "goals = [[0.3, 0.0], [0.3, 0.4]]")
            .replace(
                "name = \"wall\"",
                "name = \"a \\\"quoted\\\" name\\twith tab\"\nresolution = 1e-7\noptimum = 0.9"
            )
    );
    let p = load(&text).unwrap();
    assert_eq!(p.name(), "a \"quoted\" name\twith tab");
    assert_eq!(p.goals().len(), 2);
    let written = p.to_toml_string();
    assert!(written.contains("resolution = 1e-7"), "{written}");
    assert_eq!(load(&written).unwrap(), p);
}

#[test]
fn unreadable_file() {
    let err = Problem::from_file("/nonexistent/problem.toml").unwrap_err();
    assert!(matches!(err, ProblemFileError::Io { .. }));
    assert!(
        err.to_string()
            .starts_with("cannot read problem file `/nonexistent/problem.toml`")
    );
}

#[test]
fn quoting_escapes_control_characters() {
    assert_eq!(quote("a\u{1}b"), "\"a\\u0001b\"");
    assert_eq!(quote("back\\slash"), "\"back\\\\slash\"");
    assert_eq!(number(5e-6), "5e-6");
    assert_eq!(array(&[-0.5, 0.0, 1.0]), "[-0.5, 0.0, 1.0]");
}

/// The same file through the general TOML parser only (no fast path for box blocks).
fn through_toml_only(text: &str) -> Result<Problem, ProblemFileError> {
    toml::from_str::<super::FileSpec>(text)
        .map_err(|e| super::schema_error(text, &e))?
        .into_problem()
}

#[test]
fn the_box_block_fast_path_reads_every_file_as_toml_does() {
    for family in crate::catalogue() {
        for n in [2, 3, 5, 8] {
            for seed in 0..3 {
                let problem = family.build(n, seed).unwrap();
                let text = problem.to_toml_string();
                let fast = Problem::from_toml_str(&text).unwrap();
                assert_eq!(fast, through_toml_only(&text).unwrap(), "{}", family.name());
                assert_eq!(fast, problem, "{} round trip", family.name());
            }
        }
    }
    // Odd but valid TOML takes the general path and means the same.
    let odd = BASE.replace(
        "[[obstacles]]",
        "[[obstacles]] # the wall, with a comment\n# and a comment line",
    );
    assert_eq!(load(&odd).unwrap(), through_toml_only(&odd).unwrap());
    let underscores = BASE.replace("widths = [0.2, 0.8]", "widths = [0.2, 0.8_0]");
    assert_eq!(
        load(&underscores).is_ok(),
        through_toml_only(&underscores).is_ok()
    );
}
