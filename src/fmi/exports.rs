//! The 34 exported `fmi2*` functions of a co-simulation FMU (FMI 2.0.4 §2.1, §4.2). Each is a
//! shim: pointers become slices through [`super::ffi`], the work happens in [`Instance`], and
//! `const _: fmi2XxxTYPE = Some(fmi2Xxx)` pins every signature to the official header.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use std::ffi::c_char;
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi2::*;

use super::GUID;
use super::error::FmuError;
use super::ffi::{slice, slice_mut, string, with_instance};
use super::instance::Instance;
use super::logger::Logger;
use super::snapshot::FmuSnapshot;
use super::state::{Call, State};

const OK: fmi2Status = fmi2Status_fmi2OK;
const DISCARD: fmi2Status = fmi2Status_fmi2Discard;

fn ok(_: ()) -> fmi2Status {
    OK
}

/// Returns "default".
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}
const _: fmi2GetTypesPlatformTYPE = Some(fmi2GetTypesPlatform);

/// Returns "2.0".
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}
const _: fmi2GetVersionTYPE = Some(fmi2GetVersion);

/// Creates an instance; NULL (after logging, if a logger was given) on any invalid argument.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Instantiate(
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
        if guid != GUID {
            logger.error(&format!(
                "fmi2Instantiate: Wrong GUID: expected {GUID}, got \"{guid}\"."
            ));
            return std::ptr::null_mut();
        }
        logger.event(&format!("fmi2Instantiate: instance \"{name}\" created"));
        Box::into_raw(Box::new(Instance::new(name, logger))).cast()
    }));
    result.unwrap_or(std::ptr::null_mut())
}
const _: fmi2InstantiateTYPE = Some(fmi2Instantiate);

/// Frees an instance (NULL is a no-op); legal in every state.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    if !c.is_null() {
        // SAFETY: c came from Box::into_raw in fmi2Instantiate and is freed once (FMI 2.0.4
        // §2.1.5: no call on c after fmi2FreeInstance).
        let instance = unsafe { Box::from_raw(c.cast::<Instance>()) };
        let _ = catch_unwind(AssertUnwindSafe(|| drop(instance)));
    }
}
const _: fmi2FreeInstanceTYPE = Some(fmi2FreeInstance);

/// Switches debug logging and its categories (FMI 2.0.4 §2.1.5).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    nCategories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    with_instance(c, Call::SetDebugLogging, |inst| {
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
const _: fmi2SetDebugLoggingTYPE = Some(fmi2SetDebugLogging);

/// Stores the tolerance, start and stop time (FMI 2.0.4 §2.1.6).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    toleranceDefined: fmi2Boolean,
    tolerance: fmi2Real,
    startTime: fmi2Real,
    stopTimeDefined: fmi2Boolean,
    stopTime: fmi2Real,
) -> fmi2Status {
    with_instance(c, Call::SetupExperiment, |inst| {
        inst.setup_experiment(
            (toleranceDefined != 0).then_some(tolerance),
            startTime,
            (stopTimeDefined != 0).then_some(stopTime),
        )
        .map(ok)
    })
}
const _: fmi2SetupExperimentTYPE = Some(fmi2SetupExperiment);

/// Enters initialization mode.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> fmi2Status {
    with_instance(c, Call::EnterInitializationMode, |inst| {
        inst.state = State::InitializationMode;
        Ok(OK)
    })
}
const _: fmi2EnterInitializationModeTYPE = Some(fmi2EnterInitializationMode);

/// Builds the model from the parameters; outputs are valid afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> fmi2Status {
    with_instance(c, Call::ExitInitializationMode, |inst| {
        inst.exit_initialization()?;
        inst.state = State::StepComplete;
        Ok(OK)
    })
}
const _: fmi2ExitInitializationModeTYPE = Some(fmi2ExitInitializationMode);

/// Ends the simulation; outputs stay readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> fmi2Status {
    with_instance(c, Call::Terminate, |inst| {
        inst.state = State::Terminated;
        Ok(OK)
    })
}
const _: fmi2TerminateTYPE = Some(fmi2Terminate);

/// Back to Instantiated with every start value.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> fmi2Status {
    with_instance(c, Call::Reset, |inst| {
        inst.reset();
        Ok(OK)
    })
}
const _: fmi2ResetTYPE = Some(fmi2Reset);

/// Reads Real variables.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance(c, Call::GetReal, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        inst.get_real(vr, value).map(ok)
    })
}
const _: fmi2GetRealTYPE = Some(fmi2GetReal);

/// Reads Integer variables (the switches among them).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    with_instance(c, Call::GetInteger, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        inst.get_integer(vr, value).map(ok)
    })
}
const _: fmi2GetIntegerTYPE = Some(fmi2GetInteger);

/// Reads Boolean variables.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    with_instance(c, Call::GetBoolean, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        inst.get_boolean(vr, value).map(ok)
    })
}
const _: fmi2GetBooleanTYPE = Some(fmi2GetBoolean);

/// The FMU has no String variables: any value reference is an error.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2String,
) -> fmi2Status {
    with_instance(c, Call::GetString, |_| {
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
const _: fmi2GetStringTYPE = Some(fmi2GetString);

/// Writes Real parameters (before initialization ends) and inputs.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    with_instance(c, Call::SetReal, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        inst.set_real(vr, value).map(ok)
    })
}
const _: fmi2SetRealTYPE = Some(fmi2SetReal);

/// Writes Integer parameters, the switches among them (before initialization ends).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetInteger(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    with_instance(c, Call::SetInteger, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        inst.set_integer(vr, value).map(ok)
    })
}
const _: fmi2SetIntegerTYPE = Some(fmi2SetInteger);

/// No Boolean variable is settable: any value reference is an error.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    with_instance(c, Call::SetBoolean, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, _) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        inst.set_boolean(vr).map(ok)
    })
}
const _: fmi2SetBooleanTYPE = Some(fmi2SetBoolean);

/// The FMU has no String variables: any value reference is an error.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetString(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2String,
) -> fmi2Status {
    with_instance(c, Call::SetString, |_| {
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
const _: fmi2SetStringTYPE = Some(fmi2SetString);

/// Captures the complete instance state (allocates, or overwrites *FMUstate).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance(c, Call::GetFmuState, |inst| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        let bytes = inst.snapshot().to_bytes();
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
const _: fmi2GetFMUstateTYPE = Some(fmi2GetFMUstate);

/// Restores a captured state, including the state machine.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, FMUstate: fmi2FMUstate) -> fmi2Status {
    with_instance(c, Call::SetFmuState, |inst| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        // SAFETY: a state allocated by fmi2GetFMUstate/fmi2DeSerializeFMUstate of this FMU.
        let bytes = unsafe { &*FMUstate.cast::<Vec<u8>>() };
        inst.restore(&FmuSnapshot::from_bytes(bytes)?).map(ok)
    })
}
const _: fmi2SetFMUstateTYPE = Some(fmi2SetFMUstate);

/// Frees a captured state and sets it to NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance(c, Call::FreeFmuState, |_| {
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
const _: fmi2FreeFMUstateTYPE = Some(fmi2FreeFMUstate);

/// Size of a serialized state in bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    with_instance(c, Call::SerializedFmuStateSize, |_| {
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
const _: fmi2SerializedFMUstateSizeTYPE = Some(fmi2SerializedFMUstateSize);

/// Writes a state as pointer-free bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    serializedState: *mut fmi2Byte,
    size: usize,
) -> fmi2Status {
    with_instance(c, Call::SerializeFmuState, |_| {
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
const _: fmi2SerializeFMUstateTYPE = Some(fmi2SerializeFMUstate);

/// Reads a state from bytes (checked: magic, version, parameter count, nModes, checksum).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    serializedState: *const fmi2Byte,
    size: usize,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance(c, Call::DeSerializeFmuState, |_| {
        if FMUstate.is_null() {
            return Err(FmuError::Null("FMUstate"));
        }
        // SAFETY: `size` readable bytes (FMI 2.0.4 §2.1.8).
        let bytes = unsafe { slice(serializedState.cast::<u8>(), size, "serializedState") }?;
        FmuSnapshot::from_bytes(bytes)?;
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
const _: fmi2DeSerializeFMUstateTYPE = Some(fmi2DeSerializeFMUstate);

/// Not provided: error.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: fmi2Component,
    _vUnknown_ref: *const fmi2ValueReference,
    _nUnknown: usize,
    _vKnown_ref: *const fmi2ValueReference,
    _nKnown: usize,
    _dvKnown: *const fmi2Real,
    _dvUnknown: *mut fmi2Real,
) -> fmi2Status {
    with_instance(c, Call::GetDirectionalDerivative, |_| {
        Err(FmuError::Invalid(
            "directional derivatives are not provided (providesDirectionalDerivative = false)"
                .into(),
        ))
    })
}
const _: fmi2GetDirectionalDerivativeTYPE = Some(fmi2GetDirectionalDerivative);

/// Sets first or second time derivatives of inputs at the current communication point; the
/// inputs are the resulting polynomials over the next communication step.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *const fmi2Real,
) -> fmi2Status {
    with_instance(c, Call::SetRealInputDerivatives, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §4.2.1).
        let (vr, order, value) = unsafe {
            (
                slice(vr, nvr, "vr")?,
                slice(order, nvr, "order")?,
                slice(value, nvr, "value")?,
            )
        };
        inst.set_real_input_derivatives(vr, order, value).map(ok)
    })
}
const _: fmi2SetRealInputDerivativesTYPE = Some(fmi2SetRealInputDerivatives);

/// Time derivatives of the kinematic outputs at the current communication point.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance(c, Call::GetRealOutputDerivatives, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §4.2.1).
        let (vr, order, value) = unsafe {
            (
                slice(vr, nvr, "vr")?,
                slice(order, nvr, "order")?,
                slice_mut(value, nvr, "value")?,
            )
        };
        inst.get_real_output_derivatives(vr, order, value).map(ok)
    })
}
const _: fmi2GetRealOutputDerivativesTYPE = Some(fmi2GetRealOutputDerivatives);

/// Integrates from the communication point over the step size (error-controlled sub-steps).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DoStep(
    c: fmi2Component,
    currentCommunicationPoint: fmi2Real,
    communicationStepSize: fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean,
) -> fmi2Status {
    with_instance(c, Call::DoStep, |inst| {
        inst.do_step(currentCommunicationPoint, communicationStepSize)
            .map(ok)
    })
}
const _: fmi2DoStepTYPE = Some(fmi2DoStep);

/// Steps are synchronous: there is never a step to cancel.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> fmi2Status {
    with_instance(c, Call::CancelStep, |_| Ok(OK))
}
const _: fmi2CancelStepTYPE = Some(fmi2CancelStep);

/// No asynchronous steps: fmi2Discard.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    value: *mut fmi2Status,
) -> fmi2Status {
    with_instance(c, Call::GetStatus, |inst| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let _ = unsafe { slice_mut(value, 1, "value") }?;
        inst.logger
            .warning("fmi2GetStatus: no asynchronous step; status kinds are not available");
        Ok(DISCARD)
    })
}
const _: fmi2GetStatusTYPE = Some(fmi2GetStatus);

/// Answers fmi2LastSuccessfulTime; other kinds fmi2Discard.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance(c, Call::GetRealStatus, |inst| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let value = unsafe { slice_mut(value, 1, "value") }?;
        if s == fmi2StatusKind_fmi2LastSuccessfulTime {
            value[0] = inst.last_successful_time;
            Ok(OK)
        } else {
            Ok(DISCARD)
        }
    })
}
const _: fmi2GetRealStatusTYPE = Some(fmi2GetRealStatus);

/// No integer status kinds: fmi2Discard.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    value: *mut fmi2Integer,
) -> fmi2Status {
    with_instance(c, Call::GetIntegerStatus, |_| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let _ = unsafe { slice_mut(value, 1, "value") }?;
        Ok(DISCARD)
    })
}
const _: fmi2GetIntegerStatusTYPE = Some(fmi2GetIntegerStatus);

/// Answers fmi2Terminated (always false); other kinds fmi2Discard.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: fmi2Component,
    s: fmi2StatusKind,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    with_instance(c, Call::GetBooleanStatus, |_| {
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
const _: fmi2GetBooleanStatusTYPE = Some(fmi2GetBooleanStatus);

/// No string status kinds: fmi2Discard.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: fmi2Component,
    _s: fmi2StatusKind,
    value: *mut fmi2String,
) -> fmi2Status {
    with_instance(c, Call::GetStringStatus, |_| {
        // SAFETY: one writable value (FMI 2.0.4 §4.2.3).
        let _ = unsafe { slice_mut(value, 1, "value") }?;
        Ok(DISCARD)
    })
}
const _: fmi2GetStringStatusTYPE = Some(fmi2GetStringStatus);
