//! [`StaticAudit`]: the arm's executed motion in re-planning trials, checked independently
//! against what stands still — the fixed obstacles and the point cloud.

use std::sync::Arc;

use mit_star_robot::{AuditVerdict, MotionAudit, Scene};

use crate::replanning::replanning_scene::ReplanningSetup;
use crate::replanning::trial_record::TrialRecord;

/// Configurations the audit may compute per executed motion before it calls it undecided.
const AUDIT_BUDGET: u64 = 200_000;

/// The executed motion of trials checked against a scene's static obstacles (its fixed
/// primitives and clouds) by the continuous `f64` audit ([`MotionAudit`]: every point of a
/// cloud, by brute force), which shares no code with the checker the trials plan and judge
/// with. Moving obstacles are the trials' judge's ([`MotionJudge`](super::MotionJudge)).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StaticAudit {
    /// Trials audited.
    pub trials: usize,
    /// Straight motions audited (holds count once, repeated configurations not at all).
    pub motions: usize,
    /// The smallest clearance seen over every motion proven clear (metres).
    pub clearance: f64,
    /// One line per motion not proven clear: the trial and what touched.
    pub failures: Vec<String>,
}

impl StaticAudit {
    /// Audits the executed motion of every record of `records` made in `setup`.
    pub fn of(setup: &ReplanningSetup, records: &[&TrialRecord]) -> Self {
        let mut scene = Scene::new(setup.scene.fixed().to_vec());
        for cloud in setup.scene.clouds() {
            scene.add_shared_cloud(Arc::clone(cloud));
        }
        let audit = MotionAudit::new(&setup.robot, &scene);
        let mut out = Self {
            clearance: f64::INFINITY,
            ..Self::default()
        };
        for record in records {
            out.trials += 1;
            let states: Vec<&Vec<f64>> = record.trajectory.iter().map(|(_, q)| q).collect();
            let mut motions: Vec<(&Vec<f64>, &Vec<f64>)> =
                states.windows(2).map(|w| (w[0], w[1])).collect();
            motions.dedup();
            if motions.is_empty()
                && let Some(q) = states.first()
            {
                motions.push((q, q));
            }
            for (a, b) in motions {
                out.motions += 1;
                match audit.audit(a, b, AUDIT_BUDGET) {
                    AuditVerdict::Clear { clearance, .. } => {
                        out.clearance = out.clearance.min(clearance);
                    }
                    AuditVerdict::Collides { t, contact, .. } => out.failures.push(format!(
                        "{} {} trial {}: {contact} at t = {t:.3} of a motion",
                        record.scene, record.planner, record.trial
                    )),
                    AuditVerdict::Undecided { t, .. } => out.failures.push(format!(
                        "{} {} trial {}: a motion undecided after {AUDIT_BUDGET} \
                         configurations (certified to t = {t:.3})",
                        record.scene, record.planner, record.trial
                    )),
                }
            }
        }
        out
    }

    /// One line for the report.
    pub fn line(&self) -> String {
        let clearance = if self.clearance.is_finite() {
            format!(
                ", clearance ≥ {} mm",
                mit_star_spaces::short_number(self.clearance * 1e3)
            )
        } else {
            String::new()
        };
        format!(
            "Executed motion audited against the fixed obstacles and the cloud (independently, \
             continuously, in f64, every point): {} motions of {} trials, {} not proven \
             clear{clearance}.",
            self.motions,
            self.trials,
            self.failures.len()
        )
    }
}
