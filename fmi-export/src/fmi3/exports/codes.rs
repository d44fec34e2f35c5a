//! FMI 3's side of the core: its status codes, its logger callback, and the instance guard
//! returning fmi3Status.
#![allow(unsafe_code)]

use std::ffi::CString;

use fmi_sys::fmi3::{
    fmi3Instance, fmi3InstanceEnvironment, fmi3LogMessageCallback, fmi3Status,
    fmi3Status_fmi3Discard, fmi3Status_fmi3Error, fmi3Status_fmi3Fatal, fmi3Status_fmi3OK,
    fmi3Status_fmi3Warning,
};

use crate::error::FmuError;
use crate::instance::Instance;
use crate::logger::LogSink;
use crate::model::Model;
use crate::state::Call;
use crate::status::Status;

/// The fmi3Status of a [`Status`].
pub(crate) fn fmi3(status: Status) -> fmi3Status {
    match status {
        Status::Ok => fmi3Status_fmi3OK,
        Status::Warning => fmi3Status_fmi3Warning,
        Status::Discard => fmi3Status_fmi3Discard,
        Status::Error => fmi3Status_fmi3Error,
        Status::Fatal => fmi3Status_fmi3Fatal,
    }
}

/// [`crate::ffi::with_instance`] for an fmi3Instance, returning fmi3Status.
pub(crate) fn with_instance<M: Model>(
    instance: fmi3Instance,
    call: Call,
    f: impl FnOnce(&mut Instance<M>) -> Result<Status, FmuError>,
) -> fmi3Status {
    fmi3(crate::ffi::with_instance(instance, call, f))
}

/// The master's fmi3LogMessageCallback with its instance environment.
#[derive(Debug)]
pub(crate) struct Fmi3Sink {
    pub callback: fmi3LogMessageCallback,
    pub environment: fmi3InstanceEnvironment,
}

impl LogSink for Fmi3Sink {
    /// Calls the logger with the message as it is (FMI 3 has no format string).
    fn emit(&self, status: Status, category: &str, message: &str) {
        let Some(log) = self.callback else { return };
        let category = CString::new(category).unwrap_or_default();
        let text = CString::new(message.replace('\0', "")).unwrap_or_default();
        // SAFETY: the master passed this function to fmi3InstantiateCoSimulation (FMI 3.0
        // §2.3.1); both strings are NUL-terminated and outlive the call. The environment is the
        // master's opaque value, passed back unchanged.
        unsafe {
            log(
                self.environment,
                fmi3(status),
                category.as_ptr(),
                text.as_ptr(),
            )
        };
    }
}
