//! THE variable table of the FMU: one row per FMI variable, in value-reference order.
//!
//! This file is plain data over the table types of `fmi2-slave`: `build.rs` compiles it too and
//! renders `modelDescription.xml` from [`DESCRIPTION`], the library validates parameters against
//! its ranges, and values are got and set through one list per kind keyed by [`Vr`] (parameters in
//! `params::access`, Real outputs in `fmi::outputs`), each tested to cover exactly its rows, so the
//! code and the XML cannot disagree.

pub use fmi2_slave::description::Description;
pub use fmi2_slave::table::{Causality, Enumeration, Kind, ValueReference, Variability};

/// One variable of this FMU.
pub type Variable = fmi2_slave::table::Variable<Vr>;

/// Everything modelDescription.xml says.
pub const DESCRIPTION: Description<Vr> = Description {
    model_identifier: "FlexibleSliderCrank",
    description: "Flexible slider-crank mechanism with a clearance joint: planar ANCF connecting rod reduced by Craig-Bampton component mode synthesis (Sun et al., Mech. Mach. Theory 85, 2015)",
    author: "The FlexibleSliderCrank authors",
    version: env!("CARGO_PKG_VERSION"),
    copyright: "Copyright (c) 2026 The FlexibleSliderCrank authors",
    license: "MIT",
    generation_tool: "flexible-slider-crank build.rs (fmi2-slave)",
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
    ],
    enumerations: ENUMERATIONS,
    log_categories: LOG_CATEGORIES,
    default_experiment: DEFAULT_EXPERIMENT,
    variables: VARIABLES,
    feedthrough: FEEDTHROUGH,
    initial_dependency,
    provides_directional_derivative: true,
};

impl ValueReference for Vr {
    fn index(self) -> u32 {
        self as u32
    }
}

/// Enumeration types.
pub const ENUMERATIONS: &[Enumeration] = &[
    Enumeration {
        name: "RodFormulation",
        items: &[
            ("rigid", "rigid uniform bar"),
            ("ancf", "full ANCF beam model"),
            ("craigBampton", "ANCF beam reduced by Craig-Bampton"),
        ],
    },
    Enumeration {
        name: "JointModel",
        items: &[
            ("ideal", "ideal revolute joint"),
            (
                "dry",
                "dry clearance joint (Hertz contact with the damping law of joint.contactLaw, Coulomb friction)",
            ),
            (
                "lubricated",
                "lubricated journal bearing (short-bearing film, dry contact near the wall)",
            ),
        ],
    },
    Enumeration {
        name: "DriveMode",
        items: &[
            ("speed", "crank speed prescribed"),
            ("torque", "crank torque prescribed"),
        ],
    },
    Enumeration {
        name: "RodBoundary",
        items: &[
            (
                "pins",
                "the two pin positions; pinned-pinned modes span the end slopes",
            ),
            (
                "positionsAndSlopes",
                "positions and slopes of both end nodes (Sun et al. 2015); clamped-clamped modes",
            ),
        ],
    },
    Enumeration {
        name: "RodInitialState",
        items: &[
            (
                "equilibrated",
                "deformed by the inertial loads of the initial motion (no start-up ringing)",
            ),
            ("straight", "straight and unstressed (the reference start)"),
        ],
    },
    Enumeration {
        name: "IntegrationMethod",
        items: &[
            (
                "implicit",
                "L-stable ESDIRK5(4) with Newton iterations: steps set by the motion, not by stiffness",
            ),
            (
                "explicit",
                "Dormand-Prince 5(4), the reference method: steps bound by the highest frequency",
            ),
            (
                "generalizedAlpha",
                "generalized-alpha (Chung-Hulbert), 2nd order, numerical dissipation set by solver.spectralRadius",
            ),
        ],
    },
    Enumeration {
        name: "ContactLaw",
        items: &[
            (
                "lankaraniNikravesh",
                "Lankarani-Nikravesh (1990) hysteresis damping, for restitution near 1",
            ),
            (
                "flores",
                "Flores et al. (2011) hysteresis damping, any restitution",
            ),
            (
                "huGuo",
                "Hu and Guo (2015) hysteresis damping, any restitution",
            ),
        ],
    },
    Enumeration {
        name: "JournalStart",
        items: &[
            (
                "centred",
                "centred in the bearing (the benchmarks' start): it crosses the clearance and impacts",
            ),
            (
                "settled",
                "in quasi-static equilibrium with the ideal joint's initial reaction, at rest in the bearing: no start-up impact",
            ),
        ],
    },
    Enumeration {
        name: "RodQuadrature",
        items: &[
            (
                "full",
                "every quadrature point of the mesh the rod was reduced from",
            ),
            (
                "sampled",
                "a few weighted points fitted at initialization (energy-conserving sampling and weighting): cost independent of rod.nElements",
            ),
        ],
    },
    Enumeration {
        name: "ContactGeometry",
        items: &[
            (
                "point",
                "Hertz point contact, K penetration^1.5 (the benchmarks' law)",
            ),
            (
                "cylinder",
                "Johnson's line contact of the pin along bearingLength: a long pin sinks much less",
            ),
        ],
    },
];

/// Units: name and SI base-unit exponents (kg, m, s, A, rad), or None where FMI 2's integer
/// exponents cannot express the unit (N/m^1.5).
pub const UNITS: &[(&str, Option<[i32; 5]>)] = &[
    ("s", Some([0, 0, 1, 0, 0])),
    ("m", Some([0, 1, 0, 0, 0])),
    ("m/s", Some([0, 1, -1, 0, 0])),
    ("m/s2", Some([0, 1, -2, 0, 0])),
    ("m2", Some([0, 2, 0, 0, 0])),
    ("m4", Some([0, 4, 0, 0, 0])),
    ("kg", Some([1, 0, 0, 0, 0])),
    ("kg/m3", Some([1, -3, 0, 0, 0])),
    ("kg.m2", Some([1, 2, 0, 0, 0])),
    ("Pa", Some([1, -1, -2, 0, 0])),
    ("Pa.s", Some([1, -1, -1, 0, 0])),
    ("N", Some([1, 1, -2, 0, 0])),
    ("N.m", Some([1, 2, -2, 0, 0])),
    ("J", Some([1, 2, -2, 0, 0])),
    ("W", Some([1, 2, -3, 0, 0])),
    ("rad", Some([0, 0, 0, 0, 1])),
    ("rad/s", Some([0, 0, -1, 0, 1])),
    ("1", Some([0, 0, 0, 0, 0])),
    ("N/m1.5", None),
];

/// Default experiment: two crank revolutions of benchmark B (5000 rpm) with a 1e-4 s step; the
/// tolerance is the default of `solver.relativeTolerance`, so a master that passes it to
/// fmi2SetupExperiment runs the FMU's defaults (a smaller tolerance from the master tightens
/// `solver.relativeTolerance`, see `instance::model_parameters`).
pub const DEFAULT_EXPERIMENT: (f64, f64, f64, f64) = (0.0, 0.024, 1e-2, 1e-4);

/// Direct feedthrough, declared as the `dependencies` of ModelStructure/Outputs: each output
/// that shows a change of an input at once, before the next fmi2DoStep, with those inputs. Every
/// other output reacts to the inputs only through the motion (after a step): the positions,
/// speeds, energies and counters are states or integrals of the motion. The lists are the union
/// over every drive, joint and rod model, as measured by `packaging/python/tests/test_fmu.py`.
pub const FEEDTHROUGH: &[(Vr, &[Vr])] = &[
    (Vr::CrankTorque, ALL_INPUTS),
    (Vr::SliderAcceleration, ALL_INPUTS),
    (Vr::JointForce, ALL_INPUTS),
    (Vr::JointForceX, ALL_INPUTS),
    (Vr::JointForceY, ALL_INPUTS),
    (Vr::JointForcePeak, ALL_INPUTS),
    (Vr::SliderAccelerationPeak, ALL_INPUTS),
    (Vr::CrankPinForce, ALL_INPUTS),
    (Vr::CrankPinForceX, ALL_INPUTS),
    (Vr::CrankPinForceY, ALL_INPUTS),
    (Vr::CrankPinForcePeak, ALL_INPUTS),
    (Vr::MainBearingForce, ALL_INPUTS),
    (Vr::MainBearingForceX, ALL_INPUTS),
    (Vr::MainBearingForceY, ALL_INPUTS),
    (Vr::MainBearingForcePeak, ALL_INPUTS),
    (Vr::GuideForce, ALL_INPUTS),
    (Vr::GuideForcePeak, ALL_INPUTS),
    (Vr::RodStress, ALL_INPUTS),
    (Vr::RodStressPeak, ALL_INPUTS),
    (Vr::RodAxialForceCrankPin, ALL_INPUTS),
    (Vr::RodAxialForceSliderPin, ALL_INPUTS),
    (Vr::RodStressMax, ALL_INPUTS),
    (Vr::RodStressMin, ALL_INPUTS),
    (Vr::RodStressMaxPeak, ALL_INPUTS),
    (Vr::RodStressMinPeak, ALL_INPUTS),
    (Vr::RodStressLocation, ALL_INPUTS),
    (Vr::RodAxialForceMidspan, ALL_INPUTS),
    (Vr::RodBendingMomentMidspan, ALL_INPUTS),
    (Vr::SliderAppliedForce, &[Vr::SliderForce]),
];

/// The accelerations and the forces that follow from them react to every input at once: the
/// torque and the slider force through the equations of motion, the speed of the speed drive
/// through the stabilised drive constraint (its velocity error enters the constraint
/// acceleration). With a clearance joint the joint force depends on the motion only; the ideal
/// joint's reaction depends on the inputs, hence the union.
const ALL_INPUTS: &[Vr] = &[Vr::DriveSpeed, Vr::DriveTorque, Vr::SliderForce];

/// Whether an output (or `joint.contactStiffness`) depends, in initialization mode, on an input
/// or a parameter: the `dependencies` of ModelStructure/InitialUnknowns.
///
/// The start is a coupled equilibrium: the rod is equilibrated under the start's inertial and
/// applied loads and each journal rests where its contact carries its load, so the start's
/// positions, forces and energies depend on every physical parameter and every input (the
/// speed drive's input through the drive constraint). The exceptions are the crank's prescribed
/// start, the slider's applied force (the input and the load table at the start angle), the contact stiffness (a formula of four parameters), the model warnings (the
/// short-bearing range of a lubricated joint) and the step counters and work integrals, which
/// start at zero. The solver settings shape no start. The lists are the union over every drive,
/// joint and rod model; `packaging/python/tests/test_fmu.py` checks them against perturbations
/// in initialization mode.
fn initial_dependency(unknown: Vr, known: Vr) -> bool {
    use Vr::*;
    match unknown {
        CrankAngle => known == CrankInitialAngle,
        CrankSpeed => matches!(known, CrankInitialSpeed | DriveSpeed),
        SliderAppliedForce => matches!(
            known,
            SliderForce | SliderForceTable | SliderForceTablePeriod | CrankInitialAngle
        ),
        JointContactStiffness => matches!(
            known,
            JointClearance | JointJournalRadius | JointYoungsModulus | JointPoissonRatio
        ),
        SolverWarnings => matches!(
            known,
            JointModel
                | JointJournalRadius
                | JointBearingLength
                | CrankPinModel
                | CrankPinJournalRadius
                | CrankPinBearingLength
                | MainBearingModel
                | MainBearingJournalRadius
                | MainBearingBearingLength
        ),
        SolverSteps
        | SolverEvaluations
        | EnergyDriveWork
        | EnergySliderWork
        | EnergyMaterialDamping
        | JointContactOnsets
        | JointContactOnsetsTotal
        | CrankPinContactOnsets
        | CrankPinContactOnsetsTotal
        | MainBearingContactOnsets
        | MainBearingContactOnsetsTotal => false,
        _ => !matches!(
            known,
            SolverRelativeTolerance
                | SolverMaxStepSize
                | SolverMethod
                | SolverMaxStepsPerInterval
                | SolverSpectralRadius
                | SolverImpactErrorWeight
        ),
    }
}

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

/// Value references, dense from 0 in table order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
#[allow(missing_docs)]
pub enum Vr {
    RodFormulation = 0,
    RodNElements,
    RodNModes,
    RodLength,
    RodYoungsModulus,
    RodDensity,
    RodArea,
    RodSecondMomentOfArea,
    RodStiffnessDamping,
    CrankLength,
    CrankMass,
    CrankInertia,
    CrankInitialAngle,
    CrankInitialSpeed,
    SliderMass,
    JointModel,
    JointClearance,
    JointJournalRadius,
    JointYoungsModulus,
    JointPoissonRatio,
    JointRestitution,
    JointFriction,
    JointFrictionV0,
    JointFrictionV1,
    JointViscosity,
    JointBearingLength,
    JointSwitchEccentricity,
    DriveMode,
    Gravity,
    SolverRelativeTolerance,
    SolverMaxStepSize,
    JointContactStiffness,
    DriveSpeed,
    DriveTorque,
    SliderForce,
    CrankAngle,
    CrankSpeed,
    CrankTorque,
    SliderPosition,
    SliderVelocity,
    SliderAcceleration,
    JointForce,
    JointForceX,
    JointForceY,
    JointEccentricityX,
    JointEccentricityY,
    JointPenetration,
    JointInContact,
    RodMidspanDeflection,
    RodDeformationEnergy,
    EnergyKinetic,
    EnergyDriveWork,
    EnergyDissipated,
    SolverSteps,
    RodBoundary,
    SolverMethod,
    SolverEvaluations,
    RodInitialState,
    JointForcePeak,
    SliderAccelerationPeak,
    JointContactOnsets,
    JointContactOnsetsTotal,
    JointContactLaw,
    SolverMaxStepsPerInterval,
    EnergyContact,
    EnergyGravity,
    EnergySliderWork,
    EnergyMaterialDamping,
    SolverSpectralRadius,
    SolverWarnings,
    RodDeformationEnergyPeak,
    SolverImpactErrorWeight,
    GravityAngle,
    RodOuterFibreDistance,
    CrankPinForce,
    CrankPinForceX,
    CrankPinForceY,
    CrankPinForcePeak,
    MainBearingForce,
    MainBearingForceX,
    MainBearingForceY,
    MainBearingForcePeak,
    GuideForce,
    GuideForcePeak,
    RodStress,
    RodStressPeak,
    RodAxialForceCrankPin,
    RodAxialForceSliderPin,
    JointInitialState,
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
    RodQuadrature,
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
    CrankCentreOfMassRatio,
    SliderOffset,
    RodDampingRatio,
    RodCrankEndMass,
    RodSliderEndMass,
    RodStressMax,
    RodStressMin,
    RodStressMaxPeak,
    RodStressMinPeak,
    RodStressLocation,
    RodAxialForceMidspan,
    RodBendingMomentMidspan,
    SliderForceTable,
    SliderForceTablePeriod,
    SliderAppliedForce,
}

/// 5000 rpm in rad/s (benchmark B); the same expression as `params::BENCHMARK_SPEED`.
const SPEED: f64 = 5000.0 * core::f64::consts::TAU / 60.0;

/// The parameters and outputs of a revolute joint that can be worn besides the rod–slider joint
/// (ideal by default, the benchmark joint's values otherwise): its variable-name prefix, its name
/// starting a description and inside one, what it joins, what its eccentricity is, its journal,
/// the parts in contact, and its 20 value references in the order of the rows.
macro_rules! joint_rows {
    (
        $prefix:literal,
        $label:literal,
        $name:literal,
        $joins:literal,
        $eccentricity:literal,
        $journal:literal,
        $parts:literal,
        [
            $model:ident,
            $clearance:ident,
            $radius:ident,
            $youngs:ident,
            $poisson:ident,
            $restitution:ident,
            $law:ident,
            $friction:ident,
            $v0:ident,
            $v1:ident,
            $viscosity:ident,
            $length:ident,
            $switch:ident,
            $ex:ident,
            $ey:ident,
            $penetration:ident,
            $contact:ident,
            $onsets:ident,
            $total:ident,
            $start:ident $(,)?
        ]
    ) => {
        [
            Variable::enumeration(
                Vr::$model,
                concat!($prefix, ".model"),
                1,
                1,
                concat!($label, " joint model (", $joins, ")"),
            ),
            Variable::parameter(
                Vr::$clearance,
                concat!($prefix, ".clearance"),
                5e-4,
                0.0,
                0.1,
                "m",
                concat!(
                    $label,
                    ": radial clearance (bearing radius - journal radius)"
                ),
            ),
            Variable::parameter(
                Vr::$radius,
                concat!($prefix, ".journalRadius"),
                9.5e-3,
                1e-5,
                1.0,
                "m",
                concat!($label, ": ", $journal, " radius"),
            ),
            Variable::parameter(
                Vr::$youngs,
                concat!($prefix, ".youngsModulus"),
                207e9,
                1e6,
                1e13,
                "Pa",
                concat!($label, ": Young's modulus of ", $parts),
            ),
            Variable::parameter(
                Vr::$poisson,
                concat!($prefix, ".poissonRatio"),
                0.3,
                -0.99,
                0.499,
                "1",
                concat!($label, ": Poisson ratio of ", $parts),
            ),
            Variable::parameter(
                Vr::$restitution,
                concat!($prefix, ".restitution"),
                0.9,
                1e-3,
                1.0,
                "1",
                concat!(
                    $label,
                    ": coefficient of restitution of the dry contact (see ",
                    $prefix,
                    ".contactLaw)"
                ),
            ),
            Variable::enumeration(
                Vr::$law,
                concat!($prefix, ".contactLaw"),
                1,
                6,
                concat!($label, ": hysteresis-damping law of the dry contact force"),
            ),
            Variable::parameter(
                Vr::$friction,
                concat!($prefix, ".friction"),
                0.0,
                0.0,
                2.0,
                "1",
                concat!($label, ": Coulomb friction coefficient"),
            ),
            Variable::parameter(
                Vr::$v0,
                concat!($prefix, ".frictionV0"),
                1e-4,
                0.0,
                1.0,
                "m/s",
                concat!($label, ": slip speed below which friction vanishes"),
            ),
            Variable::parameter(
                Vr::$v1,
                concat!($prefix, ".frictionV1"),
                1e-3,
                1e-9,
                10.0,
                "m/s",
                concat!(
                    $label,
                    ": slip speed above which friction is fully developed"
                ),
            ),
            Variable::parameter(
                Vr::$viscosity,
                concat!($prefix, ".viscosity"),
                0.4,
                1e-6,
                100.0,
                "Pa.s",
                concat!($label, ": lubricant dynamic viscosity"),
            ),
            Variable::parameter(
                Vr::$length,
                concat!($prefix, ".bearingLength"),
                0.04,
                1e-5,
                10.0,
                "m",
                concat!($label, ": bearing length"),
            ),
            Variable::parameter(
                Vr::$switch,
                concat!($prefix, ".switchEccentricity"),
                0.95,
                0.01,
                0.99,
                "1",
                concat!(
                    $label,
                    ": eccentricity ratio above which dry contact takes over"
                ),
            ),
            Variable::output(
                Vr::$ex,
                concat!($prefix, ".eccentricityX"),
                "m",
                concat!($eccentricity, ", x (0 for the ideal ", $name, ")"),
            ),
            Variable::output(
                Vr::$ey,
                concat!($prefix, ".eccentricityY"),
                "m",
                concat!($eccentricity, ", y"),
            ),
            Variable::output(
                Vr::$penetration,
                concat!($prefix, ".penetration"),
                "m",
                concat!($label, " contact penetration max(|e| - c, 0)"),
            ),
            Variable {
                vr: Vr::$contact,
                name: concat!($prefix, ".inContact"),
                causality: Causality::Output,
                variability: Variability::Discrete,
                kind: Kind::Boolean,
                description: concat!($label, ": ", $parts, " in contact"),
            },
            Variable::count(
                Vr::$onsets,
                concat!($prefix, ".contactOnsets"),
                concat!(
                    "Contact onsets at the ",
                    $name,
                    " in the last communication interval"
                ),
            ),
            Variable::count(
                Vr::$total,
                concat!($prefix, ".contactOnsetsTotal"),
                concat!("Contact onsets at the ", $name, " since the start"),
            ),
            Variable::enumeration(
                Vr::$start,
                concat!($prefix, ".initialState"),
                1,
                7,
                concat!("Where the journal of a clearance ", $name, " starts"),
            ),
        ]
    };
}

/// Every variable, in value-reference order. Defaults are benchmark B (docs/model.md §5(b)).
///
/// There is no `time` variable: FMI 2.0 makes the independent variable optional, and FMIL (used by
/// the FMU Compliance Checker and libcosim) reports an independent variable without `start` as a
/// parse error although the standard forbids `start` there.
pub const VARIABLES: &[Variable] = &concat::<N_VARIABLES>(&[
    BASE_VARIABLES,
    &CRANK_PIN_VARIABLES,
    &MAIN_BEARING_VARIABLES,
    &[ROD_QUADRATURE],
    &JOINT_BEARING_VARIABLES,
    &CRANK_PIN_BEARING_VARIABLES,
    &MAIN_BEARING_BEARING_VARIABLES,
    MACHINE_VARIABLES,
]);

/// Number of variables.
const N_VARIABLES: usize =
    BASE_VARIABLES.len() + 2 * JOINT_ROWS + 1 + 3 * BEARING_ROWS + MACHINE_VARIABLES.len();

/// The rows of `parts`, one after the other, as one array of `N` rows.
const fn concat<const N: usize>(parts: &[&[Variable]]) -> [Variable; N] {
    let mut out = [parts[0][0]; N];
    let (mut i, mut part) = (0, 0);
    while part < parts.len() {
        let mut row = 0;
        while row < parts[part].len() {
            out[i] = parts[part][row];
            i += 1;
            row += 1;
        }
        part += 1;
    }
    assert!(i == N, "N_VARIABLES must count every row");
    out
}

/// The variables of the mechanism and of its rod–slider joint, in value-reference order.
const BASE_VARIABLES: &[Variable] = &[
    Variable::enumeration(
        Vr::RodFormulation,
        "rod.formulation",
        3,
        0,
        "Connecting-rod model",
    ),
    Variable::integer(
        Vr::RodNElements,
        "rod.nElements",
        8,
        1,
        64,
        "Number of ANCF elements (ancf, craigBampton)",
    ),
    Variable::integer(
        Vr::RodNModes,
        "rod.nModes",
        4,
        0,
        128,
        "Craig-Bampton fixed-interface mode shapes, each in both directions; at most 2 rod.nElements (rod.boundary = pins) or 2 rod.nElements - 2 (positionsAndSlopes)",
    ),
    Variable::parameter(
        Vr::RodLength,
        "rod.length",
        0.12,
        1e-3,
        100.0,
        "m",
        "Rod length between the pins",
    ),
    Variable::parameter(
        Vr::RodYoungsModulus,
        "rod.youngsModulus",
        207e9,
        1e6,
        1e13,
        "Pa",
        "Rod Young's modulus",
    ),
    Variable::parameter(
        Vr::RodDensity,
        "rod.density",
        7800.0,
        1.0,
        1e5,
        "kg/m3",
        "Rod density",
    ),
    Variable::parameter(
        Vr::RodArea,
        "rod.area",
        2.243_589_743_589_743_6e-4,
        1e-10,
        1.0,
        "m2",
        "Rod cross-section area",
    ),
    Variable::parameter(
        Vr::RodSecondMomentOfArea,
        "rod.secondMomentOfArea",
        4.195e-9,
        1e-20,
        1.0,
        "m4",
        "Rod second moment of area; a flexible rod must be slender: rod.length / sqrt(I / rod.area) >= 10",
    ),
    Variable::parameter(
        Vr::RodStiffnessDamping,
        "rod.stiffnessDamping",
        0.0,
        0.0,
        1.0,
        "s",
        "Strain-rate (stiffness-proportional) damping coefficient; a flexible rod takes at most 2/omega1, its first pinned-pinned bending mode critically damped (1.31e-4 s for the default rod); rod.dampingRatio gives the same damping as a ratio",
    ),
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
    Variable::parameter(
        Vr::SliderMass,
        "slider.mass",
        0.14,
        1e-6,
        1e4,
        "kg",
        "Slider mass",
    ),
    Variable::enumeration(
        Vr::JointModel,
        "joint.model",
        2,
        1,
        "Rod-slider joint model",
    ),
    Variable::parameter(
        Vr::JointClearance,
        "joint.clearance",
        5e-4,
        0.0,
        0.1,
        "m",
        "Radial clearance (bearing radius - journal radius)",
    ),
    Variable::parameter(
        Vr::JointJournalRadius,
        "joint.journalRadius",
        9.5e-3,
        1e-5,
        1.0,
        "m",
        "Journal (pin) radius",
    ),
    Variable::parameter(
        Vr::JointYoungsModulus,
        "joint.youngsModulus",
        207e9,
        1e6,
        1e13,
        "Pa",
        "Young's modulus of journal and bearing",
    ),
    Variable::parameter(
        Vr::JointPoissonRatio,
        "joint.poissonRatio",
        0.3,
        -0.99,
        0.499,
        "1",
        "Poisson ratio of journal and bearing",
    ),
    Variable::parameter(
        Vr::JointRestitution,
        "joint.restitution",
        0.9,
        1e-3,
        1.0,
        "1",
        "Coefficient of restitution of the dry contact (see joint.contactLaw)",
    ),
    Variable::parameter(
        Vr::JointFriction,
        "joint.friction",
        0.0,
        0.0,
        2.0,
        "1",
        "Coulomb friction coefficient",
    ),
    Variable::parameter(
        Vr::JointFrictionV0,
        "joint.frictionV0",
        1e-4,
        0.0,
        1.0,
        "m/s",
        "Slip speed below which friction vanishes",
    ),
    Variable::parameter(
        Vr::JointFrictionV1,
        "joint.frictionV1",
        1e-3,
        1e-9,
        10.0,
        "m/s",
        "Slip speed above which friction is fully developed",
    ),
    Variable::parameter(
        Vr::JointViscosity,
        "joint.viscosity",
        0.4,
        1e-6,
        100.0,
        "Pa.s",
        "Lubricant dynamic viscosity",
    ),
    Variable::parameter(
        Vr::JointBearingLength,
        "joint.bearingLength",
        0.04,
        1e-5,
        10.0,
        "m",
        "Bearing length",
    ),
    Variable::parameter(
        Vr::JointSwitchEccentricity,
        "joint.switchEccentricity",
        0.95,
        0.01,
        0.99,
        "1",
        "Eccentricity ratio above which dry contact takes over",
    ),
    Variable::enumeration(Vr::DriveMode, "drive.mode", 1, 2, "What drives the crank"),
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
        Vr::SolverRelativeTolerance,
        "solver.relativeTolerance",
        1e-2,
        1e-12,
        1e-1,
        "1",
        "Relative tolerance of the internal error-controlled integrator (at most 1e-4 with solver.method = explicit, 3e-2 with generalizedAlpha)",
    ),
    Variable::parameter(
        Vr::SolverMaxStepSize,
        "solver.maxStepSize",
        1e-4,
        1e-9,
        1.0,
        "s",
        "Largest internal step",
    ),
    Variable {
        vr: Vr::JointContactStiffness,
        name: "joint.contactStiffness",
        causality: Causality::CalculatedParameter,
        variability: Variability::Fixed,
        kind: Kind::Real {
            start: None,
            min: 0.0,
            max: f64::INFINITY,
            unit: "N/m1.5",
        },
        description: "Hertz point-contact stiffness 4/(3(s_i+s_j)) sqrt(Ri Rj/(Ri-Rj)), s = (1-nu^2)/E, of the rod-slider joint (joint.contactGeometry = point; the line contact has no single stiffness: its force is Johnson's law of joint.bearingLength and E/(2(1-nu^2)))",
    },
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
    Variable::output(
        Vr::JointEccentricityX,
        "joint.eccentricityX",
        "m",
        "Journal centre - bearing centre, x",
    ),
    Variable::output(
        Vr::JointEccentricityY,
        "joint.eccentricityY",
        "m",
        "Journal centre - bearing centre, y",
    ),
    Variable::output(
        Vr::JointPenetration,
        "joint.penetration",
        "m",
        "Contact penetration max(|e| - c, 0)",
    ),
    Variable {
        vr: Vr::JointInContact,
        name: "joint.inContact",
        causality: Causality::Output,
        variability: Variability::Discrete,
        kind: Kind::Boolean,
        description: "Journal and bearing in contact",
    },
    Variable::output(
        Vr::RodMidspanDeflection,
        "rod.midspanDeflection",
        "m",
        "Rod mid-span deflection from the chord, left positive",
    ),
    Variable::output(
        Vr::RodDeformationEnergy,
        "rod.deformationEnergy",
        "J",
        "Rod strain energy",
    ),
    Variable::output(
        Vr::EnergyKinetic,
        "energy.kinetic",
        "J",
        "Kinetic energy of crank, rod and slider",
    ),
    Variable::output(
        Vr::EnergyDriveWork,
        "energy.driveWork",
        "J",
        "Work done by the drive",
    ),
    Variable::output(
        Vr::EnergyDissipated,
        "energy.dissipated",
        "J",
        "Energy dissipated in the joints: the sum of joint, crankPin and mainBearing.energyDissipated",
    ),
    Variable::count(
        Vr::SolverSteps,
        "solver.steps",
        "Accepted internal integrator steps",
    ),
    Variable::enumeration(
        Vr::RodBoundary,
        "rod.boundary",
        1,
        3,
        "Craig-Bampton interface: the rod coordinates kept physical",
    ),
    Variable::enumeration(
        Vr::SolverMethod,
        "solver.method",
        1,
        5,
        "Internal time-integration method",
    ),
    Variable::count(
        Vr::SolverEvaluations,
        "solver.evaluations",
        "Right-hand-side evaluations of the internal integrator (with those of Jacobians)",
    ),
    Variable::enumeration(
        Vr::RodInitialState,
        "rod.initialState",
        1,
        4,
        "How the rod starts (the crank, slider and pins start with the ideal mechanism's motion)",
    ),
    Variable::peak(
        Vr::JointForcePeak,
        "joint.forcePeak",
        "N",
        "Largest joint.force over the last communication interval (every internal step; plot this for peaks)",
    ),
    Variable::peak(
        Vr::SliderAccelerationPeak,
        "slider.accelerationPeak",
        "m/s2",
        "Largest |slider.acceleration| over the last communication interval (every internal step)",
    ),
    Variable::count(
        Vr::JointContactOnsets,
        "joint.contactOnsets",
        "Contact onsets (journal starts touching the bearing) in the last communication interval",
    ),
    Variable::count(
        Vr::JointContactOnsetsTotal,
        "joint.contactOnsetsTotal",
        "Contact onsets since the start",
    ),
    Variable::enumeration(
        Vr::JointContactLaw,
        "joint.contactLaw",
        1,
        6,
        "Hysteresis-damping law of the dry contact force (dry joint, and the lubricated joint near the wall)",
    ),
    Variable::integer(
        Vr::SolverMaxStepsPerInterval,
        "solver.maxStepsPerInterval",
        50_000,
        1,
        i32::MAX,
        "Work limit: internal step attempts per communication interval; beyond it fmi2DoStep returns fmi2Discard naming the likely cause",
    ),
    Variable::output(
        Vr::EnergyContact,
        "energy.contact",
        "J",
        "Elastic energy stored in the joints' contacts (K penetration^2.5 / 2.5 for the point contact; the integral of the line contact's force)",
    ),
    Variable::output(
        Vr::EnergyGravity,
        "energy.gravity",
        "J",
        "Gravitational potential energy of crank, rod and slider (zero at y = 0)",
    ),
    Variable::output(
        Vr::EnergySliderWork,
        "energy.sliderWork",
        "J",
        "Work done on the slider by its external force, slider.appliedForce (the input slider.force and slider.forceTable)",
    ),
    Variable::output(
        Vr::EnergyMaterialDamping,
        "energy.materialDamping",
        "J",
        "Energy dissipated in the rod by its material damping (rod.dampingRatio or rod.stiffnessDamping)",
    ),
    Variable::parameter(
        Vr::SolverSpectralRadius,
        "solver.spectralRadius",
        0.8,
        0.0,
        1.0,
        "1",
        "Numerical dissipation of solver.method = generalizedAlpha: spectral radius at infinity (1: none, 0: unresolved frequencies removed in one step)",
    ),
    Variable::count(
        Vr::SolverWarnings,
        "solver.warnings",
        "Warnings raised since the start, also without logging: the model left the domain its laws were made for (penetration, deflection, crank speed, stroke, the line contact's range), a parameter outside a law's range, a crank speed that jumps to drive.speed at the first step, a lubricated joint's force peak inside a step that the interpolant decides; the logger gives each message",
    ),
    Variable::peak(
        Vr::RodDeformationEnergyPeak,
        "rod.deformationEnergyPeak",
        "J",
        "Largest rod.deformationEnergy over the last communication interval (every internal step's end, and within the steps in contact); its maximum over a run is the source paper's mode-count criterion",
    ),
    Variable::parameter(
        Vr::SolverImpactErrorWeight,
        "solver.impactErrorWeight",
        4.0,
        0.0,
        100.0,
        "1",
        "Dry joint, implicit methods: the journal's normal velocity in the bearing is held to solver.relativeTolerance / weight on its own (in units of the speed scale), so that every impact's peak and onset come out right; 0 leaves it to the RMS over all states (flexible rods about 2x faster, but the impacts after the first then off by up to 67 % at the default tolerance)",
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
    Variable::parameter(
        Vr::RodOuterFibreDistance,
        "rod.outerFibreDistance",
        7.4893e-3,
        1e-6,
        1.0,
        "m",
        "Outer-fibre distance of the rod's section from its neutral axis (h/2 for a rectangle of height h), for rod.stress",
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
    Variable::output(
        Vr::RodStress,
        "rod.stress",
        "Pa",
        "Largest normal stress magnitude over the rod, |N|/A + |M| c/I (axial force N, bending moment M, c = rod.outerFibreDistance)",
    ),
    Variable::peak(
        Vr::RodStressPeak,
        "rod.stressPeak",
        "Pa",
        "Largest rod.stress over the last communication interval (every internal step)",
    ),
    Variable::output(
        Vr::RodAxialForceCrankPin,
        "rod.axialForceCrankPin",
        "N",
        "Axial force of the rod's shank at the crank pin (along the rod's end tangent; rod.crankEndMass's inertia and weight excluded), tension positive",
    ),
    Variable::output(
        Vr::RodAxialForceSliderPin,
        "rod.axialForceSliderPin",
        "N",
        "Axial force of the rod's shank at the slider pin (along the rod's end tangent; rod.sliderEndMass's inertia and weight excluded), tension positive",
    ),
    Variable::enumeration(
        Vr::JointInitialState,
        "joint.initialState",
        1,
        7,
        "Where the journal of a clearance joint starts",
    ),
];

/// The Craig–Bampton rod's quadrature switch, after both joints' rows.
const ROD_QUADRATURE: Variable = Variable::enumeration(
    Vr::RodQuadrature,
    "rod.quadrature",
    1,
    8,
    "How the Craig-Bampton rod integrates its internal forces and strain energy (sampled: rod.nModes at most 8)",
);

/// Number of rows of a revolute clearance joint besides the rod–slider joint ([`joint_rows`]).
const JOINT_ROWS: usize = 20;

/// The crank pin's parameters and outputs.
const CRANK_PIN_VARIABLES: [Variable; JOINT_ROWS] = joint_rows!(
    "crankPin",
    "Crank pin",
    "crank pin",
    "the crank's pin in the rod's eye, the big end",
    "Crank pin centre - rod eye centre",
    "pin",
    "pin and eye",
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
    ]
);

/// The main bearing's parameters and outputs.
const MAIN_BEARING_VARIABLES: [Variable; JOINT_ROWS] = joint_rows!(
    "mainBearing",
    "Main bearing",
    "main bearing",
    "the crank's pivot in the ground",
    "Crank pivot centre - main bearing centre",
    "crank journal",
    "journal and bearing",
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
    ]
);

/// Number of rows of a joint's bearing-design variables ([`bearing_rows`]).
const BEARING_ROWS: usize = 10;

/// What a bearing designer reads off a revolute joint, the same for every joint: the geometry of
/// its dry contact and the outputs of its oil film, gap, friction and dissipation. Arguments: the
/// variable-name prefix, its name starting a description, the journal, and the 10 value
/// references in the order of the rows.
macro_rules! bearing_rows {
    (
        $prefix:literal,
        $label:literal,
        $journal:literal,
        [
            $geometry:ident,
            $ratio:ident,
            $thickness:ident,
            $thickness_min:ident,
            $thickness_min_start:ident,
            $pressure:ident,
            $pressure_start:ident,
            $torque:ident,
            $power:ident,
            $dissipated:ident $(,)?
        ]
    ) => {
        [
            Variable::enumeration(
                Vr::$geometry,
                concat!($prefix, ".contactGeometry"),
                1,
                9,
                concat!(
                    $label,
                    ": geometry of the dry contact's elastic law (point: Hertz; cylinder: Johnson's line contact over ",
                    $prefix,
                    ".bearingLength); the hysteresis damping, contact energy and settled start follow it"
                ),
            ),
            Variable::output(
                Vr::$ratio,
                concat!($prefix, ".eccentricityRatio"),
                "1",
                concat!(
                    $label,
                    ": eccentricity ratio |e|/c, the actual one (above 1 in metal contact); 0 for the ideal joint"
                ),
            ),
            Variable::output(
                Vr::$thickness,
                concat!($prefix, ".filmThickness"),
                "m",
                concat!(
                    $label,
                    ": minimum oil-film thickness (gap between ",
                    $journal,
                    " and bearing) c (1 - |e|/c); 0 in metal contact (see ",
                    $prefix,
                    ".penetration) and for the ideal joint"
                ),
            ),
            Variable::peak(
                Vr::$thickness_min,
                concat!($prefix, ".filmThicknessMin"),
                "m",
                concat!(
                    "Smallest ",
                    $prefix,
                    ".filmThickness over the last communication interval (every internal step's end, and within the steps in contact or with a film)"
                ),
            ),
            Variable::peak(
                Vr::$thickness_min_start,
                concat!($prefix, ".filmThicknessMinSinceStart"),
                "m",
                concat!("Smallest ", $prefix, ".filmThickness since the start"),
            ),
            Variable::peak(
                Vr::$pressure,
                concat!($prefix, ".filmPressurePeak"),
                "Pa",
                concat!(
                    $label,
                    ": largest oil-film pressure over the last communication interval, at mid-length (short-bearing field; every internal step); 0 without a film (dry and ideal joints)"
                ),
            ),
            Variable::peak(
                Vr::$pressure_start,
                concat!($prefix, ".filmPressurePeakSinceStart"),
                "Pa",
                concat!("Largest ", $prefix, ".filmPressurePeak since the start"),
            ),
            Variable::output(
                Vr::$torque,
                concat!($prefix, ".frictionTorque"),
                "N.m",
                concat!(
                    $label,
                    ": friction moment on the ",
                    $journal,
                    " about its centre, CCW positive (dry friction and the film's shear); 0 for the ideal joint"
                ),
            ),
            Variable::output(
                Vr::$power,
                concat!($prefix, ".frictionPower"),
                "W",
                concat!(
                    $label,
                    ": rate at which the joint's friction dissipates energy, >= 0 (the oil film's viscous loss in shear and squeeze; dry friction -F_T v_T); 0 for the ideal joint"
                ),
            ),
            Variable::output(
                Vr::$dissipated,
                concat!($prefix, ".energyDissipated"),
                "J",
                concat!(
                    $label,
                    ": energy dissipated in the joint since the start (friction, contact hysteresis, film); the three joints' sum to energy.dissipated; 0 for the ideal joint"
                ),
            ),
        ]
    };
}

/// The rod–slider joint's bearing-design variables.
const JOINT_BEARING_VARIABLES: [Variable; BEARING_ROWS] = bearing_rows!(
    "joint",
    "Rod-slider joint",
    "rod's pin",
    [
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
    ]
);

/// The crank pin's bearing-design variables.
const CRANK_PIN_BEARING_VARIABLES: [Variable; BEARING_ROWS] = bearing_rows!(
    "crankPin",
    "Crank pin",
    "crank pin",
    [
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
    ]
);

/// The main bearing's bearing-design variables.
const MAIN_BEARING_BEARING_VARIABLES: [Variable; BEARING_ROWS] = bearing_rows!(
    "mainBearing",
    "Main bearing",
    "crank journal",
    [
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
    ]
);

/// The user's own machine: the crank's mass distribution and the cylinder's offset.
const MACHINE_VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::CrankCentreOfMassRatio,
        "crank.centreOfMassRatio",
        0.5,
        -2.0,
        2.0,
        "1",
        "The crank's centre of mass: its distance from the pivot along the crank (towards the pin) as a fraction of crank.length; 0.5 a uniform crank, negative a counterweight beyond the pivot (crank.inertia stays about the centre of mass)",
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
    Variable::parameter(
        Vr::RodDampingRatio,
        "rod.dampingRatio",
        0.0,
        0.0,
        1.0,
        "1",
        "Material damping of the flexible rod as the damping ratio of its first pinned-pinned bending mode, omega1 = pi^2 sqrt(EI/(rho A l^4)): stiffness-proportional, so mode k gets zeta1 omega_k/omega1 (higher modes more); 0.01-0.02 is typical of steel rods, and a damped rod is both the realistic one and the fast one. Exclusive with rod.stiffnessDamping",
    ),
    Variable::parameter(
        Vr::RodCrankEndMass,
        "rod.crankEndMass",
        0.0,
        0.0,
        1e4,
        "kg",
        "Mass lumped at the crank-pin centre (the rod's big eye, its bush and bolts), beside the beam's rod.density rod.area rod.length: in the rod's inertia, weight and loads, not in its stress",
    ),
    Variable::parameter(
        Vr::RodSliderEndMass,
        "rod.sliderEndMass",
        0.0,
        0.0,
        1e4,
        "kg",
        "Mass lumped at the slider-pin centre (the rod's small eye)",
    ),
    Variable::output(
        Vr::RodStressMax,
        "rod.stressMax",
        "Pa",
        "The most tensile fibre stress over the rod, max (N/A + |M| c/I) (signed: negative when the whole rod is compressed); N axial force, tension positive, M bending moment, c = rod.outerFibreDistance",
    ),
    Variable::output(
        Vr::RodStressMin,
        "rod.stressMin",
        "Pa",
        "The most compressive fibre stress over the rod, min (N/A - |M| c/I) (signed: negative in compression)",
    ),
    Variable::peak(
        Vr::RodStressMaxPeak,
        "rod.stressMaxPeak",
        "Pa",
        "Largest rod.stressMax over the last communication interval (every internal step)",
    ),
    Variable::peak(
        Vr::RodStressMinPeak,
        "rod.stressMinPeak",
        "Pa",
        "Smallest rod.stressMin over the last communication interval (every internal step); with rod.stressMaxPeak the stress range a fatigue check reads",
    ),
    Variable::output(
        Vr::RodStressLocation,
        "rod.stressLocation",
        "1",
        "Where the largest |stress| (rod.stress) lies, as a fraction of the rod's length from the crank pin",
    ),
    Variable::output(
        Vr::RodAxialForceMidspan,
        "rod.axialForceMidspan",
        "N",
        "Axial force at the rod's middle section, tension positive",
    ),
    Variable::output(
        Vr::RodBendingMomentMidspan,
        "rod.bendingMomentMidspan",
        "N.m",
        "Bending moment at the rod's middle section, positive where the rod bends to its left (counter-clockwise curvature, looking along the rod from the crank pin)",
    ),
    Variable::string(
        Vr::SliderForceTable,
        "slider.forceTable",
        "",
        "A load on the slider tied to the crank angle: a CSV file of crank angle [deg], force [N] (a relative path is looked up in the working directory, then in the FMU's resources), periodic over slider.forceTablePeriod, interpolated monotonically (no overshoot of a combustion pulse) at every evaluation and added to the input slider.force; empty for none",
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
