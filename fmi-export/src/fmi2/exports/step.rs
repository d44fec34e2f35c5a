//! Stepping and the status queries of co-simulation.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use fmi_sys::fmi2::*;

use super::codes::with_instance;
use crate::experiment::Step;
use crate::ffi::slice_mut;
use crate::model::Model;
use crate::state::Call;
use crate::status::Status;

/// Integrates from the communication point over the step size (error-controlled sub-steps).
pub unsafe fn fmi2DoStep<M: Model>(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    with_instance::<M>(c, Call::DoStep, |inst| {
        let step = Step {
            t: currentCommunicationPoint,
            h: communicationStepSize,
            early_return: false,
            pause: false,
            resume: false,
        };
        inst.step(step).map(|_| Status::Ok)
    })
}

/// Steps are synchronous: there is never a step to cancel.
pub unsafe fn fmi2CancelStep<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::CancelStep, |_| Ok(Status::Ok))
}

/// No asynchronous steps: fmi2Discard.
pub unsafe fn fmi2GetStatus<M: Model>(
    c: fmi2Component,
    _s: fmi2StatusKind,
    value: *mut fmi2Status,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetStatus, |inst| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let _ = unsafe { slice_mut(value, 1, "value") }?;
        inst.logger()
            .warning("fmi2GetStatus: no asynchronous step; status kinds are not available");
        Ok(Status::Discard)
    })
}

/// Answers fmi2LastSuccessfulTime; other kinds fmi2Discard.
pub unsafe fn fmi2GetRealStatus<M: Model>(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetRealStatus, |inst| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let value = unsafe { slice_mut(value, 1, "value") }?;
        if s == fmi2StatusKind_fmi2LastSuccessfulTime {
            value[0] = inst.clock().last_successful_time;
            Ok(Status::Ok)
        } else {
            Ok(Status::Discard)
        }
    })
}

/// No integer status kinds: fmi2Discard.
pub unsafe fn fmi2GetIntegerStatus<M: Model>(
    c: fmi2Component,
    _s: fmi2StatusKind,
    value: *mut fmi2Integer,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetIntegerStatus, |_| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let _ = unsafe { slice_mut(value, 1, "value") }?;
        Ok(Status::Discard)
    })
}

/// Answers fmi2Terminated (always false); other kinds fmi2Discard.
pub unsafe fn fmi2GetBooleanStatus<M: Model>(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetBooleanStatus, |_| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let value = unsafe { slice_mut(value, 1, "value") }?;
        if s == fmi2StatusKind_fmi2Terminated {
            // The FMU never asks the master to end the simulation.
            value[0] = fmi2False as fmi2Boolean;
            Ok(Status::Ok)
        } else {
            Ok(Status::Discard)
        }
    })
}

/// No string status kinds: fmi2Discard.
pub unsafe fn fmi2GetStringStatus<M: Model>(
    c: fmi2Component,
    _s: fmi2StatusKind,
    value: *mut fmi2String,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetStringStatus, |_| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let _ = unsafe { slice_mut(value, 1, "value") }?;
        Ok(Status::Discard)
    })
}
