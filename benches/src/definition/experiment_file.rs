//! The TOML experiment file format: its schema ([`ExperimentFile`]) and its conversion into an
//! [`Experiment`], with errors that name the offending field.
//!
//! ```toml
//! name = "dw4"                        # default: the file's stem
//! description = "MIT* against EIT*"  # optional
//! runs = 100                          # runs per planner and problem instance (default 100)
//! seed = 0                            # run i on instance k: seed + k·100000 + i (default 0)
//! confidence = 0.99                   # of medians' and success rates' intervals (default 0.99)
//! first_solution = false              # stop each run at its first solution (default false)
//! planners = ["eit-star", "mit-star"] # configuration names, or tables:
//!
//! [parameters]                        # overrides for every planner (optional)
//! batch_size = 100
//!
//! [[planners]]                        # (instead of the list above)
//! configuration = "mit-star"
//! name = "MIT* (batch 200)"           # optional, default the paper's label
//! parameters = { batch_size = 200 }   # optional, on top of [parameters]
//!
//! [[problems]]
//! name = "dividing-walls"             # a built-in problem, or:  file = "my-problem.toml"
//! dimensions = [4, 8, 16]             # not for files (their dimension is fixed)
//! time = [0.3, 0.6, 1.5]              # seconds per run: one per dimension, or one for all
//! instances = 10                      # seeded families: layout seeds 0..9 (default 1), or
//! # instance_seeds = [3, 7]
//! # resolution = 5e-6                 # collision-check resolution (default the problem's)
//! # allow_coarse_step = true          # allow checks that can miss thin obstacles: a step
//! #                                   # coarser than the thinnest box, an arm planned with
//! #                                   # certification off (default false)
//! # padding = 0.01                    # arms: metres every robot sphere keeps from every
//! #                                   # obstacle, certified (default 0, at most 1)
//! # robot = "ur5"                     # `name = "mbm:PATH"` only: a shipped robot (panda, the
//! #                                   # default, ur5, fetch, baxter) or a folder with a URDF
//! #                                   # and SRDF
//! # group = "right_arm"               # plan only this SRDF planning group (default: every
//! #                                   # moving joint; the others take the request's values)
//! # strict_robot = true               # refuse SRDF entries naming links the robot lacks
//! # [problems.cloud]                  # `name = "mbm:PATH"` only: a point cloud obstacle,
//! # scene_as_cloud = 10000            # the keys of `CloudSpec` (the command line's cloud
//! # voxel = 0.02                      # options: files, sensor_pose, scene_as_cloud, seed,
//! #                                   # point_radius, crop_reach, remove_robot, voxel,
//! #                                   # min_distance, drop_primitives)
//! # [problems.pose_goal]              # `name = "mbm:PATH"` only: a link's pose as the goal,
//! # link = "panda_hand"               # the keys of `PoseGoalSpec` (the command line's
//! # pose = "goal"                     # --goal-pose options: pose, link, tool,
//! #                                   # position_tolerance, orientation_tolerance, ik_goals)
//! ```

use std::fmt;
use std::path::Path;

use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Serialize};

use crate::definition::cloud_spec::CloudSpec;
use crate::definition::experiment::Experiment;
use crate::definition::parameter_overrides::ParameterOverrides;
use crate::definition::planner_spec::{PlannerSpec, parse_configuration};
use crate::definition::pose_goal_spec::PoseGoalSpec;
use crate::definition::problem_source::ProblemSource;
use crate::definition::problem_spec::{ProblemSpec, check_instance_count};
use crate::definition::robot_choice::RobotChoice;
use crate::error::HarnessError;

/// The schema of an experiment file, as parsed (before names are checked).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ExperimentFile {
    /// The experiment's name.
    pub name: Option<String>,
    /// One line on what it measures.
    pub description: Option<String>,
    /// Runs per planner and problem instance.
    pub runs: Option<usize>,
    /// Base seed.
    pub seed: Option<u64>,
    /// Confidence of the intervals.
    pub confidence: Option<f64>,
    /// Stop each run at its first solution.
    pub first_solution: Option<bool>,
    /// Overrides for every planner.
    #[serde(default)]
    pub parameters: toml::Table,
    /// The planners.
    pub planners: Vec<PlannerEntry>,
    /// The problems.
    pub problems: Vec<ProblemEntry>,
}

/// A planner entry: a configuration name, or a table with a name and overrides.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum PlannerEntry {
    /// Just a configuration name (`"mit-star"`).
    Name(String),
    /// A configuration with a display name and parameter overrides.
    Table(PlannerTable),
}

/// A planner table of an experiment file.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PlannerTable {
    /// The configuration's name (`mit-star`, …).
    pub configuration: String,
    /// The name reports print.
    pub name: Option<String>,
    /// Overrides for this planner.
    #[serde(default)]
    pub parameters: toml::Table,
}

impl<'de> Deserialize<'de> for PlannerEntry {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct EntryVisitor;
        impl<'de> Visitor<'de> for EntryVisitor {
            type Value = PlannerEntry;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a configuration name or a table with `configuration`")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<PlannerEntry, E> {
                Ok(PlannerEntry::Name(v.to_owned()))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<PlannerEntry, A::Error> {
                PlannerTable::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(PlannerEntry::Table)
            }
        }
        deserializer.deserialize_any(EntryVisitor)
    }
}

/// A problem entry of an experiment file.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ProblemEntry {
    /// A built-in problem's name.
    pub name: Option<String>,
    /// A problem file's path (relative to the experiment file).
    pub file: Option<String>,
    /// Dimensions (built-in problems).
    #[serde(default)]
    pub dimensions: Vec<usize>,
    /// Seconds per run: one value, or one per dimension.
    pub time: Seconds,
    /// Number of layout seeds `0..instances` (seeded families).
    pub instances: Option<u64>,
    /// Explicit layout seeds (seeded families).
    pub instance_seeds: Option<Vec<u64>>,
    /// Collision-check resolution.
    pub resolution: Option<f64>,
    /// Allow checks that can miss thin obstacles (a coarse step; an arm without
    /// certification).
    pub allow_coarse_step: Option<bool>,
    /// Metres every robot sphere keeps from every obstacle (arm problems only; default 0).
    pub padding: Option<f64>,
    /// The robot a MotionBenchMaker folder is planned for: a shipped name (`panda`, the
    /// default, `ur5`, `fetch`, `baxter`) or a folder with a URDF and an SRDF (relative to the file).
    pub robot: Option<String>,
    /// The SRDF planning group planned (`right_arm`); default every moving joint.
    pub group: Option<String>,
    /// Refuse SRDF and allowed-collision entries naming links the robot lacks.
    pub strict_robot: Option<bool>,
    /// A point cloud among the obstacles (MotionBenchMaker problems only): the keys of
    /// [`CloudSpec`], named as the command line's cloud options.
    pub cloud: Option<CloudSpec>,
    /// A link's pose as the goal (MotionBenchMaker problems only): the keys of
    /// [`PoseGoalSpec`].
    pub pose_goal: Option<PoseGoalSpec>,
}

/// One number of seconds or a list of them; integers are accepted.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(transparent)]
pub struct Seconds(pub Vec<f64>);

impl<'de> Deserialize<'de> for Seconds {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct SecondsVisitor;
        impl<'de> Visitor<'de> for SecondsVisitor {
            type Value = Seconds;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number of seconds or a list of them")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Seconds, E> {
                Ok(Seconds(vec![v]))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Seconds, E> {
                Ok(Seconds(vec![v as f64]))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Seconds, E> {
                Ok(Seconds(vec![v as f64]))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Seconds, A::Error> {
                let mut out = Vec::new();
                while let Some(Seconds(v)) = seq.next_element::<Seconds>()? {
                    if v.len() != 1 {
                        return Err(de::Error::custom("nested lists of seconds"));
                    }
                    out.push(v[0]);
                }
                Ok(Seconds(out))
            }
        }
        deserializer.deserialize_any(SecondsVisitor)
    }
}

impl ExperimentFile {
    /// Parses the text of an experiment file; `origin` names it in errors.
    ///
    /// # Errors
    /// [`HarnessError::ExperimentFile`] with the parser's message (field and line).
    pub fn parse(text: &str, origin: &str) -> Result<Self, HarnessError> {
        toml::from_str(text).map_err(|e| HarnessError::ExperimentFile {
            file: origin.to_owned(),
            message: crate::error::clip_lines(&mit_star_problems::humanise(
                e.to_string().trim_end(),
            )),
        })
    }

    /// Checks every name and value and builds the [`Experiment`]. `default_name` names it when
    /// the file does not; relative problem file paths are resolved against `base`.
    ///
    /// # Errors
    /// [`HarnessError::ExperimentField`] naming the field (`planners[1]`, `problems[0].time`,
    /// …) and what is wrong with it.
    pub fn into_experiment(
        self,
        origin: &str,
        default_name: &str,
        base: Option<&Path>,
    ) -> Result<Experiment, HarnessError> {
        let field = |field: String, e: HarnessError| HarnessError::ExperimentField {
            experiment: origin.to_owned(),
            field,
            message: format!("is not acceptable: {e}"),
        };
        let global = ParameterOverrides::from_table(self.parameters)
            .map_err(|e| field("parameters".into(), e))?;
        let mut planners = Vec::new();
        for (i, entry) in self.planners.into_iter().enumerate() {
            let spec = match entry {
                PlannerEntry::Name(name) => parse_configuration(&name)
                    .and_then(|c| PlannerSpec::new(c, None, &global))
                    .map_err(|e| field(format!("planners[{i}]"), e))?,
                PlannerEntry::Table(t) => {
                    let c = parse_configuration(&t.configuration)
                        .map_err(|e| field(format!("planners[{i}].configuration"), e))?;
                    let own = ParameterOverrides::from_table(t.parameters)
                        .map_err(|e| field(format!("planners[{i}].parameters"), e))?;
                    PlannerSpec::new(c, t.name, &global.then(&own))
                        .map_err(|e| field(format!("planners[{i}]"), e))?
                }
            };
            planners.push(spec);
        }
        let mut problems = Vec::new();
        for (i, p) in self.problems.into_iter().enumerate() {
            problems.push(problem_spec(p, i, base, origin)?);
        }
        let experiment = Experiment {
            // An explicit name is checked as given; the default (a file's stem) is made safe.
            name: self
                .name
                .unwrap_or_else(|| crate::definition::experiment::safe_name(default_name)),
            description: self.description.unwrap_or_default(),
            planners,
            problems,
            runs: self.runs.unwrap_or(100),
            seed: self.seed.unwrap_or(0),
            confidence: self.confidence.unwrap_or(0.99),
            first_solution: self.first_solution.unwrap_or(false),
        };
        experiment.validate(origin)?;
        Ok(experiment)
    }
}

/// Converts one problem entry; errors name the field (`problems[2].time`, …).
fn problem_spec(
    p: ProblemEntry,
    index: usize,
    base: Option<&Path>,
    origin: &str,
) -> Result<ProblemSpec, HarnessError> {
    let bad = |sub: &str, e: HarnessError| HarnessError::ExperimentField {
        experiment: origin.to_owned(),
        field: format!("problems[{index}]{sub}"),
        message: format!("is not acceptable: {e}"),
    };
    let source = match (&p.name, &p.file) {
        // `mbm:PATH` is a MotionBenchMaker folder (relative to the file's folder, or to the
        // working folder for a file without one): its errors say what is wrong with it.
        (Some(name), None) if name.trim().starts_with("mbm:") => {
            let strict = p.strict_robot.unwrap_or(false);
            let robot = RobotChoice::parse(p.robot.as_deref(), base, strict)
                .map_err(|e| bad(".robot", e))?
                .with_group(p.group.as_deref());
            ProblemSource::parse_for_robot(name, base, &robot).map_err(|e| bad(".name", e))?
        }
        _ if p.robot.is_some() || p.strict_robot.is_some() || p.group.is_some() => {
            return Err(bad(
                ".robot",
                HarnessError::Usage(
                    "`robot`, `group` and `strict_robot` apply to MotionBenchMaker problems (`name = \"mbm:PATH\"`)"
                        .into(),
                ),
            ));
        }
        (Some(name), None) => match ProblemSource::parse(name, None) {
            Ok(ProblemSource::Builtin(b)) => ProblemSource::Builtin(b),
            _ => {
                return Err(bad(
                    ".name",
                    HarnessError::UnknownProblem {
                        name: name.clone(),
                        known: crate::definition::problem_source::builtin_names(),
                    },
                ));
            }
        },
        (None, Some(file)) => {
            let path = match base {
                Some(b) if Path::new(file).is_relative() => b.join(file),
                _ => file.into(),
            };
            ProblemSource::file(path).map_err(|e| bad(".file", e))?
        }
        _ => {
            return Err(bad(
                "",
                HarnessError::Usage(format!(
                    "problem entry {index} needs exactly one of `name` and `file`"
                )),
            ));
        }
    };
    let dimensions = match source.fixed_dimension().map_err(|e| bad(".file", e))? {
        Some(n) if p.dimensions.is_empty() || p.dimensions == [n] => vec![n],
        Some(n) => {
            return Err(bad(
                ".dimensions",
                HarnessError::Usage(format!(
                    "the problem file is {n}-dimensional; leave `dimensions` out"
                )),
            ));
        }
        None if p.dimensions.is_empty() => {
            return Err(bad(
                ".dimensions",
                HarnessError::Usage("a built-in problem needs `dimensions = [...]`".into()),
            ));
        }
        None => p.dimensions,
    };
    let budgets = match p.time.0.len() {
        1 => vec![p.time.0[0]; dimensions.len()],
        n if n == dimensions.len() => p.time.0,
        n => {
            return Err(bad(
                ".time",
                HarnessError::Usage(format!(
                    "has {n} budgets for {} dimensions; give one, or one per dimension",
                    dimensions.len()
                )),
            ));
        }
    };
    for &b in &budgets {
        if let Err(e) = crate::budget_duration(b) {
            return Err(bad(".time", HarnessError::Usage(e.to_string())));
        }
    }
    let instances = match (p.instances, p.instance_seeds) {
        (Some(_), Some(_)) => {
            return Err(bad(
                ".instances",
                HarnessError::Usage("give `instances` or `instance_seeds`, not both".into()),
            ));
        }
        (Some(0), None) => {
            return Err(bad(
                ".instances",
                HarnessError::Usage("must be at least 1".into()),
            ));
        }
        (Some(k), None) => {
            check_instance_count(Some(k))
                .map_err(|message| bad(".instances", HarnessError::Usage(message)))?;
            (0..k).collect()
        }
        (None, Some(seeds)) if seeds.is_empty() => {
            return Err(bad(
                ".instance_seeds",
                HarnessError::Usage("is empty".into()),
            ));
        }
        (None, Some(seeds)) => {
            check_instance_count(Some(seeds.len() as u64))
                .map_err(|message| bad(".instance_seeds", HarnessError::Usage(message)))?;
            seeds
        }
        (None, None) => vec![0],
    };
    let cloud = match p.cloud {
        None => None,
        Some(_) if !matches!(source, ProblemSource::Mbm(_)) => {
            return Err(bad(
                ".cloud",
                HarnessError::Usage(format!(
                    "point clouds are obstacles of arm problems (`name = \"mbm:PATH\"`); `{}` \
                     is a box world",
                    source.label()
                )),
            ));
        }
        Some(cloud) => {
            let cloud = cloud.relative_to(base);
            // The error names the entry and the option: `cloud.files` (--cloud).
            cloud.check(&format!("`{}` (problems[{index}])", source.label()), false)?;
            Some(cloud)
        }
    };
    let pose_goal = match p.pose_goal {
        None => None,
        Some(_) if !matches!(source, ProblemSource::Mbm(_)) => {
            return Err(bad(
                ".pose_goal",
                HarnessError::Usage(format!(
                    "a pose goal is a goal of arm problems (`name = \"mbm:PATH\"`); `{}` is a \
                     box world",
                    source.label()
                )),
            ));
        }
        Some(pose) => {
            pose.check().map_err(|e| bad(".pose_goal", e))?;
            Some(pose)
        }
    };
    let padding = mit_star_robot::Padding::new(p.padding.unwrap_or(0.0))
        .map_err(|e| bad(".padding", HarnessError::Usage(e.to_string())))?;
    if !padding.is_zero() && !matches!(source, ProblemSource::Mbm(_)) {
        return Err(bad(
            ".padding",
            HarnessError::Usage(format!(
                "a collision padding applies to arm problems (`name = \"mbm:PATH\"`); `{}` is \
                 a box world",
                source.label()
            )),
        ));
    }
    if instances.len() > 1 && !source.is_seeded() {
        return Err(bad(
            ".instances",
            HarnessError::Usage(format!(
                "`{}` does not depend on a seed: it has one instance",
                source.label()
            )),
        ));
    }
    Ok(ProblemSpec {
        source,
        dimensions,
        budgets,
        instances,
        resolution: p.resolution,
        allow_coarse_step: p.allow_coarse_step.unwrap_or(false),
        padding,
        cloud,
        pose_goal,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn load(text: &str) -> Result<Experiment, HarnessError> {
        ExperimentFile::parse(text, "test.toml")?.into_experiment("test.toml", "test", None)
    }

    const GOOD: &str = r#"
        runs = 3
        planners = ["eit-star", { configuration = "mit-star", name = "M", parameters = { batch_size = 20 } }]
        [parameters]
        batch_size = 50
        [[problems]]
        name = "dividing-walls"
        dimensions = [2, 4]
        time = 1
        [[problems]]
        name = "random-rectangles"
        dimensions = [2]
        time = [0.5]
        instances = 2
    "#;

    #[test]
    fn a_good_file_gives_the_experiment() {
        let e = load(GOOD).unwrap();
        assert_eq!(e.name, "test");
        assert_eq!(e.runs, 3);
        assert_eq!((e.seed, e.confidence), (0, 0.99));
        assert_eq!(e.planners[0].name(), "EIT*");
        assert_eq!(e.planners[0].parameters_for_seed(0).batch_size, Some(50));
        assert_eq!(e.planners[1].name(), "M");
        assert_eq!(e.planners[1].parameters_for_seed(0).batch_size, Some(20));
        assert_eq!(e.problems[0].budgets, vec![1.0, 1.0]);
        assert_eq!(e.problems[1].instances, vec![0, 1]);
        assert_eq!(e.instances().unwrap().len(), 4);
    }

    fn error(text: &str) -> String {
        load(text).unwrap_err().to_string()
    }

    #[test]
    fn errors_name_the_field() {
        let base = "planners = [\"mit-star\"]\n";
        let e = error(&format!(
            "{base}rnus = 3\n[[problems]]\nname='flanking-gap'\ndimensions=[2]\ntime=1"
        ));
        assert!(e.contains("unknown field `rnus`"), "{e}");
        let e = error(
            "planners = [\"rrt\"]\n[[problems]]\nname='flanking-gap'\ndimensions=[2]\ntime=1",
        );
        assert!(
            e.contains("`planners[0]`") && e.contains("valid planners"),
            "{e}"
        );
        let e = error(&format!(
            "{base}[[problems]]\nname='flanking-gaps'\ndimensions=[2]\ntime=1"
        ));
        assert!(
            e.contains("`problems[0].name`") && e.contains("built-in problems"),
            "{e}"
        );
        let e = error(&format!(
            "{base}[[problems]]\nname='flanking-gap'\ndimensions=[2,4]\ntime=[1,2,3]"
        ));
        assert!(
            e.contains("`problems[0].time`") && e.contains("3 budgets for 2"),
            "{e}"
        );
        let e = error(&format!(
            "{base}[[problems]]\nname='flanking-gap'\ndimensions=[2]\ntime=0"
        ));
        assert!(e.contains("`problems[0].time`"), "{e}");
        let e = error(&format!("{base}[[problems]]\nname='flanking-gap'\ntime=1"));
        assert!(e.contains("`problems[0].dimensions`"), "{e}");
        let e = error(&format!(
            "{base}[[problems]]\nname='flanking-gap'\ndimensions=[2]\ntime=1\ninstances=3"
        ));
        assert!(e.contains("`problems[0].instances`"), "{e}");
        let e = error(&format!(
            "{base}[parameters]\nbatch_size = 'x'\n[[problems]]\nname='flanking-gap'\ndimensions=[2]\ntime=1"
        ));
        assert!(
            e.contains("`parameters`") && e.contains("batch_size"),
            "{e}"
        );
        let e = error(&format!(
            "{base}[[problems]]\nfile='/no/such/file.toml'\ntime=1"
        ));
        assert!(e.contains("`problems[0].file`"), "{e}");
        let e = error(&format!(
            "{base}runs = 0\n[[problems]]\nname='flanking-gap'\ndimensions=[2]\ntime=1"
        ));
        assert!(e.contains("`runs`"), "{e}");
        let e = error("planners = [3]\nproblems = []");
        assert!(e.contains("configuration name"), "{e}");
    }
}
