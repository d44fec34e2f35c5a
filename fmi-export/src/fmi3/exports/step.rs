//! Stepping, derivatives and FMU states (FMI 3.0 §2.3.8–§2.3.11, §4.2.1).
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]
// The signatures are the C API's.
#![allow(clippy::too_many_arguments)]

use fmi_sys::fmi3::*;

use super::arrays::scalars;
use super::codes::with_instance;
use crate::calls;
use crate::error::FmuError;
use crate::experiment::Step;
use crate::experiment::StepOutcome;
use crate::ffi::{slice, slice_mut};
use crate::instance::{Instance, IntermediateUpdate};
use crate::model::Model;
use crate::number::Num;
use crate::state::Call;
use crate::status::Status;

/// Integrates from the communication point over the step size (error-controlled sub-steps). The
/// FMU never asks for the simulation to end; it returns early only where the model does and the
/// master allowed it, and then asks for event handling if the master uses Event Mode;
/// `lastSuccessfulTime` is the time reached (also after a discarded step).
///
/// With the master's intermediate-update callback (a model that provides it) the step pauses
/// after every internal step before the communication point: the instance is in Intermediate
/// Update Mode, no reference to it is held, and the callback may read the outputs there (no input
/// is set there). If it asks for an early return, and may (`canReturnEarlyAfterIntermediateUpdate`
/// and `earlyReturnAllowed`), the step ends at that internal step's end, on the clock grid (the
/// requested `earlyReturnTime` is not waited for: the step ends as soon as it can); else it
/// goes on.
pub unsafe fn fmi3DoStep<M: Model>(
    instance: fmi3Instance,
    currentCommunicationPoint: fmi3Float64,
    communicationStepSize: fmi3Float64,
    _noSetFMUStatePriorToCurrentPoint: fmi3Boolean,
    eventHandlingNeeded: *mut fmi3Boolean,
    terminateSimulation: *mut fmi3Boolean,
    earlyReturn: *mut fmi3Boolean,
    lastSuccessfulTime: *mut fmi3Float64,
) -> fmi3Status {
    let flags = Flags {
        event: eventHandlingNeeded,
        terminate: terminateSimulation,
        early: earlyReturn,
        last: lastSuccessfulTime,
    };
    let (t, h) = (currentCommunicationPoint, communicationStepSize);
    let mut pause = None;
    let mut status = with_instance::<M>(instance, Call::DoStep, |inst| {
        // SAFETY: one writable value each (FMI 3.0 §4.2.1), checked before the step.
        unsafe { flags.check() }?;
        // SAFETY: as above.
        unsafe { step(inst, t, h, flags, &mut pause) }
    });
    while let Some((time, update, can_return_early)) = pause.take() {
        let (mut requested, mut requested_time) = (false, time);
        // SAFETY: the master's callback with its environment and two writable values; no
        // reference to the instance is held while it runs (it may call the getters).
        unsafe {
            (update.callback)(
                update.environment,
                time,
                false,
                true,
                true,
                can_return_early,
                &mut requested,
                &mut requested_time,
            );
        }
        status = with_instance::<M>(instance, Call::ResumeStep, |inst| {
            if requested && can_return_early {
                let reached = inst.return_at_pause()?;
                if let Some(reached) = reached {
                    inst.logger().event(&format!(
                        "fmi3DoStep: returned early at t = {} s: requested by the master",
                        Num(reached)
                    ));
                    // SAFETY: as above.
                    unsafe { flags.write(false, true, reached) }?;
                    return Ok(Status::Ok);
                }
            }
            // SAFETY: as above.
            unsafe { step(inst, t, h, flags, &mut pause) }
        });
    }
    status
}

/// fmi3DoStep's output arguments.
#[derive(Clone, Copy)]
struct Flags {
    event: *mut fmi3Boolean,
    terminate: *mut fmi3Boolean,
    early: *mut fmi3Boolean,
    last: *mut fmi3Float64,
}

impl Flags {
    /// Refuses NULL pointers.
    ///
    /// # Safety
    /// Each pointer is NULL or valid for one write.
    unsafe fn check(self) -> Result<(), FmuError> {
        // SAFETY: the caller's contract.
        unsafe { self.write(false, false, f64::NAN) }
    }

    /// Writes eventHandlingNeeded, earlyReturn and lastSuccessfulTime (terminateSimulation is
    /// always false).
    ///
    /// # Safety
    /// As [`Flags::check`].
    unsafe fn write(self, event: bool, early: bool, last: f64) -> Result<(), FmuError> {
        // SAFETY: the caller's contract.
        unsafe {
            slice_mut(self.event, 1, "eventHandlingNeeded")?[0] = event;
            slice_mut(self.terminate, 1, "terminateSimulation")?[0] = false;
            slice_mut(self.early, 1, "earlyReturn")?[0] = early;
            slice_mut(self.last, 1, "lastSuccessfulTime")?[0] = last;
        }
        Ok(())
    }
}

/// One call of the model's step: complete, early or discarded (the flags written), or paused
/// (Intermediate Update Mode, `pause` set for the caller to call back the master).
///
/// # Safety
/// As [`Flags::check`].
unsafe fn step<M: Model>(
    inst: &mut Instance<M>,
    t: f64,
    h: f64,
    flags: Flags,
    pause: &mut Option<(f64, IntermediateUpdate, bool)>,
) -> Result<Status, FmuError> {
    let session = inst.fmi3();
    let early_allowed = session.early_return_allowed;
    let update = session.intermediate_update;
    let event_mode = session.event_mode_used;
    let can_return_early =
        early_allowed && session.interface.can_return_early_after_intermediate_update;
    let step = Step {
        t,
        h,
        early_return: early_allowed,
        pause: update.is_some(),
        resume: false,
    };
    let result = inst.step(step);
    if let (Ok(StepOutcome::Paused { time }), Some(update)) = (&result, update) {
        *pause = Some((*time, update, can_return_early));
        return Ok(Status::Ok);
    }
    let early = matches!(result, Ok(StepOutcome::ReturnedEarly { .. }));
    let last = inst.clock().last_successful_time;
    // SAFETY: the caller's contract.
    unsafe { flags.write(early && event_mode, early, last) }?;
    if let Ok(StepOutcome::ReturnedEarly { time, event }) = result {
        inst.logger().event(&format!(
            "fmi3DoStep: returned early at t = {} s: {event}",
            Num(time)
        ));
    }
    result.map(|_| Status::Ok)
}

/// Time derivatives of the outputs at the current communication point.
pub unsafe fn fmi3GetOutputDerivatives<M: Model>(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    orders: *const fmi3Int32,
    values: *mut fmi3Float64,
    nValues: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::GetRealOutputDerivatives, |inst| {
        scalars(nValueReferences, nValues)?;
        // SAFETY: nValueReferences elements each (FMI 3.0 §4.2.1).
        let (vr, orders, values) = unsafe {
            (
                slice(valueReferences, nValueReferences, "valueReferences")?,
                slice(orders, nValueReferences, "orders")?,
                slice_mut(values, nValues, "values")?,
            )
        };
        calls::output_derivatives(inst, vr, orders, values)
    })
}

/// The directional derivative sensitivity = (∂y/∂u) seed of Float64 outputs y with respect to
/// Float64 inputs u at the current point.
pub unsafe fn fmi3GetDirectionalDerivative<M: Model>(
    instance: fmi3Instance,
    unknowns: *const fmi3ValueReference,
    nUnknowns: usize,
    knowns: *const fmi3ValueReference,
    nKnowns: usize,
    seed: *const fmi3Float64,
    nSeed: usize,
    sensitivity: *mut fmi3Float64,
    nSensitivity: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::GetDirectionalDerivative, |inst| {
        if nSeed != nKnowns || nSensitivity != nUnknowns {
            return Err(FmuError::Invalid(format!(
                "nSeed = {nSeed} and nSensitivity = {nSensitivity} must equal nKnowns = \
                 {nKnowns} and nUnknowns = {nUnknowns}: every variable of this FMU is a scalar"
            )));
        }
        // SAFETY: nUnknowns and nKnowns elements (FMI 3.0 §2.3.11).
        let (unknowns, knowns, seed, sensitivity) = unsafe {
            (
                slice(unknowns, nUnknowns, "unknowns")?,
                slice(knowns, nKnowns, "knowns")?,
                slice(seed, nSeed, "seed")?,
                slice_mut(sensitivity, nSensitivity, "sensitivity")?,
            )
        };
        calls::directional_derivative(
            inst,
            unknowns,
            knowns,
            seed,
            sensitivity,
            ["unknowns", "knowns", "seed"],
        )
    })
}

/// Captures the complete instance state (allocates, or overwrites *FMUState).
pub unsafe fn fmi3GetFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    with_instance::<M>(instance, Call::GetFmuState, |inst| {
        // SAFETY: FMUState points to the master's fmi3FMUState variable (FMI 3.0 §2.3.9), NULL
        // or a state this FMU allocated.
        unsafe { calls::get_state(inst, FMUState, "FMUState") }
    })
}

/// Restores a captured state, including the state machine.
pub unsafe fn fmi3SetFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: fmi3FMUState,
) -> fmi3Status {
    with_instance::<M>(instance, Call::SetFmuState, |inst| {
        // SAFETY: a state allocated by fmi3GetFMUState/fmi3DeserializeFMUState of this FMU.
        unsafe { calls::set_state(inst, FMUState, "FMUState") }
    })
}

/// Frees a captured state and sets it to NULL.
pub unsafe fn fmi3FreeFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    with_instance::<M>(instance, Call::FreeFmuState, |_| {
        // SAFETY: *FMUState is NULL or a state this FMU allocated; it is freed once and reset.
        unsafe { calls::free_state(FMUState, "FMUState") }
    })
}

/// Size of a serialized state in bytes.
pub unsafe fn fmi3SerializedFMUStateSize<M: Model>(
    instance: fmi3Instance,
    FMUState: fmi3FMUState,
    size: *mut usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::SerializedFmuStateSize, |_| {
        // SAFETY: size points to the master's variable; FMUState is a state of this FMU.
        unsafe { calls::serialized_size(FMUState, slice_mut(size, 1, "size")?, "FMUState") }
    })
}

/// Writes a state as pointer-free bytes.
pub unsafe fn fmi3SerializeFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: fmi3FMUState,
    serializedState: *mut fmi3Byte,
    size: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::SerializeFmuState, |_| {
        // SAFETY: a state of this FMU; the master provides `size` writable bytes (FMI 3.0
        // §2.3.9).
        unsafe {
            calls::serialize(
                FMUState,
                serializedState,
                size,
                ["FMUState", "serializedState"],
            )
        }
    })
}

/// Reads a state from bytes (checked: magic, version, contents, checksum).
pub unsafe fn fmi3DeserializeFMUState<M: Model>(
    instance: fmi3Instance,
    serializedState: *const fmi3Byte,
    size: usize,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    with_instance::<M>(instance, Call::DeSerializeFmuState, |inst| {
        // SAFETY: `size` readable bytes (FMI 3.0 §2.3.9); FMUState as in fmi3GetFMUState.
        unsafe {
            let bytes = slice(serializedState, size, "serializedState")?;
            calls::deserialize(inst, bytes, FMUState, "FMUState")
        }
    })
}
