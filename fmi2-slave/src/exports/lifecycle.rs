//! Creating, setting up, initialising, terminating, resetting and freeing an instance.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use std::ffi::c_char;
use std::panic::{AssertUnwindSafe, catch_unwind};

use fmi_sys::fmi2::*;

use super::codes::{OK, ok};
use crate::error::FmuError;
use crate::ffi::{slice, string, with_instance};
use crate::logger::Logger;
use crate::model::{Instance, Model};
use crate::state::{Call, State, Version};

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
        let logger = Logger::new(
            callbacks.logger,
            callbacks.componentEnvironment,
            &name,
            loggingOn != 0,
            M::LOG_CATEGORIES,
        );
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
        create::<M>(logger, &name, &guid, resources, Version::Fmi2)
            .map_or(std::ptr::null_mut(), |instance| {
                Box::into_raw(instance).cast()
            })
    }));
    result.unwrap_or(std::ptr::null_mut())
}

/// A new instance of `M` named `name`, after checking the name and the GUID (FMI 3: the
/// instantiation token) against the model's; None, the reason logged, if either is wrong.
pub(crate) fn create<M: Model>(
    logger: Logger,
    name: &str,
    guid: &str,
    resources: Option<std::path::PathBuf>,
    version: Version,
) -> Option<Box<Instance<M>>> {
    let call = match version {
        Version::Fmi2 => "fmi2Instantiate",
        Version::Fmi3 => "fmi3InstantiateCoSimulation",
    };
    let token = match version {
        Version::Fmi2 => "GUID",
        Version::Fmi3 => "instantiationToken",
    };
    if name.is_empty() {
        logger.error(&format!("{call}: instanceName must not be NULL or empty."));
        return None;
    }
    let fmi3 = match version {
        Version::Fmi2 if guid == M::GUID => M::FMI3,
        Version::Fmi3 if guid == M::FMI3_TOKENS[0] => M::FMI3,
        Version::Fmi3 if guid == M::FMI3_TOKENS[1] => M::FMI3.scalar(),
        _ => {
            let expected = match version {
                Version::Fmi2 => M::GUID.to_string(),
                Version::Fmi3 if M::FMI3_TOKENS[0] == M::FMI3_TOKENS[1] => {
                    M::FMI3_TOKENS[0].to_string()
                }
                Version::Fmi3 => format!(
                    "{} (with arrays) or {} (without)",
                    M::FMI3_TOKENS[0],
                    M::FMI3_TOKENS[1]
                ),
            };
            logger.error(&format!(
                "{call}: Wrong {token}: expected {expected}, got \"{guid}\"."
            ));
            return None;
        }
    };
    logger.event(&format!(
        "{call}: instance \"{name}\" created (resources: {})",
        resources
            .as_ref()
            .map_or_else(|| "none".to_string(), |d| d.display().to_string())
    ));
    let mut instance = Instance::<M>::new(logger, resources);
    instance.version = version;
    instance.serve(fmi3);
    Some(Box::new(instance))
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
