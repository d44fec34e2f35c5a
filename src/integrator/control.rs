//! Error control shared by every method: tolerances, per-component error scales, the error norm,
//! the step-size controller, the initial step, and the statistics of a run.

use super::system::OdeSystem;
use crate::error::{ModelError, require_positive};

/// The step-size controller of every method, for an error estimate of order q (the power of h of
/// the embedded error, 5 for Dormand–Prince and ESDIRK5(4), 2 for generalized-α):
/// ```text
/// accepted:  h_new = h · clamp(SAFETY · err^(−1/q), MIN_FACTOR, MAX_FACTOR)   (≤ h after a rejection)
/// rejected:  h_new = h · clamp(SAFETY · err^(−1/q), MIN_FACTOR, 1)           (MIN_FACTOR if err is not finite)
/// vetoed:    h_new = h · clamp(factor, VETO_MIN, VETO_MAX)                    (an event's own factor)
/// ```
/// (Hairer, Nørsett & Wanner 1993, §II.4.)
pub(super) mod step_size {
    use crate::math;

    /// Safety factor on the optimal step.
    pub const SAFETY: f64 = 0.9;
    /// Largest shrinking per step.
    pub const MIN_FACTOR: f64 = 0.2;
    /// Largest growth per step.
    pub const MAX_FACTOR: f64 = 5.0;
    /// Range of the factor of a step vetoed by the system (a contact onset too deep).
    pub const VETO_MIN: f64 = 1e-3;
    /// See [`VETO_MIN`].
    pub const VETO_MAX: f64 = 0.99;
    /// Smallest error estimate the accepted step's factor is computed from (a zero estimate
    /// would ask for an infinite step).
    const ERROR_FLOOR: f64 = 1e-10;

    /// The factor of the next step after a step accepted with error `err` (≤ 1) of order
    /// `order`; no growth right after a rejection.
    pub fn accepted(err: f64, order: i32, rejected_last: bool) -> f64 {
        let factor = (SAFETY * math::powf(err.max(ERROR_FLOOR), -1.0 / f64::from(order)))
            .clamp(MIN_FACTOR, MAX_FACTOR);
        if rejected_last {
            factor.min(1.0)
        } else {
            factor
        }
    }

    /// The factor of the retried step after a step rejected with error `err` (> 1, or not
    /// finite) of order `order`.
    pub fn rejected(err: f64, order: i32) -> f64 {
        if err.is_finite() {
            (SAFETY * math::powf(err, -1.0 / f64::from(order))).clamp(MIN_FACTOR, 1.0)
        } else {
            MIN_FACTOR
        }
    }

    /// The factor of a step the system vetoed with its own `factor`.
    pub fn vetoed(factor: f64) -> f64 {
        factor.clamp(VETO_MIN, VETO_MAX)
    }
}

/// Error tolerances: a step is accepted when the RMS over i of
/// err_i / (absolute · sᵢ + relative · rᵢ · max(|y_i|, |y_new,i|)) is at most 1, with sᵢ and rᵢ the
/// component's [`ErrorScales`] (1 and 1 unless the system provides them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance.
    pub relative: f64,
    /// Absolute tolerance, in units of each component's scale.
    pub absolute: f64,
    /// Largest step size \[s\].
    pub max_step: f64,
    /// Smallest step size \[s\]: below it the integration fails instead of stalling.
    pub min_step: f64,
}

impl Tolerances {
    /// `rtol` for both the relative and the absolute part (the latter in units of each
    /// component's scale), steps up to `max_step` and a 1e-14 s floor.
    pub fn from_relative(rtol: f64, max_step: f64) -> Self {
        Self {
            relative: rtol,
            absolute: rtol,
            max_step,
            min_step: 1e-14,
        }
    }

    /// Checks every field; errors name the FMU parameter each comes from (the absolute tolerance
    /// is `solver.relativeTolerance` in units of each component's scale; the step floor is fixed).
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("solver.relativeTolerance", self.relative)?;
        require_positive("solver.relativeTolerance", self.absolute)?;
        require_positive("solver.maxStepSize", self.max_step)?;
        require_positive("the smallest step size", self.min_step)?;
        Ok(())
    }
}

/// Per-component weights of the error norm: component i is compared with
/// `absolute · absolute[i] + relative · relative[i] · |yᵢ|`, and each held quantity with
/// `absolute · held[k]` on its own.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorScales {
    /// Scale of each component's absolute tolerance, in its units.
    pub absolute: Vec<f64>,
    /// Weight of each component's relative tolerance (1: relative to its size, 0: absolute only,
    /// for quantities whose size depends on an arbitrary origin, such as positions).
    pub relative: Vec<f64>,
    /// Scales of the quantities held to the tolerance each on its own (max-norm), besides the RMS
    /// over all components: quantities that are a small part of the state but decide the motion,
    /// such as a journal's normal velocity in its bearing, which the RMS would let drift. The
    /// system computes their local errors ([`super::MechanicalSystem::held_errors`]).
    pub held: Vec<f64>,
}

impl ErrorScales {
    /// Scales 1 and relative weights 1 for `n` components (a classical mixed tolerance).
    pub fn uniform(n: usize) -> Self {
        Self {
            absolute: vec![1.0; n],
            relative: vec![1.0; n],
            held: Vec::new(),
        }
    }

    /// Number of components.
    pub fn len(&self) -> usize {
        self.absolute.len()
    }

    /// Whether there are no components.
    pub fn is_empty(&self) -> bool {
        self.absolute.is_empty()
    }

    /// The tolerance of component `i` at values `a`, `b` (its size is the larger).
    pub(super) fn weight(&self, i: usize, tol: &Tolerances, a: f64, b: f64) -> f64 {
        tol.absolute * self.absolute[i] + tol.relative * self.relative[i] * a.abs().max(b.abs())
    }
}

/// Integrator statistics.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (error test, contact onset, Newton failure).
    pub rejected: u64,
    /// Right-hand-side evaluations (including those of finite-difference Jacobians).
    pub evaluations: u64,
    /// Newton iterations (implicit method).
    pub newton_iterations: u64,
    /// Jacobian evaluations (implicit method).
    pub jacobians: u64,
    /// LU factorisations of the Newton matrix (implicit method).
    pub factorizations: u64,
}

/// The error norm: RMS over i of err_i / [`ErrorScales`] weight, at least the largest of the
/// held quantities' errors `held` in units of their tolerances, or ∞ when not finite.
pub(super) fn scaled_norm(
    err: &[f64],
    held: &[f64],
    y0: &[f64],
    y1: &[f64],
    scales: &ErrorScales,
    tol: &Tolerances,
) -> f64 {
    let mut sum = 0.0;
    for (i, ((e, a), b)) in err.iter().zip(y0).zip(y1).enumerate() {
        sum += (e / scales.weight(i, tol, *a, *b)).powi(2);
    }
    let mut norm = (sum / err.len().max(1) as f64).sqrt();
    for (error, scale) in held.iter().zip(&scales.held) {
        norm = norm.max(error / (tol.absolute * scale));
    }
    if norm.is_finite() {
        norm
    } else {
        f64::INFINITY
    }
}

/// Initial step size (Hairer, Nørsett & Wanner 1993, §II.4) for a method of order `order`:
/// h₀ from ‖y‖/‖f‖, then one Euler step to estimate the second derivative. `f0` holds f(t, y);
/// `y1` and `f1` are workspace. Fails where f is not defined at the Euler step's end.
#[allow(clippy::too_many_arguments)]
pub(super) fn initial_step<F: OdeSystem>(
    f: &mut F,
    t: f64,
    y: &[f64],
    f0: &[f64],
    t_end: f64,
    tol: &Tolerances,
    scales: &ErrorScales,
    order: i32,
    y1: &mut [f64],
    f1: &mut [f64],
) -> Result<f64, ModelError> {
    let n = y.len().max(1) as f64;
    let scale = |i: usize, v: f64| scales.weight(i, tol, v, v);
    let rms = |it: &mut dyn Iterator<Item = f64>| (it.map(|v| v * v).sum::<f64>() / n).sqrt();
    let d0 = rms(&mut y.iter().enumerate().map(|(i, &v)| v / scale(i, v)));
    let d1 = rms(&mut y
        .iter()
        .zip(f0)
        .enumerate()
        .map(|(i, (&v, &d))| d / scale(i, v)));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    let h0 = h0.min(tol.max_step).min(t_end - t);
    for ((y1, &v), &d) in y1.iter_mut().zip(y).zip(f0) {
        *y1 = v + h0 * d;
    }
    f.rhs(t + h0, y1, f1)?;
    let d2 = rms(&mut y
        .iter()
        .zip(f1.iter().zip(f0))
        .enumerate()
        .map(|(i, (&v, (&a, &b)))| (a - b) / scale(i, v)))
        / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        crate::math::powf(0.01 / d1.max(d2), 1.0 / f64::from(order))
    };
    Ok((100.0 * h0).min(h1).min(tol.max_step))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The controller's factors: the optimal step with the safety factor inside the bounds, no
    /// growth right after a rejection, the shortest retry for a non-finite error, and a veto
    /// kept inside its range.
    #[test]
    fn the_step_size_controller_stays_in_its_bounds() {
        use step_size::*;
        // err = 2⁻⁵: the optimal factor 2, times the safety factor.
        assert_eq!(accepted(1.0 / 32.0, 5, false), 0.9 * 2.0);
        assert_eq!(accepted(1.0 / 32.0, 5, true), 1.0);
        assert_eq!(accepted(0.0, 5, false), MAX_FACTOR);
        assert_eq!(rejected(32.0, 5), 0.9 * 0.5);
        assert_eq!(rejected(1e12, 5), MIN_FACTOR);
        assert_eq!(rejected(f64::INFINITY, 5), MIN_FACTOR);
        assert_eq!(rejected(f64::NAN, 2), MIN_FACTOR);
        assert_eq!(vetoed(0.5), 0.5);
        assert_eq!([vetoed(0.0), vetoed(2.0)], [VETO_MIN, VETO_MAX]);
    }

    /// The norm is at least the largest held quantity's error in units of its tolerance.
    #[test]
    fn held_quantities_bound_the_norm() {
        let tol = Tolerances::from_relative(1e-2, 1.0);
        let mut scales = ErrorScales::uniform(3);
        scales.held = vec![2.0, 4.0];
        let y = [1.0; 3];
        let norm = scaled_norm(&[0.0; 3], &[1.9, 1.0], &y, &y, &scales, &tol);
        assert!((norm - 1.9 / (1e-2 * 2.0)).abs() < 1e-12, "{norm}");
    }
}
