//! The joint names of a path file (`mit-star check-path --path`): a `joints:` line in the text
//! form, or the `joints` array beside `path` in the JSON that `plan --json` and `runs.jsonl`
//! write; and putting a path's coordinates into the robot's order by those names.

use serde_json::Value;

/// A path file read: its paths and, if it names them, the joints its coordinates are.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct NamedPaths {
    /// The paths, each a list of states.
    pub(crate) paths: Vec<Vec<Vec<f64>>>,
    /// The joints each state's coordinates are, in the file's order, if it says.
    pub(crate) joints: Option<Vec<String>>,
}

/// What `text` holds when it is the JSON the tool writes (it starts with `{`): one object per
/// line (`plan --json`, `runs.jsonl`), each with a `path` (an array of states; objects without
/// one, as unsolved runs, are skipped) and optionally `joints`. `None` for the text form.
///
/// # Errors
/// The line that is not such an object, or joint names that differ between lines.
pub(crate) fn json_paths(text: &str) -> Option<Result<NamedPaths, String>> {
    if !text.trim_start().starts_with('{') {
        return None;
    }
    let mut read = NamedPaths::default();
    for (number, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let at = |m: &str| format!("line {}: {m}", number + 1);
        let value: Value = match serde_json::from_str(line) {
            Ok(v) => v,
            Err(e) => return Some(Err(at(&format!("not a JSON object ({e})")))),
        };
        let states = match value.get("path") {
            Some(Value::Array(states)) if !states.is_empty() => states,
            _ => continue,
        };
        let path: Option<Vec<Vec<f64>>> = states
            .iter()
            .map(|s| {
                s.as_array()
                    .and_then(|xs| xs.iter().map(Value::as_f64).collect::<Option<Vec<f64>>>())
            })
            .collect();
        let Some(path) = path else {
            return Some(Err(at("`path` is not an array of arrays of numbers")));
        };
        let joints = match value.get("joints") {
            None | Some(Value::Null) => None,
            Some(Value::Array(names)) => {
                let names: Option<Vec<String>> = names
                    .iter()
                    .map(|n| n.as_str().map(str::to_owned))
                    .collect();
                match names {
                    Some(names) => Some(names),
                    None => return Some(Err(at("`joints` is not an array of names"))),
                }
            }
            Some(_) => return Some(Err(at("`joints` is not an array of names"))),
        };
        if let Some(joints) = joints {
            match &read.joints {
                Some(earlier) if *earlier != joints => {
                    return Some(Err(at("`joints` differs from an earlier line's")));
                }
                _ => read.joints = Some(joints),
            }
        }
        read.paths.push(path);
    }
    Some(Ok(read))
}

/// The text form's `joints:` line taken out of `text` (replaced by a comment, so line
/// numbers stay): `joints: a, b, c` (names separated by commas or spaces), at most one,
/// before the first state.
///
/// # Errors
/// A second `joints:` line, one after a state, or one naming no joint.
pub(crate) fn take_joints_line(text: &str) -> Result<(String, Option<Vec<String>>), String> {
    let mut joints = None;
    let mut seen_state = false;
    let mut lines = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let content = line.split('#').next().unwrap_or("").trim();
        let Some(names) = content.strip_prefix("joints:") else {
            seen_state |= !content.is_empty();
            lines.push(line);
            continue;
        };
        let at = |m: &str| format!("line {}: {m}", number + 1);
        if joints.is_some() {
            return Err(at("a second `joints:` line (one per file)"));
        }
        if seen_state {
            return Err(at("`joints:` must come before the first state"));
        }
        let names: Vec<String> = names
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty())
            .map(str::to_owned)
            .collect();
        if names.is_empty() {
            return Err(at("`joints:` names no joint"));
        }
        joints = Some(names);
        lines.push("#");
    }
    Ok((lines.join("\n"), joints))
}

/// Why a file's joint names cannot be put into the robot's order: the names it lacks, those
/// the robot does not have, and those given twice (each possibly empty).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct JointMismatch {
    /// The robot's joints the file does not name.
    pub(crate) missing: Vec<String>,
    /// Names in the file that are not the robot's joints.
    pub(crate) unknown: Vec<String>,
    /// Names the file gives more than once.
    pub(crate) repeated: Vec<String>,
}

impl std::fmt::Display for JointMismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let parts: Vec<String> = [
            ("missing", &self.missing),
            ("not the robot's", &self.unknown),
            ("named twice", &self.repeated),
        ]
        .into_iter()
        .filter(|(_, names)| !names.is_empty())
        .map(|(what, names)| format!("{what}: {}", names.join(", ")))
        .collect();
        write!(f, "{}", parts.join("; "))
    }
}

/// For each of the robot's coordinates (`robot`, in order), its index among the file's
/// joints `file`: the permutation that puts a state of the file into the robot's order.
///
/// # Errors
/// [`JointMismatch`] unless `file` names each of the robot's joints exactly once.
pub(crate) fn robot_order(file: &[String], robot: &[String]) -> Result<Vec<usize>, JointMismatch> {
    let mut repeated: Vec<String> = Vec::new();
    for (i, name) in file.iter().enumerate() {
        if file[..i].contains(name) && !repeated.contains(name) {
            repeated.push(name.clone());
        }
    }
    let missing: Vec<String> = robot
        .iter()
        .filter(|r| !file.contains(r))
        .cloned()
        .collect();
    let unknown: Vec<String> = file
        .iter()
        .filter(|f| !robot.contains(f))
        .cloned()
        .collect();
    if !(missing.is_empty() && unknown.is_empty() && repeated.is_empty()) {
        return Err(JointMismatch {
            missing,
            unknown,
            repeated,
        });
    }
    Ok(robot
        .iter()
        .map(|r| file.iter().position(|f| f == r).unwrap_or(0))
        .collect())
}

/// `paths`' states put into the robot's order by `order` ([`robot_order`]); a state of
/// another length is left as it is (the checks refuse it, naming its length).
pub(crate) fn reorder(paths: &mut [Vec<Vec<f64>>], order: &[usize]) {
    for state in paths.iter_mut().flatten() {
        if state.len() == order.len() {
            *state = order.iter().map(|&i| state[i]).collect();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(text: &str) -> Vec<String> {
        text.split(' ').map(str::to_owned).collect()
    }

    #[test]
    fn a_joints_line_is_taken_out_and_only_one_before_the_states() {
        let (text, joints) = take_joints_line("# c\njoints: a, b c\n0 0 0\n").unwrap();
        assert_eq!(joints, Some(names("a b c")));
        assert_eq!(text, "# c\n#\n0 0 0");
        assert_eq!(take_joints_line("0 0\n").unwrap().1, None);
        let e = take_joints_line("0 0\njoints: a b\n").unwrap_err();
        assert!(e.contains("line 2") && e.contains("before"), "{e}");
        let e = take_joints_line("joints: a\njoints: a\n").unwrap_err();
        assert!(e.contains("second"), "{e}");
        assert!(
            take_joints_line("joints:\n")
                .unwrap_err()
                .contains("no joint")
        );
    }

    #[test]
    fn json_lines_give_their_paths_and_joints_and_skip_runs_without_a_path() {
        let text = concat!(
            r#"{"path": [[0, 1], [2, 3]], "joints": ["a", "b"]}"#,
            "\n",
            r#"{"path": []}"#,
            "\n",
            r#"{"path": [[4, 5]]}"#,
            "\n"
        );
        let read = json_paths(text).unwrap().unwrap();
        assert_eq!(read.paths.len(), 2);
        assert_eq!(read.paths[1], vec![vec![4.0, 5.0]]);
        assert_eq!(read.joints, Some(names("a b")));
        assert!(json_paths("0 0\n").is_none());
        let e = json_paths("{\"path\": [[\"x\"]]}").unwrap().unwrap_err();
        assert!(e.contains("line 1"), "{e}");
        let e = json_paths(
            "{\"path\": [[0]], \"joints\": [\"a\"]}\n{\"path\": [[0]], \"joints\": [\"b\"]}",
        )
        .unwrap()
        .unwrap_err();
        assert!(e.contains("line 2") && e.contains("differs"), "{e}");
    }

    #[test]
    fn states_are_put_in_the_robots_order_by_name_or_the_mismatch_is_named() {
        let robot = names("a b c");
        let order = robot_order(&names("c a b"), &robot).unwrap();
        let mut paths = vec![vec![vec![3.0, 1.0, 2.0]]];
        reorder(&mut paths, &order);
        assert_eq!(paths[0][0], vec![1.0, 2.0, 3.0]);
        let e = robot_order(&names("a b d b"), &robot).unwrap_err();
        assert_eq!(e.missing, names("c"));
        assert_eq!(e.unknown, names("d"));
        assert_eq!(e.repeated, names("b"));
        assert_eq!(
            e.to_string(),
            "missing: c; not the robot's: d; named twice: b"
        );
    }
}
