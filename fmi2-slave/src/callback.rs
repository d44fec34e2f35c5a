//! The one call into the master's variadic logger callback (unsafe: a C function pointer).
#![allow(unsafe_code)]

use std::ffi::CStr;

use fmi_sys::fmi2::{fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status};

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
