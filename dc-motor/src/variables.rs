//! The variable table of the DC-motor FMU: one row per FMI variable, in value-reference order.
//!
//! Plain data over the table types of `fmi-export`: `build.rs` renders `modelDescription.xml`
//! from [`DESCRIPTION`], and the FMU reads and writes values through an exhaustive `match` on
//! [`Vr`], so the code and the XML cannot disagree.

pub use fmi_core::description::Description;
pub use fmi_core::interface::{Fmi3Interface, Terminal};
pub use fmi_core::table::{Causality, Kind, ValueReference};

/// One variable of this FMU.
pub type Variable = fmi_core::table::Variable<Vr>;

/// FMI 3 additions: the shaft as a terminal (the motor has no events to return early at, no
/// arrays).
pub const FMI3: Fmi3Interface = Fmi3Interface {
    terminals: &[Terminal {
        name: "shaftFlange",
        kind: "rotationalFlange",
        description: "The shaft's load end: the load's speed in, the shaft torque out; connects to the crank's flange terminal (w out, tau in)",
        members: &[("w", "shaft.speed"), ("tau", "shaft.torque")],
    }],
    ..Fmi3Interface::NONE
};

/// Everything modelDescription.xml says.
pub const DESCRIPTION: Description<Vr> = Description {
    model_identifier: "DcMotor",
    description: "DC motor with a PI speed controller (voltage limit, anti-windup by back-calculation) driving a load through a torsional shaft: shaft speed in, shaft torque out",
    author: "The FlexibleSliderCrank authors",
    version: env!("CARGO_PKG_VERSION"),
    copyright: "Copyright (c) 2026 The FlexibleSliderCrank authors",
    license: "MIT",
    generation_tool: "dc-motor build.rs (fmi-export)",
    max_input_derivative_order: 2,
    max_output_derivative_order: 1,
    units: UNITS,
    display_units: &[("rad/s", "rpm", 60.0 / core::f64::consts::TAU)],
    variable_display_units: &[
        (Vr::ShaftSpeed, "rpm"),
        (Vr::SpeedSetPoint, "rpm"),
        (Vr::MotorSpeed, "rpm"),
    ],
    enumerations: &[],
    log_categories: LOG_CATEGORIES,
    default_experiment: (0.0, 0.024, 1e-6, 1e-4),
    variables: VARIABLES,
    feedthrough: FEEDTHROUGH,
    rate_feedthrough: &[],
    initial_dependency,
    provides_directional_derivative: true,
};

/// Units: name and SI base-unit exponents (kg, m, s, A, K, rad).
pub const UNITS: &[(&str, Option<[i32; 6]>, f64)] = &[
    ("s", Some([0, 0, 1, 0, 0, 0]), 1.0),
    ("rad", Some([0, 0, 0, 0, 0, 1]), 1.0),
    ("rad/s", Some([0, 0, -1, 0, 0, 1]), 1.0),
    ("A", Some([0, 0, 0, 1, 0, 0]), 1.0),
    ("V", Some([1, 2, -3, -1, 0, 0]), 1.0),
    ("Ohm", Some([1, 2, -3, -2, 0, 0]), 1.0),
    ("H", Some([1, 2, -2, -2, 0, 0]), 1.0),
    ("N.m", Some([1, 2, -2, 0, 0, 0]), 1.0),
    ("N.m/A", Some([1, 2, -2, -1, 0, 0]), 1.0),
    ("N.m/rad", Some([1, 2, -2, 0, 0, -1]), 1.0),
    ("N.m.s/rad", Some([1, 2, -1, 0, 0, -1]), 1.0),
    ("V.s/rad", Some([1, 2, -2, -1, 0, -1]), 1.0),
    ("V/rad", Some([1, 2, -3, -1, 0, -1]), 1.0),
    ("kg.m2", Some([1, 2, 0, 0, 0, 0]), 1.0),
];

/// Log categories.
pub const LOG_CATEGORIES: &[(&str, &str)] = &[
    ("logEvents", "Initialisation and step information"),
    ("logStatusWarning", "Warnings"),
    (
        "logStatusError",
        "Errors: illegal calls, invalid arguments and parameters",
    ),
    ("logAll", "Everything"),
];

/// Value references.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Vr {
    MotorResistance = 0,
    MotorInductance,
    MotorTorqueConstant,
    MotorInertia,
    MotorFriction,
    ShaftStiffness,
    ShaftDamping,
    ControllerGain,
    ControllerIntegralGain,
    ControllerTrackingTime,
    SupplyVoltageLimit,
    ShaftInitialTorque,
    SolverStepSize,
    ShaftLoadInertia,
    ShaftSpeed,
    SpeedSetPoint,
    ShaftTorque,
    MotorSpeed,
    MotorCurrent,
    MotorVoltage,
    ShaftTwist,
    SolverWarnings,
}

impl ValueReference for Vr {
    fn index(self) -> u32 {
        self as u32
    }
}

/// Direct feedthrough: the shaft torque reacts to the shaft speed through the shaft's damping,
/// the voltage to the set-point through the proportional gain (unless it is at its limit).
pub const FEEDTHROUGH: &[(Vr, &[Vr])] = &[
    (Vr::ShaftTorque, &[Vr::ShaftSpeed]),
    (Vr::MotorVoltage, &[Vr::SpeedSetPoint]),
];

/// Whether an output depends, in initialization mode, on an input or a parameter: the
/// `dependencies` of ModelStructure/InitialUnknowns. The motor starts in steady state at the
/// set-point ω = ω_set with the shaft torque τ₀ = `shaft.initialTorque` (`MotorParameters::steady_state`):
/// i = (τ₀ + b ω)/k_t, u = clamp(R i + k_t ω) held by the integrator (zero without integral
/// action), φ = τ₀/c; the shaft torque c φ + d (ω − ω_L) = τ₀ + d (ω_set − ω_L).
fn initial_dependency(unknown: Vr, known: Vr) -> bool {
    use Vr::*;
    match unknown {
        ShaftTorque => matches!(
            known,
            ShaftDamping | ShaftInitialTorque | ShaftSpeed | SpeedSetPoint
        ),
        MotorSpeed => known == SpeedSetPoint,
        MotorCurrent => matches!(
            known,
            MotorFriction | MotorTorqueConstant | ShaftInitialTorque | SpeedSetPoint
        ),
        MotorVoltage => matches!(
            known,
            MotorFriction
                | MotorResistance
                | MotorTorqueConstant
                | ShaftInitialTorque
                | SpeedSetPoint
                | ControllerIntegralGain
                | SupplyVoltageLimit
        ),
        ShaftTwist => matches!(known, ShaftInitialTorque | ShaftStiffness),
        // The warnings count starts at zero.
        _ => false,
    }
}

/// 5000 rpm in rad/s.
const SPEED: f64 = 5000.0 * core::f64::consts::TAU / 60.0;

/// Every variable, in value-reference order.
pub const VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::MotorResistance,
        "motor.resistance",
        0.2,
        1e-6,
        1e3,
        "Ohm",
        "Armature resistance R",
    ),
    Variable::parameter(
        Vr::MotorInductance,
        "motor.inductance",
        5e-4,
        1e-7,
        10.0,
        "H",
        "Armature inductance L",
    ),
    Variable::parameter(
        Vr::MotorTorqueConstant,
        "motor.torqueConstant",
        0.2,
        1e-4,
        100.0,
        "N.m/A",
        "Torque constant k (also the back-EMF constant, V.s/rad)",
    ),
    Variable::parameter(
        Vr::MotorInertia,
        "motor.inertia",
        0.01,
        1e-7,
        1e3,
        "kg.m2",
        "Inertia of the rotor (and flywheel) J",
    ),
    Variable::parameter(
        Vr::MotorFriction,
        "motor.friction",
        1e-4,
        0.0,
        1e3,
        "N.m.s/rad",
        "Viscous friction b of the rotor bearings",
    ),
    Variable::parameter(
        Vr::ShaftStiffness,
        "shaft.stiffness",
        2e4,
        1e-3,
        1e9,
        "N.m/rad",
        "Torsional stiffness of the shaft to the load",
    ),
    Variable::parameter(
        Vr::ShaftDamping,
        "shaft.damping",
        2.0,
        0.0,
        1e6,
        "N.m.s/rad",
        "Torsional damping of the shaft",
    ),
    Variable::parameter(
        Vr::ControllerGain,
        "controller.gain",
        2.0,
        0.0,
        1e6,
        "V.s/rad",
        "Proportional gain Kp of the PI speed controller",
    ),
    Variable::parameter(
        Vr::ControllerIntegralGain,
        "controller.integralGain",
        40.0,
        0.0,
        1e8,
        "V/rad",
        "Integral gain Ki of the PI speed controller",
    ),
    Variable::parameter(
        Vr::ControllerTrackingTime,
        "controller.trackingTime",
        0.05,
        1e-6,
        1e3,
        "s",
        "Anti-windup tracking time Tt: the integral state follows the voltage limit at the rate (u - v)/(Ki Tt)",
    ),
    Variable::parameter(
        Vr::SupplyVoltageLimit,
        "supply.voltageLimit",
        200.0,
        1e-3,
        1e5,
        "V",
        "Largest armature voltage magnitude the converter gives",
    ),
    Variable::parameter(
        Vr::ShaftInitialTorque,
        "shaft.initialTorque",
        0.0,
        -1e6,
        1e6,
        "N.m",
        "Shaft torque at the start; the motor starts in steady state at speed.setPoint holding it (controller at its set-point)",
    ),
    Variable::parameter(
        Vr::SolverStepSize,
        "solver.stepSize",
        1e-5,
        1e-9,
        1.0,
        "s",
        "Largest internal step (classical Runge-Kutta, steps of equal length per communication step)",
    ),
    Variable::parameter(
        Vr::ShaftLoadInertia,
        "shaft.loadInertia",
        0.0,
        0.0,
        1e6,
        "kg.m2",
        "Inertia of the load at the driven end of the shaft (0: unknown). When set, each new communication step is checked for the stability of the shaft's coupling to that load with inputs held over the step, and an unstable one is warned of (solver.warnings)",
    ),
    Variable::input(
        Vr::ShaftSpeed,
        "shaft.speed",
        SPEED,
        -1e5,
        1e5,
        "rad/s",
        "Speed of the driven end of the shaft (the load's speed, e.g. crank.speed)",
    ),
    Variable::input(
        Vr::SpeedSetPoint,
        "speed.setPoint",
        SPEED,
        -1e5,
        1e5,
        "rad/s",
        "Set-point of the motor speed",
    ),
    Variable::output(
        Vr::ShaftTorque,
        "shaft.torque",
        "N.m",
        "Torque the shaft applies to the load (e.g. to drive.torque)",
    ),
    Variable::output(Vr::MotorSpeed, "motor.speed", "rad/s", "Rotor speed"),
    Variable::output(Vr::MotorCurrent, "motor.current", "A", "Armature current"),
    Variable::output(
        Vr::MotorVoltage,
        "motor.voltage",
        "V",
        "Armature voltage (the controller's output within the voltage limit)",
    ),
    Variable::output(
        Vr::ShaftTwist,
        "shaft.twist",
        "rad",
        "Twist of the shaft (rotor angle minus load angle)",
    ),
    Variable::count(
        Vr::SolverWarnings,
        "solver.warnings",
        "Warnings since the start: communication steps at which the shaft's coupling to its load (shaft.loadInertia) is unstable",
    ),
];
