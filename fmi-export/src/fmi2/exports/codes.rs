//! FMI 2's side of the core: its status codes, its logger callback, and the instance guard
//! returning fmi2Status.
#![allow(unsafe_code)]

use std::ffi::CString;

use fmi_sys::fmi2::{
    fmi2CallbackLogger, fmi2Component, fmi2ComponentEnvironment, fmi2Status,
    fmi2Status_fmi2Discard, fmi2Status_fmi2Error, fmi2Status_fmi2Fatal, fmi2Status_fmi2OK,
    fmi2Status_fmi2Warning,
};

use crate::error::FmuError;
use crate::instance::Instance;
use crate::logger::LogSink;
use crate::model::Model;
use crate::state::Call;
use crate::status::Status;

/// The fmi2Status of a [`Status`].
pub(crate) fn fmi2(status: Status) -> fmi2Status {
    match status {
        Status::Ok => fmi2Status_fmi2OK,
        Status::Warning => fmi2Status_fmi2Warning,
        Status::Discard => fmi2Status_fmi2Discard,
        Status::Error => fmi2Status_fmi2Error,
        Status::Fatal => fmi2Status_fmi2Fatal,
    }
}

/// [`crate::ffi::with_instance`] for an fmi2Component, returning fmi2Status.
pub(crate) fn with_instance<M: Model>(
    c: fmi2Component,
    call: Call,
    f: impl FnOnce(&mut Instance<M>) -> Result<Status, FmuError>,
) -> fmi2Status {
    fmi2(crate::ffi::with_instance(c, call, f))
}

/// The master's fmi2CallbackLogger with its environment and the instance's name.
#[derive(Debug)]
pub(crate) struct Fmi2Sink {
    pub callback: fmi2CallbackLogger,
    pub environment: fmi2ComponentEnvironment,
    pub instance_name: CString,
}

impl LogSink for Fmi2Sink {
    /// Calls the logger with `"%s"` as the format, so the text is never interpreted, and with
    /// `#` doubled: `#r12#` is FMI 2's value-reference macro (FMI 2.0.4 §2.1.5).
    fn emit(&self, status: Status, category: &str, message: &str) {
        let Some(log) = self.callback else { return };
        let category = CString::new(category).unwrap_or_default();
        let text = CString::new(message.replace('#', "##").replace('\0', "")).unwrap_or_default();
        // SAFETY: the master passed this function in fmi2CallbackFunctions (FMI 2.0.4 §2.1.5) with
        // the printf-style signature; every string is NUL-terminated and outlives the call, and
        // "%s" consumes exactly the one variadic argument given. The environment is the master's
        // opaque value, passed back unchanged.
        unsafe {
            log(
                self.environment,
                self.instance_name.as_ptr(),
                fmi2(status),
                category.as_ptr(),
                c"%s".as_ptr(),
                text.as_ptr(),
            );
        }
    }
}
