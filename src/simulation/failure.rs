//! Why an interval failed: the messages of the work limit and of integrator failures, with the
//! parameters that usually cause them.

use crate::error::ModelError;
use crate::params::Parameters;

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
             [{t_start}, {t_end}] s, stopped at t = {} s with a step of {:.3e} s. {}; raise \
             solver.maxStepsPerInterval to go on",
        p.max_steps_per_interval,
        stopped_at,
        step_size,
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
             for that motion (rod.youngsModulus = {:e} Pa, rod.secondMomentOfArea = {:e} m4, \
             rod.length = {} m, crank.initialSpeed = {} rad/s); start with rod.initialState = \
             straight, or make the rod stiffer or the start slower",
        p.rod.youngs_modulus, p.rod.second_moment_of_area, p.rod.length, p.crank_initial_speed
    ))
}

/// The parameters that make the equations stiff or non-smooth, with their values.
fn likely_causes(p: &Parameters) -> String {
    let joint = format!("{:?}", p.joint_model).to_lowercase();
    format!(
        "Likely causes: sticking friction (joint.friction = {}), strong material damping \
             (rod.stiffnessDamping = {} s), a very stiff contact or film (joint.clearance = {:e} m \
             with joint.model = {joint}: the contact and film stiffness grow as the clearance \
             shrinks) or a tight tolerance (solver.relativeTolerance = {:e})",
        p.friction, p.rod.stiffness_damping, p.clearance, p.relative_tolerance
    )
}
