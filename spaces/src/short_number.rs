//! [`short_number`]: numbers for messages.

/// A number for a message, at most four significant digits: `0.25`, `1.414`, `7.071e-6`,
/// `1e308`, `inf` — so that a value like `1e308` never prints as 309 digits and an extent as
/// `1.4142135623730951`. Integers below 10⁷ print whole.
///
/// ```
/// use mit_star_spaces::short_number;
/// assert_eq!(short_number(0.25), "0.25");
/// assert_eq!(short_number(2f64.sqrt()), "1.414");
/// assert_eq!(short_number(1234567.0), "1234567");
/// assert_eq!(short_number(7.0710678e-6), "7.071e-6");
/// assert_eq!(short_number(1e308), "1e308");
/// assert_eq!(short_number(-3e-9), "-3e-9");
/// assert_eq!(short_number(f64::NAN), "NaN");
/// assert_eq!(short_number(-0.0), "-0");
/// ```
pub fn short_number(value: f64) -> String {
    let magnitude = value.abs();
    if !value.is_finite() || magnitude == 0.0 || (value.fract() == 0.0 && magnitude < 1e7) {
        return format!("{value}");
    }
    if (1e-4..1e7).contains(&magnitude) {
        let decimals = (3 - magnitude.log10().floor() as i32).max(0) as usize;
        let text = format!("{value:.decimals$}");
        return if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            text
        };
    }
    let text = format!("{value:.3e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
    format!("{mantissa}e{exponent}")
}
