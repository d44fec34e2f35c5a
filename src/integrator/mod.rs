//! Error-controlled time integration of first-order systems y' = f(t, y).
//!
//! The method is the explicit embedded Runge–Kutta pair of Dormand and Prince, order 5 with a 4th
//! order error estimate, local extrapolation, first-same-as-last, and the standard step-size
//! controller. It is the integrator of choice for the reduced rod, whose highest frequency is far
//! below the full model's (MODEL.md §6); BENCHMARKS.md records how it was chosen.
//!
//! # References
//! - J. R. Dormand, P. J. Prince (1980), A family of embedded Runge–Kutta formulae, J. Comput. Appl.
//!   Math. 6, 19–26.
//! - E. Hairer, S. P. Nørsett, G. Wanner (1993), Solving Ordinary Differential Equations I, 2nd ed.,
//!   §II.4 (step-size control, initial step) and §II.5 (DOPRI5).

mod dormand_prince;

pub use dormand_prince::DormandPrince;

use crate::error::{ModelError, require_positive};

/// A first-order system y' = f(t, y) with optional hooks on step acceptance.
///
/// The hooks let a system with impacts refuse a step that would start a contact too deep
/// (Flores & Ambrósio 2010: keep the first penetration small) and update discrete state (the
/// impact velocity of a contact event) only at accepted steps, never at trial stages.
pub trait OdeSystem {
    /// Writes f(t, y) to `dy`.
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]);

    /// Called for a step (t₀, y₀) → (t₁, y₁) that passed the error test: `None` accepts it,
    /// `Some(factor)` rejects it and retries with the step size multiplied by `factor` ∈ (0, 1).
    fn check_step(&mut self, _t0: f64, _y0: &[f64], _t1: f64, _y1: &[f64]) -> Option<f64> {
        None
    }

    /// Called once a step (t₀, y₀) → (t₁, y₁) has been accepted.
    fn accept_step(&mut self, _t0: f64, _y0: &[f64], _t1: f64, _y1: &[f64]) {}
}

impl<F: FnMut(f64, &[f64], &mut [f64])> OdeSystem for F {
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        self(t, y, dy)
    }
}

/// Error tolerances: a step is accepted when ‖err_i / (atol + rtol·max(|y_i|, |y_new,i|))‖_rms ≤ 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance.
    pub relative: f64,
    /// Absolute tolerance (in the units of each state component).
    pub absolute: f64,
    /// Largest step size \[s\].
    pub max_step: f64,
    /// Smallest step size \[s\]: below it the integration fails instead of stalling.
    pub min_step: f64,
}

impl Tolerances {
    /// Checks every field; errors name the FMU parameter.
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("solver.relativeTolerance", self.relative)?;
        require_positive("solver.absoluteTolerance", self.absolute)?;
        require_positive("solver.maxStepSize", self.max_step)?;
        require_positive("solver.minStepSize", self.min_step)?;
        Ok(())
    }
}

/// Integrator statistics.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
}
