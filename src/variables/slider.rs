//! The slider's variables: mass, guide offset, applied force and its crank-angle table, and its
//! motion and guide loads.

use super::vr::{Variable, Vr};

/// The slider's rows.
pub(super) const VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::SliderMass,
        "slider.mass",
        0.14,
        1e-6,
        1e4,
        "kg",
        "Slider mass",
    ),
    Variable::input(
        Vr::SliderForce,
        "slider.force",
        0.0,
        -1e7,
        1e7,
        "N",
        "External force on the slider along the guide, +x (away from the crank) positive: negative pushes the slider towards the crank; slider.forceTable adds to it",
    ),
    Variable::output(
        Vr::SliderPosition,
        "slider.position",
        "m",
        "Slider position along the guide: the slider pin's x from the crank pivot",
    ),
    Variable::output(
        Vr::SliderVelocity,
        "slider.velocity",
        "m/s",
        "Slider velocity",
    ),
    Variable::output(
        Vr::SliderAcceleration,
        "slider.acceleration",
        "m/s2",
        "Slider acceleration",
    ),
    Variable::peak(
        Vr::SliderAccelerationPeak,
        "slider.accelerationPeak",
        "m/s2",
        "Largest |slider.acceleration| over the last communication interval (every internal step)",
    ),
    Variable::output(
        Vr::GuideForce,
        "guide.force",
        "N",
        "Normal force of the guide on the slider, along y",
    ),
    Variable::peak(
        Vr::GuideForcePeak,
        "guide.forcePeak",
        "N",
        "Largest |guide.force| over the last communication interval (every internal step)",
    ),
    Variable::parameter(
        Vr::SliderOffset,
        "slider.offset",
        0.0,
        -10.0,
        10.0,
        "m",
        "Cylinder (piston-pin) offset: the guide line's distance from the crank pivot along +y; a full turn needs crank.length + |slider.offset| < rod.length. With an offset, crank angle zero is not a dead centre: they lie at asin(e/(l + r)) and pi + asin(e/(l - r))",
    ),
    Variable::string(
        Vr::SliderForceTable,
        "slider.forceTable",
        "",
        "A load on the slider tied to the crank angle: a CSV file of crank angle [deg] (or [rad] where the header's first field says rad), force [N] (a relative path is looked up in the working directory, then in the FMU's resources), periodic over slider.forceTablePeriod, interpolated monotonically (no overshoot of a combustion pulse) at every evaluation and added to the input slider.force; empty for none",
    ),
    Variable::integer(
        Vr::SliderForceTablePeriod,
        "slider.forceTablePeriod",
        360,
        360,
        720,
        "Period of slider.forceTable in degrees of crank angle: 360, or 720 for a four-stroke cycle (crank angle 0 at the table's 0)",
    ),
    Variable::output(
        Vr::SliderAppliedForce,
        "slider.appliedForce",
        "N",
        "The total external force on the slider along the guide: the input slider.force and slider.forceTable at the crank angle (negative pushes the slider towards the crank)",
    ),
];
