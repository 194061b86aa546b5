//! [`IkSolution`]: a configuration the solver found, with how well it meets the target.

/// A configuration placing the solver's frame within the target's tolerances (up to the
/// solver's [accuracy](crate::IkSolver::accuracy)), within the joint limits, and valid by the
/// checker it was solved with.
#[derive(Debug, Clone, PartialEq)]
pub struct IkSolution {
    /// The configuration (one value per coordinate of the model).
    pub configuration: Vec<f64>,
    /// Its distance to the target's position tolerance set, in metres.
    pub position_error: f64,
    /// Its angle to the target's orientation tolerance set, in radians.
    pub orientation_error: f64,
    /// Attempts it took (1: the first start converged to it).
    pub attempts: usize,
    /// Solver iterations over all those attempts.
    pub iterations: usize,
}
