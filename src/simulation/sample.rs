//! The layout of a sample of the peak-held quantities ([`Sample`]): which position holds what,
//! shared by the peak holds and the cycle results.

use crate::joint::JointRole;

/// Number of peak-held quantities: seven loads, each joint's eccentricity ratio and film pressure
/// (by role), the rod's tension and compression.
pub(super) const SERIES: usize = 15;

/// The peak-held magnitudes of one instant: the rod–slider joint's force, the slider
/// acceleration, the deformation energy, the crank pin's, the main bearing's and the guide's
/// forces, the rod stress, each joint's eccentricity ratio and film pressure, the rod's tension
/// and compression (`Peaks::from_sample`).
pub(super) type Sample = [f64; SERIES];

/// Position in a [`Sample`] of the main bearing's eccentricity ratio (the other joints follow in
/// role order), and of its film pressure.
pub(super) const ECCENTRICITY_RATIO: usize = 7;
pub(super) const FILM_PRESSURE: usize = 10;

/// Positions in a [`Sample`] of the crank pin's and the main bearing's forces.
pub(super) const CRANK_PIN_FORCE: usize = 3;
pub(super) const MAIN_BEARING_FORCE: usize = 4;

/// The position in a [`Sample`] of the force at the joint `role`.
pub(super) fn force_series(role: JointRole) -> usize {
    match role {
        JointRole::RodSlider => 0,
        JointRole::CrankPin => CRANK_PIN_FORCE,
        JointRole::MainBearing => MAIN_BEARING_FORCE,
    }
}
