//! The communication clock: time points on a binary grid, so that every master gets the same
//! results.

/// Resolution of the simulation clock: 2⁻⁴⁰ s ≈ 0.91 ps.
///
/// Target and start times are rounded to this binary grid. Masters represent the same
/// communication point differently (fmpy: n·Δt in floating point; libcosim: integer nanoseconds
/// converted to seconds), which differ in the last bits; in a nonlinear model such differences
/// can grow without bound. On the grid they coincide, so every master gets bit-identical results.
/// The shift (≤ 0.46 ps) is far below any time scale of a mechanical or electrical model.
pub const CLOCK_RESOLUTION: f64 = 1.0 / (1u64 << 40) as f64;

/// `t` rounded to the clock grid ([`CLOCK_RESOLUTION`]).
pub fn on_clock_grid(t: f64) -> f64 {
    (t / CLOCK_RESOLUTION).round() * CLOCK_RESOLUTION
}

/// The largest time on the clock grid ([`CLOCK_RESOLUTION`]) that is not after `t`.
pub fn on_clock_grid_below(t: f64) -> f64 {
    (t / CLOCK_RESOLUTION).floor() * CLOCK_RESOLUTION
}
