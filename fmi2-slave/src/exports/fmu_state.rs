//! Getting, setting, freeing, serializing and deserializing FMU states.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use fmi_sys::fmi2::*;

use super::codes::{OK, ok};
use crate::error::FmuError;
use crate::ffi::{slice, slice_mut, with_instance};
use crate::model::Model;
use crate::state::Call;

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
