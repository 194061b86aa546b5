//! The self-collision pairs of a [`RobotModel`]: SRDF disabled pairs, a scene's allowed
//! collisions, and how strictly unknown link names are treated.

use std::collections::HashSet;
use std::path::Path;

use crate::{ModelError, ModelWarning, RobotModel};

impl RobotModel {
    /// The same model, strict or lenient about link names (lenient by default). A strict model
    /// refuses SRDF and allowed-collision entries naming links it does not have
    /// ([`ModelError::UnknownLink`]); a lenient one ignores them and records a
    /// [`ModelWarning`] naming them ([`warnings`](Self::warnings)). Set it before applying an
    /// SRDF: it governs the entries applied after it.
    ///
    /// ```
    /// let urdf = include_str!("../../data/panda/panda_spherized.urdf");
    /// let model = mit_star_robot::RobotModel::from_urdf_str(urdf)?;
    /// assert!(model.clone().allow_collisions([("box_link", "panda_hand")]).is_ok());
    /// assert!(model.strict(true).allow_collisions([("box_link", "panda_hand")]).is_err());
    /// # Ok::<(), mit_star_robot::ModelError>(())
    /// ```
    #[must_use]
    pub fn strict(mut self, strict: bool) -> Self {
        self.strict = strict;
        self
    }

    /// `true` if unknown link names are errors (see [`strict`](Self::strict)).
    pub fn is_strict(&self) -> bool {
        self.strict
    }

    /// What was ignored so far: one warning per SRDF or allowed-collision matrix applied that
    /// named links the model does not have (never in strict mode).
    pub fn warnings(&self) -> &[ModelWarning] {
        &self.warnings
    }

    /// The same model with `warning` added to its [`warnings`](Self::warnings).
    pub(crate) fn with_warning(mut self, warning: ModelWarning) -> Self {
        self.warnings.push(warning);
        self
    }

    /// Applies an SRDF document: its `disable_collisions` pairs are no longer checked.
    ///
    /// # Errors
    /// [`ModelError::Srdf`] for malformed XML; in [strict mode](Self::strict),
    /// [`ModelError::UnknownLink`] for a pair naming a link the robot does not have (else
    /// such pairs are skipped and a [`ModelWarning`] names them).
    pub fn with_srdf_str(self, text: &str) -> Result<Self, ModelError> {
        self.with_srdf_named(text, "SRDF text")
    }

    /// As [`with_srdf_str`](Self::with_srdf_str), errors and warnings naming the document
    /// `origin` (a file name, say, for an SRDF compiled in).
    ///
    /// # Errors
    /// As [`with_srdf_str`](Self::with_srdf_str).
    pub fn with_srdf_named(self, text: &str, origin: &str) -> Result<Self, ModelError> {
        let pairs = crate::model::srdf::disabled_pairs(text, origin)?;
        self.disable(&pairs, origin)
    }

    /// Applies an SRDF file (see [`with_srdf_str`](Self::with_srdf_str)).
    ///
    /// # Errors
    /// [`ModelError::Io`] if it cannot be read, else as [`with_srdf_str`](Self::with_srdf_str).
    pub fn with_srdf_file(self, path: &Path) -> Result<Self, ModelError> {
        let text = ModelError::read_text(path, "SRDF")?;
        let origin = path.display().to_string();
        let pairs = crate::model::srdf::disabled_pairs(&text, &origin)?;
        self.disable(&pairs, &origin)
    }

    /// Stops checking the given link pairs for self-collision (a MoveIt scene's
    /// allowed-collision matrix). Pairs involving links without spheres change nothing.
    ///
    /// # Errors
    /// In [strict mode](Self::strict), [`ModelError::UnknownLink`] for a name that is not a
    /// link of the robot (else the pair is skipped and a [`ModelWarning`] names it).
    pub fn allow_collisions<'a>(
        self,
        pairs: impl IntoIterator<Item = (&'a str, &'a str)>,
    ) -> Result<Self, ModelError> {
        let pairs: Vec<(String, String)> = pairs
            .into_iter()
            .map(|(a, b)| (a.to_owned(), b.to_owned()))
            .collect();
        self.disable(&pairs, "allowed-collision matrix")
    }

    fn disable(mut self, pairs: &[(String, String)], origin: &str) -> Result<Self, ModelError> {
        let mut off = HashSet::new();
        let (mut unknown, mut entries) = (Vec::<String>::new(), 0);
        for (a, b) in pairs {
            match (self.link_index(a), self.link_index(b)) {
                (Some(i), Some(j)) => {
                    off.insert((i.min(j), i.max(j)));
                }
                (i, j) => {
                    let missing = if i.is_none() { a } else { b };
                    if self.strict {
                        return Err(ModelError::UnknownLink {
                            origin: origin.to_owned(),
                            link: missing.clone(),
                            robot: self.name.clone(),
                        });
                    }
                    entries += 1;
                    for (name, index) in [(a, i), (b, j)] {
                        if index.is_none() && !unknown.contains(name) {
                            unknown.push(name.clone());
                        }
                    }
                }
            }
        }
        if entries > 0 {
            self.warnings.push(ModelWarning::UnknownLinks {
                origin: origin.to_owned(),
                robot: self.name.clone(),
                links: unknown,
                entries,
            });
        }
        self.pairs.retain(|p| !off.contains(p));
        Ok(self)
    }
}
