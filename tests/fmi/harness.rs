//! Loads the library (the development build's, which `cargo test` builds anyway) once, captures
//! the FMU's log messages by instance name, and wraps the raw calls in small safe methods.

use std::collections::HashMap;
use std::ffi::CString;
use std::path::PathBuf;
use std::sync::{Mutex, OnceLock};

use flexible_slider_crank::fmi::GUID;
use fmi_export::table::{Kind, Variable};
use fmi_sys::fmi2::*;

/// Path of the development library `lib<name>.so`, built on demand.
fn library_of(name: &str) -> PathBuf {
    crate::development_build::build().join(format!("lib{name}.so"))
}

/// Path of the slider-crank's library.
pub fn library_path() -> PathBuf {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    PATH.get_or_init(|| library_of("flexible_slider_crank"))
        .clone()
}

/// The slider-crank's loaded library (one per test process).
pub fn fmu() -> &'static Fmi2Binding {
    static FMU: OnceLock<Fmi2Binding> = OnceLock::new();
    FMU.get_or_init(|| {
        init_logging();
        // SAFETY: loading our own FMU library; its initialisers do nothing.
        unsafe { Fmi2Binding::new(library_path()) }.unwrap()
    })
}

/// The DC motor's loaded library (one per test process).
pub fn motor() -> &'static Fmi2Binding {
    static MOTOR: OnceLock<Fmi2Binding> = OnceLock::new();
    MOTOR.get_or_init(|| {
        init_logging();
        // SAFETY: loading our own FMU library; its initialisers do nothing.
        unsafe { Fmi2Binding::new(library_of("dc_motor")) }.unwrap()
    })
}

/// The lubrication circuit's loaded library (one per test process).
pub fn circuit() -> &'static Fmi2Binding {
    static CIRCUIT: OnceLock<Fmi2Binding> = OnceLock::new();
    CIRCUIT.get_or_init(|| {
        init_logging();
        // SAFETY: loading our own FMU library; its initialisers do nothing.
        unsafe { Fmi2Binding::new(library_of("lube_circuit")) }.unwrap()
    })
}

/// Messages received per instance name.
static MESSAGES: OnceLock<Mutex<HashMap<String, Vec<String>>>> = OnceLock::new();

struct Collect;

impl log::Log for Collect {
    fn enabled(&self, _: &log::Metadata<'_>) -> bool {
        true
    }
    fn log(&self, record: &log::Record<'_>) {
        let map = MESSAGES.get_or_init(Default::default);
        map.lock()
            .unwrap()
            .entry(record.target().to_string())
            .or_default()
            .push(record.args().to_string());
    }
    fn flush(&self) {}
}

fn init_logging() {
    static LOGGER: Collect = Collect;
    let _ = log::set_logger(&LOGGER);
    log::set_max_level(log::LevelFilter::Trace);
}

/// Messages logged so far by the instance called `name`.
pub fn messages(name: &str) -> Vec<String> {
    MESSAGES
        .get_or_init(Default::default)
        .lock()
        .unwrap()
        .get(name)
        .cloned()
        .unwrap_or_default()
}

/// Callbacks whose logger forwards to the `log` crate (fmi-sys's C shim).
pub fn callbacks() -> fmi2CallbackFunctions {
    fmi2CallbackFunctions {
        logger: Some(fmi_sys::fmi2::logger::callback_logger_handler),
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: std::ptr::null_mut(),
    }
}

/// Raw fmi2Instantiate with every argument given (debug logging on).
pub fn instantiate_raw(
    name: Option<&str>,
    kind: fmi2Type,
    guid: Option<&str>,
    resources: Option<&str>,
    callbacks: Option<&fmi2CallbackFunctions>,
) -> fmi2Component {
    instantiate_with_logging(name, kind, guid, resources, callbacks, true)
}

/// Raw fmi2Instantiate with the loggingOn switch given.
pub fn instantiate_with_logging(
    name: Option<&str>,
    kind: fmi2Type,
    guid: Option<&str>,
    resources: Option<&str>,
    callbacks: Option<&fmi2CallbackFunctions>,
    logging_on: bool,
) -> fmi2Component {
    let name = name.map(|s| CString::new(s).unwrap());
    let guid = guid.map(|s| CString::new(s).unwrap());
    let resources = resources.map(|s| CString::new(s).unwrap());
    let ptr = |s: &Option<CString>| s.as_ref().map_or(std::ptr::null(), |s| s.as_ptr());
    // SAFETY: valid NUL-terminated strings or NULL, and a callbacks struct that outlives the call.
    unsafe {
        fmu().fmi2Instantiate(
            ptr(&name),
            kind,
            ptr(&guid),
            ptr(&resources),
            callbacks.map_or(std::ptr::null(), |c| c as *const _),
            0,
            i32::from(logging_on),
        )
    }
}

/// A live instance, freed on drop.
pub struct Instance {
    pub c: fmi2Component,
    pub name: String,
    /// The library the instance comes from.
    lib: &'static Fmi2Binding,
}

// SAFETY: an FMU instance may be used from any thread, one call at a time (docs/fmi.md §1.4).
unsafe impl Send for Instance {}

impl Drop for Instance {
    fn drop(&mut self) {
        // SAFETY: c is live and freed once.
        unsafe { self.lib.fmi2FreeInstance(self.c) };
    }
}

impl Instance {
    /// A co-simulation instance with the correct GUID.
    pub fn new(name: &str) -> Self {
        Self::with_resources(name, None)
    }

    /// A co-simulation instance with the correct GUID and the resource location `resources`.
    pub fn with_resources(name: &str, resources: Option<&str>) -> Self {
        let c = instantiate_raw(
            Some(name),
            fmi2Type_fmi2CoSimulation,
            Some(GUID),
            resources,
            Some(&callbacks()),
        );
        assert!(!c.is_null(), "instantiation failed: {:?}", messages(name));
        Self::adopt(c, name)
    }

    /// The slider-crank instance `c`, instantiated as `name`, freed on drop.
    pub fn adopt(c: fmi2Component, name: &str) -> Self {
        Self {
            c,
            name: name.to_string(),
            lib: fmu(),
        }
    }

    /// A co-simulation instance of the DC motor.
    pub fn motor(name: &str) -> Self {
        Self::companion(motor(), dc_motor::GUID, name)
    }

    /// A co-simulation instance of the lubrication circuit.
    pub fn circuit(name: &str) -> Self {
        Self::companion(circuit(), lube_circuit::GUID, name)
    }

    /// A co-simulation instance `name` of the library `lib` whose GUID is `guid`.
    fn companion(lib: &'static Fmi2Binding, guid: &str, name: &str) -> Self {
        let name_c = CString::new(name).unwrap();
        let guid = CString::new(guid).unwrap();
        // SAFETY: NUL-terminated strings and a callbacks struct that outlive the call.
        let c = unsafe {
            lib.fmi2Instantiate(
                name_c.as_ptr(),
                fmi2Type_fmi2CoSimulation,
                guid.as_ptr(),
                std::ptr::null(),
                &callbacks(),
                0,
                1,
            )
        };
        assert!(!c.is_null(), "instantiation failed: {:?}", messages(name));
        Self {
            c,
            name: name.to_string(),
            lib,
        }
    }

    /// Messages logged by this instance.
    pub fn messages(&self) -> Vec<String> {
        messages(&self.name)
    }

    /// The last message, or "".
    pub fn last_message(&self) -> String {
        self.messages().pop().unwrap_or_default()
    }

    pub fn setup(&self, start: f64, stop: Option<f64>) -> fmi2Status {
        // SAFETY: live instance.
        unsafe {
            self.lib.fmi2SetupExperiment(
                self.c,
                0,
                0.0,
                start,
                i32::from(stop.is_some()),
                stop.unwrap_or(0.0),
            )
        }
    }
    pub fn enter(&self) -> fmi2Status {
        // SAFETY: live instance.
        unsafe { self.lib.fmi2EnterInitializationMode(self.c) }
    }
    pub fn exit(&self) -> fmi2Status {
        // SAFETY: live instance.
        unsafe { self.lib.fmi2ExitInitializationMode(self.c) }
    }
    /// Setup, enter and exit initialization: ready to step.
    pub fn initialize(&self) {
        assert_eq!(self.setup(0.0, None), fmi2Status_fmi2OK);
        assert_eq!(self.enter(), fmi2Status_fmi2OK);
        assert_eq!(self.exit(), fmi2Status_fmi2OK, "{:?}", self.messages());
    }
    pub fn do_step(&self, t: f64, h: f64) -> fmi2Status {
        // SAFETY: live instance.
        unsafe { self.lib.fmi2DoStep(self.c, t, h, 1) }
    }
    pub fn terminate(&self) -> fmi2Status {
        // SAFETY: live instance.
        unsafe { self.lib.fmi2Terminate(self.c) }
    }
    pub fn reset(&self) -> fmi2Status {
        // SAFETY: live instance.
        unsafe { self.lib.fmi2Reset(self.c) }
    }
    pub fn set_real(&self, vr: u32, value: f64) -> fmi2Status {
        // SAFETY: one value reference and one value.
        unsafe { self.lib.fmi2SetReal(self.c, &vr, 1, &value) }
    }
    pub fn set_integer(&self, vr: u32, value: i32) -> fmi2Status {
        // SAFETY: one value reference and one value.
        unsafe { self.lib.fmi2SetInteger(self.c, &vr, 1, &value) }
    }
    pub fn set_string(&self, vr: u32, value: &str) -> fmi2Status {
        let value = CString::new(value).unwrap();
        let pointer = value.as_ptr();
        // SAFETY: one value reference and one NUL-terminated string.
        unsafe { self.lib.fmi2SetString(self.c, &vr, 1, &pointer) }
    }
    /// fmi2GetString of one variable; the text copied before the next call.
    pub fn get_string(&self, vr: u32) -> (fmi2Status, Option<String>) {
        let mut value: fmi2String = std::ptr::null();
        // SAFETY: one value reference and one writable string pointer.
        let status = unsafe { self.lib.fmi2GetString(self.c, &vr, 1, &mut value) };
        let text = (!value.is_null()).then(|| {
            // SAFETY: not NULL: a NUL-terminated string the FMU keeps until the next call.
            let text = unsafe { std::ffi::CStr::from_ptr(value) };
            text.to_string_lossy().into_owned()
        });
        (status, text)
    }
    pub fn get_real(&self, vr: u32) -> (fmi2Status, f64) {
        let mut value = f64::NAN;
        // SAFETY: one value reference and one writable value.
        let status = unsafe { self.lib.fmi2GetReal(self.c, &vr, 1, &mut value) };
        (status, value)
    }
    pub fn get_reals(&self, vrs: &[u32]) -> Vec<f64> {
        let mut values = vec![f64::NAN; vrs.len()];
        // SAFETY: vrs.len() references and writable values.
        let status = unsafe {
            self.lib
                .fmi2GetReal(self.c, vrs.as_ptr(), vrs.len(), values.as_mut_ptr())
        };
        assert_eq!(status, fmi2Status_fmi2OK, "{:?}", self.messages());
        values
    }
    pub fn get_integer(&self, vr: u32) -> (fmi2Status, i32) {
        let mut value = -1;
        // SAFETY: one value reference and one writable value.
        let status = unsafe { self.lib.fmi2GetInteger(self.c, &vr, 1, &mut value) };
        (status, value)
    }
    /// fmi2GetFMUstate into a new state.
    pub fn get_state(&self) -> fmi2FMUstate {
        let mut state: fmi2FMUstate = std::ptr::null_mut();
        // SAFETY: writable state pointer.
        let status = unsafe { self.lib.fmi2GetFMUstate(self.c, &mut state) };
        assert_eq!(status, fmi2Status_fmi2OK);
        state
    }
    pub fn set_state(&self, state: fmi2FMUstate) -> fmi2Status {
        // SAFETY: a state of this FMU.
        unsafe { self.lib.fmi2SetFMUstate(self.c, state) }
    }
    pub fn free_state(&self, mut state: fmi2FMUstate) {
        // SAFETY: a state of this FMU, freed once.
        let status = unsafe { self.lib.fmi2FreeFMUstate(self.c, &mut state) };
        assert_eq!(status, fmi2Status_fmi2OK);
        assert!(state.is_null());
    }
    pub fn serialize(&self, state: fmi2FMUstate) -> Vec<u8> {
        let mut size = 0usize;
        // SAFETY: a state of this FMU; writable size.
        let status = unsafe {
            self.lib
                .fmi2SerializedFMUstateSize(self.c, state, &mut size)
        };
        assert_eq!(status, fmi2Status_fmi2OK);
        let mut bytes = vec![0u8; size];
        // SAFETY: `size` writable bytes.
        let status = unsafe {
            self.lib
                .fmi2SerializeFMUstate(self.c, state, bytes.as_mut_ptr().cast(), size)
        };
        assert_eq!(status, fmi2Status_fmi2OK);
        bytes
    }
    pub fn deserialize(&self, bytes: &[u8]) -> (fmi2Status, fmi2FMUstate) {
        let mut state: fmi2FMUstate = std::ptr::null_mut();
        // SAFETY: `bytes.len()` readable bytes; writable state pointer.
        let status = unsafe {
            self.lib
                .fmi2DeSerializeFMUstate(self.c, bytes.as_ptr().cast(), bytes.len(), &mut state)
        };
        (status, state)
    }
}

/// The start value of the Real variable `name` of a variable table.
pub fn real_start<V>(table: &[Variable<V>], name: &str) -> f64 {
    match table.iter().find(|v| v.name == name).map(|v| &v.kind) {
        Some(Kind::Real { start: Some(s), .. }) => *s,
        _ => panic!("no Real {name} with a start value"),
    }
}

/// Value reference of a variable by name.
pub fn vr(name: &str) -> u32 {
    flexible_slider_crank::variables::VARIABLES
        .iter()
        .find(|v| v.name == name)
        .map(|v| v.vr as u32)
        .unwrap_or_else(|| panic!("no variable {name}"))
}
