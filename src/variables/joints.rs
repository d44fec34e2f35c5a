//! The three revolute joints' variables — the rod–slider joint (`joint`), the crank pin
//! (`crankPin`) and the main bearing (`mainBearing`) — from one definition of a joint's rows, and
//! the loads each carries.

use super::enumerations::{
    CONTACT_GEOMETRY, CONTACT_LAW, FEED, FEED_LOCATION, FILM_MODEL, JOINT_MODEL, JOURNAL_START,
    THERMAL_MODEL, THERMAL_START,
};
use super::feed_rows::{FEED_ROWS, feed_rows};
use super::joint_rows::{JOINT_ROWS, joint_rows};
use super::surface_rows::{SURFACE_ROWS, surface_rows};
use super::thermal_rows::{THERMAL_ROWS, thermal_rows};
use super::vr::{Variable, Vr};
use fmi_core::table::{Causality, Kind, Variability};

/// The rod–slider joint (the small end): dry by default, benchmark B's clearance joint.
const ROD_SLIDER_JOINT: [Variable; JOINT_ROWS] = joint_rows!(
    "joint",
    "Rod-slider joint",
    "rod-slider joint",
    "the rod's pin in the slider's bearing, the small end",
    "Rod pin centre - slider bearing centre",
    "pin",
    "rod's pin",
    "pin and bearing",
    2,
    [
        JointModel,
        JointClearance,
        JointJournalRadius,
        JointYoungsModulus,
        JointPoissonRatio,
        JointRestitution,
        JointContactLaw,
        JointFriction,
        JointFrictionV0,
        JointFrictionV1,
        JointViscosity,
        JointBearingLength,
        JointSwitchEccentricity,
        JointEccentricityX,
        JointEccentricityY,
        JointPenetration,
        JointInContact,
        JointContactOnsets,
        JointContactOnsetsTotal,
        JointInitialState,
        JointContactGeometry,
        JointEccentricityRatio,
        JointFilmThickness,
        JointFilmThicknessMin,
        JointFilmThicknessMinSinceStart,
        JointFilmPressurePeak,
        JointFilmPressurePeakSinceStart,
        JointFrictionTorque,
        JointFrictionPower,
        JointEnergyDissipated,
        JointFilmModel,
        JointOilFlow,
        JointFilmThicknessMinCycle,
        JointFilmThicknessMinCycleAngle,
        JointFilmPressurePeakCycle,
        JointFilmPressurePeakCycleAngle,
        JointForcePeakCycle,
        JointForcePeakCycleAngle,
        JointFrictionPowerMeanCycle,
        JointOilFlowMeanCycle,
    ]
);

/// The crank pin (the big end), ideal by default.
const CRANK_PIN: [Variable; JOINT_ROWS] = joint_rows!(
    "crankPin",
    "Crank pin",
    "crank pin",
    "the crank's pin in the rod's eye, the big end",
    "Crank pin centre - rod eye centre",
    "pin",
    "crank pin",
    "pin and eye",
    1,
    [
        CrankPinModel,
        CrankPinClearance,
        CrankPinJournalRadius,
        CrankPinYoungsModulus,
        CrankPinPoissonRatio,
        CrankPinRestitution,
        CrankPinContactLaw,
        CrankPinFriction,
        CrankPinFrictionV0,
        CrankPinFrictionV1,
        CrankPinViscosity,
        CrankPinBearingLength,
        CrankPinSwitchEccentricity,
        CrankPinEccentricityX,
        CrankPinEccentricityY,
        CrankPinPenetration,
        CrankPinInContact,
        CrankPinContactOnsets,
        CrankPinContactOnsetsTotal,
        CrankPinInitialState,
        CrankPinContactGeometry,
        CrankPinEccentricityRatio,
        CrankPinFilmThickness,
        CrankPinFilmThicknessMin,
        CrankPinFilmThicknessMinSinceStart,
        CrankPinFilmPressurePeak,
        CrankPinFilmPressurePeakSinceStart,
        CrankPinFrictionTorque,
        CrankPinFrictionPower,
        CrankPinEnergyDissipated,
        CrankPinFilmModel,
        CrankPinOilFlow,
        CrankPinFilmThicknessMinCycle,
        CrankPinFilmThicknessMinCycleAngle,
        CrankPinFilmPressurePeakCycle,
        CrankPinFilmPressurePeakCycleAngle,
        CrankPinForcePeakCycle,
        CrankPinForcePeakCycleAngle,
        CrankPinFrictionPowerMeanCycle,
        CrankPinOilFlowMeanCycle,
    ]
);

/// The main bearing (the crank's pivot), ideal by default.
const MAIN_BEARING: [Variable; JOINT_ROWS] = joint_rows!(
    "mainBearing",
    "Main bearing",
    "main bearing",
    "the crank's pivot in the ground",
    "Crank pivot centre - main bearing centre",
    "crank journal",
    "crank journal",
    "journal and bearing",
    1,
    [
        MainBearingModel,
        MainBearingClearance,
        MainBearingJournalRadius,
        MainBearingYoungsModulus,
        MainBearingPoissonRatio,
        MainBearingRestitution,
        MainBearingContactLaw,
        MainBearingFriction,
        MainBearingFrictionV0,
        MainBearingFrictionV1,
        MainBearingViscosity,
        MainBearingBearingLength,
        MainBearingSwitchEccentricity,
        MainBearingEccentricityX,
        MainBearingEccentricityY,
        MainBearingPenetration,
        MainBearingInContact,
        MainBearingContactOnsets,
        MainBearingContactOnsetsTotal,
        MainBearingInitialState,
        MainBearingContactGeometry,
        MainBearingEccentricityRatio,
        MainBearingFilmThickness,
        MainBearingFilmThicknessMin,
        MainBearingFilmThicknessMinSinceStart,
        MainBearingFilmPressurePeak,
        MainBearingFilmPressurePeakSinceStart,
        MainBearingFrictionTorque,
        MainBearingFrictionPower,
        MainBearingEnergyDissipated,
        MainBearingFilmModel,
        MainBearingOilFlow,
        MainBearingFilmThicknessMinCycle,
        MainBearingFilmThicknessMinCycleAngle,
        MainBearingFilmPressurePeakCycle,
        MainBearingFilmPressurePeakCycleAngle,
        MainBearingForcePeakCycle,
        MainBearingForcePeakCycleAngle,
        MainBearingFrictionPowerMeanCycle,
        MainBearingOilFlowMeanCycle,
    ]
);

/// The rod-slider joint's rough surfaces.
const ROD_SLIDER_SURFACES: [Variable; SURFACE_ROWS] = surface_rows!(
    "joint",
    "Rod-slider joint",
    [
        JointRoughness,
        JointBoundaryFriction,
        JointAsperityDensityProduct,
        JointAsperityRoughnessRatio,
        JointAsperityForce,
        JointAsperityPressurePeak,
        JointAsperityFrictionPower,
        JointFilmRatio,
        JointAsperityForcePeakCycle,
        JointMetalContactFractionCycle,
    ]
);

/// The crank pin's rough surfaces.
const CRANK_PIN_SURFACES: [Variable; SURFACE_ROWS] = surface_rows!(
    "crankPin",
    "Crank pin",
    [
        CrankPinRoughness,
        CrankPinBoundaryFriction,
        CrankPinAsperityDensityProduct,
        CrankPinAsperityRoughnessRatio,
        CrankPinAsperityForce,
        CrankPinAsperityPressurePeak,
        CrankPinAsperityFrictionPower,
        CrankPinFilmRatio,
        CrankPinAsperityForcePeakCycle,
        CrankPinMetalContactFractionCycle,
    ]
);

/// The main bearing's rough surfaces.
const MAIN_BEARING_SURFACES: [Variable; SURFACE_ROWS] = surface_rows!(
    "mainBearing",
    "Main bearing",
    [
        MainBearingRoughness,
        MainBearingBoundaryFriction,
        MainBearingAsperityDensityProduct,
        MainBearingAsperityRoughnessRatio,
        MainBearingAsperityForce,
        MainBearingAsperityPressurePeak,
        MainBearingAsperityFrictionPower,
        MainBearingFilmRatio,
        MainBearingAsperityForcePeakCycle,
        MainBearingMetalContactFractionCycle,
    ]
);

/// The rod-slider joint's heat balance.
const ROD_SLIDER_THERMAL: [Variable; THERMAL_ROWS] = thermal_rows!(
    "joint",
    "Rod-slider joint",
    [
        JointThermalModel,
        JointThermalStart,
        JointHeatCapacity,
        JointHeatTransferCoefficient,
        JointFilmTemperature,
        JointViscosityEffective,
        JointHeatFlow,
        JointFilmTemperatureMaxCycle,
    ]
);

/// The crank pin's heat balance.
const CRANK_PIN_THERMAL: [Variable; THERMAL_ROWS] = thermal_rows!(
    "crankPin",
    "Crank pin",
    [
        CrankPinThermalModel,
        CrankPinThermalStart,
        CrankPinHeatCapacity,
        CrankPinHeatTransferCoefficient,
        CrankPinFilmTemperature,
        CrankPinViscosityEffective,
        CrankPinHeatFlow,
        CrankPinFilmTemperatureMaxCycle,
    ]
);

/// The main bearing's heat balance.
const MAIN_BEARING_THERMAL: [Variable; THERMAL_ROWS] = thermal_rows!(
    "mainBearing",
    "Main bearing",
    [
        MainBearingThermalModel,
        MainBearingThermalStart,
        MainBearingHeatCapacity,
        MainBearingHeatTransferCoefficient,
        MainBearingFilmTemperature,
        MainBearingViscosityEffective,
        MainBearingHeatFlow,
        MainBearingFilmTemperatureMaxCycle,
    ]
);

/// The rod-slider joint's feed.
const ROD_SLIDER_FEED: [Variable; FEED_ROWS] = feed_rows!(
    "joint",
    "Rod-slider joint",
    "the shell's in the slider along the guide's x axis, the journal's along the rod at its pin",
    [
        JointFeed,
        JointFeedLocation,
        JointFeedPosition,
        JointFeedDiameter,
        JointFeedGrooveLength,
        JointFeedFlow,
    ]
);

/// The crank pin's feed.
const CRANK_PIN_FEED: [Variable; FEED_ROWS] = feed_rows!(
    "crankPin",
    "Crank pin",
    "the shell's in the rod's eye along the rod at its end, the journal's along the crank from its pivot to the pin",
    [
        CrankPinFeed,
        CrankPinFeedLocation,
        CrankPinFeedPosition,
        CrankPinFeedDiameter,
        CrankPinFeedGrooveLength,
        CrankPinFeedFlow,
    ]
);

/// The main bearing's feed.
const MAIN_BEARING_FEED: [Variable; FEED_ROWS] = feed_rows!(
    "mainBearing",
    "Main bearing",
    "the shell's along the ground's x axis, the journal's along the crank from its pivot to the pin",
    [
        MainBearingFeed,
        MainBearingFeedLocation,
        MainBearingFeedPosition,
        MainBearingFeedDiameter,
        MainBearingFeedGrooveLength,
        MainBearingFeedFlow,
    ]
);

/// The three joints' rows, their rough surfaces', heat balances' and feeds', and their loads and
/// the rod–slider joint's contact stiffness.
pub(super) const VARIABLES: [&[Variable]; 13] = [
    &ROD_SLIDER_JOINT,
    &CRANK_PIN,
    &MAIN_BEARING,
    LOADS,
    &ROD_SLIDER_SURFACES,
    &CRANK_PIN_SURFACES,
    &MAIN_BEARING_SURFACES,
    &ROD_SLIDER_THERMAL,
    &CRANK_PIN_THERMAL,
    &MAIN_BEARING_THERMAL,
    &ROD_SLIDER_FEED,
    &CRANK_PIN_FEED,
    &MAIN_BEARING_FEED,
];

/// The force each joint carries (its components and peak) and the rod–slider joint's contact
/// stiffness.
const LOADS: &[Variable] = &[
    Variable::output(
        Vr::JointContactStiffness,
        "joint.contactStiffness",
        "N/m1.5",
        "Hertz point-contact stiffness 4/(3(s_i+s_j)) sqrt(Ri Rj/(Ri-Rj)), s = (1-nu^2)/E, of the rod-slider joint (joint.contactGeometry = point; the line contact has no single stiffness: its force is Johnson's law of joint.bearingLength and E/(2(1-nu^2)))",
    )
    .calculated(),
    Variable::output(
        Vr::JointForce,
        "joint.force",
        "N",
        "Magnitude of the joint force on the journal",
    ),
    Variable::output(
        Vr::JointForceX,
        "joint.forceX",
        "N",
        "Joint force on the journal, x",
    ),
    Variable::output(
        Vr::JointForceY,
        "joint.forceY",
        "N",
        "Joint force on the journal, y",
    ),
    Variable::peak(
        Vr::JointForcePeak,
        "joint.forcePeak",
        "N",
        "Largest joint.force over the last communication interval (every internal step; plot this for peaks)",
    ),
    Variable::output(
        Vr::CrankPinForce,
        "crankPin.force",
        "N",
        "Magnitude of the force of the crank on the rod at the crank pin",
    ),
    Variable::output(
        Vr::CrankPinForceX,
        "crankPin.forceX",
        "N",
        "Force of the crank on the rod at the crank pin, x",
    ),
    Variable::output(
        Vr::CrankPinForceY,
        "crankPin.forceY",
        "N",
        "Force of the crank on the rod at the crank pin, y",
    ),
    Variable::peak(
        Vr::CrankPinForcePeak,
        "crankPin.forcePeak",
        "N",
        "Largest crankPin.force over the last communication interval (every internal step; plot this for peaks)",
    ),
    Variable::output(
        Vr::MainBearingForce,
        "mainBearing.force",
        "N",
        "Magnitude of the force of the ground on the crank at the main bearing (crank pivot)",
    ),
    Variable::output(
        Vr::MainBearingForceX,
        "mainBearing.forceX",
        "N",
        "Force of the ground on the crank at the main bearing, x",
    ),
    Variable::output(
        Vr::MainBearingForceY,
        "mainBearing.forceY",
        "N",
        "Force of the ground on the crank at the main bearing, y",
    ),
    Variable::peak(
        Vr::MainBearingForcePeak,
        "mainBearing.forcePeak",
        "N",
        "Largest mainBearing.force over the last communication interval (every internal step; plot this for peaks)",
    ),
];
