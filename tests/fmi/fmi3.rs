//! The FMI 3.0 functions of the same library, through the C API: the run equals FMI 2's bit for
//! bit, an early return stops at a contact onset on the clock grid and loses nothing, and every
//! argument and call the FMU does not take is refused with a message in FMI 3's names.

use std::collections::HashMap;
use std::ffi::{CStr, CString, c_char};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};

use flexible_slider_crank::fmi::FMI3_TOKEN as GUID;
use flexible_slider_crank::simulation::CLOCK_RESOLUTION;
use flexible_slider_crank::variables::{Causality, FMI3, Kind, N_SECTIONS, VARIABLES};
use fmi_sys::fmi3::*;

use crate::harness::{Instance, library_path, vr};

const OK: fmi3Status = fmi3Status_fmi3OK;
const ERROR: fmi3Status = fmi3Status_fmi3Error;
/// The independent variable's value reference.
const TIME: u32 = fmi_export::fmi3::description::TIME_VALUE_REFERENCE;

/// The library's FMI 3 functions (one per test process).
fn fmu3() -> &'static Fmi3Binding {
    static FMU: OnceLock<Fmi3Binding> = OnceLock::new();
    // SAFETY: loading our own FMU library; its initialisers do nothing.
    FMU.get_or_init(|| unsafe { Fmi3Binding::new(library_path()) }.unwrap())
}

/// Messages by instance environment (a number each instance gets).
static MESSAGES: OnceLock<Mutex<HashMap<usize, Vec<String>>>> = OnceLock::new();

unsafe extern "C" fn log_message(
    environment: fmi3InstanceEnvironment,
    _status: fmi3Status,
    category: fmi3String,
    message: fmi3String,
) {
    // SAFETY: the FMU passes NUL-terminated strings valid during the call.
    let text = |p: *const c_char| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned();
    let line = format!("[{}] {}", text(category), text(message));
    let map = MESSAGES.get_or_init(Default::default);
    map.lock()
        .unwrap()
        .entry(environment as usize)
        .or_default()
        .push(line);
}

/// One FMI 3 co-simulation instance, freed on drop.
struct Instance3 {
    c: fmi3Instance,
    id: usize,
    /// Created with eventModeUsed.
    event_mode: bool,
}

impl Instance3 {
    /// Instantiates with the token `token`, event mode and early return as given; None if the
    /// FMU refused (its messages are then under the returned id).
    fn try_new(token: &str, event_mode: bool, early_return: bool) -> (Option<Self>, usize) {
        Self::with_update(token, event_mode, early_return, None)
    }

    /// As [`Instance3::try_new`], with an intermediate-update callback.
    fn with_update(
        token: &str,
        event_mode: bool,
        early_return: bool,
        update: fmi3IntermediateUpdateCallback,
    ) -> (Option<Self>, usize) {
        static NEXT: AtomicUsize = AtomicUsize::new(1);
        let id = NEXT.fetch_add(1, Ordering::Relaxed);
        let name = CString::new(format!("fmi3-{id}")).unwrap();
        let token = CString::new(token).unwrap();
        // SAFETY: NUL-terminated strings that outlive the call; the environment is a number the
        // logger only uses as a key.
        let c = unsafe {
            fmu3().fmi3InstantiateCoSimulation(
                name.as_ptr(),
                token.as_ptr(),
                std::ptr::null(),
                false,
                true,
                event_mode,
                early_return,
                std::ptr::null(),
                0,
                id as fmi3InstanceEnvironment,
                Some(log_message),
                update,
            )
        };
        ((!c.is_null()).then_some(Self { c, id, event_mode }), id)
    }

    /// An instance in Step Mode with the default parameters.
    fn initialized(early_return: bool) -> Self {
        let (inst, id) = Self::try_new(GUID, false, early_return);
        let inst = inst.unwrap_or_else(|| panic!("{:?}", messages(id)));
        // SAFETY: a live instance.
        unsafe {
            assert_eq!(
                fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
                OK
            );
            assert_eq!(fmu3().fmi3ExitInitializationMode(inst.c), OK);
        }
        inst
    }

    fn messages(&self) -> Vec<String> {
        messages(self.id)
    }

    /// fmi3DoStep: status, earlyReturn, lastSuccessfulTime.
    fn do_step(&self, t: f64, h: f64) -> (fmi3Status, bool, f64) {
        let (mut event, mut terminate, mut early, mut last) = (true, true, false, f64::NAN);
        // SAFETY: a live instance and four writable values.
        let status = unsafe {
            fmu3().fmi3DoStep(
                self.c,
                t,
                h,
                false,
                &mut event,
                &mut terminate,
                &mut early,
                &mut last,
            )
        };
        if status == OK {
            assert!(!terminate, "never a terminate request");
            assert_eq!(
                event,
                early && self.event_mode,
                "events only with event mode"
            );
        }
        (status, early, last)
    }

    fn get_float64(&self, vrs: &[u32]) -> (fmi3Status, Vec<f64>) {
        let mut values = vec![f64::NAN; vrs.len()];
        // SAFETY: a live instance and as many values as value references.
        let status = unsafe {
            fmu3().fmi3GetFloat64(
                self.c,
                vrs.as_ptr(),
                vrs.len(),
                values.as_mut_ptr(),
                values.len(),
            )
        };
        (status, values)
    }
}

impl Drop for Instance3 {
    fn drop(&mut self) {
        // SAFETY: a live instance, freed once.
        unsafe { fmu3().fmi3FreeInstance(self.c) };
    }
}

fn messages(id: usize) -> Vec<String> {
    MESSAGES
        .get_or_init(Default::default)
        .lock()
        .unwrap()
        .get(&id)
        .cloned()
        .unwrap_or_default()
}

/// The value references of every Float64 output.
fn real_outputs() -> Vec<u32> {
    VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Output && matches!(v.kind, Kind::Real { .. }))
        .map(|v| v.vr as u32)
        .collect()
}

/// FMI 3 and FMI 2 instances of the same library step the defaults through 30 ms of impacts with
/// the same results, bit for bit, at every communication point; `time` is the time reached.
#[test]
fn fmi3_steps_bit_identical_to_fmi2() {
    let outputs = real_outputs();
    let fmi2 = Instance::new("fmi3-twin");
    fmi2.initialize();
    let fmi3 = Instance3::initialized(false);
    let h = 1e-4;
    for k in 0..300 {
        let t = f64::from(k) * h;
        assert_eq!(fmi2.do_step(t, h), OK);
        assert_eq!(fmi3.do_step(t, h), (OK, false, t + h));
        let (status, values) = fmi3.get_float64(&outputs);
        assert_eq!(status, OK);
        let expected = fmi2.get_reals(&outputs);
        let same = values
            .iter()
            .zip(&expected)
            .all(|(a, b)| a.to_bits() == b.to_bits());
        assert!(same, "t = {} s: FMI 3 differs from FMI 2", t + h);
        assert_eq!(fmi3.get_float64(&[TIME]).1, [t + h]);
    }
}

/// With early return allowed, fmi3DoStep stops at the end of the internal step in which a joint
/// comes into contact: before the communication point, on the clock grid, with the onset
/// counted there (every onset but one whose step ends at a communication point); the next step
/// continues from there, and at every regular communication point
/// the state and the onset count equal the run without early return, bit for bit.
#[test]
fn early_return_stops_at_contact_onsets_and_loses_nothing() {
    let onsets = vr("joint.contactOnsetsTotal");
    let state = [
        vr("crank.angle"),
        vr("slider.position"),
        vr("slider.velocity"),
        vr("joint.force"),
    ];
    let count = |inst: &Instance3| {
        let mut value = -1;
        // SAFETY: a live instance, one value.
        let status = unsafe { fmu3().fmi3GetInt32(inst.c, &onsets, 1, &mut value, 1) };
        assert_eq!(status, OK);
        value
    };
    let regular = Instance3::initialized(false);
    let early = Instance3::initialized(true);
    let h = 1e-4;
    let mut t = 0.0;
    let (mut returns, mut at_points) = (0, 0);
    for k in 1..=300 {
        let point = f64::from(k) * h;
        assert_eq!(regular.do_step(point - h, h), (OK, false, point));
        loop {
            let before = count(&early);
            let (status, returned, last) = early.do_step(t, point - t);
            assert_eq!(status, OK, "{:?}", early.messages());
            if !returned {
                assert_eq!(last, point);
                at_points += count(&early) - before;
                t = point;
                break;
            }
            returns += 1;
            assert!(t < last && last < point, "{t} < {last} < {point}");
            assert_eq!(last % CLOCK_RESOLUTION, 0.0, "{last} is off the clock grid");
            assert_eq!(
                count(&early),
                before + 1,
                "the onset is counted at {last} s"
            );
            assert_eq!(early.get_float64(&[TIME]).1, [last]);
            t = last;
        }
        assert_eq!(count(&early), count(&regular), "t = {point} s");
        let (a, b) = (early.get_float64(&state).1, regular.get_float64(&state).1);
        assert_eq!(a, b, "t = {point} s");
    }
    assert!(returns > 10, "{returns} early returns in 30 ms of impacts");
    // Every onset returns but one whose step ends at a communication point (none to return to).
    assert_eq!(returns + at_points, count(&early));
    assert!(
        at_points * 20 < returns,
        "{at_points} onsets without a return"
    );
    assert!(
        early
            .messages()
            .iter()
            .any(|m| m.contains("fmi3DoStep: returned early at t = ")
                && m.contains("contact onset in joint")),
        "{:?}",
        early.messages()
    );
}

/// A state taken through FMI 3, serialized and restored into another instance, continues bit for
/// bit.
#[test]
fn fmi3_states_replay_bit_for_bit() {
    let outputs = real_outputs();
    let a = Instance3::initialized(false);
    assert_eq!(a.do_step(0.0, 5e-3).0, OK);
    let mut state: fmi3FMUState = std::ptr::null_mut();
    let mut size = 0;
    // SAFETY: live instances; the state and buffer are this FMU's and as large as it says.
    let bytes = unsafe {
        assert_eq!(fmu3().fmi3GetFMUState(a.c, &mut state), OK);
        assert_eq!(fmu3().fmi3SerializedFMUStateSize(a.c, state, &mut size), OK);
        let mut bytes = vec![0u8; size];
        assert_eq!(
            fmu3().fmi3SerializeFMUState(a.c, state, bytes.as_mut_ptr(), size),
            OK
        );
        assert_eq!(fmu3().fmi3FreeFMUState(a.c, &mut state), OK);
        bytes
    };
    let b = Instance3::initialized(false);
    // SAFETY: as above.
    unsafe {
        assert_eq!(
            fmu3().fmi3DeserializeFMUState(b.c, bytes.as_ptr(), bytes.len(), &mut state),
            OK
        );
        assert_eq!(fmu3().fmi3SetFMUState(b.c, state), OK);
        assert_eq!(fmu3().fmi3FreeFMUState(b.c, &mut state), OK);
    }
    for inst in [&a, &b] {
        assert_eq!(inst.do_step(5e-3, 5e-3).0, OK);
    }
    assert_eq!(a.get_float64(&outputs), b.get_float64(&outputs));
}

/// Instantiation refuses a wrong token and event mode; the switches are Int64 Enumerations with
/// their items checked; types the FMU has no variable of, a count that is not one value per
/// reference, `time` as a settable and the functions of capabilities it lacks are errors whose
/// messages name the FMI 3 function and the variable.
#[test]
fn fmi3_refuses_what_it_does_not_take() {
    let (none, id) = Instance3::try_new("{not-the-token}", false, false);
    assert!(none.is_none());
    assert!(messages(id)[0].contains("fmi3InstantiateCoSimulation: Wrong instantiationToken"));
    let (inst, _) = Instance3::try_new(GUID, false, false);
    let inst = inst.unwrap();
    let last = |inst: &Instance3| inst.messages().last().cloned().unwrap_or_default();
    assert_eq!(inst.do_step(0.0, 1e-4).0, ERROR);
    assert!(last(&inst).contains("fmi3DoStep: Illegal call sequence."));
    // SAFETY: a live instance; every pointer is valid for the counts given.
    unsafe { assert_eq!(fmu3().fmi3Reset(inst.c), OK) };

    let model = vr("joint.model");
    let get_switch = |inst: &Instance3| {
        let mut item = 0i64;
        // SAFETY: as above.
        let status = unsafe { fmu3().fmi3GetInt64(inst.c, &model, 1, &mut item, 1) };
        (status, item)
    };
    // SAFETY: as above.
    unsafe {
        assert_eq!(fmu3().fmi3SetInt64(inst.c, &model, 1, &2, 1), OK);
        assert_eq!(fmu3().fmi3SetInt64(inst.c, &model, 1, &9, 1), ERROR);
    }
    assert!(last(&inst).contains("fmi3SetInt64: joint.model = 9 is outside the allowed range"));
    // SAFETY: as above.
    unsafe {
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(fmu3().fmi3SetInt64(inst.c, &model, 1, &2, 1), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
    }
    assert_eq!(get_switch(&inst), (OK, 2));
    let length = vr("rod.length");
    let mut value = 0.0f32;
    // SAFETY: as above.
    unsafe {
        assert_eq!(
            fmu3().fmi3GetFloat32(inst.c, &length, 1, &mut value, 1),
            ERROR
        );
    }
    assert!(last(&inst).contains("fmi3GetFloat32: value reference"));
    assert!(last(&inst).contains("(rod.length) is not of type Float32"));
    // SAFETY: as above.
    unsafe {
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
    }
    let mut values = [0.0; 2];
    // SAFETY: as above (two values for one reference: refused before they are read).
    let status = unsafe { fmu3().fmi3GetFloat64(inst.c, &length, 1, values.as_mut_ptr(), 2) };
    assert_eq!(status, ERROR);
    assert!(last(&inst).contains("nValues = 2 but the variables named have 1 element"));
    // SAFETY: as above.
    unsafe {
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(fmu3().fmi3SetFloat64(inst.c, &TIME, 1, &1.0, 1), ERROR);
    }
    assert!(last(&inst).contains("time is the independent variable"));
    // SAFETY: as above.
    unsafe {
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(fmu3().fmi3EnterEventMode(inst.c), ERROR);
        assert!(last(&inst).contains("fmi3EnterEventMode: Illegal call sequence."));
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3ExitInitializationMode(inst.c), OK);
        assert_eq!(fmu3().fmi3EnterEventMode(inst.c), ERROR);
    }
    assert!(last(&inst).contains("created with eventModeUsed = false"));
}

/// With event mode (and early return) the instance starts in Event Mode after initialization,
/// and every early return at a contact onset asks for it: there the joint that came into
/// contact reads inContact, the discrete states settle at once, and Step Mode continues; the
/// run is the one with early return alone, bit for bit, and a step in Event Mode is refused.
#[test]
fn event_mode_at_each_contact_onset_changes_nothing() {
    let (inst, id) = Instance3::try_new(GUID, true, true);
    let events = inst.unwrap_or_else(|| panic!("{:?}", messages(id)));
    let plain = Instance3::initialized(true);
    let flags = [
        vr("joint.inContact"),
        vr("crankPin.inContact"),
        vr("mainBearing.inContact"),
    ];
    let settle = |inst: &Instance3| {
        let mut out = [true; 5];
        let mut next = f64::NAN;
        let [a, b, c, d, e] = &mut out;
        // SAFETY: a live instance, one writable value each.
        let status = unsafe { fmu3().fmi3UpdateDiscreteStates(inst.c, a, b, c, d, e, &mut next) };
        assert_eq!((status, out), (OK, [false; 5]));
        // SAFETY: as above.
        assert_eq!(unsafe { fmu3().fmi3EnterStepMode(inst.c) }, OK);
    };
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(events.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3ExitInitializationMode(events.c), OK);
    }
    assert_eq!(events.do_step(0.0, 1e-4).0, ERROR, "a step in Event Mode");
    assert!(
        events
            .messages()
            .last()
            .unwrap()
            .contains("fmi3DoStep: Illegal call sequence.")
    );
    // SAFETY: a live instance (Error state: start again).
    unsafe {
        assert_eq!(fmu3().fmi3Reset(events.c), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(events.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3ExitInitializationMode(events.c), OK);
    }
    settle(&events);
    let (h, mut t, mut entered) = (1e-4, 0.0, 0);
    for k in 1..=300 {
        let point = f64::from(k) * h;
        loop {
            let (status, early, last) = events.do_step(t, point - t);
            assert_eq!(status, OK, "{:?}", events.messages());
            assert_eq!(plain.do_step(t, point - t), (OK, early, last));
            t = last;
            if !early {
                break;
            }
            // SAFETY: a live instance; one value per reference.
            unsafe { assert_eq!(fmu3().fmi3EnterEventMode(events.c), OK) };
            entered += 1;
            let mut in_contact = [false; 3];
            // SAFETY: as above.
            let status = unsafe {
                fmu3().fmi3GetBoolean(events.c, flags.as_ptr(), 3, in_contact.as_mut_ptr(), 3)
            };
            assert_eq!(status, OK);
            assert!(
                in_contact.contains(&true),
                "an onset at {t} s: {in_contact:?}"
            );
            settle(&events);
        }
        let outputs = real_outputs();
        assert_eq!(
            events.get_float64(&outputs).1,
            plain.get_float64(&outputs).1
        );
    }
    assert!(entered > 10, "{entered} events in 30 ms of impacts");
}

mod arrays;
mod intermediate;
mod ramps;
mod state_machine;
