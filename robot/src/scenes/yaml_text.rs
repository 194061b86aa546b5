//! [`read_yaml`]: MoveIt's YAML files, parsed with limits that scale with the text.

use serde::de::DeserializeOwned;
use serde_saphyr::budget::{Budget, BudgetBreach};
use serde_saphyr::{Error, Options};

use crate::SceneError;

/// Parses `text` (from `origin`, named in errors) as YAML of type `T`.
///
/// The parser's safety budget exists to stop inputs whose *parsed* size explodes — alias
/// bombs, deep nesting — and those limits stay. Its counts of nodes, events and scalar bytes,
/// though, cannot exceed the length of text already in memory by more than a small factor, so
/// they are raised to that length: a scene of 50 000 primitives is a large file, not an
/// attack. A limit that is still breached is reported naming it.
pub(crate) fn read_yaml<T: DeserializeOwned>(text: &str, origin: &str) -> Result<T, SceneError> {
    let mut budget = Budget::default();
    // Every node and event takes at least one byte of text (aliases, which do not, keep their
    // own caps); a flow collection's closing bracket is the second event of its opening one.
    budget.max_nodes = budget.max_nodes.max(text.len() + 1);
    budget.max_events = budget.max_events.max(2 * text.len() + 16);
    budget.max_total_scalar_bytes = budget.max_total_scalar_bytes.max(text.len());
    let mut options = Options::default();
    options.budget = Some(budget.clone());
    serde_saphyr::from_str_with_options(text, options).map_err(|e| SceneError::Yaml {
        origin: origin.to_owned(),
        message: match original(&e) {
            Error::Budget { breach, .. } => breached(breach, &budget),
            _ => e.to_string(),
        },
    })
}

/// The error under the parser's wrappers (source snippets, alias expansion).
fn original(mut e: &Error) -> &Error {
    while let Error::WithSnippet { error, .. } | Error::AliasError { error, .. } = e {
        e = error;
    }
    e
}

/// A breached limit of the YAML parser, in words: which limit, its value, and why it stands.
fn breached(breach: &BudgetBreach, limits: &Budget) -> String {
    let (what, limit) = match breach {
        BudgetBreach::Events { events } => (
            format!("{events} parser events (aliases replay their anchor's)"),
            limits.max_events,
        ),
        BudgetBreach::Nodes { nodes } => (
            format!("{nodes} nodes (aliases replay their anchor's)"),
            limits.max_nodes,
        ),
        BudgetBreach::Aliases { aliases } => {
            (format!("{aliases} aliases (`*name`)"), limits.max_aliases)
        }
        BudgetBreach::Anchors { anchors } => {
            (format!("{anchors} anchors (`&name`)"), limits.max_anchors)
        }
        BudgetBreach::Depth { depth } => (format!("nesting {depth} deep"), limits.max_depth),
        BudgetBreach::Documents { documents } => {
            (format!("{documents} documents"), limits.max_documents)
        }
        BudgetBreach::MergeKeys { merge_keys } => (
            format!("{merge_keys} merge keys (`<<`)"),
            limits.max_merge_keys,
        ),
        other => {
            return format!(
                "the YAML breaks a limit of the parser's safety budget ({other:?}); MoveIt's \
                 scene and request files never come near it"
            );
        }
    };
    format!(
        "the YAML has {what}, more than the parser accepts ({limit}): a limit that stops inputs \
         whose expansion explodes (alias bombs, runaway nesting). MoveIt writes scenes and \
         requests without aliases; write the values out"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, serde::Deserialize)]
    struct Numbers {
        values: Vec<f64>,
    }

    #[test]
    fn long_inputs_pass_and_alias_bombs_are_refused_naming_the_limit() {
        // 400 000 scalars: above the parser's default node budget of 250 000.
        let long = format!("values: [{}]", vec!["1"; 400_000].join(", "));
        let numbers: Numbers = read_yaml(&long, "long.yaml").unwrap();
        assert_eq!(numbers.values.len(), 400_000);

        let mut bomb = String::from("a: &a [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n");
        for level in 1..12 {
            let alias = format!("*{}", (b'a' + level - 1) as char);
            let list = [alias.as_str(); 10].join(", ");
            bomb += &format!("{0}: &{0} [{1}]\n", (b'a' + level) as char, list);
        }
        bomb += "values: [1]\n";
        let error = read_yaml::<Numbers>(&bomb, "bomb.yaml")
            .unwrap_err()
            .to_string();
        assert!(error.starts_with("bomb.yaml"), "{error}");
        assert!(error.contains("more than the parser accepts"), "{error}");
    }
}
