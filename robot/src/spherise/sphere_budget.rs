//! A whole model's covers within a sphere budget (`--max-spheres`): the finest tolerance,
//! common to every link, whose covers fit.
//!
//! A cover at tolerance `t` keeps the guarantee at `t` (every point of the geometry inside,
//! no sphere farther than `t` from it), so the budget trades only how far spheres reach
//! beyond the meshes, never whether they contain them. The search grows `t` by the square
//! root of the excess (at least a fifth, at most fourfold) until the covers fit, then
//! halves the last bracket geometrically [`BISECTIONS`] times: the tolerance found is within
//! a factor `1.2^(1/16)` (1.1 %) of the finest that fits when the growth took its
//! smallest step, at the price of a handful of
//! covers (coarse covers are quick: the cells fall with the cube of the tolerance).

use super::spherise_error::SpheriseError;

/// Geometric halvings of the bracket once a tolerance fits.
const BISECTIONS: u32 = 4;

/// The most covers the growth phase makes before giving up.
const MAX_GROWTHS: u32 = 60;

/// The covers of the finest tolerance found, from `tolerance` up, whose sphere count
/// (`cover(t).0`) is at most `budget`. `minimum` is the least count any tolerance gives
/// (spheres kept as they are, and one per mesh).
///
/// # Errors
/// [`SpheriseError::BadOption`] for a budget below `minimum` (or one never met), and
/// `cover`'s errors.
pub(super) fn fit_budget<T>(
    budget: usize,
    minimum: usize,
    tolerance: f64,
    mut cover: impl FnMut(f64) -> Result<(usize, T), SpheriseError>,
) -> Result<T, SpheriseError> {
    let refuse = || SpheriseError::BadOption {
        what: "the sphere budget (--max-spheres)",
        rule: "at least the spheres kept as they are (sphere elements, fallback spheres) plus one per collision mesh",
        value: format!("{budget} (the model needs at least {minimum})"),
    };
    if budget < minimum.max(1) {
        return Err(refuse());
    }
    let (mut count, mut best) = cover(tolerance)?;
    if count <= budget {
        return Ok(best);
    }
    let (mut low, mut high) = (tolerance, tolerance);
    let mut growths = 0;
    loop {
        growths += 1;
        if growths > MAX_GROWTHS {
            return Err(refuse());
        }
        high *= (count as f64 / budget as f64).sqrt().clamp(1.2, 4.0);
        let (c, covers) = cover(high)?;
        if c <= budget {
            best = covers;
            break;
        }
        (low, count) = (high, c);
    }
    for _ in 0..BISECTIONS {
        let middle = (low * high).sqrt();
        let (c, covers) = cover(middle)?;
        if c <= budget {
            (high, best) = (middle, covers);
        } else {
            low = middle;
        }
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A model whose count falls as `1 / t²` (10 000 spheres at 1 mm).
    fn model(t: f64) -> Result<(usize, f64), SpheriseError> {
        Ok(((0.01 / (t * t)).ceil() as usize, t))
    }

    #[test]
    fn the_finest_fitting_tolerance_is_found_within_a_few_percent() {
        let t = fit_budget(100, 3, 0.001, model).unwrap();
        // 100 spheres need t ≥ 10 mm.
        assert!((0.01..0.0105).contains(&t), "{t}");
        assert_eq!(fit_budget(10_000, 3, 0.001, model).unwrap(), 0.001);
        let mut covers = 0;
        fit_budget(5, 3, 0.001, |t| {
            covers += 1;
            model(t)
        })
        .unwrap();
        assert!(covers <= 20, "{covers}");
    }

    #[test]
    fn a_budget_below_the_minimum_is_refused() {
        let e = fit_budget(2, 3, 0.001, model).unwrap_err();
        assert!(e.to_string().contains("at least 3"), "{e}");
        // A count that never falls to the budget ends with the same error.
        assert!(fit_budget(5, 1, 0.001, |t| Ok((6, t))).is_err());
    }
}
