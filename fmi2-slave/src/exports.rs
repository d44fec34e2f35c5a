//! The 34 `fmi2*` functions of a co-simulation FMU (FMI 2.0.4 §2.1, §4.2), generic over the
//! [`Model`]; [`crate::export_fmi2!`] exports them under their C names. Each is a shim: pointers
//! become slices through [`super::ffi`], the state machine is checked there, and the work happens
//! in the [`Instance`] and its model.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]
// The macro-generated exports call these with the master's arguments.

use std::ffi::c_char;
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi2::*;

use super::error::FmuError;
use super::ffi::{slice, slice_mut, string, with_instance};
use super::logger::Logger;
use super::model::{Instance, Model};
use super::state::{Call, State};

/// The C types of the FMI 2.0 headers, for [`crate::export_fmi2!`].
pub mod sys {
    pub use fmi_sys::fmi2::*;
}

const OK: fmi2Status = fmi2Status_fmi2OK;
const DISCARD: fmi2Status = fmi2Status_fmi2Discard;

fn ok(_: ()) -> fmi2Status {
    OK
}

/// Returns "default".
pub fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

/// Returns "2.0".
pub fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

/// Creates an instance; NULL (after logging, if a logger was given) on any invalid argument.
pub unsafe fn fmi2Instantiate<M: Model>(
    instanceName: fmi2String,
    fmuType: fmi2Type,
    fmuGUID: fmi2String,
    _fmuResourceLocation: fmi2String,
    functions: *const fmi2CallbackFunctions,
    _visible: fmi2Boolean,
    loggingOn: fmi2Boolean,
) -> fmi2Component {
    if functions.is_null() {
        return std::ptr::null_mut();
    }
    // SAFETY: non-NULL; the master's struct is valid during the call and is copied by value
    // (FMI 2.0.4 §2.1.5: the FMU must not rely on it afterwards).
    let callbacks = unsafe { *functions };
    if callbacks.logger.is_none() {
        return std::ptr::null_mut();
    }
    let result = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: NUL-terminated strings from the master, copied here.
        let name = unsafe { string(instanceName) }.unwrap_or_default();
        let logger = Logger::new(
            callbacks.logger,
            callbacks.componentEnvironment,
            &name,
            loggingOn != 0,
            M::LOG_CATEGORIES,
        );
        if name.is_empty() {
            logger.error("fmi2Instantiate: instanceName must not be NULL or empty.");
            return std::ptr::null_mut();
        }
        if fmuType != fmi2Type_fmi2CoSimulation {
            logger.error(&format!(
                "fmi2Instantiate: fmuType = {fmuType}: this FMU supports co-simulation (fmi2CoSimulation = 1) only."
            ));
            return std::ptr::null_mut();
        }
        // SAFETY: as above.
        let guid = unsafe { string(fmuGUID) }.unwrap_or_default();
        if guid != M::GUID {
            logger.error(&format!(
                "fmi2Instantiate: Wrong GUID: expected {}, got \"{guid}\".",
                M::GUID
            ));
            return std::ptr::null_mut();
        }
        logger.event(&format!("fmi2Instantiate: instance \"{name}\" created"));
        Box::into_raw(Box::new(Instance::<M>::new(logger))).cast()
    }));
    result.unwrap_or(std::ptr::null_mut())
}

/// Frees an instance (NULL is a no-op); legal in every state.
pub unsafe fn fmi2FreeInstance<M: Model>(c: fmi2Component) {
    if !c.is_null() {
        // SAFETY: c came from Box::into_raw in fmi2Instantiate and is freed once (FMI 2.0.4
        // §2.1.5: no call on c after fmi2FreeInstance).
        let instance = unsafe { Box::from_raw(c.cast::<Instance<M>>()) };
        let _ = catch_unwind(AssertUnwindSafe(|| drop(instance)));
    }
}

/// Switches debug logging and its categories (FMI 2.0.4 §2.1.5).
pub unsafe fn fmi2SetDebugLogging<M: Model>(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    nCategories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetDebugLogging, |inst| {
        // SAFETY: nCategories strings per FMI 2.0.4 §2.1.5.
        let pointers = unsafe { slice(categories, nCategories, "categories") }?;
        let mut names = Vec::with_capacity(pointers.len());
        for &p in pointers {
            // SAFETY: each is a NUL-terminated category name.
            names.push(unsafe { string(p) }.ok_or(FmuError::Null("categories[i]"))?);
        }
        inst.logger
            .set_debug_logging(loggingOn != 0, &names)
            .map_err(FmuError::Invalid)?;
        Ok(OK)
    })
}

/// Stores the tolerance, start and stop time (FMI 2.0.4 §2.1.6).
pub unsafe fn fmi2SetupExperiment<M: Model>(
    c: fmi2Component,
    toleranceDefined: fmi2Boolean,
    tolerance: fmi2Real,
    startTime: fmi2Real,
    stopTimeDefined: fmi2Boolean,
    stopTime: fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetupExperiment, |inst| {
        inst.model
            .setup_experiment(
                &inst.logger,
                (toleranceDefined != 0).then_some(tolerance),
                startTime,
                (stopTimeDefined != 0).then_some(stopTime),
            )
            .map(ok)
    })
}

/// Enters initialization mode.
pub unsafe fn fmi2EnterInitializationMode<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::EnterInitializationMode, |inst| {
        inst.state = State::InitializationMode;
        Ok(OK)
    })
}

/// Builds the model from the parameters; outputs are valid afterwards.
pub unsafe fn fmi2ExitInitializationMode<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::ExitInitializationMode, |inst| {
        inst.model.exit_initialization(&inst.logger)?;
        inst.state = State::StepComplete;
        Ok(OK)
    })
}

/// Ends the simulation; outputs stay readable.
pub unsafe fn fmi2Terminate<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::Terminate, |inst| {
        inst.state = State::Terminated;
        Ok(OK)
    })
}

/// Back to Instantiated with every start value.
pub unsafe fn fmi2Reset<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::Reset, |inst| {
        inst.reset();
        Ok(OK)
    })
}

/// Reads Real variables.
pub unsafe fn fmi2GetReal<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetReal, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        inst.model.get_real(&inst.logger, vr, value).map(ok)
    })
}

/// Reads Integer variables (the switches among them).
pub unsafe fn fmi2GetInteger<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetInteger, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        inst.model.get_integer(&inst.logger, vr, value).map(ok)
    })
}

/// Reads Boolean variables.
pub unsafe fn fmi2GetBoolean<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetBoolean, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        inst.model.get_boolean(&inst.logger, vr, value).map(ok)
    })
}

/// The FMU has no String variables: any value reference is an error.
pub unsafe fn fmi2GetString<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2String,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetString, |_| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, _) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        match vr.first() {
            Some(r) => Err(FmuError::Invalid(format!(
                "value reference {r} is not a String variable"
            ))),
            None => Ok(OK),
        }
    })
}

/// Writes Real parameters (before initialization ends) and inputs.
pub unsafe fn fmi2SetReal<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetReal, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        inst.model.set_real(inst.state, vr, value).map(ok)
    })
}

/// Writes Integer parameters, the switches among them (before initialization ends).
pub unsafe fn fmi2SetInteger<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetInteger, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        inst.model.set_integer(inst.state, vr, value).map(ok)
    })
}

/// No Boolean variable is settable: any value reference is an error.
pub unsafe fn fmi2SetBoolean<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetBoolean, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        inst.model.set_boolean(inst.state, vr, value).map(ok)
    })
}

/// The FMU has no String variables: any value reference is an error.
pub unsafe fn fmi2SetString<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2String,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetString, |_| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, _) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        match vr.first() {
            Some(r) => Err(FmuError::Invalid(format!(
                "value reference {r} is not a String variable"
            ))),
            None => Ok(OK),
        }
    })
}

/// Captures the complete instance state (allocates, or overwrites *FMUstate).
pub unsafe fn fmi2GetFMUstate<M: Model>(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetFmuState, |inst| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        let bytes = inst.serialize();
        // SAFETY: FMUstate points to the master's fmi2FMUstate variable (FMI 2.0.4 §2.1.8); a
        // non-NULL value is a state this FMU allocated (Box<Vec<u8>>) and is overwritten.
        unsafe {
            if (*FMUstate).is_null() {
                *FMUstate = Box::into_raw(Box::new(bytes)).cast();
            } else {
                *(*FMUstate).cast::<Vec<u8>>() = bytes;
            }
        }
        Ok(OK)
    })
}

/// Restores a captured state, including the state machine.
pub unsafe fn fmi2SetFMUstate<M: Model>(c: fmi2Component, FMUstate: fmi2FMUstate) -> fmi2Status {
    with_instance::<M>(c, Call::SetFmuState, |inst| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        // SAFETY: a state allocated by fmi2GetFMUstate/fmi2DeSerializeFMUstate of this FMU.
        let bytes = unsafe { &*FMUstate.cast::<Vec<u8>>() };
        inst.deserialize(bytes, true).map(ok)
    })
}

/// Frees a captured state and sets it to NULL.
pub unsafe fn fmi2FreeFMUstate<M: Model>(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance::<M>(c, Call::FreeFmuState, |_| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        // SAFETY: *FMUstate is NULL or a state this FMU allocated; it is freed once and reset.
        unsafe {
            if !(*FMUstate).is_null() {
                drop(Box::from_raw((*FMUstate).cast::<Vec<u8>>()));
                *FMUstate = std::ptr::null_mut();
            }
        }
        Ok(OK)
    })
}

/// Size of a serialized state in bytes.
pub unsafe fn fmi2SerializedFMUstateSize<M: Model>(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    with_instance::<M>(c, Call::SerializedFmuStateSize, |_| {
        if FMUstate.is_null() || size.is_null() {
            return Err(FmuError::Null(if size.is_null() {
                "size"
            } else {
                "FMUstate"
            }));
        }
        // SAFETY: a state of this FMU; size points to the master's variable.
        unsafe { *size = (*FMUstate.cast::<Vec<u8>>()).len() };
        Ok(OK)
    })
}

/// Writes a state as pointer-free bytes.
pub unsafe fn fmi2SerializeFMUstate<M: Model>(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    serializedState: *mut fmi2Byte,
    size: usize,
) -> fmi2Status {
    with_instance::<M>(c, Call::SerializeFmuState, |_| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        // SAFETY: a state of this FMU.
        let bytes = unsafe { &*FMUstate.cast::<Vec<u8>>() };
        if size < bytes.len() {
            return Err(FmuError::Invalid(format!(
                "size = {size} is smaller than the serialized state ({} bytes)",
                bytes.len()
            )));
        }
        // SAFETY: the master provides `size` writable bytes (FMI 2.0.4 §2.1.8).
        let out =
            unsafe { slice_mut(serializedState.cast::<u8>(), bytes.len(), "serializedState") }?;
        out.copy_from_slice(bytes);
        Ok(OK)
    })
}

/// Reads a state from bytes (checked: magic, version, parameter count, nModes, checksum).
pub unsafe fn fmi2DeSerializeFMUstate<M: Model>(
    c: fmi2Component,
    serializedState: *const fmi2Byte,
    size: usize,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance::<M>(c, Call::DeSerializeFmuState, |inst| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        // SAFETY: `size` readable bytes (FMI 2.0.4 §2.1.8).
        let bytes = unsafe { slice(serializedState.cast::<u8>(), size, "serializedState") }?;
        inst.deserialize(bytes, false)?;
        // SAFETY: as in fmi2GetFMUstate.
        unsafe {
            if (*FMUstate).is_null() {
                *FMUstate = Box::into_raw(Box::new(bytes.to_vec())).cast();
            } else {
                *(*FMUstate).cast::<Vec<u8>>() = bytes.to_vec();
            }
        }
        Ok(OK)
    })
}

/// Not provided: error.
pub unsafe fn fmi2GetDirectionalDerivative<M: Model>(
    c: fmi2Component,
    _vUnknown_ref: *const fmi2ValueReference,
    _nUnknown: usize,
    _vKnown_ref: *const fmi2ValueReference,
    _nKnown: usize,
    _dvKnown: *const fmi2Real,
    _dvUnknown: *mut fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetDirectionalDerivative, |_| {
        Err(FmuError::Invalid(
            "directional derivatives are not provided (providesDirectionalDerivative = false)"
                .into(),
        ))
    })
}

/// Sets first or second time derivatives of inputs at the current communication point; the
/// inputs are the resulting polynomials over the next communication step.
pub unsafe fn fmi2SetRealInputDerivatives<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *const fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetRealInputDerivatives, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §4.2.1).
        let (vr, order, value) = unsafe {
            (
                slice(vr, nvr, "vr")?,
                slice(order, nvr, "order")?,
                slice(value, nvr, "value")?,
            )
        };
        inst.model
            .set_real_input_derivatives(vr, order, value)
            .map(ok)
    })
}

/// Time derivatives of the kinematic outputs at the current communication point.
pub unsafe fn fmi2GetRealOutputDerivatives<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetRealOutputDerivatives, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §4.2.1).
        let (vr, order, value) = unsafe {
            (
                slice(vr, nvr, "vr")?,
                slice(order, nvr, "order")?,
                slice_mut(value, nvr, "value")?,
            )
        };
        inst.model
            .get_real_output_derivatives(&inst.logger, vr, order, value)
            .map(ok)
    })
}

/// Integrates from the communication point over the step size (error-controlled sub-steps).
pub unsafe fn fmi2DoStep<M: Model>(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    with_instance::<M>(c, Call::DoStep, |inst| {
        inst.model
            .do_step(
                &inst.logger,
                currentCommunicationPoint,
                communicationStepSize,
            )
            .map(ok)
    })
}

/// Steps are synchronous: there is never a step to cancel.
pub unsafe fn fmi2CancelStep<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::CancelStep, |_| Ok(OK))
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
        inst.logger
            .warning("fmi2GetStatus: no asynchronous step; status kinds are not available");
        Ok(DISCARD)
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
            value[0] = inst.model.last_successful_time();
            Ok(OK)
        } else {
            Ok(DISCARD)
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
        Ok(DISCARD)
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
            Ok(OK)
        } else {
            Ok(DISCARD)
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
        Ok(DISCARD)
    })
}

/// Exports the 34 `fmi2*` functions of a co-simulation FMU for the model type `$model`
/// (one invocation per shared library); `const _: fmi2XxxTYPE = Some(fmi2Xxx)` pins every
/// signature to the official header.
#[macro_export]
macro_rules! export_fmi2 {
    ($model:ty) => {
        /// See `fmi2_slave::exports::fmi2GetTypesPlatform`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetTypesPlatform() -> *const ::std::ffi::c_char {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            $crate::exports::fmi2GetTypesPlatform()
        }
        const _: $crate::exports::sys::fmi2GetTypesPlatformTYPE = Some(fmi2GetTypesPlatform);
        /// See `fmi2_slave::exports::fmi2GetVersion`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetVersion() -> *const ::std::ffi::c_char {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            $crate::exports::fmi2GetVersion()
        }
        const _: $crate::exports::sys::fmi2GetVersionTYPE = Some(fmi2GetVersion);
        /// See `fmi2_slave::exports::fmi2Instantiate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2Instantiate(
            instanceName: $crate::exports::sys::fmi2String,
            fmuType: $crate::exports::sys::fmi2Type,
            fmuGUID: $crate::exports::sys::fmi2String,
            _fmuResourceLocation: $crate::exports::sys::fmi2String,
            functions: *const $crate::exports::sys::fmi2CallbackFunctions,
            _visible: $crate::exports::sys::fmi2Boolean,
            loggingOn: $crate::exports::sys::fmi2Boolean,
        ) -> $crate::exports::sys::fmi2Component {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2Instantiate::<$model>(
                    instanceName,
                    fmuType,
                    fmuGUID,
                    _fmuResourceLocation,
                    functions,
                    _visible,
                    loggingOn,
                )
            }
        }
        const _: $crate::exports::sys::fmi2InstantiateTYPE = Some(fmi2Instantiate);
        /// See `fmi2_slave::exports::fmi2FreeInstance`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2FreeInstance(c: $crate::exports::sys::fmi2Component) {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2FreeInstance::<$model>(c) }
        }
        const _: $crate::exports::sys::fmi2FreeInstanceTYPE = Some(fmi2FreeInstance);
        /// See `fmi2_slave::exports::fmi2SetDebugLogging`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetDebugLogging(
            c: $crate::exports::sys::fmi2Component,
            loggingOn: $crate::exports::sys::fmi2Boolean,
            nCategories: usize,
            categories: *const $crate::exports::sys::fmi2String,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2SetDebugLogging::<$model>(
                    c,
                    loggingOn,
                    nCategories,
                    categories,
                )
            }
        }
        const _: $crate::exports::sys::fmi2SetDebugLoggingTYPE = Some(fmi2SetDebugLogging);
        /// See `fmi2_slave::exports::fmi2SetupExperiment`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetupExperiment(
            c: $crate::exports::sys::fmi2Component,
            toleranceDefined: $crate::exports::sys::fmi2Boolean,
            tolerance: $crate::exports::sys::fmi2Real,
            startTime: $crate::exports::sys::fmi2Real,
            stopTimeDefined: $crate::exports::sys::fmi2Boolean,
            stopTime: $crate::exports::sys::fmi2Real,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2SetupExperiment::<$model>(
                    c,
                    toleranceDefined,
                    tolerance,
                    startTime,
                    stopTimeDefined,
                    stopTime,
                )
            }
        }
        const _: $crate::exports::sys::fmi2SetupExperimentTYPE = Some(fmi2SetupExperiment);
        /// See `fmi2_slave::exports::fmi2EnterInitializationMode`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2EnterInitializationMode(
            c: $crate::exports::sys::fmi2Component,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2EnterInitializationMode::<$model>(c) }
        }
        const _: $crate::exports::sys::fmi2EnterInitializationModeTYPE =
            Some(fmi2EnterInitializationMode);
        /// See `fmi2_slave::exports::fmi2ExitInitializationMode`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2ExitInitializationMode(
            c: $crate::exports::sys::fmi2Component,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2ExitInitializationMode::<$model>(c) }
        }
        const _: $crate::exports::sys::fmi2ExitInitializationModeTYPE =
            Some(fmi2ExitInitializationMode);
        /// See `fmi2_slave::exports::fmi2Terminate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2Terminate(
            c: $crate::exports::sys::fmi2Component,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2Terminate::<$model>(c) }
        }
        const _: $crate::exports::sys::fmi2TerminateTYPE = Some(fmi2Terminate);
        /// See `fmi2_slave::exports::fmi2Reset`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2Reset(
            c: $crate::exports::sys::fmi2Component,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2Reset::<$model>(c) }
        }
        const _: $crate::exports::sys::fmi2ResetTYPE = Some(fmi2Reset);
        /// See `fmi2_slave::exports::fmi2GetReal`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetReal(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::exports::sys::fmi2Real,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetReal::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2GetRealTYPE = Some(fmi2GetReal);
        /// See `fmi2_slave::exports::fmi2GetInteger`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetInteger(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::exports::sys::fmi2Integer,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetInteger::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2GetIntegerTYPE = Some(fmi2GetInteger);
        /// See `fmi2_slave::exports::fmi2GetBoolean`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetBoolean(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::exports::sys::fmi2Boolean,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetBoolean::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2GetBooleanTYPE = Some(fmi2GetBoolean);
        /// See `fmi2_slave::exports::fmi2GetString`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetString(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::exports::sys::fmi2String,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetString::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2GetStringTYPE = Some(fmi2GetString);
        /// See `fmi2_slave::exports::fmi2SetReal`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetReal(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::exports::sys::fmi2Real,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2SetReal::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2SetRealTYPE = Some(fmi2SetReal);
        /// See `fmi2_slave::exports::fmi2SetInteger`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetInteger(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::exports::sys::fmi2Integer,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2SetInteger::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2SetIntegerTYPE = Some(fmi2SetInteger);
        /// See `fmi2_slave::exports::fmi2SetBoolean`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetBoolean(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::exports::sys::fmi2Boolean,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2SetBoolean::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2SetBooleanTYPE = Some(fmi2SetBoolean);
        /// See `fmi2_slave::exports::fmi2SetString`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetString(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::exports::sys::fmi2String,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2SetString::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::exports::sys::fmi2SetStringTYPE = Some(fmi2SetString);
        /// See `fmi2_slave::exports::fmi2GetFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetFMUstate(
            c: $crate::exports::sys::fmi2Component,
            FMUstate: *mut $crate::exports::sys::fmi2FMUstate,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetFMUstate::<$model>(c, FMUstate) }
        }
        const _: $crate::exports::sys::fmi2GetFMUstateTYPE = Some(fmi2GetFMUstate);
        /// See `fmi2_slave::exports::fmi2SetFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetFMUstate(
            c: $crate::exports::sys::fmi2Component,
            FMUstate: $crate::exports::sys::fmi2FMUstate,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2SetFMUstate::<$model>(c, FMUstate) }
        }
        const _: $crate::exports::sys::fmi2SetFMUstateTYPE = Some(fmi2SetFMUstate);
        /// See `fmi2_slave::exports::fmi2FreeFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2FreeFMUstate(
            c: $crate::exports::sys::fmi2Component,
            FMUstate: *mut $crate::exports::sys::fmi2FMUstate,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2FreeFMUstate::<$model>(c, FMUstate) }
        }
        const _: $crate::exports::sys::fmi2FreeFMUstateTYPE = Some(fmi2FreeFMUstate);
        /// See `fmi2_slave::exports::fmi2SerializedFMUstateSize`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
            c: $crate::exports::sys::fmi2Component,
            FMUstate: $crate::exports::sys::fmi2FMUstate,
            size: *mut usize,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2SerializedFMUstateSize::<$model>(c, FMUstate, size) }
        }
        const _: $crate::exports::sys::fmi2SerializedFMUstateSizeTYPE =
            Some(fmi2SerializedFMUstateSize);
        /// See `fmi2_slave::exports::fmi2SerializeFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SerializeFMUstate(
            c: $crate::exports::sys::fmi2Component,
            FMUstate: $crate::exports::sys::fmi2FMUstate,
            serializedState: *mut $crate::exports::sys::fmi2Byte,
            size: usize,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2SerializeFMUstate::<$model>(c, FMUstate, serializedState, size)
            }
        }
        const _: $crate::exports::sys::fmi2SerializeFMUstateTYPE = Some(fmi2SerializeFMUstate);
        /// See `fmi2_slave::exports::fmi2DeSerializeFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
            c: $crate::exports::sys::fmi2Component,
            serializedState: *const $crate::exports::sys::fmi2Byte,
            size: usize,
            FMUstate: *mut $crate::exports::sys::fmi2FMUstate,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2DeSerializeFMUstate::<$model>(
                    c,
                    serializedState,
                    size,
                    FMUstate,
                )
            }
        }
        const _: $crate::exports::sys::fmi2DeSerializeFMUstateTYPE = Some(fmi2DeSerializeFMUstate);
        /// See `fmi2_slave::exports::fmi2GetDirectionalDerivative`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
            c: $crate::exports::sys::fmi2Component,
            _vUnknown_ref: *const $crate::exports::sys::fmi2ValueReference,
            _nUnknown: usize,
            _vKnown_ref: *const $crate::exports::sys::fmi2ValueReference,
            _nKnown: usize,
            _dvKnown: *const $crate::exports::sys::fmi2Real,
            _dvUnknown: *mut $crate::exports::sys::fmi2Real,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2GetDirectionalDerivative::<$model>(
                    c,
                    _vUnknown_ref,
                    _nUnknown,
                    _vKnown_ref,
                    _nKnown,
                    _dvKnown,
                    _dvUnknown,
                )
            }
        }
        const _: $crate::exports::sys::fmi2GetDirectionalDerivativeTYPE =
            Some(fmi2GetDirectionalDerivative);
        /// See `fmi2_slave::exports::fmi2SetRealInputDerivatives`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            order: *const $crate::exports::sys::fmi2Integer,
            value: *const $crate::exports::sys::fmi2Real,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2SetRealInputDerivatives::<$model>(c, vr, nvr, order, value)
            }
        }
        const _: $crate::exports::sys::fmi2SetRealInputDerivativesTYPE =
            Some(fmi2SetRealInputDerivatives);
        /// See `fmi2_slave::exports::fmi2GetRealOutputDerivatives`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
            c: $crate::exports::sys::fmi2Component,
            vr: *const $crate::exports::sys::fmi2ValueReference,
            nvr: usize,
            order: *const $crate::exports::sys::fmi2Integer,
            value: *mut $crate::exports::sys::fmi2Real,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2GetRealOutputDerivatives::<$model>(c, vr, nvr, order, value)
            }
        }
        const _: $crate::exports::sys::fmi2GetRealOutputDerivativesTYPE =
            Some(fmi2GetRealOutputDerivatives);
        /// See `fmi2_slave::exports::fmi2DoStep`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2DoStep(
            c: $crate::exports::sys::fmi2Component,
            currentCommunicationPoint: $crate::exports::sys::fmi2Real,
            communicationStepSize: $crate::exports::sys::fmi2Real,
            _noSetFMUStatePriorToCurrentPoint: $crate::exports::sys::fmi2Boolean,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::exports::fmi2DoStep::<$model>(
                    c,
                    currentCommunicationPoint,
                    communicationStepSize,
                    _noSetFMUStatePriorToCurrentPoint,
                )
            }
        }
        const _: $crate::exports::sys::fmi2DoStepTYPE = Some(fmi2DoStep);
        /// See `fmi2_slave::exports::fmi2CancelStep`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2CancelStep(
            c: $crate::exports::sys::fmi2Component,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2CancelStep::<$model>(c) }
        }
        const _: $crate::exports::sys::fmi2CancelStepTYPE = Some(fmi2CancelStep);
        /// See `fmi2_slave::exports::fmi2GetStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetStatus(
            c: $crate::exports::sys::fmi2Component,
            _s: $crate::exports::sys::fmi2StatusKind,
            value: *mut $crate::exports::sys::fmi2Status,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetStatus::<$model>(c, _s, value) }
        }
        const _: $crate::exports::sys::fmi2GetStatusTYPE = Some(fmi2GetStatus);
        /// See `fmi2_slave::exports::fmi2GetRealStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetRealStatus(
            c: $crate::exports::sys::fmi2Component,
            s: $crate::exports::sys::fmi2StatusKind,
            value: *mut $crate::exports::sys::fmi2Real,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetRealStatus::<$model>(c, s, value) }
        }
        const _: $crate::exports::sys::fmi2GetRealStatusTYPE = Some(fmi2GetRealStatus);
        /// See `fmi2_slave::exports::fmi2GetIntegerStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetIntegerStatus(
            c: $crate::exports::sys::fmi2Component,
            _s: $crate::exports::sys::fmi2StatusKind,
            value: *mut $crate::exports::sys::fmi2Integer,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetIntegerStatus::<$model>(c, _s, value) }
        }
        const _: $crate::exports::sys::fmi2GetIntegerStatusTYPE = Some(fmi2GetIntegerStatus);
        /// See `fmi2_slave::exports::fmi2GetBooleanStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetBooleanStatus(
            c: $crate::exports::sys::fmi2Component,
            s: $crate::exports::sys::fmi2StatusKind,
            value: *mut $crate::exports::sys::fmi2Boolean,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetBooleanStatus::<$model>(c, s, value) }
        }
        const _: $crate::exports::sys::fmi2GetBooleanStatusTYPE = Some(fmi2GetBooleanStatus);
        /// See `fmi2_slave::exports::fmi2GetStringStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetStringStatus(
            c: $crate::exports::sys::fmi2Component,
            _s: $crate::exports::sys::fmi2StatusKind,
            value: *mut $crate::exports::sys::fmi2String,
        ) -> $crate::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::exports::fmi2GetStringStatus::<$model>(c, _s, value) }
        }
        const _: $crate::exports::sys::fmi2GetStringStatusTYPE = Some(fmi2GetStringStatus);
    };
}
