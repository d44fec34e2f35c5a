//! The model structure: which outputs react to which inputs at once (direct feedthrough), and
//! what each unknown depends on in initialization mode.

use super::vr::Vr;

/// Direct feedthrough, declared as the `dependencies` of ModelStructure/Outputs: each output
/// that shows a change of an input at once, before the next fmi2DoStep, with those inputs. Every
/// other output reacts to the inputs only through the motion (after a step): the positions,
/// speeds, energies and counters are states or integrals of the motion. The lists are the union
/// over every drive, joint and rod model, as measured by `packaging/python/tests/test_fmu.py`.
pub(super) const FEEDTHROUGH: &[(Vr, &[Vr])] = &[
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
    (Vr::JointOilFlow, &[Vr::OilSupplyPressure]),
    (Vr::CrankPinOilFlow, &[Vr::OilSupplyPressure]),
    (Vr::MainBearingOilFlow, &[Vr::OilSupplyPressure]),
    (Vr::JointHeatFlow, OIL_SUPPLY),
    (Vr::CrankPinHeatFlow, OIL_SUPPLY),
    (Vr::MainBearingHeatFlow, OIL_SUPPLY),
    (Vr::JointFeedFlow, &[Vr::OilSupplyPressure]),
    (Vr::CrankPinFeedFlow, &[Vr::OilSupplyPressure]),
    (Vr::MainBearingFeedFlow, &[Vr::OilSupplyPressure]),
];

/// The oil supply's inputs: a fed joint's oil flow follows the pressure at once, and the heat the
/// flow carries both the flow and the supply temperature.
const OIL_SUPPLY: &[Vr] = &[Vr::OilSupplyTemperature, Vr::OilSupplyPressure];

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
/// short-bearing range of a lubricated joint) and the step counters, work integrals and
/// dissipated energies, which start at zero. The solver settings shape no start. The lists are the union over every drive,
/// joint and rod model; `packaging/python/tests/test_fmu.py` checks them against perturbations
/// in initialization mode.
pub(super) fn initial_dependency(unknown: Vr, known: Vr) -> bool {
    let start_in_cycle = |known| {
        matches!(
            known,
            Vr::CrankInitialAngle | Vr::SliderForceTable | Vr::SliderForceTablePeriod
        )
    };
    use Vr::*;
    match unknown {
        CrankAngle => known == CrankInitialAngle,
        CrankSpeed => matches!(known, CrankInitialSpeed | DriveSpeed),
        SliderAppliedForce => matches!(
            known,
            SliderForce | SliderForceTable | SliderForceTablePeriod | CrankInitialAngle
        ),
        SolverIntegrationTolerance => matches!(known, SolverRelativeTolerance | MainBearingModel),
        JointContactStiffness => matches!(
            known,
            JointClearance | JointJournalRadius | JointYoungsModulus | JointPoissonRatio
        ),
        SolverWarnings => matches!(
            known,
            JointModel
                | JointJournalRadius
                | JointBearingLength
                | JointFilmModel
                | CrankPinModel
                | CrankPinJournalRadius
                | CrankPinBearingLength
                | CrankPinFilmModel
                | MainBearingModel
                | MainBearingJournalRadius
                | MainBearingBearingLength
                | MainBearingFilmModel
        ),
        // before a step the cycle under way holds the present instant: its angles are the
        // crank's start within the load cycle (a film's only at a clearance joint), its means
        // (over no time) zero
        JointForcePeakCycleAngle | CrankPinForcePeakCycleAngle | MainBearingForcePeakCycleAngle => {
            start_in_cycle(known)
        }
        JointFilmThicknessMinCycleAngle | JointFilmPressurePeakCycleAngle => {
            start_in_cycle(known) || known == JointModel
        }
        CrankPinFilmThicknessMinCycleAngle | CrankPinFilmPressurePeakCycleAngle => {
            start_in_cycle(known) || known == CrankPinModel
        }
        MainBearingFilmThicknessMinCycleAngle | MainBearingFilmPressurePeakCycleAngle => {
            start_in_cycle(known) || known == MainBearingModel
        }
        JointFrictionPowerMeanCycle
        | JointOilFlowMeanCycle
        | CrankPinFrictionPowerMeanCycle
        | CrankPinOilFlowMeanCycle
        | MainBearingFrictionPowerMeanCycle
        | MainBearingOilFlowMeanCycle
        | JointMetalContactFractionCycle
        | CrankPinMetalContactFractionCycle
        | MainBearingMetalContactFractionCycle
        | SolverSteps
        | SolverEvaluations
        | EnergyDriveWork
        | EnergySliderWork
        | EnergyMaterialDamping
        | EnergyDissipated
        | JointEnergyDissipated
        | CrankPinEnergyDissipated
        | MainBearingEnergyDissipated
        | JointContactOnsets
        | JointContactOnsetsTotal
        | CrankPinContactOnsets
        | CrankPinContactOnsetsTotal
        | MainBearingContactOnsets
        | MainBearingContactOnsetsTotal
        | CycleNumber => false,
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
