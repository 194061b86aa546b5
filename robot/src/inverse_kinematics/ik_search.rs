//! The search of [`IkSolver`]: attempts from the start and from random restarts, each a
//! Levenberg–Marquardt descent within the joint limits.

use std::f64::consts::TAU;

use glam::DVec3;
use mit_star_spaces::{StateSpace, Stop, wrap_angle};
use mit_star_validity::StateValidity;

use crate::inverse_kinematics::dls_step::dls_step;
use crate::inverse_kinematics::ik_solver::Limits;
use crate::{IkError, IkSolution, IkSolver, PoseTarget};

/// How one descent ended: converged, gave up, or stopped; with the errors it reached.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Descent {
    Converged(f64, f64),
    Failed(f64, f64),
    Stopped(f64, f64),
}

/// The damping beyond which a descent is stuck (steps no longer reduce the error).
const MAX_LAMBDA2: f64 = 1e2;

/// How far below the set damping `λ²` may fall after successful steps.
const FLOOR_FACTOR: f64 = 1e-6;

impl IkSolver {
    /// A configuration placing the solver's frame at `target`: first a descent from
    /// `start`, then from random configurations until one converges to a configuration
    /// `validity` accepts, or the attempts ([`restarts`](Self::restarts)) run out, or `stop`
    /// fires (polled every iteration).
    ///
    /// # Errors
    /// [`IkError::WrongLength`] or [`IkError::NonFiniteCoordinate`] for a bad `start`;
    /// [`IkError::Unreachable`] when every attempt failed, [`IkError::Stopped`] when `stop`
    /// fired, both with the smallest errors reached.
    pub fn solve(
        &mut self,
        target: &PoseTarget,
        start: &[f64],
        validity: &dyn StateValidity,
        stop: &dyn Stop,
    ) -> Result<IkSolution, IkError> {
        self.solve_avoiding(target, start, &[], validity, stop)
    }

    /// As [`solve`](Self::solve), accepting only a configuration at least
    /// [`distinct_distance`](Self::distinct_distance) (in the joint space's metric) from
    /// each of `avoid`.
    ///
    /// # Errors
    /// As [`solve`](Self::solve); also [`IkError::WrongLength`] for a configuration of
    /// `avoid` of the wrong length.
    pub fn solve_avoiding(
        &mut self,
        target: &PoseTarget,
        start: &[f64],
        avoid: &[Vec<f64>],
        validity: &dyn StateValidity,
        stop: &dyn Stop,
    ) -> Result<IkSolution, IkError> {
        self.check_configuration(start)?;
        for other in avoid {
            self.check_configuration(other)?;
        }
        let (mut best, mut best_cost) = ((f64::INFINITY, f64::INFINITY), f64::INFINITY);
        let (mut iterations, mut rejected) = (0, 0);
        for attempt in 0..=self.restarts {
            if stop.should_stop() {
                return Err(IkError::Stopped {
                    attempts: attempt,
                    position_error: best.0,
                    orientation_error: best.1,
                });
            }
            if attempt == 0 {
                let coordinates = self.scratch.q.iter_mut().zip(&self.limits).zip(start);
                for ((q, &limits), &value) in coordinates {
                    *q = admit(limits, value);
                }
            } else {
                self.space
                    .sample_uniform(&mut self.rng, &mut self.scratch.q);
            }
            let outcome = self.descend(target, stop, &mut iterations);
            let (Descent::Converged(p, o) | Descent::Failed(p, o) | Descent::Stopped(p, o)) =
                outcome;
            if p * p + o * o < best_cost {
                (best, best_cost) = ((p, o), p * p + o * o);
            }
            match outcome {
                Descent::Stopped(..) => {
                    return Err(IkError::Stopped {
                        attempts: attempt + 1,
                        position_error: best.0,
                        orientation_error: best.1,
                    });
                }
                Descent::Failed(..) => {}
                Descent::Converged(p, o) => {
                    let q = &self.scratch.q;
                    let distinct = avoid
                        .iter()
                        .all(|s| self.space.distance(q, s) >= self.distinct);
                    if distinct && validity.is_valid(q) {
                        return Ok(IkSolution {
                            configuration: q.clone(),
                            position_error: p,
                            orientation_error: o,
                            attempts: attempt + 1,
                            iterations,
                        });
                    }
                    rejected += 1;
                }
            }
        }
        Err(IkError::Unreachable {
            attempts: self.restarts + 1,
            rejected,
            position_error: best.0,
            orientation_error: best.1,
        })
    }

    /// One Levenberg–Marquardt descent from `scratch.q` (within the limits), leaving the
    /// configuration reached there.
    fn descend(&mut self, target: &PoseTarget, stop: &dyn Stop, iterations: &mut usize) -> Descent {
        let (accuracy_p, accuracy_o) = self.accuracy;
        let s = &mut self.scratch;
        let mut pose = self.chain.pose(&s.q, &mut s.poses) * self.tool;
        let (mut rp, mut ro) = target.residuals(&pose);
        let mut cost = rp.error * rp.error + ro.error * ro.error;
        let floor = self.damping * self.damping;
        let mut lambda2 = floor;
        let mut fresh = true;
        for _ in 0..self.iterations {
            if rp.error <= accuracy_p && ro.error <= accuracy_o {
                return Descent::Converged(rp.error, ro.error);
            }
            if stop.should_stop() {
                return Descent::Stopped(rp.error, ro.error);
            }
            *iterations += 1;
            if fresh {
                self.chain
                    .jacobian(&s.poses, pose.translation, &mut s.columns);
                fresh = false;
            }
            dls_step(&s.columns, &rp, &ro, lambda2, &mut s.dq);
            // A coordinate at a limit that the step pushes beyond it is locked (its column
            // zeroed until the next accepted step recomputes the Jacobian) and the step
            // solved again without it: the others then make up for it.
            let mut locked = false;
            for i in 0..s.q.len() {
                if let Some(limits) = &self.limits[i] {
                    let (q, d) = (s.q[i], s.dq[i]);
                    let beyond = (q <= limits.lower && d < 0.0) || (q >= limits.upper && d > 0.0);
                    if beyond && wrapped(q + d, limits).is_none() {
                        s.columns[i] = (DVec3::ZERO, DVec3::ZERO);
                        locked = true;
                    }
                }
            }
            if locked {
                dls_step(&s.columns, &rp, &ro, lambda2, &mut s.dq);
            }
            let largest = s.dq.iter().fold(0.0_f64, |m, d| m.max(d.abs()));
            let scale = if largest > self.max_step {
                self.max_step / largest
            } else {
                1.0
            };
            for i in 0..s.q.len() {
                let value = s.q[i] + scale * s.dq[i];
                s.trial[i] = admit(self.limits[i], value);
            }
            let trial_pose = self.chain.pose(&s.trial, &mut s.poses) * self.tool;
            let (tp, to) = target.residuals(&trial_pose);
            let trial_cost = tp.error * tp.error + to.error * to.error;
            if trial_cost < cost {
                std::mem::swap(&mut s.q, &mut s.trial);
                (pose, rp, ro, cost) = (trial_pose, tp, to, trial_cost);
                lambda2 = (lambda2 * 0.1).max(floor * FLOOR_FACTOR);
                fresh = true;
            } else {
                lambda2 *= 10.0;
                if lambda2 > MAX_LAMBDA2 {
                    return Descent::Failed(rp.error, ro.error);
                }
            }
        }
        if rp.error <= accuracy_p && ro.error <= accuracy_o {
            Descent::Converged(rp.error, ro.error)
        } else {
            Descent::Failed(rp.error, ro.error)
        }
    }
}

/// `value` as a value of a coordinate with `limits` (`None`: a continuous joint): wrapped
/// into `[-π, π]` for a continuous joint; for a limited one, itself if within the limits,
/// else a full turn away if that is within them (a revolute joint with more than a turn of
/// range), else clamped.
#[inline]
fn admit(limits: Option<Limits>, value: f64) -> f64 {
    match limits {
        None => wrap_angle(value),
        Some(l) if value < l.lower || value > l.upper => {
            wrapped(value, &l).unwrap_or(value.clamp(l.lower, l.upper))
        }
        Some(_) => value,
    }
}

/// `value` a full turn up or down, if the joint turns and that lies within its limits.
#[inline]
fn wrapped(value: f64, limits: &Limits) -> Option<f64> {
    let range = limits.lower..=limits.upper;
    if !limits.turns {
        return None;
    }
    [value + TAU, value - TAU]
        .into_iter()
        .find(|v| range.contains(v))
}
