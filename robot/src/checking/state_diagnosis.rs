//! [`StateDiagnosis`]: what one arm configuration touches, by name — the answer to "why is
//! my start refused?".

use std::fmt;

use glam::{DAffine3, DVec3};
use mit_star_spaces::JointKind;
use mit_star_validity::StateValidity;

use crate::{ArmChecker, Kinematics, RobotModel, Scene};

/// A joint outside its limits.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitViolation {
    /// The joint's name.
    pub joint: String,
    /// Its value in the configuration.
    pub value: f64,
    /// Its lower limit.
    pub lower: f64,
    /// Its upper limit.
    pub upper: f64,
}

/// How close a link comes to an obstacle or to another link: the smallest gap between one of
/// its spheres and the other, in metres (`f64`), negative when they overlap.
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    /// The link.
    pub link: String,
    /// The obstacle's id in the scene, the other link's name, or a cloud's name and the
    /// index of its nearest point (`camera point 1234`).
    pub other: String,
    /// The smallest gap, metres: negative for an overlap (for an obstacle, at least that
    /// deep: the distance to a solid is 0 inside it).
    pub gap: f64,
}

/// One configuration of an arm, diagnosed in `f64`: the checker's verdict, then what makes it
/// invalid — joints outside their limits, links meeting obstacles, pairs of links meeting
/// each other (those the model checks: its self-collision pairs after the SRDF and the
/// scene's allowed-collision matrix) — and, for a valid one, the nearest obstacle.
///
/// A contact is reported when its gap is at most the checker's [margin](ArmChecker::margin)
/// (for an obstacle, the margin and the checker's [padding](ArmChecker::padding)): the checker
/// grows every sphere by it, so a gap that small is refused too.
///
/// ```
/// use mit_star_robot::{ArmProblem, StateDiagnosis};
/// let robot = ArmProblem::panda()?;
/// let scene = mit_star_robot::Scene::new(vec![]);
/// let checker = mit_star_robot::ArmChecker::new(&robot, &scene);
/// let home = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
/// let diagnosis = StateDiagnosis::of(&robot, &scene, &checker, &home);
/// assert!(diagnosis.valid && diagnosis.limits.is_empty());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct StateDiagnosis {
    /// The planners' checker calls the configuration valid.
    pub valid: bool,
    /// Joints outside their limits.
    pub limits: Vec<LimitViolation>,
    /// Links meeting obstacles (gap at most the margin and the padding), closest first.
    pub scene: Vec<Contact>,
    /// Pairs of links meeting each other (gap at most the margin), closest first.
    pub itself: Vec<Contact>,
    /// The link and obstacle closest to each other, if the scene has obstacles.
    pub nearest: Option<Contact>,
    /// The checker's margin, metres.
    pub margin: f64,
    /// The checker's padding from obstacles, metres (0 without one).
    pub padding: f64,
}

impl StateDiagnosis {
    /// `true` if the configuration is refused only for coming within the padding of the
    /// scene: within the joint limits, clear of itself, and every contact with an obstacle
    /// further than the margin.
    pub fn only_padding(&self) -> bool {
        !self.valid
            && self.limits.is_empty()
            && self.itself.is_empty()
            && !self.scene.is_empty()
            && self.scene.iter().all(|c| c.gap > self.margin)
    }

    /// The diagnosis of configuration `q` of `robot` in `scene`, with `checker` (built from
    /// the two) giving the verdict and the margin. A configuration of the wrong length is
    /// invalid, with nothing else said.
    pub fn of(robot: &RobotModel, scene: &Scene, checker: &ArmChecker, q: &[f64]) -> Self {
        let space = robot.joint_space();
        let mut diagnosis = Self {
            valid: q.len() == space.joints().len() && checker.is_valid(q),
            limits: Vec::new(),
            scene: Vec::new(),
            itself: Vec::new(),
            nearest: None,
            margin: checker.margin(),
            padding: checker.padding().metres(),
        };
        if q.len() != space.joints().len() || q.iter().any(|x| !x.is_finite()) {
            return diagnosis;
        }
        for (joint, &value) in space.joints().iter().zip(q) {
            if let JointKind::Revolute { lower, upper } | JointKind::Prismatic { lower, upper } =
                joint.kind
                && !(lower..=upper).contains(&value)
            {
                diagnosis.limits.push(LimitViolation {
                    joint: joint.name.clone(),
                    value,
                    lower,
                    upper,
                });
            }
        }
        let fk = Kinematics::new(robot);
        let mut poses = vec![DAffine3::IDENTITY; fk.link_count()];
        let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
        fk.sphere_centers_f64(q, &mut poses, &mut centers);
        let links = robot.links();
        let margin = checker.margin();
        let keep = margin + checker.padding().metres();
        let with_spheres = (0..links.len()).filter(|&l| !robot.link_sphere_range(l).is_empty());
        for link in with_spheres {
            for (obstacle, id) in scene.obstacles().iter().zip(scene.ids()) {
                let gap = robot
                    .link_sphere_range(link)
                    .map(|i| obstacle.distance_f64(centers[i].0) - centers[i].1)
                    .fold(f64::INFINITY, f64::min);
                let contact = Contact {
                    link: links[link].name.clone(),
                    other: id.clone(),
                    gap,
                };
                if gap <= keep {
                    diagnosis.scene.push(contact.clone());
                }
                if diagnosis.nearest.as_ref().is_none_or(|n| gap < n.gap) {
                    diagnosis.nearest = Some(contact);
                }
            }
            // Clouds: every point, in `f64`; the nearest point's ball names the contact.
            for cloud in scene.clouds() {
                let (gap, point) = robot
                    .link_sphere_range(link)
                    .map(|i| {
                        let (point, d) = cloud.nearest_ball_f64(centers[i].0);
                        (d - centers[i].1, point)
                    })
                    .fold(
                        (f64::INFINITY, 0),
                        |best, x| if x.0 < best.0 { x } else { best },
                    );
                let contact = Contact {
                    link: links[link].name.clone(),
                    other: format!("{} point {point}", cloud.name()),
                    gap,
                };
                if gap <= keep {
                    diagnosis.scene.push(contact.clone());
                }
                if diagnosis.nearest.as_ref().is_none_or(|n| gap < n.gap) {
                    diagnosis.nearest = Some(contact);
                }
            }
        }
        for &(a, b) in robot.self_collision_pairs() {
            let gap = robot
                .link_sphere_range(a)
                .flat_map(|i| robot.link_sphere_range(b).map(move |j| (i, j)))
                .map(|(i, j)| centers[i].0.distance(centers[j].0) - centers[i].1 - centers[j].1)
                .fold(f64::INFINITY, f64::min);
            if gap <= 2.0 * margin {
                diagnosis.itself.push(Contact {
                    link: links[a].name.clone(),
                    other: links[b].name.clone(),
                    gap,
                });
            }
        }
        diagnosis.scene.sort_by(|x, y| x.gap.total_cmp(&y.gap));
        diagnosis.itself.sort_by(|x, y| x.gap.total_cmp(&y.gap));
        diagnosis
    }
}

impl fmt::Display for StateDiagnosis {
    /// The verdict, then one indented line per finding (no final line break).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mm = |gap: f64| {
            if gap < 0.0 {
                format!("overlap {:.3} mm", -gap * 1e3)
            } else {
                format!("gap {:.3} mm", gap * 1e3)
            }
        };
        let mut lines = vec![if self.valid {
            "valid".to_owned()
        } else {
            "INVALID (refused by the planners' checker)".to_owned()
        }];
        for v in &self.limits {
            lines.push(format!(
                "  joint {} = {} is outside its limits [{}, {}]",
                v.joint, v.value, v.lower, v.upper
            ));
        }
        for c in &self.scene {
            lines.push(if c.gap > self.margin {
                format!(
                    "  link {} is within the padding ({} mm) of obstacle {} ({})",
                    c.link,
                    mit_star_spaces::short_number(self.padding * 1e3),
                    c.other,
                    mm(c.gap)
                )
            } else {
                format!(
                    "  link {} meets obstacle {} ({})",
                    c.link,
                    c.other,
                    mm(c.gap)
                )
            });
        }
        for c in &self.itself {
            lines.push(format!(
                "  link {} meets link {} ({})",
                c.link,
                c.other,
                mm(c.gap)
            ));
        }
        if let Some(c) = self.nearest.as_ref().filter(|_| self.scene.is_empty()) {
            lines.push(format!(
                "  nearest obstacle: {} to link {} ({})",
                c.other,
                c.link,
                mm(c.gap)
            ));
        }
        write!(f, "{}", lines.join("\n"))
    }
}

#[cfg(test)]
mod tests {
    use glam::DQuat;

    use super::*;
    use crate::{ArmProblem, Obstacle, Shape};

    const HOME: [f64; 7] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];

    #[test]
    fn a_ball_on_the_hand_is_named_and_a_clear_scene_gives_the_nearest_obstacle() {
        let robot = ArmProblem::panda().unwrap();
        let fk = Kinematics::new(&robot);
        let mut poses = vec![DAffine3::IDENTITY; fk.link_count()];
        let mut centers = vec![(DVec3::ZERO, 0.0); fk.sphere_count()];
        fk.sphere_centers_f64(&HOME, &mut poses, &mut centers);
        let hand = robot
            .links()
            .iter()
            .position(|l| l.name == "panda_hand")
            .unwrap();
        let at = centers[robot.link_sphere_range(hand).start].0;
        for (offset, touching) in [(0.0, true), (0.5, false)] {
            let ball = Obstacle::new(
                Shape::Sphere { radius: 0.01 },
                at + DVec3::new(0.0, 0.0, offset),
                DQuat::IDENTITY,
            );
            let scene = Scene::new(vec![ball]);
            let checker = ArmChecker::new(&robot, &scene);
            let d = StateDiagnosis::of(&robot, &scene, &checker, &HOME);
            assert_eq!(d.valid, !touching, "{d}");
            assert_eq!(
                d.scene.iter().any(|c| c.link == "panda_hand"),
                touching,
                "{d}"
            );
            let nearest = d.nearest.as_ref().unwrap();
            assert_eq!(nearest.other, "obstacle0");
            assert_eq!(nearest.gap < 0.0, touching, "{d}");
            assert!(d.itself.is_empty() && d.limits.is_empty(), "{d}");
        }
    }

    #[test]
    fn limits_and_self_collision_are_named_and_a_short_state_is_only_invalid() {
        let robot = ArmProblem::panda().unwrap();
        let scene = Scene::new(vec![]);
        let checker = ArmChecker::new(&robot, &scene);
        let d = StateDiagnosis::of(
            &robot,
            &scene,
            &checker,
            &[3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        );
        assert!(!d.valid);
        assert_eq!(d.limits.len(), 1);
        assert_eq!(d.limits[0].joint, "panda_joint1");
        assert!(
            d.itself
                .iter()
                .any(|c| c.link == "panda_link5" && c.other == "panda_hand"),
            "{d}"
        );
        assert!(d.nearest.is_none());
        let short = StateDiagnosis::of(&robot, &scene, &checker, &[0.0; 3]);
        assert!(!short.valid && short.limits.is_empty() && short.itself.is_empty());
    }
}
