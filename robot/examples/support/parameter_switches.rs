//! What the arm examples take after their positional arguments: `name=value` switches setting
//! the planners' [`Parameters`], parsed one way for all of them.

use mit_star::Parameters;
use serde_json::Value;

/// Sets the parameter `name` of `parameters` to `value`, by the name and the value its
/// serialised form uses (the names of `--set` and of experiment files: `batch_size=25`,
/// `frontier_rays=false`, `connection=k-nearest`, `eis_expansion_rule=per-invalid-edge`,
/// `near_terminals=0.3`); `false` if no parameter has that name, so an example can read its
/// own options first. The value is read as JSON (`25`, `0.3`, `true`), or as a string when it is
/// not JSON (`k-nearest`). Panics on a value the parameter does not take: these are measurement
/// scripts, and a typo must not run the default silently.
pub(crate) fn set_parameter(parameters: &mut Parameters, name: &str, value: &str) -> bool {
    let Value::Object(mut fields) =
        serde_json::to_value(&*parameters).expect("the parameters serialise")
    else {
        unreachable!("the parameters serialise to an object");
    };
    if !fields.contains_key(name) {
        return false;
    }
    let parsed = serde_json::from_str(value).unwrap_or_else(|_| Value::String(value.to_owned()));
    fields.insert(name.to_owned(), parsed);
    *parameters = serde_json::from_value(Value::Object(fields))
        .unwrap_or_else(|e| panic!("the parameter {name} does not take {value}: {e}"));
    true
}
