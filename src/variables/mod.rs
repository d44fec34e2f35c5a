//! THE variable table of the FMU: one row per FMI variable, written by component (the rod, the
//! crank and its drive, the slider, gravity, the three joints from one definition, the solver, the
//! energy account) and assembled in value-reference order.
//!
//! This module is plain data over the table types of `fmi-export`: `build.rs` compiles it too and
//! renders `modelDescription.xml` from [`DESCRIPTION`], the library validates parameters against
//! its ranges, and values are got and set through one list per kind keyed by [`Vr`] (parameters in
//! `params::access`, Real outputs in `fmi::outputs`), each tested to cover exactly its rows, so the
//! code and the XML cannot disagree.

pub use fmi_core::description::Description;
pub use fmi_core::table::{Causality, Kind, ValueReference, Variability};

mod crank;
mod energy;
mod enumerations;
mod feed_rows;
mod gravity;
mod joint_rows;
mod joints;
mod oil;
mod rod;
mod sections;
mod slider;
mod solver;
mod structure;
mod surface_rows;
mod thermal_rows;
mod vr;

pub use enumerations::*;
pub use sections::{FMI3, N_SECTIONS, SectionArray};
pub use vr::{Variable, Vr};

/// Everything modelDescription.xml says.
pub const DESCRIPTION: Description<Vr> = Description {
    model_identifier: "FlexibleSliderCrank",
    description: "Flexible slider-crank mechanism with a clearance joint: planar ANCF connecting rod reduced by Craig-Bampton component mode synthesis (Sun et al., Mech. Mach. Theory 85, 2015)",
    author: "The FlexibleSliderCrank authors",
    version: env!("CARGO_PKG_VERSION"),
    copyright: "Copyright (c) 2026 The FlexibleSliderCrank authors",
    license: "MIT",
    generation_tool: "flexible-slider-crank build.rs (fmi-export)",
    max_input_derivative_order: 2,
    max_output_derivative_order: 2,
    units: UNITS,
    display_units: &[
        ("rad/s", "rpm", 60.0 / core::f64::consts::TAU),
        ("rad", "deg", 180.0 / core::f64::consts::PI),
        ("m", "mm", 1e3),
        ("m", "um", 1e6),
        ("N", "kN", 1e-3),
        ("Pa", "MPa", 1e-6),
    ],
    variable_display_units: &[
        (Vr::CrankInitialSpeed, "rpm"),
        (Vr::DriveSpeed, "rpm"),
        (Vr::CrankSpeed, "rpm"),
        (Vr::CrankInitialAngle, "deg"),
        (Vr::CrankAngle, "deg"),
        (Vr::GravityAngle, "deg"),
        (Vr::JointClearance, "mm"),
        (Vr::JointJournalRadius, "mm"),
        (Vr::JointEccentricityX, "mm"),
        (Vr::JointEccentricityY, "mm"),
        (Vr::JointPenetration, "mm"),
        (Vr::RodMidspanDeflection, "mm"),
        (Vr::SliderPosition, "mm"),
        (Vr::JointForce, "kN"),
        (Vr::JointForceX, "kN"),
        (Vr::JointForceY, "kN"),
        (Vr::JointForcePeak, "kN"),
        (Vr::CrankPinForce, "kN"),
        (Vr::CrankPinForceX, "kN"),
        (Vr::CrankPinForceY, "kN"),
        (Vr::CrankPinForcePeak, "kN"),
        (Vr::MainBearingForce, "kN"),
        (Vr::MainBearingForceX, "kN"),
        (Vr::MainBearingForceY, "kN"),
        (Vr::MainBearingForcePeak, "kN"),
        (Vr::GuideForce, "kN"),
        (Vr::GuideForcePeak, "kN"),
        (Vr::RodStress, "MPa"),
        (Vr::RodStressPeak, "MPa"),
        (Vr::RodStressMax, "MPa"),
        (Vr::RodStressMin, "MPa"),
        (Vr::RodStressMaxPeak, "MPa"),
        (Vr::RodStressMinPeak, "MPa"),
        (Vr::RodAxialForceCrankPin, "kN"),
        (Vr::RodAxialForceSliderPin, "kN"),
        (Vr::RodOuterFibreDistance, "mm"),
        (Vr::CrankPinClearance, "mm"),
        (Vr::CrankPinJournalRadius, "mm"),
        (Vr::CrankPinEccentricityX, "mm"),
        (Vr::CrankPinEccentricityY, "mm"),
        (Vr::CrankPinPenetration, "mm"),
        (Vr::MainBearingClearance, "mm"),
        (Vr::MainBearingJournalRadius, "mm"),
        (Vr::MainBearingEccentricityX, "mm"),
        (Vr::MainBearingEccentricityY, "mm"),
        (Vr::MainBearingPenetration, "mm"),
        (Vr::JointFilmThickness, "um"),
        (Vr::JointFilmThicknessMin, "um"),
        (Vr::JointFilmThicknessMinSinceStart, "um"),
        (Vr::JointFilmPressurePeak, "MPa"),
        (Vr::JointFilmPressurePeakSinceStart, "MPa"),
        (Vr::CrankPinFilmThickness, "um"),
        (Vr::CrankPinFilmThicknessMin, "um"),
        (Vr::CrankPinFilmThicknessMinSinceStart, "um"),
        (Vr::CrankPinFilmPressurePeak, "MPa"),
        (Vr::CrankPinFilmPressurePeakSinceStart, "MPa"),
        (Vr::MainBearingFilmThickness, "um"),
        (Vr::MainBearingFilmThicknessMin, "um"),
        (Vr::MainBearingFilmThicknessMinSinceStart, "um"),
        (Vr::MainBearingFilmPressurePeak, "MPa"),
        (Vr::MainBearingFilmPressurePeakSinceStart, "MPa"),
        (Vr::JointRoughness, "um"),
        (Vr::CrankPinRoughness, "um"),
        (Vr::MainBearingRoughness, "um"),
        (Vr::JointAsperityPressurePeak, "MPa"),
        (Vr::CrankPinAsperityPressurePeak, "MPa"),
        (Vr::MainBearingAsperityPressurePeak, "MPa"),
    ],
    enumerations: ENUMERATIONS,
    log_categories: LOG_CATEGORIES,
    default_experiment: DEFAULT_EXPERIMENT,
    variables: VARIABLES,
    feedthrough: structure::FEEDTHROUGH,
    rate_feedthrough: &[Vr::DriveSpeed],
    initial_dependency: structure::initial_dependency,
    provides_directional_derivative: true,
};

/// Units: name, SI base-unit exponents (kg, m, s, A, K, rad) and the factor to the base unit, or
/// None where FMI 2's integer exponents cannot express the unit (N/m^1.5).
pub const UNITS: &[(&str, Option<[i32; 6]>, f64)] = &[
    ("s", Some([0, 0, 1, 0, 0, 0]), 1.0),
    ("m", Some([0, 1, 0, 0, 0, 0]), 1.0),
    ("m/s", Some([0, 1, -1, 0, 0, 0]), 1.0),
    ("m/s2", Some([0, 1, -2, 0, 0, 0]), 1.0),
    ("m2", Some([0, 2, 0, 0, 0, 0]), 1.0),
    ("m4", Some([0, 4, 0, 0, 0, 0]), 1.0),
    ("kg", Some([1, 0, 0, 0, 0, 0]), 1.0),
    ("kg/m3", Some([1, -3, 0, 0, 0, 0]), 1.0),
    ("kg.m2", Some([1, 2, 0, 0, 0, 0]), 1.0),
    ("Pa", Some([1, -1, -2, 0, 0, 0]), 1.0),
    ("Pa.s", Some([1, -1, -1, 0, 0, 0]), 1.0),
    ("N", Some([1, 1, -2, 0, 0, 0]), 1.0),
    ("N.m", Some([1, 2, -2, 0, 0, 0]), 1.0),
    ("J", Some([1, 2, -2, 0, 0, 0]), 1.0),
    ("W", Some([1, 2, -3, 0, 0, 0]), 1.0),
    ("rad", Some([0, 0, 0, 0, 0, 1]), 1.0),
    (
        "deg",
        Some([0, 0, 0, 0, 0, 1]),
        core::f64::consts::PI / 180.0,
    ),
    ("rad/s", Some([0, 0, -1, 0, 0, 1]), 1.0),
    ("m3/s", Some([0, 3, -1, 0, 0, 0]), 1.0),
    ("1", Some([0, 0, 0, 0, 0, 0]), 1.0),
    ("K", Some([0, 0, 0, 0, 1, 0]), 1.0),
    ("J/K", Some([1, 2, -2, 0, -1, 0]), 1.0),
    ("W/K", Some([1, 2, -3, 0, -1, 0]), 1.0),
    ("J/(kg.K)", Some([0, 2, -2, 0, -1, 0]), 1.0),
    ("N/m1.5", None, 1.0),
];

/// Default experiment: two crank revolutions of benchmark B (5000 rpm) with a 1e-4 s step; the
/// tolerance is the default of `solver.relativeTolerance`, so a master that passes it to
/// fmi2SetupExperiment runs the FMU's defaults (a smaller tolerance from the master tightens
/// `solver.relativeTolerance`, see `instance::model_parameters`).
pub const DEFAULT_EXPERIMENT: (f64, f64, f64, f64) = (0.0, 0.024, 1e-2, 1e-4);

/// Log categories: name and description.
pub const LOG_CATEGORIES: &[(&str, &str)] = &[
    ("logEvents", "Initialisation, contact and step information"),
    ("logStatusWarning", "Warnings"),
    ("logStatusDiscard", "Steps that could not be completed"),
    (
        "logStatusError",
        "Errors: illegal calls, invalid arguments and parameters",
    ),
    ("logStatusFatal", "Fatal errors"),
    ("logAll", "Everything"),
];

/// Every variable, in value-reference order. Defaults are benchmark B (docs/model.md §5(b)).
///
/// There is no `time` variable: FMI 2.0 makes the independent variable optional, and FMIL (used by
/// the FMU Compliance Checker and libcosim) reports an independent variable without `start` as a
/// parse error although the standard forbids `start` there.
pub const VARIABLES: &[Variable] = &in_value_reference_order::<N_VARIABLES>(&PARTS);

/// The table's parts, by component.
const PARTS: [&[Variable]; 21] = [
    rod::VARIABLES,
    crank::VARIABLES,
    slider::VARIABLES,
    gravity::VARIABLES,
    joints::VARIABLES[0],
    joints::VARIABLES[1],
    joints::VARIABLES[2],
    joints::VARIABLES[3],
    solver::VARIABLES,
    energy::VARIABLES,
    joints::VARIABLES[4],
    joints::VARIABLES[5],
    joints::VARIABLES[6],
    oil::VARIABLES,
    joints::VARIABLES[7],
    joints::VARIABLES[8],
    joints::VARIABLES[9],
    oil::SUPPLY,
    joints::VARIABLES[10],
    joints::VARIABLES[11],
    joints::VARIABLES[12],
];

/// Number of variables.
const N_VARIABLES: usize = {
    let (mut n, mut part) = (0, 0);
    while part < PARTS.len() {
        n += PARTS[part].len();
        part += 1;
    }
    n
};

/// The rows of `parts` as one array of `N` rows, each at the index of its value reference; fails
/// to compile unless every index from 0 to N − 1 has exactly one row.
const fn in_value_reference_order<const N: usize>(parts: &[&[Variable]]) -> [Variable; N] {
    let mut out = [parts[0][0]; N];
    let mut placed = [false; N];
    let mut part = 0;
    while part < parts.len() {
        let mut row = 0;
        while row < parts[part].len() {
            let variable = parts[part][row];
            let index = variable.vr as usize;
            assert!(index < N, "a value reference beyond the table");
            assert!(!placed[index], "two rows with one value reference");
            out[index] = variable;
            placed[index] = true;
            row += 1;
        }
        part += 1;
    }
    out
}
