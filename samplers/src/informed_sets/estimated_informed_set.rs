//! [`EstimatedInformedSet`]: MIT*'s estimate of the informed set before a valid solution exists
//! (spec §6, paper Alg. 3).

use crate::{CostBound, SamplerError};

/// How the expansion factor `e_γ` follows from the reliability `γ`. Serialised as `paper` or
/// `authors`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ExpansionForm {
    /// The paper's equation, `e_γ = √(1 + (1 − γ)²)` (the default).
    #[default]
    Paper,
    /// The authors' implementation, `e_γ = √(1 + (1 − γ))`.
    Authors,
}

impl ExpansionForm {
    /// The expansion factor for reliability `γ ∈ [0, 1]`; at least 1.
    pub fn factor(self, reliability: f64) -> f64 {
        let doubt = 1.0 - reliability;
        match self {
            Self::Paper => (1.0 + doubt * doubt).sqrt(),
            Self::Authors => (1.0 + doubt).sqrt(),
        }
    }
}

/// When an existing estimate expands (case 3). The [`Estimated`](crate::Estimated) wrapper
/// applies the rule; a planner driving an [`EstimatedInformedSet`] directly applies it itself —
/// the estimate only records it. Serialised as `per-batch` or `per-invalid-edge`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ExpansionRule {
    /// Once per batch sampled inside the estimate that ends without a valid solution (the
    /// authors' code; the default).
    #[default]
    PerBatch,
    /// On every invalid edge of the lazy path once an estimate exists (a literal reading of
    /// Alg. 1; grows geometrically).
    PerInvalidEdge,
}

/// MIT*'s estimated informed set: the cost `s̃_est` that bounds sampling while no valid solution
/// exists, its reliability and its expansion factor.
///
/// When the forward search finds an edge `x_s → x_t` of the lazy path invalid, the lazy solution
/// through it had the admissible cost `ŝ_adm = g(x_s) + ĉ(x_s, x_t) + ĥ(x_t)`, of which
/// `γ = g(x_s) / ŝ_adm` was already verified. The estimate inflates `ŝ_adm` by `e_γ ≥ 1` — the
/// more of the path was unverified, the more — to `s̃_est = ŝ_adm · e_γ`, and multiplies by `e_γ`
/// again on each [`expand`](Self::expand). The set itself (a hyperspheroid per goal) is an
/// [`InformedSet`](crate::InformedSet) sampled under [`CostBound::Estimated`].
///
/// ```
/// use mit_star_samplers::{CostBound, EstimatedInformedSet, ExpansionForm};
/// let mut eis = EstimatedInformedSet::new();
/// assert_eq!(eis.bound(), CostBound::Unbounded);
/// // Half of a lazy solution of cost 2 was verified: γ = 0.5, e_γ = √1.25.
/// let cost = eis.create(1.0, 0.4, 0.6)?;
/// assert!((cost - 2.0 * 1.25f64.sqrt()).abs() < 1e-12);
/// assert!((eis.expand().unwrap() - 2.0 * 1.25).abs() < 1e-12);
/// // The authors' form: e_γ = √1.5.
/// let mut eis = EstimatedInformedSet::new().with_form(ExpansionForm::Authors);
/// assert!((eis.create(1.0, 0.4, 0.6)? - 2.0 * 1.5f64.sqrt()).abs() < 1e-12);
/// # Ok::<(), mit_star_samplers::SamplerError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EstimatedInformedSet {
    form: ExpansionForm,
    rule: ExpansionRule,
    estimate: Option<Estimate>,
}

/// The numbers of one estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Estimate {
    admissible: f64,
    reliability: f64,
    factor: f64,
    cost: f64,
    expansions: u32,
}

impl EstimatedInformedSet {
    /// No estimate yet, paper form, per-batch expansion.
    pub fn new() -> Self {
        Self::default()
    }

    /// Sets how `e_γ` is computed (applies to the next [`create`](Self::create)).
    #[must_use]
    pub fn with_form(mut self, form: ExpansionForm) -> Self {
        self.form = form;
        self
    }

    /// Sets the expansion rule the planner should follow.
    #[must_use]
    pub fn with_rule(mut self, rule: ExpansionRule) -> Self {
        self.rule = rule;
        self
    }

    /// How `e_γ` is computed.
    pub fn form(&self) -> ExpansionForm {
        self.form
    }

    /// When the planner expands the estimate.
    pub fn rule(&self) -> ExpansionRule {
        self.rule
    }

    /// Creates the estimate from the failed lazy solution through `x_s → x_t` — `g_source`
    /// `= g(x_s)`, `c_hat_edge = ĉ(x_s, x_t)`, `h_target = ĥ(x_t)` — replacing any earlier one,
    /// and returns `s̃_est`.
    ///
    /// # Errors
    /// [`SamplerError::NegativeCost`] if an input is negative or not finite;
    /// [`SamplerError::ZeroAdmissibleCost`] if they sum to zero. The estimate is left unchanged.
    pub fn create(
        &mut self,
        g_source: f64,
        c_hat_edge: f64,
        h_target: f64,
    ) -> Result<f64, SamplerError> {
        for (name, value) in [
            ("cost-to-come g(x_s)", g_source),
            ("edge-cost estimate ĉ(x_s, x_t)", c_hat_edge),
            ("cost-to-go estimate ĥ(x_t)", h_target),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(SamplerError::NegativeCost { name, value });
            }
        }
        let admissible = g_source + c_hat_edge + h_target;
        if !admissible.is_finite() {
            return Err(SamplerError::NegativeCost {
                name: "admissible solution cost ŝ_adm",
                value: admissible,
            });
        }
        if admissible == 0.0 {
            return Err(SamplerError::ZeroAdmissibleCost);
        }
        let reliability = (g_source / admissible).min(1.0);
        let factor = self.form.factor(reliability);
        let cost = admissible * factor;
        self.estimate = Some(Estimate {
            admissible,
            reliability,
            factor,
            cost,
            expansions: 0,
        });
        Ok(cost)
    }

    /// Paper Alg. 3 verbatim: expands the estimate if one exists, else creates it. Returns
    /// `s̃_est`.
    ///
    /// # Errors
    /// As [`create`](Self::create), when there is no estimate yet.
    pub fn update(
        &mut self,
        g_source: f64,
        c_hat_edge: f64,
        h_target: f64,
    ) -> Result<f64, SamplerError> {
        match self.expand() {
            Some(cost) => Ok(cost),
            None => self.create(g_source, c_hat_edge, h_target),
        }
    }

    /// Expands the estimate, `s̃_est ← s̃_est · e_γ`, and returns the new cost; `None` (and no
    /// change) if there is no estimate.
    pub fn expand(&mut self) -> Option<f64> {
        let estimate = self.estimate.as_mut()?;
        estimate.cost *= estimate.factor;
        estimate.expansions += 1;
        Some(estimate.cost)
    }

    /// Forgets the estimate (e.g. once a valid solution exists, or on a planner reset). The form
    /// and rule are kept.
    pub fn clear(&mut self) {
        self.estimate = None;
    }

    /// `true` if an estimate exists.
    pub fn is_active(&self) -> bool {
        self.estimate.is_some()
    }

    /// The estimated cost `s̃_est`, `None` if there is no estimate.
    pub fn cost(&self) -> Option<f64> {
        self.estimate.map(|e| e.cost)
    }

    /// The sampling bound: [`CostBound::Estimated`] with `s̃_est`, or
    /// [`CostBound::Unbounded`] without an estimate.
    pub fn bound(&self) -> CostBound {
        self.cost()
            .map_or(CostBound::Unbounded, CostBound::Estimated)
    }

    /// The admissible cost `ŝ_adm` of the failed lazy solution.
    pub fn admissible_cost(&self) -> Option<f64> {
        self.estimate.map(|e| e.admissible)
    }

    /// The reliability `γ = g(x_s) / ŝ_adm ∈ [0, 1]`.
    pub fn reliability(&self) -> Option<f64> {
        self.estimate.map(|e| e.reliability)
    }

    /// The expansion factor `e_γ`.
    pub fn expansion_factor(&self) -> Option<f64> {
        self.estimate.map(|e| e.factor)
    }

    /// How many times the estimate was expanded since it was created.
    pub fn expansions(&self) -> u32 {
        self.estimate.map_or(0, |e| e.expansions)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn create_computes_the_paper_quantities() {
        let mut eis = EstimatedInformedSet::new();
        let cost = eis.create(3.0, 1.0, 2.0).unwrap();
        let gamma: f64 = 0.5;
        let factor = (1.0 + (1.0 - gamma) * (1.0 - gamma)).sqrt();
        assert_eq!(eis.admissible_cost(), Some(6.0));
        assert_eq!(eis.reliability(), Some(gamma));
        assert!((eis.expansion_factor().unwrap() - factor).abs() < 1e-15);
        assert!((cost - 6.0 * factor).abs() < 1e-12);
        assert_eq!(eis.bound(), CostBound::Estimated(cost));
    }

    #[test]
    fn expansion_multiplies_and_clear_forgets() {
        let mut eis = EstimatedInformedSet::new().with_form(ExpansionForm::Authors);
        assert_eq!(eis.expand(), None);
        let first = eis.update(0.0, 1.0, 1.0).unwrap();
        // γ = 0: e_γ = √2 in both forms.
        assert!((first - 2.0 * 2f64.sqrt()).abs() < 1e-12);
        let second = eis.update(5.0, 5.0, 5.0).unwrap();
        assert!(
            (second - 4.0).abs() < 1e-12,
            "update expands an existing estimate"
        );
        assert_eq!(eis.expansions(), 1);
        eis.clear();
        assert!(!eis.is_active());
        assert_eq!(eis.cost(), None);
        assert_eq!(eis.form(), ExpansionForm::Authors);
    }

    #[test]
    fn fully_verified_paths_do_not_expand() {
        let mut eis = EstimatedInformedSet::new();
        assert_eq!(eis.create(2.0, 0.0, 0.0), Ok(2.0));
        assert_eq!(eis.expand(), Some(2.0));
    }

    #[test]
    fn malformed_inputs_are_rejected_and_leave_the_estimate() {
        let mut eis = EstimatedInformedSet::new().with_rule(ExpansionRule::PerInvalidEdge);
        eis.create(1.0, 1.0, 1.0).unwrap();
        assert!(matches!(
            eis.create(-1.0, 1.0, 1.0),
            Err(SamplerError::NegativeCost { value: -1.0, .. })
        ));
        assert!(matches!(
            eis.create(1.0, f64::INFINITY, 1.0),
            Err(SamplerError::NegativeCost { .. })
        ));
        assert_eq!(
            eis.create(0.0, 0.0, 0.0),
            Err(SamplerError::ZeroAdmissibleCost)
        );
        assert_eq!(eis.admissible_cost(), Some(3.0));
        assert_eq!(eis.rule(), ExpansionRule::PerInvalidEdge);
    }
}
