//! Stepping, derivatives and FMU states (FMI 3.0 §2.3.8–§2.3.11, §4.2.1).
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]
// The signatures are the C API's.
#![allow(clippy::too_many_arguments)]

use fmi_sys::fmi3::*;

use super::arrays::scalars;
use super::values::refuse;
use crate::error::FmuError;
use crate::exports::codes::OK;
use crate::ffi::{slice_mut, with_instance};
use crate::model::{Model, StepOutcome};
use crate::number::Num;
use crate::state::Call;

/// Integrates from the communication point over the step size (error-controlled sub-steps). The
/// FMU never asks for the simulation to end; it returns early only where the model does and the
/// master allowed it, and then asks for event handling if the master uses Event Mode;
/// `lastSuccessfulTime` is the time reached (also after a discarded step).
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
    with_instance::<M>(instance, Call::DoStep, |inst| {
        // SAFETY: one writable value each (FMI 3.0 §4.2.1).
        let (event, terminate, early, last) = unsafe {
            (
                slice_mut(eventHandlingNeeded, 1, "eventHandlingNeeded")?,
                slice_mut(terminateSimulation, 1, "terminateSimulation")?,
                slice_mut(earlyReturn, 1, "earlyReturn")?,
                slice_mut(lastSuccessfulTime, 1, "lastSuccessfulTime")?,
            )
        };
        let result = inst.model.do_step(
            &inst.logger,
            currentCommunicationPoint,
            communicationStepSize,
            inst.early_return_allowed,
        );
        terminate[0] = false;
        early[0] = matches!(result, Ok(StepOutcome::ReturnedEarly { .. }));
        event[0] = early[0] && inst.event_mode_used;
        last[0] = inst.model.last_successful_time();
        if let Ok(StepOutcome::ReturnedEarly { time, event }) = result {
            inst.logger.event(&format!(
                "fmi3DoStep: returned early at t = {} s: {event}",
                Num(time)
            ));
        }
        result.map(|_| OK)
    })
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
    if nValues != nValueReferences {
        let error = scalars(nValueReferences, nValues);
        return refuse::<M>(instance, Call::GetRealOutputDerivatives, error);
    }
    // SAFETY: the master's arguments under the same contract as FMI 2's.
    unsafe {
        crate::exports::fmi2GetRealOutputDerivatives::<M>(
            instance,
            valueReferences,
            nValueReferences,
            orders,
            values,
        )
    }
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
    if nSeed != nKnowns || nSensitivity != nUnknowns {
        let error = Err(FmuError::Invalid(format!(
            "nSeed = {nSeed} and nSensitivity = {nSensitivity} must equal nKnowns = {nKnowns} \
             and nUnknowns = {nUnknowns}: every variable of this FMU is a scalar"
        )));
        return refuse::<M>(instance, Call::GetDirectionalDerivative, error);
    }
    // SAFETY: the master's arguments under the same contract as FMI 2's.
    unsafe {
        crate::exports::fmi2GetDirectionalDerivative::<M>(
            instance,
            unknowns,
            nUnknowns,
            knowns,
            nKnowns,
            seed,
            sensitivity,
        )
    }
}

/// Captures the complete instance state.
pub unsafe fn fmi3GetFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    // SAFETY: the same contract as FMI 2's; the state is the same opaque pointer.
    unsafe { crate::exports::fmi2GetFMUstate::<M>(instance, FMUState) }
}

/// Restores a captured state, including the state machine.
pub unsafe fn fmi3SetFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: fmi3FMUState,
) -> fmi3Status {
    // SAFETY: as above.
    unsafe { crate::exports::fmi2SetFMUstate::<M>(instance, FMUState) }
}

/// Frees a captured state and sets it to NULL.
pub unsafe fn fmi3FreeFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    // SAFETY: as above.
    unsafe { crate::exports::fmi2FreeFMUstate::<M>(instance, FMUState) }
}

/// Size of a serialized state in bytes.
pub unsafe fn fmi3SerializedFMUStateSize<M: Model>(
    instance: fmi3Instance,
    FMUState: fmi3FMUState,
    size: *mut usize,
) -> fmi3Status {
    // SAFETY: as above.
    unsafe { crate::exports::fmi2SerializedFMUstateSize::<M>(instance, FMUState, size) }
}

/// Writes a state as pointer-free bytes.
pub unsafe fn fmi3SerializeFMUState<M: Model>(
    instance: fmi3Instance,
    FMUState: fmi3FMUState,
    serializedState: *mut fmi3Byte,
    size: usize,
) -> fmi3Status {
    // SAFETY: as above; bytes are bytes, whatever their signedness in the header.
    unsafe {
        crate::exports::fmi2SerializeFMUstate::<M>(instance, FMUState, serializedState.cast(), size)
    }
}

/// Reads a state from bytes (checked: magic, version, contents, checksum).
pub unsafe fn fmi3DeserializeFMUState<M: Model>(
    instance: fmi3Instance,
    serializedState: *const fmi3Byte,
    size: usize,
    FMUState: *mut fmi3FMUState,
) -> fmi3Status {
    // SAFETY: as above.
    unsafe {
        crate::exports::fmi2DeSerializeFMUstate::<M>(
            instance,
            serializedState.cast(),
            size,
            FMUState,
        )
    }
}
