//! The unsafe edge of the FMI layer: raw pointers to slices and strings (NULL-checked), the
//! instance guard with `catch_unwind`, and the shim that exports a C function of either version by
//! forwarding its arguments to the generic one ([`crate::forward_export!`]).
#![allow(unsafe_code)]

use std::ffi::{CStr, c_char, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};

use super::error::FmuError;
use super::instance::Instance;
use super::model::Model;
use super::state::Call;
use super::status::Status;

/// `n` values at `ptr` (any pointer when n = 0); NULL with n > 0 is an error naming `name`.
///
/// # Safety
/// A non-NULL `ptr` must point to `n` valid values for the duration of the call (FMI 2.0.4 §2.1.7).
pub unsafe fn slice<'a, T>(
    ptr: *const T,
    n: usize,
    name: &'static str,
) -> Result<&'a [T], FmuError> {
    if n == 0 {
        Ok(&[])
    } else if ptr.is_null() {
        Err(FmuError::Null(name))
    } else {
        // SAFETY: non-NULL and n values long per the caller's contract.
        Ok(unsafe { std::slice::from_raw_parts(ptr, n) })
    }
}

/// Mutable version of [`slice()`].
///
/// # Safety
/// A non-NULL `ptr` must point to `n` writable values for the duration of the call.
pub unsafe fn slice_mut<'a, T>(
    ptr: *mut T,
    n: usize,
    name: &'static str,
) -> Result<&'a mut [T], FmuError> {
    if n == 0 {
        Ok(&mut [])
    } else if ptr.is_null() {
        Err(FmuError::Null(name))
    } else {
        // SAFETY: non-NULL and n writable values per the caller's contract.
        Ok(unsafe { std::slice::from_raw_parts_mut(ptr, n) })
    }
}

/// A C string as `&str` (None for NULL; invalid UTF-8 is replaced).
///
/// # Safety
/// A non-NULL `ptr` must be NUL-terminated and valid for the duration of the call.
pub unsafe fn string(ptr: *const c_char) -> Option<String> {
    if ptr.is_null() {
        None
    } else {
        // SAFETY: NUL-terminated per the caller's contract (FMI 2.0.4 fmi2String).
        Some(
            unsafe { CStr::from_ptr(ptr) }
                .to_string_lossy()
                .into_owned(),
        )
    }
}

/// A panic payload as text.
pub fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

/// Runs `f` on the instance behind `c` (fmi2Component, fmi3Instance) if `call` is legal in its
/// state: errors are logged and move the instance to the Error state, a discarded step to
/// StepFailed, and a panic is caught, logged and poisons the instance (only Reset and
/// FreeInstance are accepted afterwards).
pub fn with_instance<M: Model>(
    c: *mut c_void,
    call: Call,
    f: impl FnOnce(&mut Instance<M>) -> Result<Status, FmuError>,
) -> Status {
    if c.is_null() {
        return Status::Error;
    }
    // SAFETY: a non-NULL instance pointer is one returned by fmi2Instantiate or
    // fmi3InstantiateCoSimulation (Box::into_raw, [`crate::calls::create`]) and not yet freed, and
    // the master calls one instance's functions one at a time (FMI 2.0.4 §2.1.5, FMI 3.0 §2.3).
    let instance = unsafe { &mut *c.cast::<Instance<M>>() };
    let version = instance.version();
    let name = || call.name(version);
    let result = catch_unwind(AssertUnwindSafe(|| {
        instance.machine().admit(call, version)?;
        let status = f(instance)?;
        instance.succeeded(call);
        Ok(status)
    }));
    let (logger, machine) = instance.logger_and_machine();
    match result {
        Ok(Ok(status)) => status,
        Ok(Err(e @ FmuError::Discard { .. })) => {
            let message = format!("{}: {e}", name());
            logger.discard(&message);
            machine.discarded(message);
            Status::Discard
        }
        Ok(Err(e)) => {
            let message = match e {
                FmuError::IllegalCall(_) => e.to_string(),
                _ => format!("{}: {e}", name()),
            };
            logger.error(&message);
            machine.failed(message);
            Status::Error
        }
        Err(payload) => {
            logger.error(&format!(
                "{}: internal error: {}",
                name(),
                panic_text(&*payload)
            ));
            machine.poison(format!("{}: internal error", name()));
            Status::Error
        }
    }
}

/// Exported functions of either version, each forwarding its C arguments, unchanged, to the
/// generic function of the same name over the model (`$crate::$version::exports::$name::<$model>`),
/// its signature pinned to the header's `$pinned`; for [`crate::export_fmi2!`] and
/// [`crate::export_fmi3!`].
#[doc(hidden)]
#[macro_export]
macro_rules! forward_export {
    ($version:ident, $model:ty;
     $($name:ident: $pinned:ident, ($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty;)*) => {$(
        #[doc = concat!(
            "See `fmi_export::", stringify!($version), "::exports::", stringify!($name), "`."
        )]
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name($($arg: $ty,)*) -> $ret {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::$version::exports::$name::<$model>($($arg,)*) }
        }
        const _: $crate::$version::exports::sys::$pinned = Some($name);
    )*};
}
