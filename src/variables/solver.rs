//! The solver's settings and counters.

use super::enumerations::INTEGRATION_METHOD;
use super::vr::{Variable, Vr};

/// The solver's rows.
pub(super) const VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::SolverRelativeTolerance,
        "solver.relativeTolerance",
        1e-2,
        1e-12,
        1e-1,
        "1",
        "Relative tolerance of the internal error-controlled integrator (at most 1e-4 with solver.method = explicit, 3e-2 with generalizedAlpha; a model with mainBearing.model = dry is integrated at 1e-3 at most: solver.integrationTolerance)",
    ),
    Variable::output(
        Vr::SolverIntegrationTolerance,
        "solver.integrationTolerance",
        "1",
        "Relative tolerance the model is integrated at: solver.relativeTolerance, tightened by the tolerance of fmi2SetupExperiment where that is smaller, and at most 1e-3 with mainBearing.model = dry (a worn main bearing's later impacts are 2 % low in their upper decile at 1e-2)",
    )
    .calculated(),
    Variable::parameter(
        Vr::SolverMaxStepSize,
        "solver.maxStepSize",
        1e-4,
        1e-9,
        1.0,
        "s",
        "Largest internal step",
    ),
    Variable::count(
        Vr::SolverSteps,
        "solver.steps",
        "Accepted internal integrator steps",
    ),
    Variable::enumeration(
        Vr::SolverMethod,
        "solver.method",
        1,
        INTEGRATION_METHOD,
        "Internal time-integration method",
    ),
    Variable::count(
        Vr::SolverEvaluations,
        "solver.evaluations",
        "Right-hand-side evaluations of the internal integrator (with those of Jacobians)",
    ),
    Variable::integer(
        Vr::SolverMaxStepsPerInterval,
        "solver.maxStepsPerInterval",
        50_000,
        1,
        i32::MAX,
        "Work limit: internal step attempts per communication interval; beyond it fmi2DoStep returns fmi2Discard naming the likely cause",
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
    Variable::parameter(
        Vr::SolverImpactErrorWeight,
        "solver.impactErrorWeight",
        4.0,
        0.0,
        100.0,
        "1",
        "Dry joint, implicit methods: the journal's normal velocity in the bearing is held to solver.relativeTolerance / weight on its own (in units of the speed scale), so that every impact's peak and onset come out right; 0 leaves it to the RMS over all states (flexible rods about 2x faster, but the impacts after the first then off by up to 67 % at the default tolerance)",
    ),
];
