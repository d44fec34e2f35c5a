//! The calls into the master's logger callbacks (unsafe: C function pointers): FMI 2's variadic
//! one and FMI 3's.
#![allow(unsafe_code)]

use std::ffi::CStr;

use fmi_sys::fmi2::{fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status};
use fmi_sys::fmi3::{fmi3InstanceEnvironment, fmi3LogMessageCallback};

/// Calls the master's logger with `"%s"` as the format, so the text is never interpreted.
// The environment pointer is the master's opaque value, passed back unchanged, never dereferenced.
#[allow(clippy::not_unsafe_ptr_arg_deref)]
pub fn call_logger(
    callback: fmi2CallbackLogger,
    environment: fmi2ComponentEnvironment,
    instance_name: &CStr,
    status: fmi2Status,
    category: &CStr,
    message: &CStr,
) {
    if let Some(log) = callback {
        // SAFETY: the master passed this function in fmi2CallbackFunctions (FMI 2.0.4 §2.1.5) with
        // the printf-style signature; every string is NUL-terminated and outlives the call, and
        // "%s" consumes exactly the one variadic argument given.
        unsafe {
            log(
                environment,
                instance_name.as_ptr(),
                status,
                category.as_ptr(),
                c"%s".as_ptr(),
                message.as_ptr(),
            );
        }
    }
}

/// Calls FMI 3's logger (no format string: the message is passed as it is).
// The environment pointer is the master's opaque value, passed back unchanged, never dereferenced.
#[allow(clippy::not_unsafe_ptr_arg_deref)]
pub fn call_logger3(
    callback: fmi3LogMessageCallback,
    environment: fmi3InstanceEnvironment,
    status: fmi2Status,
    category: &CStr,
    message: &CStr,
) {
    if let Some(log) = callback {
        // SAFETY: the master passed this function to fmi3InstantiateCoSimulation (FMI 3.0
        // §2.3.1); both strings are NUL-terminated and outlive the call.
        unsafe { log(environment, status, category.as_ptr(), message.as_ptr()) };
    }
}
