//! What the integrators integrate: a first-order system with step hooks, and a mechanical one
//! with its coordinates first.

use crate::error::ModelError;

/// A first-order system y' = f(t, y) with optional hooks on step acceptance; f may be undefined
/// at a point (a singular configuration), which it says.
///
/// The hooks let a system with impacts refuse a step that would start a contact too deep
/// (Flores & Ambrósio 2010: keep the first penetration small), aim the next step at an
/// approaching contact instead of overshooting it, and update discrete state (the impact
/// velocity of a contact event) only at accepted steps, never at trial stages.
pub trait OdeSystem {
    /// Writes f(t, y) to `dy`, or says why f is not defined there (`dy` is then unspecified).
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), ModelError>;

    /// Called for a step (t₀, y₀) → (t₁, y₁) that passed the error test: `None` accepts it,
    /// `Some(factor)` rejects it and retries with the step size multiplied by `factor` ∈ (0, 1).
    fn check_step(&mut self, _t0: f64, _y0: &[f64], _t1: f64, _y1: &[f64]) -> Option<f64> {
        None
    }

    /// Called once a step (t₀, y₀) → (t₁, y₁) has been accepted; returns the largest size of
    /// the next step (`None`: no limit beyond the error control's).
    fn accept_step(&mut self, _t0: f64, _y0: &[f64], _t1: f64, _y1: &[f64]) -> Option<f64> {
        None
    }
}

/// A closure is a system defined everywhere.
impl<F: FnMut(f64, &[f64], &mut [f64])> OdeSystem for F {
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), ModelError> {
        self(t, y, dy);
        Ok(())
    }
}

/// A mechanical system in first-order form y = [q, q̇, w]: q' = q̇, q̈ = a(t, q, q̇, w), and
/// quadrature states w whose rates do not depend on w (work integrals, the drive angle).
pub trait MechanicalSystem: OdeSystem {
    /// Number of coordinates n (the lengths of q and of q̇).
    fn n_coordinates(&self) -> usize;

    /// The local errors of the quantities held on their own ([`super::ErrorScales::held`], one
    /// per scale), for the error estimate `err` of a step ending at `y`, written to `out`.
    fn held_errors(&self, _y: &[f64], _err: &[f64], _out: &mut [f64]) {}
}
