//! Getting, setting, freeing, serializing and deserializing FMU states ([`crate::calls`]).
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use fmi_sys::fmi2::*;

use super::codes::with_instance;
use crate::calls;
use crate::ffi::{slice, slice_mut};
use crate::model::Model;
use crate::state::Call;

/// Captures the complete instance state (allocates, or overwrites *FMUstate).
pub unsafe fn fmi2GetFMUstate<M: Model>(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetFmuState, |inst| {
        // SAFETY: FMUstate points to the master's fmi2FMUstate variable (FMI 2.0.4 §2.1.8), NULL
        // or a state this FMU allocated.
        unsafe { calls::get_state(inst, FMUstate, "FMUstate") }
    })
}

/// Restores a captured state, including the state machine.
pub unsafe fn fmi2SetFMUstate<M: Model>(c: fmi2Component, FMUstate: fmi2FMUstate) -> fmi2Status {
    with_instance::<M>(c, Call::SetFmuState, |inst| {
        // SAFETY: a state allocated by fmi2GetFMUstate/fmi2DeSerializeFMUstate of this FMU.
        unsafe { calls::set_state(inst, FMUstate, "FMUstate") }
    })
}

/// Frees a captured state and sets it to NULL.
pub unsafe fn fmi2FreeFMUstate<M: Model>(
    c: fmi2Component,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance::<M>(c, Call::FreeFmuState, |_| {
        // SAFETY: *FMUstate is NULL or a state this FMU allocated; it is freed once and reset.
        unsafe { calls::free_state(FMUstate, "FMUstate") }
    })
}

/// Size of a serialized state in bytes.
pub unsafe fn fmi2SerializedFMUstateSize<M: Model>(
    c: fmi2Component,
    FMUstate: fmi2FMUstate,
    size: *mut usize,
) -> fmi2Status {
    with_instance::<M>(c, Call::SerializedFmuStateSize, |_| {
        // SAFETY: size points to the master's variable; FMUstate is a state of this FMU.
        unsafe { calls::serialized_size(FMUstate, slice_mut(size, 1, "size")?, "FMUstate") }
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
        // SAFETY: a state of this FMU; the master provides `size` writable bytes (FMI 2.0.4
        // §2.1.8).
        unsafe {
            calls::serialize(
                FMUstate,
                serializedState.cast(),
                size,
                ["FMUstate", "serializedState"],
            )
        }
    })
}

/// Reads a state from bytes (checked: magic, version, contents, checksum).
pub unsafe fn fmi2DeSerializeFMUstate<M: Model>(
    c: fmi2Component,
    serializedState: *const fmi2Byte,
    size: usize,
    FMUstate: *mut fmi2FMUstate,
) -> fmi2Status {
    with_instance::<M>(c, Call::DeSerializeFmuState, |inst| {
        // SAFETY: `size` readable bytes (FMI 2.0.4 §2.1.8); FMUstate as in fmi2GetFMUstate.
        unsafe {
            let bytes = slice(serializedState.cast::<u8>(), size, "serializedState")?;
            calls::deserialize(inst, bytes, FMUstate, "FMUstate")
        }
    })
}
