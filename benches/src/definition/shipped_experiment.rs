//! [`ShippedExperiment`]: the experiment files embedded in the binary.

use crate::error::HarnessError;

/// An experiment file shipped with the tool (`benches/experiments/*.toml`), embedded in the
/// binary so that `mit-star bench --experiment NAME` works from any folder.
///
/// ```
/// use mit_star_benches::ShippedExperiment;
/// let names: Vec<&str> = ShippedExperiment::all().iter().map(|e| e.name).collect();
/// assert_eq!(
///     names,
///     ["paper-table", "ablation", "ablation-study", "smoke", "panda-mbm", "paper-planners", "panda-pose-goals"]
/// );
/// assert!(ShippedExperiment::find("smoke")?.text.contains("[[problems]]"));
/// # Ok::<(), mit_star_benches::HarnessError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShippedExperiment {
    /// The name (the file's stem).
    pub name: &'static str,
    /// One line on what it runs.
    pub summary: &'static str,
    /// The file's text.
    pub text: &'static str,
    /// Data its problems read from the working folder, and how to get it (`None`: none).
    pub data: Option<&'static str>,
}

static SHIPPED: [ShippedExperiment; 7] = [
    ShippedExperiment {
        name: "paper-table",
        summary: "the paper's Table I: MIT* vs EIT* on FG, RR (10 layouts), DW and GE, the paper's budgets, 100 runs",
        text: include_str!("../../experiments/paper-table.toml"),
        data: None,
    },
    ShippedExperiment {
        name: "ablation",
        summary: "the paper's ablation: MIT*, EIT*, MIT*-AS, MIT*-EIS, MIT*-SC and MIT*-SR on GE R^2 (0.01 s) and DW R^4 (0.07 s), 100 runs",
        text: include_str!("../../experiments/ablation.toml"),
        data: None,
    },
    ShippedExperiment {
        name: "ablation-study",
        summary: "the ablation study of docs/guide/src/reference/ablation-study.md: the six configurations to their first solution on GE R^2/R^4, DW R^4/R^8, FG R^4, 200 runs (about 3 minutes on 2 cores)",
        text: include_str!("../../experiments/ablation-study.toml"),
        data: None,
    },
    ShippedExperiment {
        name: "smoke",
        summary: "a quick check: all five configurations on FG R^4, DW R^4, GE R^2, RR R^4 (layout 1), 20 runs (about a minute on 2 cores)",
        text: include_str!("../../experiments/smoke.toml"),
        data: None,
    },
    ShippedExperiment {
        name: "panda-mbm",
        summary: "the Franka Panda in five of MotionBenchMaker's seven scenes (bookshelf_small, bookshelf_tall, box, cage, table_pick) × 100 problems: MIT*, EIT*, BIT*, FCIT*, RRT-Connect and AORRTC, 1 s, 1 run (extract robot/data/panda/mbm_problems.tar.bz2 into target/ first; about 20 minutes on 2 cores)",
        text: include_str!("../../experiments/panda-mbm.toml"),
        data: Some(
            "MotionBenchMaker scene folders in target/: `mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/`",
        ),
    },
    ShippedExperiment {
        name: "paper-planners",
        summary: "the paper's planner comparison: MIT*, EIT*, AIT*, BIT*, ABIT*, Informed RRT*, RRT-Connect on FG, DW, GE (R^4, R^8) and GE R^2, the paper's budgets, 100 runs (about 20 minutes on 2 cores)",
        text: include_str!("../../experiments/paper-planners.toml"),
        data: None,
    },
    ShippedExperiment {
        name: "panda-pose-goals",
        summary: "the Franka Panda in MotionBenchMaker's seven scenes × 20 problems with the goal given as the hand's pose (inverse kinematics while planning): RRT-Connect, AORRTC and MIT*, 1 s, 1 run (extract robot/data/panda/mbm_problems.tar.bz2 into target/ first; about 4 minutes on 2 cores)",
        text: include_str!("../../experiments/panda-pose-goals.toml"),
        data: Some(
            "MotionBenchMaker scene folders in target/: `mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/`",
        ),
    },
];

impl ShippedExperiment {
    /// Every shipped experiment.
    pub fn all() -> &'static [ShippedExperiment] {
        &SHIPPED
    }

    /// The shipped experiment `name`.
    ///
    /// # Errors
    /// [`HarnessError::UnknownExperiment`] listing the shipped names.
    pub fn find(name: &str) -> Result<&'static ShippedExperiment, HarnessError> {
        SHIPPED
            .iter()
            .find(|e| e.name == name.trim())
            .ok_or_else(|| HarnessError::UnknownExperiment {
                name: name.trim().to_owned(),
                known: SHIPPED
                    .iter()
                    .map(|e| e.name)
                    .collect::<Vec<_>>()
                    .join(", "),
            })
    }
}
