//! Why an interval failed: the messages of the work limit and of integrator failures, with the
//! parameters that usually cause them.

use crate::error::{ModelError, Num};
use crate::integrator::Method;
use crate::params::{JointModel, Parameters, RodFormulation};

/// The error of an interval [t_start, t_end] that ran out of work
/// ([`Parameters::max_steps_per_interval`]): where it stopped, at what step size, and the
/// parameters that usually cause it.
pub(super) fn work_limit(
    p: &Parameters,
    (t_start, t_end): (f64, f64),
    stopped_at: f64,
    step_size: f64,
) -> ModelError {
    ModelError::Numerical(format!(
        "solver.maxStepsPerInterval = {} internal steps exhausted in the communication interval \
             [{}, {}] s, stopped at t = {} s with a step of {} s. {}; raise \
             solver.maxStepsPerInterval to go on",
        p.max_steps_per_interval,
        Num(t_start),
        Num(t_end),
        Num(stopped_at),
        Num(step_size),
        likely_causes(p)
    ))
}

/// An integrator failure (step-size floor, singular Newton matrix) with the parameters that
/// usually cause it.
pub(super) fn step_failure(p: &Parameters, error: ModelError) -> ModelError {
    match error {
        ModelError::Numerical(message) => {
            ModelError::Numerical(format!("{message}. {}", likely_causes(p)))
        }
        other => other,
    }
}

/// A quasi-static start (`rod.initialState` = equilibrated) that failed, with what usually causes
/// it: a rod so compliant that its deflection under the inertial loads of the initial motion is
/// far from the straight rod the Newton iteration starts from.
pub(super) fn unequilibrated(p: &Parameters, error: &ModelError) -> ModelError {
    ModelError::Numerical(format!(
        "rod.initialState = equilibrated: the rod's quasi-static deflection under the inertial \
             loads of the initial motion was not found: {error}. Likely cause: a rod too compliant \
             for that motion (rod.youngsModulus = {} Pa, rod.secondMomentOfArea = {} m4, \
             rod.length = {} m, {}); start with rod.initialState = straight, or make the rod \
             stiffer or the start slower",
        Num(p.rod.youngs_modulus),
        Num(p.rod.second_moment_of_area),
        Num(p.rod.length),
        match p.crank_initial_speed {
            Some(speed) => format!("crank.initialSpeed = {} rad/s", Num(speed)),
            None => "the crank starting at drive.speed".to_string(),
        }
    ))
}

/// Tolerances below this count as a likely cause of a stalled interval.
const TIGHT_TOLERANCE: f64 = 1e-5;

/// The parameters of `p` that make the equations stiff or non-smooth, with their values: only
/// those that apply (friction only with friction, material damping only with it, …), and the
/// tolerance last.
fn likely_causes(p: &Parameters) -> String {
    let clearance_joint = p.joint.model != JointModel::Ideal;
    let mut causes = Vec::new();
    if clearance_joint && p.joint.friction > 0.0 {
        causes.push(format!(
            "sticking friction (joint.friction = {})",
            Num(p.joint.friction)
        ));
    }
    if p.rod_formulation != RodFormulation::Rigid && p.rod.damping() > 0.0 {
        causes.push(format!(
            "strong material damping (rod.stiffnessDamping = {} s, rod.dampingRatio = {})",
            Num(p.rod.stiffness_damping),
            Num(p.rod.damping_ratio)
        ));
    }
    if clearance_joint {
        let joint = format!("{:?}", p.joint.model).to_lowercase();
        causes.push(format!(
            "a very stiff contact or film (joint.clearance = {} m with joint.model = {joint}: the \
             contact and film stiffness grow as the clearance shrinks)",
            Num(p.joint.clearance)
        ));
    }
    if p.rod_formulation == RodFormulation::Ancf && p.method == Method::DormandPrince {
        causes.push(format!(
            "the full rod's highest frequencies with the explicit method (rod.nElements = {}: \
             they grow as its square)",
            p.n_elements
        ));
    }
    let tolerance = format!(
        "a tight tolerance (solver.relativeTolerance = {})",
        Num(p.relative_tolerance)
    );
    if p.relative_tolerance < TIGHT_TOLERANCE || causes.is_empty() {
        causes.push(tolerance);
    }
    let last = causes.pop().unwrap_or_default();
    if causes.is_empty() {
        format!("Likely cause: {last}")
    } else {
        format!("Likely causes: {} or {last}", causes.join(", "))
    }
}
