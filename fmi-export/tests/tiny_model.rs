//! The layer without the mechanism: a first-order lag ẏ = (u − y)/τ, solved exactly, whose output
//! crossing a threshold upwards is an event, exported through both FMI versions by the layer's own
//! macros and driven through their C functions. It checks what the layer promises every model:
//! the state machine and the checks before the model is called, the outcome of a step (FMI 3's
//! early return at the event, on the clock grid), the time variable, and messages in each
//! version's names.
#![allow(unsafe_code, missing_docs)]
// A test's helpers may panic; the lag runs on one platform here, so std's ln and exp serve.
#![allow(clippy::unwrap_used, clippy::disallowed_methods)]

use std::ffi::{CStr, CString, c_char};
use std::sync::Mutex;

use fmi_export::clock::{CLOCK_RESOLUTION, on_clock_grid};
use fmi_export::codec::{ByteReader, ByteWriter};
use fmi_export::fmi3::description::TIME_VALUE_REFERENCE;
use fmi_export::fmi3::interface::{ArrayVariable, Fmi3Interface, StructuralParameter};
use fmi_export::model::{Context, Var};
use fmi_export::table::{Causality, ValueReference, Variable};
use fmi_export::{FmuError, Model, State, Step, StepOutcome};
use fmi_sys::fmi2::{fmi2CallbackFunctions, fmi2Type_fmi2CoSimulation};
use fmi_sys::fmi3::{fmi3InstanceEnvironment, fmi3Status, fmi3String};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Vr {
    Tau,
    Threshold,
    U,
    Y,
    Crossings,
}

impl ValueReference for Vr {
    fn index(self) -> u32 {
        self as u32
    }
}

const VARIABLES: &[Variable<Vr>] = &[
    Variable::parameter(Vr::Tau, "lag.tau", 0.2, 1e-3, 10.0, "s", "time constant"),
    Variable::parameter(
        Vr::Threshold,
        "lag.threshold",
        0.5,
        -10.0,
        10.0,
        "1",
        "event level",
    ),
    Variable::input(Vr::U, "lag.u", 1.0, -10.0, 10.0, "1", "input"),
    Variable::output(Vr::Y, "lag.y", "1", "output"),
    Variable::count(
        Vr::Crossings,
        "lag.crossings",
        "upward crossings of the threshold",
    ),
];

/// FMI 3: the powers y, y², …, yⁿ of the output as an array, n a structural parameter.
const POWERS: u32 = TIME_VALUE_REFERENCE + 2;
const N_POWERS: u32 = TIME_VALUE_REFERENCE + 1;
const FMI3: Fmi3Interface = Fmi3Interface {
    might_return_early: true,
    has_event_mode: true,
    provides_intermediate_update: false,
    can_return_early_after_intermediate_update: false,
    structural_parameters: &[StructuralParameter {
        vr: N_POWERS,
        name: "lag.nPowers",
        description: "number of powers",
        start: 2,
        min: 1,
        max: 4,
    }],
    arrays: &[ArrayVariable {
        vr: POWERS,
        name: "lag.powers",
        description: "y, y², …",
        causality: Causality::Output,
        unit: "1",
        dimension: 0,
    }],
    terminals: &[],
    input_derivatives: true,
};

/// What the instance holds for the lag: its input u among them.
type Cx<'a> = Context<'a, [f64; 1]>;

/// The lag's state; y(0) = 0.
#[derive(Debug, Default)]
struct Lag {
    tau: f64,
    threshold: f64,
    y: f64,
    crossings: i32,
    /// Whether the output has crossed the threshold (it then stays above: ẏ > 0 for u = 1).
    above: bool,
}

impl Model for Lag {
    const GUID: &'static str = "{tiny-lag}";
    const FMI3_TOKENS: [&'static str; 2] = ["{tiny-lag-3}", "{tiny-lag-3}"];
    const LOG_CATEGORIES: &'static [(&'static str, &'static str)] =
        &[("logEvents", "events"), ("logStatusError", "errors")];
    const STATE_MAGIC: [u8; 4] = *b"TLAG";
    const STATE_VERSION: u32 = 1;
    type Vr = Vr;
    type Inputs = [f64; 1];
    const VARIABLES: &'static [Variable<Vr>] = VARIABLES;
    const FMI3: Fmi3Interface = FMI3;

    fn new() -> Self {
        Self {
            tau: 0.2,
            threshold: 0.5,
            ..Self::default()
        }
    }

    fn exit_initialization(&mut self, _cx: &Cx) -> Result<(), FmuError> {
        Ok(())
    }

    /// y(t + h) = u + (y − u) e^(−h/τ); the upward crossing of the threshold at
    /// t + τ ln((y − u)/(threshold − u)), on the clock grid rounded down.
    fn do_step(&mut self, cx: &Cx, step: &Step) -> Result<StepOutcome, FmuError> {
        let (t, h, early_return) = (step.t, step.h, step.early_return);
        let end = on_clock_grid(t + h);
        let [u] = cx.inputs.stepping().value;
        let below = !self.above && self.threshold < u;
        let crossing = t + self.tau * ((self.y - u) / (self.threshold - u)).ln();
        let at = (crossing / CLOCK_RESOLUTION).floor() * CLOCK_RESOLUTION;
        let (reach, outcome) = if below && early_return && t < at && at < end {
            let event = "threshold crossed";
            (at, StepOutcome::ReturnedEarly { time: at, event })
        } else {
            (end, StepOutcome::Completed { time: end })
        };
        if below && crossing <= reach + CLOCK_RESOLUTION {
            self.crossings += 1;
            self.above = true;
        }
        self.y = u + (self.y - u) * (-(reach - t) / self.tau).exp();
        Ok(outcome)
    }

    fn get_real(&mut self, cx: &Cx, vars: &[Var<Vr>], value: &mut [f64]) -> Result<(), FmuError> {
        for (v, x) in vars.iter().zip(value) {
            *x = match v.vr {
                Vr::Tau => self.tau,
                Vr::Threshold => self.threshold,
                Vr::U => cx.inputs.reading().value[0],
                Vr::Y => self.y,
                Vr::Crossings => unreachable!("an Integer"),
            };
        }
        Ok(())
    }

    fn get_array(&mut self, _cx: &Cx, array: usize, value: &mut [f64]) -> Result<(), FmuError> {
        assert_eq!(array, 0);
        for (k, x) in (1..).zip(value) {
            *x = self.y.powi(k);
        }
        Ok(())
    }

    fn set_real(&mut self, _state: State, vars: &[Var<Vr>], value: &[f64]) -> Result<(), FmuError> {
        for (v, &x) in vars.iter().zip(value) {
            match v.vr {
                Vr::Tau => self.tau = x,
                Vr::Threshold => self.threshold = x,
                _ => unreachable!("checked settable"),
            }
        }
        Ok(())
    }

    fn get_integer(
        &mut self,
        _cx: &Cx,
        vars: &[Var<Vr>],
        value: &mut [i32],
    ) -> Result<(), FmuError> {
        value[..vars.len()].fill(self.crossings);
        Ok(())
    }

    fn save(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter(out);
        for x in [self.tau, self.threshold, self.y] {
            w.f64(x);
        }
        w.u64(self.crossings as u64);
        w.flag(self.above);
    }

    fn load(&mut self, _cx: &Cx, bytes: &[u8], apply: bool) -> Result<(), FmuError> {
        let mut r = ByteReader::new(bytes);
        let x = [r.f64()?, r.f64()?, r.f64()?];
        let (crossings, above) = (r.u64()? as i32, r.flag()?);
        if apply {
            [self.tau, self.threshold, self.y] = x;
            (self.crossings, self.above) = (crossings, above);
        }
        Ok(())
    }
}

fmi_export::export_fmi2!(Lag);
fmi_export::export_fmi3!(Lag);
use fmi2_exports::*;
use fmi3_exports::*;

static MESSAGES: Mutex<Vec<String>> = Mutex::new(Vec::new());

unsafe extern "C" fn log3(
    _environment: fmi3InstanceEnvironment,
    _status: fmi3Status,
    _category: fmi3String,
    message: fmi3String,
) {
    // SAFETY: a NUL-terminated string valid during the call.
    let text = unsafe { CStr::from_ptr(message) }.to_string_lossy();
    MESSAGES.lock().unwrap().push(text.into_owned());
}

fn last_message() -> String {
    MESSAGES.lock().unwrap().last().cloned().unwrap_or_default()
}

/// Whether any message so far contains `text` (robust against the other tests' messages).
fn logged(text: &str) -> bool {
    MESSAGES.lock().unwrap().iter().any(|m| m.contains(text))
}

const OK: u32 = 0;
const ERROR: u32 = 3;

/// A new FMI 3 instance of the lag, early return allowed or not.
fn instantiate3(name: &str, early_return: bool) -> *mut std::ffi::c_void {
    let (name, token) = (
        CString::new(name).unwrap(),
        CString::new(Lag::FMI3_TOKENS[0]).unwrap(),
    );
    // SAFETY: NUL-terminated strings that outlive the call.
    let c = unsafe {
        fmi3InstantiateCoSimulation(
            name.as_ptr(),
            token.as_ptr(),
            std::ptr::null(),
            false,
            true,
            false,
            early_return,
            std::ptr::null(),
            0,
            std::ptr::null_mut(),
            Some(log3),
            None,
        )
    };
    assert!(!c.is_null(), "{}", last_message());
    c
}

/// An FMI 3 instance of the lag in Step Mode, early return allowed or not.
fn lag3(name: &str, early_return: bool) -> *mut std::ffi::c_void {
    let c = instantiate3(name, early_return);
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            fmi3EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmi3ExitInitializationMode(c), OK);
    }
    c
}

/// fmi3DoStep: status, earlyReturn, lastSuccessfulTime.
fn step3(c: *mut std::ffi::c_void, t: f64, h: f64) -> (u32, bool, f64) {
    let (mut event, mut terminate, mut early, mut last) = (true, true, false, f64::NAN);
    // SAFETY: a live instance and four writable values.
    let status = unsafe {
        fmi3DoStep(
            c,
            t,
            h,
            false,
            &mut event,
            &mut terminate,
            &mut early,
            &mut last,
        )
    };
    (status, early, last)
}

fn get3(c: *mut std::ffi::c_void, vr: u32) -> f64 {
    let mut x = f64::NAN;
    // SAFETY: a live instance, one value.
    assert_eq!(unsafe { fmi3GetFloat64(c, &vr, 1, &mut x, 1) }, OK);
    x
}

/// With early return the step ends where the output reaches the threshold, τ ln 2 for u = 1 and a
/// threshold of ½, on the clock grid; the master continues from there, and the output follows
/// 1 − e^(−t/τ) throughout. Without it, the same steps reach the communication points.
#[test]
fn fmi3_returns_early_at_the_models_event() {
    let c = lag3("tiny-early", true);
    let tau = 0.2;
    let crossing = tau * std::f64::consts::LN_2;
    let (h, mut t, mut returns) = (0.1, 0.0, 0);
    for k in 1..=5 {
        let point = f64::from(k) * h;
        loop {
            let (status, early, last) = step3(c, t, point - t);
            assert_eq!(status, OK, "{}", last_message());
            let y = get3(c, Vr::Y as u32);
            assert!(
                (y - (1.0 - (-last / tau).exp())).abs() < 1e-14,
                "y({last}) = {y}"
            );
            assert_eq!(get3(c, TIME_VALUE_REFERENCE), last);
            t = last;
            if !early {
                assert_eq!(last, on_clock_grid(point));
                break;
            }
            returns += 1;
            assert!(
                crossing - CLOCK_RESOLUTION < last && last <= crossing,
                "{last}"
            );
            assert_eq!(last % CLOCK_RESOLUTION, 0.0);
            assert!(logged("fmi3DoStep: returned early at t = "));
            assert!(logged("threshold crossed"));
        }
    }
    assert_eq!(returns, 1);
    let mut crossings = 0;
    // SAFETY: a live instance, one value; freed once.
    unsafe {
        assert_eq!(
            fmi3GetInt32(c, &(Vr::Crossings as u32), 1, &mut crossings, 1),
            OK
        );
        fmi3FreeInstance(c);
    }
    assert_eq!(crossings, 1);

    let c = lag3("tiny-grid", false);
    for k in 0..5 {
        let t = f64::from(k) * h;
        assert_eq!(step3(c, t, h), (OK, false, on_clock_grid(t + h)));
    }
    // SAFETY: a live instance, freed once.
    unsafe { fmi3FreeInstance(c) };
}

/// The layer's checks come before the model: a value reference of another type, a count that is
/// not one value per reference, a parameter after initialization, an Int64 for an Int32 and a
/// call out of order are refused in FMI 3's names; `time` cannot be set; FMI 2 instances of the
/// same model say fmi2.
#[test]
fn the_layer_refuses_before_the_model_in_each_versions_names() {
    let c = lag3("tiny-refusals", false);
    let (tau, y, count) = (Vr::Tau as u32, Vr::Y as u32, Vr::Crossings as u32);
    let mut x = [0.0; 2];
    let mut n = 0i64;
    // SAFETY: a live instance; every pointer is valid for the counts given.
    unsafe {
        assert_eq!(fmi3GetInt32(c, &y, 1, &mut 0, 1), ERROR);
        assert!(logged(
            "fmi3GetInt32: value reference 3 (lag.y) is not of type Int32"
        ));
        assert_eq!(fmi3Reset(c), OK);
        assert_eq!(
            fmi3EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmi3GetFloat64(c, &y, 1, x.as_mut_ptr(), 2), ERROR);
        assert!(logged("nValues = 2 but the variables named have 1 element"));
        assert_eq!(fmi3Reset(c), OK);
        assert_eq!(
            fmi3EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmi3GetInt64(c, &count, 1, &mut n, 1), ERROR);
        assert!(logged("(lag.crossings) is not of type Int64"));
        assert_eq!(fmi3Reset(c), OK);
        assert_eq!(
            fmi3EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmi3ExitInitializationMode(c), OK);
        assert_eq!(fmi3SetFloat64(c, &tau, 1, &0.5, 1), ERROR);
        assert!(logged(
            "fmi3SetFloat64: variable lag.tau (Parameter) cannot be set"
        ));
        assert_eq!(fmi3Reset(c), OK);
        assert_eq!(fmi3SetFloat64(c, &TIME_VALUE_REFERENCE, 1, &1.0, 1), ERROR);
        assert!(logged("time is the independent variable"));
        assert_eq!(fmi3Reset(c), OK);
        assert_eq!(step3(c, 0.0, 0.1).0, ERROR);
        assert!(logged("fmi3DoStep: Illegal call sequence."));
        fmi3FreeInstance(c);
    }

    let callbacks = fmi2CallbackFunctions {
        logger: Some(fmi_sys::fmi2::logger::callback_logger_handler),
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: std::ptr::null_mut(),
    };
    let (name, guid) = (
        CString::new("tiny-fmi2").unwrap(),
        CString::new(Lag::GUID).unwrap(),
    );
    // SAFETY: NUL-terminated strings and callbacks that outlive the calls; a live instance.
    unsafe {
        let c = fmi2Instantiate(
            name.as_ptr(),
            fmi2Type_fmi2CoSimulation,
            guid.as_ptr(),
            std::ptr::null::<c_char>(),
            &callbacks,
            0,
            1,
        );
        assert!(!c.is_null());
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
        assert_eq!(fmi2EnterInitializationMode(c), OK);
        assert_eq!(fmi2ExitInitializationMode(c), OK);
        // FMI 2 has no early return: the step reaches the communication point across the event.
        assert_eq!(fmi2DoStep(c, 0.0, 0.5, 1), OK);
        let mut y = 0.0;
        assert_eq!(fmi2GetReal(c, &(Vr::Y as u32), 1, &mut y), OK);
        assert!((y - (1.0 - (-0.5f64 / 0.2).exp())).abs() < 1e-14);
        fmi2FreeInstance(c);
    }
}

/// The layer sizes an array by its structural parameter, set in Configuration Mode only: a get
/// names scalars and arrays in one call, nValues their total size, each array filled by the
/// model; a wrong total is refused before the model is called.
#[test]
fn fmi3_arrays_are_sized_by_structural_parameters() {
    let c = instantiate3("tiny-arrays", false);
    // SAFETY: a live instance, every pointer valid for the counts given.
    unsafe {
        assert_eq!(fmi3SetUInt64(c, &N_POWERS, 1, &3, 1), ERROR);
        assert!(logged("it is set in Configuration Mode only"));
        assert_eq!(fmi3Reset(c), OK);
        assert_eq!(fmi3EnterConfigurationMode(c), OK);
        assert_eq!(fmi3SetUInt64(c, &N_POWERS, 1, &5, 1), ERROR);
        assert!(logged(
            "lag.nPowers = 5 is outside the allowed range [1, 4]"
        ));
        assert_eq!(fmi3Reset(c), OK);
        assert_eq!(fmi3EnterConfigurationMode(c), OK);
        assert_eq!(fmi3SetUInt64(c, &N_POWERS, 1, &3, 1), OK);
        assert_eq!(fmi3ExitConfigurationMode(c), OK);
        assert_eq!(
            fmi3EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmi3ExitInitializationMode(c), OK);
        assert_eq!(step3(c, 0.0, 0.1).0, OK);
        let refs = [Vr::Y as u32, POWERS, TIME_VALUE_REFERENCE, POWERS];
        let mut values = [f64::NAN; 8];
        assert_eq!(
            fmi3GetFloat64(c, refs.as_ptr(), 4, values.as_mut_ptr(), 8),
            OK
        );
        let y = values[0];
        assert!(y > 0.3, "{values:?}");
        assert_eq!(&values[1..4], &[y, y * y, y * y * y]);
        assert_eq!(values[4], on_clock_grid(0.1));
        assert_eq!(&values[5..8], &values[1..4]);
        assert_eq!(
            fmi3GetFloat64(c, refs.as_ptr(), 4, values.as_mut_ptr(), 7),
            ERROR
        );
        assert!(logged(
            "nValues = 7 but the variables named have 8 elements"
        ));
        fmi3FreeInstance(c);
    }
}
