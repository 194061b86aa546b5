//! [`Scene`]: the problem instances of one problem in one dimension — a MotionBenchMaker
//! scene's problems, random rectangles' layouts, or a single box world — summarised together.

use crate::definition::problem_instance::ProblemInstance;
use crate::definition::problem_source::ProblemSource;

/// The instances of an experiment that share a problem label and a dimension: what `bench`
/// summarises and draws by default (one table row per planner, one figure).
///
/// A scene of one instance (a box world, or a folder's single problem) keeps that instance's
/// id and title, so a box-world experiment's files are named as its instances are.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene {
    /// File-name-safe id: the instance's id for a scene of one instance, else
    /// `<label>-n<dimension>` (`box_panda-n7`).
    pub id: String,
    /// The label and the dimension: `box_panda R^7`, `dividing-walls R^4`,
    /// `random-rectangles R^8 #3` for a scene of one seeded layout.
    pub title: String,
    /// The problem's label.
    pub label: String,
    /// The indices of its instances in the experiment, in experiment order.
    pub instances: Vec<usize>,
    /// `true` for a MotionBenchMaker folder (its instances are problems, not layouts).
    pub arm: bool,
}

impl Scene {
    /// The scenes of `instances`, in the order their first instance appears.
    ///
    /// ```
    /// let experiment = mit_star_benches::Experiment::from_toml_str(
    ///     "planners = ['mit-star']\n[[problems]]\nname = 'random-rectangles'\n\
    ///      dimensions = [2, 4]\ntime = 1\ninstance_seeds = [1, 2]\n\
    ///      [[problems]]\nname = 'dividing-walls'\ndimensions = [2]\ntime = 1\n",
    ///     "scenes",
    ///     None,
    /// )?;
    /// let scenes = mit_star_benches::Scene::of(&experiment.instances()?);
    /// let ids: Vec<&str> = scenes.iter().map(|s| s.id.as_str()).collect();
    /// assert_eq!(ids, ["random-rectangles-n2", "random-rectangles-n4", "dividing-walls-n2"]);
    /// assert_eq!(scenes[0].instances, [0, 1]);
    /// assert_eq!(scenes[2].title, "dividing-walls R^2");
    /// # Ok::<(), mit_star_benches::HarnessError>(())
    /// ```
    pub fn of(instances: &[ProblemInstance]) -> Vec<Self> {
        let mut scenes: Vec<Self> = Vec::new();
        for (index, instance) in instances.iter().enumerate() {
            let same = |s: &&mut Self| {
                s.label == instance.label
                    && instances[s.instances[0]].dimension == instance.dimension
            };
            match scenes.iter_mut().find(|s| same(s)) {
                Some(scene) => scene.instances.push(index),
                None => scenes.push(Self {
                    id: instance.id.clone(),
                    title: instance.title(),
                    label: instance.label.clone(),
                    instances: vec![index],
                    arm: matches!(instance.source, ProblemSource::Mbm(_)),
                }),
            }
        }
        for scene in &mut scenes {
            if scene.instances.len() > 1 {
                let dimension = instances[scene.instances[0]].dimension;
                scene.id = ProblemInstance::make_id(&scene.label, dimension, None);
                scene.title = format!("{} R^{dimension}", scene.label);
            }
        }
        scenes
    }

    /// What its instances are called: `problems` (a MotionBenchMaker folder's) or `layouts`
    /// (a seeded family's), in the singular for one.
    pub fn instance_noun(&self) -> &'static str {
        match (self.arm, self.instances.len()) {
            (true, 1) => "problem",
            (true, _) => "problems",
            (false, 1) => "layout",
            (false, _) => "layouts",
        }
    }
}
