//! Planning groups: which joints are the configuration's coordinates (an SRDF `<group>` or a
//! list of joints), and the values the other joints are held at.

use std::path::Path;

use crate::{ModelError, ModelWarning, RobotModel};

impl RobotModel {
    /// The same robot planning only the joints of the SRDF's planning group `group`, as
    /// MoveIt reads a `<group>`: a `<joint>` entry adds that joint, a `<link>` entry the joint
    /// above the link, a `<chain base_link tip_link>` the joints from the base (excluded) down
    /// to the tip, and a nested `<group>` its joints. Fixed joints in a group are ignored;
    /// mimic joints follow their leader whether named or not. Every other joint is held at
    /// its value ([`held_joints`](Self::held_joints): MoveIt's default, 0 or the middle of
    /// its limits, until [`with_joint_positions`](Self::with_joint_positions) changes it).
    ///
    /// Members naming joints or links the model lacks are skipped with a
    /// [`ModelWarning::UnknownGroupMembers`] (errors in [strict](Self::strict) mode).
    ///
    /// ```
    /// let urdf = include_str!("../../data/fetch/fetch_spherized.urdf");
    /// let srdf = include_str!("../../data/fetch/fetch.srdf");
    /// let fetch = mit_star_robot::RobotModel::from_urdf_str(urdf)?;
    /// assert_eq!(fetch.joint_names().len(), 8);
    /// let arm = fetch.with_group_str(srdf, "arm")?;
    /// assert_eq!(arm.joint_names().len(), 7);
    /// assert_eq!(arm.held_joints(), [("torso_lift_joint", 0.0)]);
    /// # Ok::<(), mit_star_robot::ModelError>(())
    /// ```
    ///
    /// # Errors
    /// [`ModelError::Srdf`] for malformed XML, [`ModelError::UnknownGroup`] listing the
    /// groups, [`ModelError::BadGroup`] for a chain whose base is not above its tip or a group
    /// including itself, [`ModelError::NoJoints`] for a group without a moving joint.
    pub fn with_group_str(self, srdf: &str, group: &str) -> Result<Self, ModelError> {
        self.with_group_named(srdf, "SRDF text", group)
    }

    /// As [`with_group_str`](Self::with_group_str), errors naming the document `origin`.
    ///
    /// # Errors
    /// As [`with_group_str`](Self::with_group_str).
    pub fn with_group_named(
        mut self,
        srdf: &str,
        origin: &str,
        group: &str,
    ) -> Result<Self, ModelError> {
        let document = roxmltree::Document::parse(srdf).map_err(|e| ModelError::Srdf {
            origin: origin.to_owned(),
            message: e.to_string(),
        })?;
        let groups: Vec<roxmltree::Node<'_, '_>> = document
            .root_element()
            .children()
            .filter(|n| n.has_tag_name("group"))
            .collect();
        let mut reader = GroupReader {
            model: &self,
            groups: &groups,
            origin,
            joints: Vec::new(),
            unknown: Vec::new(),
            open: Vec::new(),
        };
        if !groups.iter().any(|g| g.attribute("name") == Some(group)) {
            return Err(ModelError::UnknownGroup {
                origin: origin.to_owned(),
                group: group.to_owned(),
                known: groups
                    .iter()
                    .filter_map(|g| g.attribute("name"))
                    .collect::<Vec<_>>()
                    .join(", "),
            });
        }
        reader.read(group)?;
        let (joints, unknown) = (reader.joints, reader.unknown);
        if !unknown.is_empty() {
            if self.strict {
                return Err(ModelError::BadGroup {
                    origin: origin.to_owned(),
                    group: group.to_owned(),
                    why: format!("the robot has no {}", unknown.join(", ")),
                });
            }
            self.warnings.push(ModelWarning::UnknownGroupMembers {
                origin: origin.to_owned(),
                group: group.to_owned(),
                names: unknown,
            });
        }
        let names: Vec<&str> = joints.iter().map(String::as_str).collect();
        self.with_planned_joints(&names)
    }

    /// The names of the planning groups an SRDF document defines, in document order.
    ///
    /// # Errors
    /// [`ModelError::Srdf`] for malformed XML.
    pub fn srdf_groups(srdf: &str) -> Result<Vec<String>, ModelError> {
        let document = roxmltree::Document::parse(srdf).map_err(|e| ModelError::Srdf {
            origin: "SRDF text".into(),
            message: e.to_string(),
        })?;
        Ok(document
            .root_element()
            .children()
            .filter(|n| n.has_tag_name("group"))
            .filter_map(|g| g.attribute("name").map(str::to_owned))
            .collect())
    }

    /// Reads the SRDF file at `path` and plans its group `group` (see
    /// [`with_group_str`](Self::with_group_str)).
    ///
    /// # Errors
    /// [`ModelError::Io`] if it cannot be read, else as [`with_group_str`](Self::with_group_str).
    pub fn with_group_file(self, path: &Path, group: &str) -> Result<Self, ModelError> {
        let text = ModelError::read_text(path, "SRDF")?;
        self.with_group_named(&text, &path.display().to_string(), group)
    }

    /// The same robot planning exactly the moving joints named (in tree order, whatever the
    /// order here); fixed and mimic joints named are ignored, and the others are held.
    ///
    /// # Errors
    /// [`ModelError::BadGroup`] for a name that is not a joint of the URDF,
    /// [`ModelError::NoJoints`] if no moving joint is named.
    pub fn with_planned_joints(mut self, names: &[&str]) -> Result<Self, ModelError> {
        if let Some(name) = names
            .iter()
            .find(|&&n| !self.link_joints.iter().flatten().any(|j| j == n))
        {
            return Err(ModelError::BadGroup {
                origin: "joint list".into(),
                group: names.join(", "),
                why: format!("`{name}` is not a joint of robot `{}`", self.name),
            });
        }
        for joint in &mut self.joints {
            joint.planned = names.contains(&joint.name.as_str());
        }
        self.rebuild()?;
        Ok(self)
    }

    /// The same robot with held joints (those not planned, mimic joints aside) at the given
    /// values: a MotionBenchMaker request's `start_state`, say. Values are clamped into the
    /// joint's limits (wrapped into `[-π, π]` for a continuous joint); names of planned,
    /// mimic or unknown joints are ignored.
    ///
    /// # Errors
    /// None once the model loaded (the joints' structure does not change); typed because the
    /// frames are derived again.
    pub fn with_joint_positions<'a>(
        mut self,
        values: impl IntoIterator<Item = (&'a str, f64)>,
    ) -> Result<Self, ModelError> {
        let mut changed = false;
        for (name, value) in values {
            if let Some(joint) = self
                .joints
                .iter_mut()
                .find(|j| j.name == name && !j.planned && j.mimic.is_none() && value.is_finite())
            {
                joint.value = joint.admit(value);
                changed = true;
            }
        }
        if changed {
            self.rebuild()?;
        }
        Ok(self)
    }

    /// The moving joints that are not coordinates (mimic joints aside), with the values they
    /// are held at, in tree order.
    pub fn held_joints(&self) -> Vec<(&str, f64)> {
        self.joints
            .iter()
            .filter(|j| !j.planned && j.mimic.is_none())
            .map(|j| (j.name.as_str(), j.value))
            .collect()
    }
}

/// Collects the joints of a group, following nested groups.
struct GroupReader<'a, 'd> {
    model: &'a RobotModel,
    groups: &'a [roxmltree::Node<'d, 'd>],
    origin: &'a str,
    joints: Vec<String>,
    unknown: Vec<String>,
    /// The groups being read (a group inside itself is refused).
    open: Vec<String>,
}

impl GroupReader<'_, '_> {
    fn read(&mut self, group: &str) -> Result<(), ModelError> {
        let bad = |why: String| ModelError::BadGroup {
            origin: self.origin.to_owned(),
            group: group.to_owned(),
            why,
        };
        if self.open.iter().any(|g| g == group) {
            return Err(bad(format!(
                "it includes itself (through {})",
                self.open.join(" > ")
            )));
        }
        let groups = self.groups;
        let Some(node) = groups.iter().find(|g| g.attribute("name") == Some(group)) else {
            return Err(bad(format!(
                "it includes group `{group}`, which is not defined"
            )));
        };
        self.open.push(group.to_owned());
        for entry in node.children().filter(|n| n.is_element()) {
            let attribute = |name: &str| {
                entry.attribute(name).ok_or_else(|| {
                    bad(format!(
                        "<{}> without a `{name}` attribute",
                        entry.tag_name().name()
                    ))
                })
            };
            match entry.tag_name().name() {
                "joint" => self.joint(attribute("name")?),
                "link" => self.link(attribute("name")?),
                "chain" => self.chain(attribute("base_link")?, attribute("tip_link")?, group)?,
                "group" => self.read(attribute("name")?)?,
                _ => {}
            }
        }
        self.open.pop();
        Ok(())
    }

    fn joint(&mut self, name: &str) {
        if self.model.link_joints.iter().flatten().any(|j| j == name) {
            if !self.joints.iter().any(|j| j == name) {
                self.joints.push(name.to_owned());
            }
        } else {
            self.unknown.push(format!("joint `{name}`"));
        }
    }

    fn link(&mut self, name: &str) {
        match self.model.link_index(name) {
            Some(link) => {
                if let Some(joint) = self.model.link_joints[link].clone() {
                    self.joint(&joint);
                }
            }
            None => self.unknown.push(format!("link `{name}`")),
        }
    }

    fn chain(&mut self, base: &str, tip: &str, group: &str) -> Result<(), ModelError> {
        let (Some(base_index), Some(tip_index)) =
            (self.model.link_index(base), self.model.link_index(tip))
        else {
            for link in [base, tip] {
                if self.model.link_index(link).is_none() {
                    self.unknown.push(format!("link `{link}`"));
                }
            }
            return Ok(());
        };
        let mut on_chain = Vec::new();
        let mut at = Some(tip_index);
        while let Some(link) = at.filter(|&l| l != base_index) {
            on_chain.push(link);
            at = self.model.links()[link].parent;
        }
        if at.is_none() {
            return Err(ModelError::BadGroup {
                origin: self.origin.to_owned(),
                group: group.to_owned(),
                why: format!("chain base `{base}` is not above its tip `{tip}`"),
            });
        }
        for link in on_chain.into_iter().rev() {
            if let Some(joint) = self.model.link_joints[link].clone() {
                self.joint(&joint);
            }
        }
        Ok(())
    }
}
