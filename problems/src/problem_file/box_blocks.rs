//! A fast path for the bulk of large problem files: `[[obstacles]]` and `[[anti_obstacles]]`
//! blocks of the plain form
//!
//! ```toml
//! [[obstacles]]
//! center = [0.1, -0.25]
//! widths = [0.2, 0.05]
//! ```
//!
//! read line by line, so that a world of 100 000 boxes (7 MB) loads in a fraction of the time a
//! general TOML parser takes. Anything else in such a block — another key, an inline table, a
//! number TOML writes differently (`1_000`, `0x10`), a multi-line array — makes the whole file
//! go through the TOML parser instead, so the fast path never changes what a file means nor the
//! errors it gets.

use super::BoxSpec;

/// A box block being read: anti-obstacle?, its centre and widths once seen.
type Block = (bool, Option<Vec<f64>>, Option<Vec<f64>>);

/// The file with its plain box blocks taken out, and those blocks (obstacles, anti-obstacles)
/// in file order; `None` if any box block is not plain.
pub(super) fn split_box_blocks(text: &str) -> Option<(String, Vec<BoxSpec>, Vec<BoxSpec>)> {
    let mut rest = String::with_capacity(text.len().min(1 << 16));
    let (mut obstacles, mut antis) = (Vec::new(), Vec::new());
    let mut current: Option<Block> = None;
    let finish =
        |block: Block, obstacles: &mut Vec<BoxSpec>, antis: &mut Vec<BoxSpec>| -> Option<()> {
            let (anti, center, widths) = block;
            let spec = BoxSpec {
                center: center?,
                widths: widths?,
            };
            if anti {
                antis.push(spec);
            } else {
                obstacles.push(spec);
            }
            Some(())
        };
    for line in text.lines() {
        let code = line.split('#').next().unwrap_or("").trim();
        if code.starts_with('[') {
            if let Some(block) = current.take() {
                finish(block, &mut obstacles, &mut antis)?;
            }
            match code {
                "[[obstacles]]" => current = Some((false, None, None)),
                "[[anti_obstacles]]" => current = Some((true, None, None)),
                _ => {
                    if code.contains("obstacles") {
                        return None;
                    }
                    rest.push_str(line);
                    rest.push('\n');
                }
            }
            continue;
        }
        match current.as_mut() {
            None => {
                rest.push_str(line);
                rest.push('\n');
            }
            Some(_) if code.is_empty() => {}
            Some((_, center, widths)) => {
                let (key, value) = code.split_once('=')?;
                let slot = match key.trim() {
                    "center" => center,
                    "widths" => widths,
                    _ => return None,
                };
                if slot.is_some() {
                    return None;
                }
                *slot = Some(numbers(value.trim())?);
            }
        }
    }
    if let Some(block) = current.take() {
        finish(block, &mut obstacles, &mut antis)?;
    }
    Some((rest, obstacles, antis))
}

/// A one-line TOML array of numbers, `[1, -0.5, 2e-3]`.
fn numbers(value: &str) -> Option<Vec<f64>> {
    let inner = value.strip_prefix('[')?.strip_suffix(']')?.trim();
    if inner.is_empty() {
        return Some(Vec::new());
    }
    let inner = inner.strip_suffix(',').unwrap_or(inner);
    inner.split(',').map(|t| number(t.trim())).collect()
}

/// A TOML integer or float, in the forms TOML allows (no underscores, no bases, no leading
/// zeros; `inf` and `nan` with an optional sign).
fn number(token: &str) -> Option<f64> {
    let unsigned = token.strip_prefix(['+', '-']).unwrap_or(token);
    if matches!(unsigned, "inf" | "nan") {
        return token.parse().ok();
    }
    let (mantissa, exponent) = match unsigned.split_once(['e', 'E']) {
        Some((m, e)) => (m, Some(e.strip_prefix(['+', '-']).unwrap_or(e))),
        None => (unsigned, None),
    };
    let (whole, fraction) = match mantissa.split_once('.') {
        Some((w, f)) => (w, Some(f)),
        None => (mantissa, None),
    };
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let plain = digits(whole)
        && !(whole.len() > 1 && whole.starts_with('0'))
        && fraction.is_none_or(digits)
        && exponent.is_none_or(digits);
    if plain { token.parse().ok() } else { None }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_read_as_toml_reads_them() {
        for (text, value) in [
            ("0", 0.0),
            ("-0.5", -0.5),
            ("+1e3", 1000.0),
            ("2E-3", 0.002),
            ("1.5e+2", 150.0),
        ] {
            assert_eq!(number(text), Some(value), "{text}");
        }
        assert!(number("inf").unwrap().is_infinite());
        assert!(number("-nan").unwrap().is_nan());
        for not_plain in [
            "1_000", "0x10", "007", ".5", "1.", "1e", "NaN", "infinity", "",
        ] {
            assert_eq!(number(not_plain), None, "{not_plain}");
        }
        assert_eq!(numbers("[1, 2.5,]"), Some(vec![1.0, 2.5]));
        assert_eq!(numbers("[]"), Some(vec![]));
        assert_eq!(numbers("[1, [2]]"), None);
    }

    #[test]
    fn plain_blocks_are_taken_out_and_others_refused() {
        let text = "name = 'x'\n[bounds]\nlower = [0]\nupper = [1]\n\
                    [[obstacles]]  # a wall\ncenter = [0.5]\n\nwidths = [0.1]\n\
                    [[anti_obstacles]]\nwidths = [0.05]\ncenter = [0.5]\n";
        let (rest, obstacles, antis) = split_box_blocks(text).unwrap();
        assert_eq!(rest, "name = 'x'\n[bounds]\nlower = [0]\nupper = [1]\n");
        assert_eq!((obstacles.len(), antis.len()), (1, 1));
        assert_eq!(antis[0].widths, vec![0.05]);
        for odd in [
            "[[obstacles]]\ncenter = [0.5]\nwidths = [0.1]\ncolour = 'red'\n",
            "[[obstacles]]\ncenter = [0.5]\n",
            "[[obstacles]]\ncenter = [0.5,\n 0.2]\nwidths = [0.1]\n",
            "[[obstacles]]\ncenter = [1_0]\nwidths = [0.1]\n",
            "[obstacles]\ncenter = [0.5]\n",
            "[[obstacles]]\ncenter = [0.5]\ncenter = [0.5]\nwidths = [0.1]\n",
        ] {
            assert!(split_box_blocks(odd).is_none(), "{odd}");
        }
    }
}
