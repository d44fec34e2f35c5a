//! Intermediate update: the callback reads every internal step and changes nothing.

use super::*;

/// What the intermediate-update callback of each instance (by environment) saw and does: the
/// instance, whether to ask for an early return at its next call, and per call the time given,
/// the `time` and `joint.force` read there, and whether it could ask to return early.
#[derive(Default)]
struct Intermediate {
    instance: usize,
    request_early_return: bool,
    try_to_free: bool,
    calls: Vec<(f64, f64, f64, bool)>,
}

static INTERMEDIATE: OnceLock<Mutex<HashMap<usize, Intermediate>>> = OnceLock::new();

fn intermediate() -> std::sync::MutexGuard<'static, HashMap<usize, Intermediate>> {
    INTERMEDIATE.get_or_init(Default::default).lock().unwrap()
}

/// Reads `time` and `joint.force` through the C API while the step is paused.
unsafe extern "C" fn on_intermediate_update(
    environment: fmi3InstanceEnvironment,
    time: fmi3Float64,
    set_requested: fmi3Boolean,
    get_allowed: fmi3Boolean,
    step_finished: fmi3Boolean,
    can_return_early: fmi3Boolean,
    early_return_requested: *mut fmi3Boolean,
    _early_return_time: *mut fmi3Float64,
) {
    assert!(!set_requested && get_allowed && step_finished);
    let id = environment as usize;
    let (instance, request, free) = {
        let mut map = intermediate();
        let entry = map.get_mut(&id).unwrap();
        let request = std::mem::take(&mut entry.request_early_return);
        let free = std::mem::take(&mut entry.try_to_free);
        (entry.instance as fmi3Instance, request, free)
    };
    if free {
        // SAFETY: the paused instance (the FMU refuses to free it here).
        unsafe { fmu3().fmi3FreeInstance(instance) };
    }
    let refs = [TIME, vr("joint.force")];
    let mut values = [f64::NAN; 2];
    // SAFETY: the paused instance; two values for two references.
    let status =
        unsafe { fmu3().fmi3GetFloat64(instance, refs.as_ptr(), 2, values.as_mut_ptr(), 2) };
    assert_eq!(status, OK);
    intermediate()
        .get_mut(&id)
        .unwrap()
        .calls
        .push((time, values[0], values[1], can_return_early));
    // SAFETY: one writable value from the FMU.
    unsafe { *early_return_requested = request };
}

/// With an intermediate-update callback the step pauses after every internal step: the callback
/// reads the outputs there (`time` is the internal step's end, the joint force finite), may ask
/// to return early where the master allowed early return, and without that request the run is
/// the one without callback, bit for bit, early returns at onsets included. An early return the
/// callback asks for ends the step at that internal step's end on the clock grid; the next step
/// starts there. Freeing the instance from the callback is refused.
#[test]
fn intermediate_update_reads_every_internal_step_and_changes_nothing() {
    let (inst, id) = Instance3::with_update(GUID, false, true, Some(on_intermediate_update));
    let paused = inst.unwrap_or_else(|| panic!("{:?}", messages(id)));
    intermediate().insert(
        paused.id,
        Intermediate {
            instance: paused.c as usize,
            ..Intermediate::default()
        },
    );
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(paused.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3ExitInitializationMode(paused.c), OK);
    }
    let plain = Instance3::initialized(true);
    let outputs = real_outputs();
    let (h, mut t) = (1e-4, 0.0);
    for k in 1..=100 {
        let point = f64::from(k) * h;
        loop {
            let before = intermediate()[&paused.id].calls.len();
            let (status, early, last) = paused.do_step(t, point - t);
            assert_eq!(status, OK, "{:?}", paused.messages());
            assert_eq!(plain.do_step(t, point - t), (OK, early, last));
            let calls = &intermediate()[&paused.id].calls;
            for &(time, read_time, force, can_return_early) in &calls[before..] {
                assert!(t < time && time < last, "{t} < {time} < {last}");
                assert_eq!(read_time, time);
                assert!(force.is_finite());
                assert!(can_return_early);
            }
            t = last;
            if !early {
                break;
            }
        }
        assert_eq!(
            paused.get_float64(&outputs).1,
            plain.get_float64(&outputs).1
        );
    }
    let calls = intermediate()[&paused.id].calls.len();
    assert!(calls > 100, "{calls} intermediate updates in 10 ms");
    // An early return asked for at the next pause.
    intermediate()
        .get_mut(&paused.id)
        .unwrap()
        .request_early_return = true;
    let (status, early, last) = paused.do_step(t, 1e-3);
    let (pause, ..) = *intermediate()[&paused.id].calls.last().unwrap();
    assert_eq!((status, early), (OK, true));
    assert_eq!(last, (pause / CLOCK_RESOLUTION).floor() * CLOCK_RESOLUTION);
    assert!(
        paused
            .messages()
            .last()
            .unwrap()
            .contains("requested by the master")
    );
    t = last;
    intermediate().get_mut(&paused.id).unwrap().try_to_free = true;
    assert_eq!(paused.do_step(t, 1e-3).0, OK);
    assert!(
        paused
            .messages()
            .iter()
            .any(|m| m.contains("fmi3FreeInstance: not allowed from inside fmi3DoStep")),
        "{:?}",
        paused.messages()
    );
}
