//! The step-control loop of every method: propose a step (ending exactly at a limit it nearly
//! reaches), try it, then accept it, retry it shorter after a failed error test or a failed
//! trial, or shorten it as the system's veto asks, until a step is accepted or the attempts run
//! out. The methods supply the trial step and what accepting its candidate means for them
//! ([`Method`]); the step sizes come from [`step_size`].

use super::control::{Stats, Tolerances, step_size};
use super::system::OdeSystem;
use crate::error::{ModelError, Num};

/// A proposal that reaches this fraction of the distance to the limit ends exactly there, so no
/// sliver of a step is left before it.
pub(super) const LIMIT_REACH: f64 = 1.01;

/// The outcome of one trial step.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Trial {
    /// The candidate's scaled error norm (∞ when not finite); it passes at most 1.
    Error(f64),
    /// The trial failed before an error estimate (Newton did not converge): retry with the step
    /// multiplied by this factor (1: the same step, with a fresh Jacobian).
    Failed(f64),
    /// The system is not defined at a point of the trial (its error says why, a singular
    /// configuration): retry with the step multiplied by this factor.
    Undefined(f64, ModelError),
}

/// A method's part in the loop, for a system `F`.
pub(super) trait Method<F: OdeSystem> {
    /// The proposed size of the next step, which the loop reads and updates.
    fn proposal(&mut self) -> &mut f64;
    /// The run's statistics, whose steps and rejections the loop counts.
    fn stats(&mut self) -> &mut Stats;
    /// The exponent q of the error estimate, O(h^q).
    fn error_order(&self) -> i32;
    /// One trial step of size `h` from (`t`, `y`), its candidate left in [`Method::candidate`].
    fn trial(&mut self, f: &mut F, t: f64, y: &[f64], h: f64) -> Trial;
    /// The candidate of the last trial step.
    fn candidate(&self) -> &[f64];
    /// Takes the candidate as the new point `y` (its start, before the call) of a step `h`
    /// accepted with error `err`, and returns the factor on `h` of the next step.
    fn commit(&mut self, y: &mut [f64], h: f64, err: f64, rejected_last: bool) -> f64;
}

/// Takes one accepted step of `method` from (`*t`, `y`), retrying rejected ones, in at most
/// `max_attempts` trial steps; with a `limit` the step ends there at the latest (exactly, when
/// the proposal reaches it or nearly does, [`LIMIT_REACH`]). Returns `false` when the attempts
/// ran out before a step was accepted; then, as on failure (the step size below the smallest),
/// `*t` and `y` hold the last accepted point.
pub(super) fn step<F: OdeSystem, M: Method<F>>(
    method: &mut M,
    f: &mut F,
    (t, y): (&mut f64, &mut [f64]),
    limit: Option<f64>,
    tolerances: &Tolerances,
    max_attempts: u64,
) -> Result<bool, ModelError> {
    let mut rejected_last = false;
    for _ in 0..max_attempts {
        let proposal = method.proposal().min(tolerances.max_step);
        let last = limit.is_some_and(|end| LIMIT_REACH * proposal >= end - *t);
        let (h, t_new) = match limit {
            Some(end) if last => (end - *t, end),
            _ => (proposal, *t + proposal),
        };
        let trial = method.trial(f, *t, y, h);
        let factor = match &trial {
            &Trial::Error(err) if err <= 1.0 => {
                match f.check_step(*t, y, t_new, method.candidate()) {
                    Some(veto) => step_size::vetoed(veto),
                    None => {
                        method.stats().steps += 1;
                        let next_limit = f.accept_step(*t, y, t_new, method.candidate());
                        *t = t_new;
                        let factor = method.commit(y, h, err, rejected_last);
                        let proposed = method.proposal();
                        // Keep the unclamped proposal when the step was shortened to hit the limit.
                        if !last || h >= *proposed {
                            *proposed = h * factor;
                        }
                        if let Some(next_limit) = next_limit {
                            *proposed = proposed.min(next_limit);
                        }
                        return Ok(true);
                    }
                }
            }
            &Trial::Error(err) => step_size::rejected(err, method.error_order()),
            &Trial::Failed(factor) | &Trial::Undefined(factor, _) => factor,
        };
        method.stats().rejected += 1;
        rejected_last = true;
        *method.proposal() = h * factor;
        if *method.proposal() < tolerances.min_step {
            let why = match &trial {
                Trial::Error(err) => format!("error estimate {}", Num(*err)),
                Trial::Failed(_) => "Newton did not converge".to_string(),
                Trial::Undefined(_, e) => e.to_string(),
            };
            return Err(ModelError::Numerical(format!(
                "step size {} s fell below the minimum {} s at t = {} s ({why})",
                Num(*method.proposal()),
                Num(tolerances.min_step),
                Num(*t)
            )));
        }
    }
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A method whose trials return scripted outcomes, and whose candidate is y + h.
    struct Scripted {
        proposal: f64,
        stats: Stats,
        outcomes: Vec<Trial>,
        tried: Vec<f64>,
        candidate: Vec<f64>,
    }

    impl Scripted {
        fn new(proposal: f64, outcomes: &[Trial]) -> Self {
            Self {
                proposal,
                stats: Stats::default(),
                outcomes: outcomes.iter().rev().cloned().collect(),
                tried: Vec::new(),
                candidate: vec![0.0],
            }
        }
    }

    impl<F: OdeSystem> Method<F> for Scripted {
        fn proposal(&mut self) -> &mut f64 {
            &mut self.proposal
        }
        fn stats(&mut self) -> &mut Stats {
            &mut self.stats
        }
        fn error_order(&self) -> i32 {
            5
        }
        fn trial(&mut self, _f: &mut F, _t: f64, y: &[f64], h: f64) -> Trial {
            self.tried.push(h);
            self.candidate[0] = y[0] + h;
            self.outcomes.pop().unwrap_or(Trial::Error(0.5))
        }
        fn candidate(&self) -> &[f64] {
            &self.candidate
        }
        fn commit(&mut self, y: &mut [f64], _h: f64, _err: f64, rejected_last: bool) -> f64 {
            y.copy_from_slice(&self.candidate);
            if rejected_last { 1.0 } else { 2.0 }
        }
    }

    /// A system that vetoes its first `vetoes` steps with factor 0.5.
    struct Vetoing {
        vetoes: u32,
    }

    impl OdeSystem for Vetoing {
        fn rhs(&mut self, _t: f64, _y: &[f64], dy: &mut [f64]) -> Result<(), ModelError> {
            dy.fill(1.0);
            Ok(())
        }
        fn check_step(&mut self, _t0: f64, _y0: &[f64], _t1: f64, _y1: &[f64]) -> Option<f64> {
            (self.vetoes > 0).then(|| {
                self.vetoes -= 1;
                0.5
            })
        }
    }

    fn run(
        method: &mut Scripted,
        vetoes: u32,
        limit: Option<f64>,
        attempts: u64,
    ) -> (Result<bool, ModelError>, f64) {
        let tolerances = Tolerances::from_relative(1e-3, 1.0);
        let (mut t, mut y) = (0.0, [0.0]);
        let accepted = step(
            method,
            &mut Vetoing { vetoes },
            (&mut t, &mut y),
            limit,
            &tolerances,
            attempts,
        );
        (accepted, t)
    }

    /// A proposal within [`LIMIT_REACH`] of the limit ends exactly there (one short of it does
    /// not); a proposal shortened to the limit is kept for the next step.
    #[test]
    fn a_step_that_nearly_reaches_the_limit_ends_there() {
        let mut m = Scripted::new(0.995, &[]);
        assert_eq!(run(&mut m, 0, Some(1.0), 1), (Ok(true), 1.0));
        assert_eq!((m.tried[0], m.proposal), (1.0, 2.0));
        let mut m = Scripted::new(0.98, &[]);
        assert_eq!(run(&mut m, 0, Some(1.0), 1), (Ok(true), 0.98));
        assert_eq!(m.proposal, 0.98 * 2.0);
        let mut m = Scripted::new(0.9, &[]);
        assert_eq!(run(&mut m, 0, Some(0.5), 1), (Ok(true), 0.5));
        assert_eq!(m.proposal, 0.9);
    }

    /// A failed error test retries with the controller's factor, a failed trial (or one that met
    /// a point where the system is not defined) with its own,
    /// a veto with the system's; each counts as a rejection, and the step after them does not
    /// grow.
    #[test]
    fn rejections_retry_shorter_and_count() {
        let undefined = Trial::Undefined(0.2, ModelError::Numerical("locked".into()));
        let outcomes = [
            Trial::Error(32.0),
            Trial::Failed(0.25),
            undefined,
            Trial::Error(0.5),
        ];
        let mut m = Scripted::new(0.1, &outcomes);
        let last = 0.1 * 0.45 * 0.25 * 0.2;
        assert_eq!(run(&mut m, 1, None, 10), (Ok(true), last * 0.5));
        let expected = [0.1, 0.1 * 0.45, 0.1 * 0.45 * 0.25, last, last * 0.5];
        assert_eq!(m.tried, expected);
        assert_eq!((m.stats.steps, m.stats.rejected), (1, 4));
        assert_eq!(m.proposal, expected[4]);
    }

    /// Attempts running out leave the point where it was; a step below the smallest is an error
    /// that says why.
    #[test]
    fn running_out_of_attempts_or_step_size_is_reported() {
        let mut m = Scripted::new(0.1, &[Trial::Error(2.0)]);
        assert_eq!(run(&mut m, 0, None, 1), (Ok(false), 0.0));
        let mut m = Scripted::new(1e-14, &[Trial::Failed(0.25)]);
        let (result, t) = run(&mut m, 0, None, 10);
        let message = result.unwrap_err().to_string();
        assert!(message.contains("Newton did not converge"), "{message}");
        assert_eq!(t, 0.0);
        // A system not defined along the step names why.
        let why = "singular constraint Jacobian (locked configuration)";
        let undefined = Trial::Undefined(0.25, ModelError::Numerical(why.into()));
        let mut m = Scripted::new(1e-14, &[undefined]);
        let message = run(&mut m, 0, None, 10).0.unwrap_err().to_string();
        assert!(message.contains(why), "{message}");
    }
}
