//! Creating, setting up, initialising, terminating, resetting and freeing an instance.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use std::ffi::{CString, c_char};
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi2::*;

use super::codes::{Fmi2Sink, with_instance};
use crate::calls;
use crate::ffi::{slice, string};
use crate::logger::Logger;
use crate::model::Model;
use crate::state::{Call, Version};
use crate::status::{Status, ok};

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
    fmuResourceLocation: fmi2String,
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
        let sink = Fmi2Sink {
            callback: callbacks.logger,
            environment: callbacks.componentEnvironment,
            instance_name: CString::new(name.replace('\0', "")).unwrap_or_default(),
        };
        let logger = Logger::new(Box::new(sink), loggingOn != 0, M::LOG_CATEGORIES);
        if fmuType != fmi2Type_fmi2CoSimulation {
            logger.error(&format!(
                "fmi2Instantiate: fmuType = {fmuType}: this FMU supports co-simulation (fmi2CoSimulation = 1) only."
            ));
            return std::ptr::null_mut();
        }
        // SAFETY: as above.
        let guid = unsafe { string(fmuGUID) }.unwrap_or_default();
        // SAFETY: as above (NULL allowed: no resources).
        let location = unsafe { string(fmuResourceLocation) }.unwrap_or_default();
        let resources = directory_of_uri(&location).filter(|d| d.is_dir());
        calls::create::<M>(logger, &name, &guid, resources, Version::Fmi2)
            .map_or(std::ptr::null_mut(), |instance| {
                Box::into_raw(instance).cast()
            })
    }));
    result.unwrap_or(std::ptr::null_mut())
}

/// Frees an instance (NULL is a no-op); legal in every state.
pub unsafe fn fmi2FreeInstance<M: Model>(c: fmi2Component) {
    // SAFETY: c is NULL or came from fmi2Instantiate and is freed once (FMI 2.0.4 §2.1.5: no
    // call on c after fmi2FreeInstance).
    unsafe { calls::free_instance::<M>(c) }
}

/// Switches debug logging and its categories (FMI 2.0.4 §2.1.5).
pub unsafe fn fmi2SetDebugLogging<M: Model>(
    c: fmi2Component,
    loggingOn: fmi2Boolean,
    nCategories: usize,
    categories: *const fmi2String,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetDebugLogging, |inst| {
        // SAFETY: nCategories NUL-terminated strings per FMI 2.0.4 §2.1.5.
        unsafe {
            let pointers = slice(categories, nCategories, "categories")?;
            calls::set_debug_logging(inst, loggingOn != 0, pointers)
        }
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
        let experiment = (
            (toleranceDefined != 0).then_some(tolerance),
            startTime,
            (stopTimeDefined != 0).then_some(stopTime),
        );
        inst.setup_experiment(experiment).map(ok)
    })
}

/// Enters initialization mode.
pub unsafe fn fmi2EnterInitializationMode<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::EnterInitializationMode, |_| Ok(Status::Ok))
}

/// Builds the model from the parameters; outputs are valid afterwards.
pub unsafe fn fmi2ExitInitializationMode<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::ExitInitializationMode, |inst| {
        inst.exit_initialization().map(ok)
    })
}

/// Ends the simulation; outputs stay readable.
pub unsafe fn fmi2Terminate<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::Terminate, calls::terminate)
}

/// Back to Instantiated with every start value.
pub unsafe fn fmi2Reset<M: Model>(c: fmi2Component) -> fmi2Status {
    with_instance::<M>(c, Call::Reset, calls::reset)
}

/// The directory a `file:` URI names (fmi2Instantiate's fmuResourceLocation): `file:///a/b`,
/// `file:/a/b` or `file://localhost/a/b`, percent-escapes decoded; `None` for another scheme or
/// host, or an undecodable escape.
fn directory_of_uri(uri: &str) -> Option<std::path::PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let path = match rest.strip_prefix("//") {
        Some(authority) => {
            let slash = authority.find('/')?;
            let host = &authority[..slash];
            if !(host.is_empty() || host.eq_ignore_ascii_case("localhost")) {
                return None;
            }
            &authority[slash..]
        }
        None => rest,
    };
    let mut bytes = Vec::with_capacity(path.len());
    let mut chars = path.bytes();
    while let Some(b) = chars.next() {
        if b == b'%' {
            let hex = [chars.next()?, chars.next()?];
            let hex = std::str::from_utf8(&hex).ok()?;
            bytes.push(u8::from_str_radix(hex, 16).ok()?);
        } else {
            bytes.push(b);
        }
    }
    let path = String::from_utf8(bytes).ok()?;
    // A Windows drive letter follows the slash: file:///C:/dir.
    let path = match path.as_bytes() {
        [b'/', _, b':', ..] => &path[1..],
        _ => &path,
    };
    Some(std::path::PathBuf::from(path))
}

#[cfg(test)]
mod tests {
    use super::directory_of_uri;
    use std::path::PathBuf;

    /// The spellings of a local `file:` URI give its path, escapes decoded and a Windows drive
    /// letter kept; another host, another scheme or a broken escape give none.
    #[test]
    fn file_uris_name_their_directory() {
        let path = |s: &str| Some(PathBuf::from(s));
        assert_eq!(
            directory_of_uri("file:///tmp/fmu/resources"),
            path("/tmp/fmu/resources")
        );
        assert_eq!(directory_of_uri("file:/tmp/a%20b"), path("/tmp/a b"));
        assert_eq!(directory_of_uri("file://localhost/tmp/r/"), path("/tmp/r/"));
        assert_eq!(
            directory_of_uri("file:///C:/Temp/fmu%25x"),
            path("C:/Temp/fmu%x")
        );
        assert_eq!(directory_of_uri("file://server/share"), None);
        assert_eq!(directory_of_uri("http://localhost/tmp"), None);
        assert_eq!(directory_of_uri("file:///tmp/%2"), None);
        assert_eq!(directory_of_uri("file:///tmp/%zz"), None);
    }
}
