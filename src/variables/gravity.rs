//! Gravity, in which the whole mechanism sits.

use super::vr::{Variable, Vr};

/// Gravity's rows.
pub(super) const VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::Gravity,
        "gravity",
        0.0,
        -1000.0,
        1000.0,
        "m/s2",
        "Gravitational acceleration, along -y unless gravityAngle turns it",
    ),
    Variable::parameter(
        Vr::GravityAngle,
        "gravityAngle",
        0.0,
        -7.0,
        7.0,
        "rad",
        "Direction of gravity: angle from -y, counter-clockwise positive (0: across the guide along -y; -90 deg: along -x, a vertical guide with the slider above the crank pivot)",
    ),
];
