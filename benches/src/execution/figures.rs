//! [`Figures`]: which figures and 3-D views a results folder gets.

/// Which figures (`plots/`) and 3-D views (`views/`) [`ResultsFolder::finish`] draws.
///
/// [`ResultsFolder::finish`]: crate::ResultsFolder::finish
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Figures {
    /// None (`--no-plots`).
    None,
    /// One figure per scene, every instance of the scene pooled, and the 3-D view of its
    /// hardest instance (`bench`'s default). A box world is a scene of its own.
    #[default]
    Scenes,
    /// Those of [`Scenes`](Self::Scenes), and a figure and a 3-D view of every problem
    /// instance (`--per-problem`).
    ScenesAndProblems,
}

impl Figures {
    /// The choice of `bench` and `merge`: `--no-plots` wins over `--per-problem`.
    pub fn from_flags(no_plots: bool, per_problem: bool) -> Self {
        match (no_plots, per_problem) {
            (true, _) => Self::None,
            (false, false) => Self::Scenes,
            (false, true) => Self::ScenesAndProblems,
        }
    }

    /// `true` unless [`None`](Self::None).
    pub fn any(self) -> bool {
        self != Self::None
    }

    /// `true` for [`ScenesAndProblems`](Self::ScenesAndProblems).
    pub fn per_problem(self) -> bool {
        self == Self::ScenesAndProblems
    }
}
