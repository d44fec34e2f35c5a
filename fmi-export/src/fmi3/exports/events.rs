//! Event Mode of co-simulation (FMI 3.0 §4.2.2–§4.2.4), for a model with `hasEventMode` whose master
//! sets `eventModeUsed`: the instance enters it after initialization and where a step returned
//! early at an event of the model (`eventHandlingNeeded`). The model's events change only its
//! discrete outputs, which the master reads there: one update settles them, and Step Mode continues
//! from the same time.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use fmi_sys::fmi3::*;

use super::codes::with_instance;
use crate::error::FmuError;
use crate::ffi::slice_mut;
use crate::model::Model;
use crate::state::Call;
use crate::status::Status;

/// Enters Event Mode from Step Mode, for an instance created with `eventModeUsed`.
pub unsafe fn fmi3EnterEventMode<M: Model>(instance: fmi3Instance) -> fmi3Status {
    with_instance::<M>(instance, Call::EnterEventMode, |inst| {
        if !inst.fmi3().event_mode_used {
            return Err(FmuError::Invalid(if inst.fmi3().interface.has_event_mode {
                "the instance was created with eventModeUsed = false".into()
            } else {
                "not supported: the FMU has no event mode (hasEventMode = false)".into()
            }));
        }
        Ok(Status::Ok)
    })
}

/// Settles the discrete states at the event: nothing more changes (the model's events are settled
/// where they happen), no next event time is known, the simulation goes on.
pub unsafe fn fmi3UpdateDiscreteStates<M: Model>(
    instance: fmi3Instance,
    discreteStatesNeedUpdate: *mut fmi3Boolean,
    terminateSimulation: *mut fmi3Boolean,
    nominalsOfContinuousStatesChanged: *mut fmi3Boolean,
    valuesOfContinuousStatesChanged: *mut fmi3Boolean,
    nextEventTimeDefined: *mut fmi3Boolean,
    nextEventTime: *mut fmi3Float64,
) -> fmi3Status {
    with_instance::<M>(instance, Call::UpdateDiscreteStates, |_| {
        // SAFETY: one writable value each (FMI 3.0 §3.2.1).
        unsafe {
            for (flag, name) in [
                (discreteStatesNeedUpdate, "discreteStatesNeedUpdate"),
                (terminateSimulation, "terminateSimulation"),
                (
                    nominalsOfContinuousStatesChanged,
                    "nominalsOfContinuousStatesChanged",
                ),
                (
                    valuesOfContinuousStatesChanged,
                    "valuesOfContinuousStatesChanged",
                ),
                (nextEventTimeDefined, "nextEventTimeDefined"),
            ] {
                slice_mut(flag, 1, name)?[0] = false;
            }
            slice_mut(nextEventTime, 1, "nextEventTime")?[0] = 0.0;
        }
        Ok(Status::Ok)
    })
}

/// Leaves Event Mode for Step Mode.
pub unsafe fn fmi3EnterStepMode<M: Model>(instance: fmi3Instance) -> fmi3Status {
    with_instance::<M>(instance, Call::EnterStepMode, |_| Ok(Status::Ok))
}
