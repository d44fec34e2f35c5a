//! A small master for the fuzz targets: safe wrappers around the FMU's exported `fmi2*`
//! functions, called in-process (the same functions the shared library exports), and the
//! variable table they pick value references and values from.
//!
//! The wrappers keep the master's side of the FMI contract — live pointers, buffers of the
//! stated length, no use of a freed instance or state — so that everything a run can provoke
//! is the FMU's own behaviour.

use std::ffi::{CString, c_char};
use std::ptr;

use flexible_slider_crank::fmi::GUID;
use flexible_slider_crank::fmi::fmi2_exports as fmi;
use flexible_slider_crank::variables::{ENUMERATIONS, Kind, VARIABLES};
use fmi_sys::fmi2::*;

/// Callbacks with fmi-sys's logger (forwarding to the `log` crate, which drops everything here).
fn callbacks() -> &'static fmi2CallbackFunctions {
    struct Shared(fmi2CallbackFunctions);
    // SAFETY: the callbacks hold function pointers and a null environment only.
    unsafe impl Sync for Shared {}
    static CALLBACKS: Shared = Shared(fmi2CallbackFunctions {
        logger: Some(fmi_sys::fmi2::logger::callback_logger_handler),
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: ptr::null_mut(),
    });
    &CALLBACKS.0
}

/// One instance of the FMU, freed on drop, with the FMU states it has handed out.
pub struct Instance {
    c: fmi2Component,
    states: Vec<fmi2FMUstate>,
}

impl Instance {
    /// fmi2Instantiate with logging on (so that every message is formatted), as a co-simulation
    /// slave or (refused) for model exchange, with the FMU's GUID or a wrong one; None if the FMU
    /// refuses.
    pub fn new(name: &str, guid_ok: bool, model_exchange: bool) -> Option<Self> {
        let name = CString::new(name).ok()?;
        let guid = CString::new(if guid_ok { GUID } else { "{not-this-fmu}" }).ok()?;
        let kind = if model_exchange {
            fmi2Type_fmi2ModelExchange
        } else {
            fmi2Type_fmi2CoSimulation
        };
        // SAFETY: live strings and callbacks for the duration of the call.
        let c = unsafe {
            fmi::fmi2Instantiate(
                name.as_ptr(),
                kind,
                guid.as_ptr(),
                c"file:///tmp".as_ptr(),
                callbacks(),
                0,
                1,
            )
        };
        (!c.is_null()).then(|| Self {
            c,
            states: Vec::new(),
        })
    }

    /// fmi2SetupExperiment.
    pub fn setup(&mut self, tolerance: Option<f64>, start: f64, stop: Option<f64>) -> fmi2Status {
        // SAFETY: a live instance.
        unsafe {
            fmi::fmi2SetupExperiment(
                self.c,
                i32::from(tolerance.is_some()),
                tolerance.unwrap_or(0.0),
                start,
                i32::from(stop.is_some()),
                stop.unwrap_or(0.0),
            )
        }
    }

    /// fmi2EnterInitializationMode.
    pub fn enter_initialization(&mut self) -> fmi2Status {
        // SAFETY: a live instance.
        unsafe { fmi::fmi2EnterInitializationMode(self.c) }
    }

    /// fmi2ExitInitializationMode.
    pub fn exit_initialization(&mut self) -> fmi2Status {
        // SAFETY: a live instance.
        unsafe { fmi::fmi2ExitInitializationMode(self.c) }
    }

    /// fmi2Terminate.
    pub fn terminate(&mut self) -> fmi2Status {
        // SAFETY: a live instance.
        unsafe { fmi::fmi2Terminate(self.c) }
    }

    /// fmi2Reset.
    pub fn reset(&mut self) -> fmi2Status {
        // SAFETY: a live instance.
        unsafe { fmi::fmi2Reset(self.c) }
    }

    /// fmi2DoStep.
    pub fn do_step(&mut self, t: f64, h: f64, no_set_prior: bool) -> fmi2Status {
        // SAFETY: a live instance.
        unsafe { fmi::fmi2DoStep(self.c, t, h, i32::from(no_set_prior)) }
    }

    /// fmi2CancelStep.
    pub fn cancel_step(&mut self) -> fmi2Status {
        // SAFETY: a live instance.
        unsafe { fmi::fmi2CancelStep(self.c) }
    }

    /// fmi2SetReal of one value.
    pub fn set_real(&mut self, vr: u32, value: f64) -> fmi2Status {
        // SAFETY: one value reference and one value.
        unsafe { fmi::fmi2SetReal(self.c, &vr, 1, &value) }
    }

    /// fmi2SetInteger of one value.
    pub fn set_integer(&mut self, vr: u32, value: i32) -> fmi2Status {
        // SAFETY: one value reference and one value.
        unsafe { fmi::fmi2SetInteger(self.c, &vr, 1, &value) }
    }

    /// fmi2SetBoolean of one value.
    pub fn set_boolean(&mut self, vr: u32, value: i32) -> fmi2Status {
        // SAFETY: one value reference and one value.
        unsafe { fmi::fmi2SetBoolean(self.c, &vr, 1, &value) }
    }

    /// fmi2SetString of one value (a string with an interior NUL is not sent).
    pub fn set_string(&mut self, vr: u32, value: &str) -> fmi2Status {
        let Ok(value) = CString::new(value) else {
            return fmi2Status_fmi2OK;
        };
        let p: *const c_char = value.as_ptr();
        // SAFETY: one value reference and one live string.
        unsafe { fmi::fmi2SetString(self.c, &vr, 1, &p) }
    }

    /// fmi2GetReal, fmi2GetInteger, fmi2GetBoolean and fmi2GetString of the given value
    /// references (each call with all of them, so most calls mix valid and invalid ones).
    pub fn get_all(&mut self, vrs: &[u32]) {
        let n = vrs.len();
        let (mut r, mut i, mut b) = (vec![0.0; n], vec![0; n], vec![0; n]);
        let mut s: Vec<fmi2String> = vec![ptr::null(); n];
        // SAFETY: buffers of n elements each.
        unsafe {
            fmi::fmi2GetReal(self.c, vrs.as_ptr(), n, r.as_mut_ptr());
            fmi::fmi2GetInteger(self.c, vrs.as_ptr(), n, i.as_mut_ptr());
            fmi::fmi2GetBoolean(self.c, vrs.as_ptr(), n, b.as_mut_ptr());
            fmi::fmi2GetString(self.c, vrs.as_ptr(), n, s.as_mut_ptr());
        }
    }

    /// Every status query, for every status kind and one beyond.
    pub fn statuses(&mut self) {
        let (mut s, mut r, mut i, mut b) = (0, 0.0, 0, 0);
        let mut text: fmi2String = ptr::null();
        for kind in 0..5 {
            // SAFETY: one output value each.
            unsafe {
                fmi::fmi2GetStatus(self.c, kind, &mut s);
                fmi::fmi2GetRealStatus(self.c, kind, &mut r);
                fmi::fmi2GetIntegerStatus(self.c, kind, &mut i);
                fmi::fmi2GetBooleanStatus(self.c, kind, &mut b);
                fmi::fmi2GetStringStatus(self.c, kind, &mut text);
            }
        }
    }

    /// The time the last fmi2DoStep reached (fmi2GetRealStatus, fmi2LastSuccessfulTime).
    pub fn time(&mut self) -> Option<f64> {
        let mut t = 0.0;
        // SAFETY: one output value.
        let status = unsafe {
            fmi::fmi2GetRealStatus(self.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t)
        };
        (status == fmi2Status_fmi2OK).then_some(t)
    }

    /// fmi2SetRealInputDerivatives of one input.
    pub fn set_input_derivative(&mut self, vr: u32, order: i32, value: f64) -> fmi2Status {
        // SAFETY: one value reference, order and value.
        unsafe { fmi::fmi2SetRealInputDerivatives(self.c, &vr, 1, &order, &value) }
    }

    /// fmi2GetRealOutputDerivatives of one output.
    pub fn get_output_derivative(&mut self, vr: u32, order: i32) -> fmi2Status {
        let mut value = 0.0;
        // SAFETY: one value reference, order and output value.
        unsafe { fmi::fmi2GetRealOutputDerivatives(self.c, &vr, 1, &order, &mut value) }
    }

    /// fmi2GetDirectionalDerivative of one unknown with respect to one known.
    pub fn directional_derivative(&mut self, unknown: u32, known: u32) -> fmi2Status {
        let (seed, mut value) = (1.0, 0.0);
        // SAFETY: one reference each, one seed and one output value.
        unsafe {
            fmi::fmi2GetDirectionalDerivative(self.c, &unknown, 1, &known, 1, &seed, &mut value)
        }
    }

    /// fmi2GetFMUstate into a new slot, or into slot `reuse` (which the FMU then overwrites).
    pub fn get_state(&mut self, reuse: Option<usize>) -> fmi2Status {
        match reuse.filter(|&k| k < self.states.len()) {
            Some(k) => {
                // SAFETY: a state this instance handed out and has not freed.
                unsafe { fmi::fmi2GetFMUstate(self.c, &mut self.states[k]) }
            }
            None => {
                let mut s: fmi2FMUstate = ptr::null_mut();
                // SAFETY: a fresh output pointer.
                let status = unsafe { fmi::fmi2GetFMUstate(self.c, &mut s) };
                if !s.is_null() {
                    self.states.push(s);
                }
                status
            }
        }
    }

    /// fmi2SetFMUstate from slot k, if it exists.
    pub fn set_state(&mut self, k: usize) -> fmi2Status {
        match self.states.get(k) {
            // SAFETY: a state this instance handed out and has not freed.
            Some(&s) => unsafe { fmi::fmi2SetFMUstate(self.c, s) },
            None => fmi2Status_fmi2OK,
        }
    }

    /// fmi2FreeFMUstate of slot k, if it exists.
    pub fn free_state(&mut self, k: usize) -> fmi2Status {
        if k >= self.states.len() {
            return fmi2Status_fmi2OK;
        }
        let mut s = self.states.swap_remove(k);
        // SAFETY: a state this instance handed out, freed once.
        unsafe { fmi::fmi2FreeFMUstate(self.c, &mut s) }
    }

    /// fmi2SerializedFMUstateSize and fmi2SerializeFMUstate of slot k: the bytes, if both succeed.
    pub fn serialize(&mut self, k: usize) -> Option<Vec<u8>> {
        let &s = self.states.get(k)?;
        let mut size = 0;
        // SAFETY: a live state and one output value.
        if unsafe { fmi::fmi2SerializedFMUstateSize(self.c, s, &mut size) } != fmi2Status_fmi2OK {
            return None;
        }
        let mut bytes = vec![0u8; size];
        // SAFETY: a buffer of the size the FMU asked for.
        let status =
            unsafe { fmi::fmi2SerializeFMUstate(self.c, s, bytes.as_mut_ptr().cast(), size) };
        (status == fmi2Status_fmi2OK).then_some(bytes)
    }

    /// fmi2DeSerializeFMUstate of `bytes` into a new slot.
    pub fn deserialize(&mut self, bytes: &[u8]) -> fmi2Status {
        let mut s: fmi2FMUstate = ptr::null_mut();
        // SAFETY: bytes.len() bytes and a fresh output pointer.
        let status = unsafe {
            fmi::fmi2DeSerializeFMUstate(self.c, bytes.as_ptr().cast(), bytes.len(), &mut s)
        };
        if !s.is_null() {
            self.states.push(s);
        }
        status
    }

    /// Number of FMU states this instance holds.
    pub fn state_count(&self) -> usize {
        self.states.len()
    }
}

impl Drop for Instance {
    fn drop(&mut self) {
        for k in (0..self.states.len()).rev() {
            self.free_state(k);
        }
        // SAFETY: a live instance, freed once.
        unsafe { fmi::fmi2FreeInstance(self.c) }
    }
}

/// Number of value references in the table.
pub fn variable_count() -> u32 {
    VARIABLES.len() as u32
}

/// A value for the variable at `vr` chosen by `pick`: its start, its bounds, just beyond them,
/// zero, non-finite values, a value inside its range, or `raw` itself.
pub fn value_for(vr: u32, pick: u8, raw: f64) -> f64 {
    let (start, min, max) = match VARIABLES.get(vr as usize).map(|v| v.kind) {
        Some(Kind::Real {
            start, min, max, ..
        }) => (start.unwrap_or(0.0), min, max),
        Some(Kind::Integer { start, min, max }) => (
            f64::from(start.unwrap_or(0)),
            f64::from(min),
            f64::from(max),
        ),
        Some(Kind::Enumeration { start, type_index }) => {
            let items = ENUMERATIONS.get(type_index).map_or(1, |e| e.items.len());
            (f64::from(start), 1.0, items as f64)
        }
        _ => (0.0, 0.0, 1.0),
    };
    match pick % 10 {
        0 => start,
        1 => min,
        2 => max,
        3 => min.next_down(),
        4 => max.next_up(),
        5 => 0.0,
        6 => f64::NAN,
        7 => f64::INFINITY,
        8 => min + (max - min).min(1e6) * raw.abs().fract(),
        _ => raw,
    }
}
