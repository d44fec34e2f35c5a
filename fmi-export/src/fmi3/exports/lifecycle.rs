//! Creating, initialising, terminating, resetting and freeing an instance (FMI 3.0 §2.3.1–§2.3.5,
//! §4.2): Initialization Mode leads to Step Mode, or to Event Mode for a master that uses it.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]
// The signatures are the C API's.
#![allow(clippy::too_many_arguments)]

use std::ffi::c_char;
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi3::*;

use super::codes::{Fmi3Sink, with_instance};
use crate::calls;
use crate::error::FmuError;
use crate::ffi::{slice, string};
use crate::instance::{Instance, IntermediateUpdate};
use crate::logger::Logger;
use crate::model::Model;
use crate::state::{Call, State, Version};
use crate::status::ok;

/// Returns "3.0".
pub fn fmi3GetVersion() -> *const c_char {
    c"3.0".as_ptr()
}

/// Creates a co-simulation instance; NULL (after logging, if a logger was given) on any invalid
/// argument. Event mode is refused for a model without (hasEventMode = false); `eventModeUsed`
/// and `earlyReturnAllowed` are kept for fmi3DoStep.
pub unsafe fn fmi3InstantiateCoSimulation<M: Model>(
    instanceName: fmi3String,
    instantiationToken: fmi3String,
    resourcePath: fmi3String,
    _visible: fmi3Boolean,
    loggingOn: fmi3Boolean,
    eventModeUsed: fmi3Boolean,
    earlyReturnAllowed: fmi3Boolean,
    _requiredIntermediateVariables: *const fmi3ValueReference,
    _nRequiredIntermediateVariables: usize,
    instanceEnvironment: fmi3InstanceEnvironment,
    logMessage: fmi3LogMessageCallback,
    intermediateUpdate: fmi3IntermediateUpdateCallback,
) -> fmi3Instance {
    let result = catch_unwind(AssertUnwindSafe(|| {
        let sink = Fmi3Sink {
            callback: logMessage,
            environment: instanceEnvironment,
        };
        let logger = Logger::new(Box::new(sink), loggingOn, M::LOG_CATEGORIES);
        if eventModeUsed && !M::FMI3.has_event_mode {
            logger.error(
                "fmi3InstantiateCoSimulation: eventModeUsed = true, but this FMU has no event \
                 mode (hasEventMode = false): it handles its events inside fmi3DoStep.",
            );
            return None;
        }
        // SAFETY: NUL-terminated strings from the master (FMI 3.0 §2.3.1), copied here; NULL
        // is allowed for the resource path (no resources).
        let (name, token, path) = unsafe {
            (
                string(instanceName).unwrap_or_default(),
                string(instantiationToken).unwrap_or_default(),
                string(resourcePath),
            )
        };
        let resources = path.map(std::path::PathBuf::from).filter(|d| d.is_dir());
        let mut instance = calls::create::<M>(logger, &name, &token, resources, Version::Fmi3)?;
        let session = instance.fmi3_mut();
        session.early_return_allowed = earlyReturnAllowed;
        session.event_mode_used = eventModeUsed;
        session.intermediate_update = intermediateUpdate
            .filter(|_| M::FMI3.provides_intermediate_update)
            .map(|callback| IntermediateUpdate {
                callback,
                environment: instanceEnvironment,
            });
        Some(Box::into_raw(instance).cast())
    }));
    result.ok().flatten().unwrap_or(std::ptr::null_mut())
}

/// Model exchange and scheduled execution are not provided: logs why and returns NULL.
pub fn instantiate_other(
    call: &str,
    instanceEnvironment: fmi3InstanceEnvironment,
    logMessage: fmi3LogMessageCallback,
) -> fmi3Instance {
    let sink = Fmi3Sink {
        callback: logMessage,
        environment: instanceEnvironment,
    };
    let logger = Logger::new(Box::new(sink), false, &[]);
    logger.error(&format!(
        "{call}: this FMU supports co-simulation only (fmi3InstantiateCoSimulation)."
    ));
    std::ptr::null_mut()
}

/// Frees an instance (NULL is a no-op); legal in every state but from inside the step's
/// intermediate-update callback, where the step still needs the instance (refused, logged).
pub unsafe fn fmi3FreeInstance<M: Model>(instance: fmi3Instance) {
    if !instance.is_null() {
        // SAFETY: an instance of this FMU not yet freed; no reference to it is live (fmi3DoStep
        // holds none while the callback runs).
        let inst = unsafe { &*instance.cast::<Instance<M>>() };
        if inst.machine().state() == State::IntermediateUpdate {
            inst.logger().error(
                "fmi3FreeInstance: not allowed from inside fmi3DoStep's intermediate-update \
                 callback; the instance is kept",
            );
            return;
        }
    }
    // SAFETY: an instance of this FMU from fmi3InstantiateCoSimulation, freed once (FMI 3.0
    // §2.3.1).
    unsafe { calls::free_instance::<M>(instance) }
}

/// Switches debug logging and its categories (FMI 3.0 §2.3.2).
pub unsafe fn fmi3SetDebugLogging<M: Model>(
    instance: fmi3Instance,
    loggingOn: fmi3Boolean,
    nCategories: usize,
    categories: *const fmi3String,
) -> fmi3Status {
    with_instance::<M>(instance, Call::SetDebugLogging, |inst| {
        // SAFETY: nCategories NUL-terminated strings (FMI 3.0 §2.3.2).
        unsafe {
            let pointers = slice(categories, nCategories, "categories")?;
            calls::set_debug_logging(inst, loggingOn, pointers)
        }
    })
}

/// Stores the tolerance, start and stop time and enters Initialization Mode.
pub unsafe fn fmi3EnterInitializationMode<M: Model>(
    instance: fmi3Instance,
    toleranceDefined: fmi3Boolean,
    tolerance: fmi3Float64,
    startTime: fmi3Float64,
    stopTimeDefined: fmi3Boolean,
    stopTime: fmi3Float64,
) -> fmi3Status {
    with_instance::<M>(instance, Call::EnterInitializationMode, |inst| {
        let experiment = (
            toleranceDefined.then_some(tolerance),
            startTime,
            stopTimeDefined.then_some(stopTime),
        );
        inst.setup_experiment(experiment).map(ok)
    })
}

/// Builds the model from the parameters and enters Step Mode, or Event Mode if the master uses it;
/// outputs are valid afterwards.
pub unsafe fn fmi3ExitInitializationMode<M: Model>(instance: fmi3Instance) -> fmi3Status {
    with_instance::<M>(instance, Call::ExitInitializationMode, |inst| {
        inst.exit_initialization().map(ok)
    })
}

/// Ends the simulation; outputs stay readable.
pub unsafe fn fmi3Terminate<M: Model>(instance: fmi3Instance) -> fmi3Status {
    with_instance::<M>(instance, Call::Terminate, calls::terminate)
}

/// Back to Instantiated with every start value.
pub unsafe fn fmi3Reset<M: Model>(instance: fmi3Instance) -> fmi3Status {
    with_instance::<M>(instance, Call::Reset, calls::reset)
}

/// A function of a capability the FMU does not declare (clocks, model exchange, scheduled
/// execution, adjoint derivatives, variable dependencies): logs that and returns fmi3Error.
pub fn unsupported<M: Model>(instance: fmi3Instance, call: &'static str, why: &str) -> fmi3Status {
    with_instance::<M>(instance, Call::Other(call), |_| {
        Err(FmuError::Invalid(format!("not supported: {why}")))
    })
}
