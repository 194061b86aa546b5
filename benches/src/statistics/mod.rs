//! Statistics as PDT computes them: medians of order statistics with nonparametric confidence
//! intervals (unsolved runs count as `+∞`), Clopper–Pearson intervals of success rates, and
//! both over time from anytime traces.

mod anytime_series;
mod beta;
mod binomial;
mod clopper_pearson;
mod median;

pub use anytime_series::{AnytimeSeries, cost_at, log_time_grid};
pub use beta::{beta_quantile, ln_gamma, regularized_incomplete_beta};
pub use binomial::binomial_cdf;
pub use clopper_pearson::ClopperPearson;
pub use median::{MedianEstimate, MedianInterval, median_index};
