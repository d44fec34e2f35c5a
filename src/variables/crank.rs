//! The crank's and the drive's variables: geometry, mass, start, the drive mode and its inputs, and
//! the crank's motion and loads.

use super::enumerations::DRIVE_MODE;
use super::vr::{Variable, Vr};

/// 5000 rpm in rad/s (benchmark B); the same expression as `params::BENCHMARK_SPEED`.
const SPEED: f64 = 5000.0 * core::f64::consts::TAU / 60.0;

/// The crank's and the drive's rows.
pub(super) const VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::CrankLength,
        "crank.length",
        0.05,
        1e-4,
        10.0,
        "m",
        "Crank length, pivot to pin",
    ),
    Variable::parameter(
        Vr::CrankMass,
        "crank.mass",
        0.3,
        1e-6,
        1e4,
        "kg",
        "Crank mass (its centre of mass at crank.centreOfMassRatio along the crank)",
    ),
    Variable::parameter(
        Vr::CrankInertia,
        "crank.inertia",
        1e-4,
        1e-12,
        1e4,
        "kg.m2",
        "Crank moment of inertia about its centre of mass",
    ),
    Variable::parameter(
        Vr::CrankInitialAngle,
        "crank.initialAngle",
        0.0,
        -1000.0,
        1000.0,
        "rad",
        "Initial crank angle",
    ),
    Variable::parameter(
        Vr::CrankInitialSpeed,
        "crank.initialSpeed",
        SPEED,
        -1e4,
        1e4,
        "rad/s",
        "Initial crank speed (mechanism starts with ideal-joint velocities); not set, the crank starts at drive.speed's value, in either drive mode",
    ),
    Variable::enumeration(
        Vr::DriveMode,
        "drive.mode",
        1,
        DRIVE_MODE,
        "What drives the crank",
    ),
    Variable::input(
        Vr::DriveSpeed,
        "drive.speed",
        SPEED,
        -1e4,
        1e4,
        "rad/s",
        "Prescribed crank speed (drive.mode = speed)",
    ),
    Variable::input(
        Vr::DriveTorque,
        "drive.torque",
        0.0,
        -1e6,
        1e6,
        "N.m",
        "Crank torque (drive.mode = torque)",
    ),
    Variable::output(
        Vr::CrankAngle,
        "crank.angle",
        "rad",
        "Crank angle from +x (the guide's direction, from the crank pivot towards the slider), counter-clockwise positive",
    ),
    Variable::output(
        Vr::CrankSpeed,
        "crank.speed",
        "rad/s",
        "Crank angular speed",
    ),
    Variable::output(
        Vr::CrankTorque,
        "crank.torque",
        "N.m",
        "Torque the drive applies to the crank (CCW positive)",
    ),
    Variable::parameter(
        Vr::CrankCentreOfMassRatio,
        "crank.centreOfMassRatio",
        0.5,
        -2.0,
        2.0,
        "1",
        "The crank's centre of mass: its distance from the pivot along the crank (towards the pin) as a fraction of crank.length; 0.5 a uniform crank, negative a counterweight beyond the pivot (crank.inertia stays about the centre of mass)",
    ),
    Variable::count(
        Vr::CycleNumber,
        "cycle.number",
        "Load cycles completed (crank-angle periods of slider.forceTablePeriod, a revolution without a load table, bounded by its multiples): the cycle the *Cycle results describe, from the communication point at or after the crank angle reaches its end boundary; 0 while the first is under way, whose results they show so far",
    ),
];
