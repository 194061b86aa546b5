//! Writing a [`Problem`] as a problem file: [`Problem::to_toml_string`].

use crate::Problem;

impl Problem {
    /// Writes the problem as a problem file that [`from_toml_str`](Self::from_toml_str) reads
    /// back to an equal problem (numbers are written in their shortest exact form).
    pub fn to_toml_string(&self) -> String {
        let mut out = String::new();
        out.push_str(&format!("name = {}\n", quote(self.name())));
        out.push_str(&format!("resolution = {}\n", number(self.resolution())));
        if self.coarse_step_allowed() {
            out.push_str("allow_coarse_step = true\n");
        }
        if let Some(optimum) = self.optimum() {
            out.push_str(&format!("optimum = {}\n", number(optimum)));
        }
        out.push_str(&format!("start = {}\n", array(self.start())));
        match self.goals() {
            [goal] => out.push_str(&format!("goal = {}\n", array(goal))),
            goals => {
                let goals: Vec<String> = goals.iter().map(|g| array(g)).collect();
                out.push_str(&format!("goals = [{}]\n", goals.join(", ")));
            }
        }
        let world = self.world();
        out.push_str("\n[bounds]\n");
        out.push_str(&format!("lower = {}\n", array(world.lower())));
        out.push_str(&format!("upper = {}\n", array(world.upper())));
        for (table, boxes) in [
            ("obstacles", world.obstacles()),
            ("anti_obstacles", world.anti_obstacles()),
        ] {
            for b in boxes {
                out.push_str(&format!("\n[[{table}]]\n"));
                out.push_str(&format!("center = {}\n", array(&b.center)));
                out.push_str(&format!("widths = {}\n", array(&b.widths)));
            }
        }
        for lattice in world.lattices() {
            out.push_str("\n[[lattices]]\n");
            out.push_str(&format!("count = {}\n", lattice.count));
            out.push_str(&format!("spacing = {}\n", number(lattice.spacing)));
            out.push_str(&format!("side = {}\n", number(lattice.side)));
        }
        out
    }
}

/// A finite number in TOML: Rust's shortest round-trip form (`0.1`, `5e-6`, `-0.0`) is valid
/// TOML float syntax.
pub(super) fn number(value: f64) -> String {
    format!("{value:?}")
}

/// An array of numbers.
pub(super) fn array(values: &[f64]) -> String {
    let values: Vec<String> = values.iter().map(|&v| number(v)).collect();
    format!("[{}]", values.join(", "))
}

/// A TOML basic string.
pub(super) fn quote(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
