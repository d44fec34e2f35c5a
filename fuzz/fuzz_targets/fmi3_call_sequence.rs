//! Coverage-guided fuzzing of fmi3* call sequences on one instance: any order of the calls an
//! FMI 3 co-simulation master can make — Configuration Mode and the structural parameter, Event
//! Mode, early return, the intermediate-update callback (which reads, and may ask to return early
//! or try to free the instance), value references of every kind with counts right or wrong, FMU
//! states. Whatever the sequence, every call must return a status (never crash, hang or abort)
//! and the instance must free cleanly.

#![no_main]

use std::cell::Cell;
use std::ffi::CString;
use std::ptr;

use arbitrary::Arbitrary;
use flexible_slider_crank::fmi::FMI3_TOKEN;
use flexible_slider_crank::fmi::fmi3_exports as fmi;
use flexible_slider_crank::variables::{FMI3, N_SECTIONS};
use flexible_slider_crank_fuzz::{value_for, variable_count};
use fmi_sys::fmi3::*;
use libfuzzer_sys::fuzz_target;

/// One call of the master.
#[derive(Arbitrary, Debug)]
enum Call {
    EnterConfiguration,
    SetSections(u16),
    ExitConfiguration,
    EnterInitialization {
        start: f64,
        stop: Option<f64>,
    },
    ExitInitialization,
    EnterEventMode,
    UpdateDiscreteStates,
    EnterStepMode,
    /// fmi3DoStep at the instance's time (or `t` itself) with one of a few step sizes.
    DoStep {
        at_time: bool,
        t: f64,
        size: u8,
    },
    /// fmi3GetFloat64 of up to 8 value references (the table's, `time`, the arrays, others), with
    /// the right count of values or one off.
    GetFloat64 {
        picks: Vec<u8>,
        off_by_one: bool,
    },
    SetFloat64 {
        pick: u8,
        value_pick: u8,
        raw: f64,
    },
    SetInt64 {
        pick: u8,
        value: i64,
    },
    Terminate,
    Reset,
    StateRoundTrip {
        flip: Option<(u16, u8)>,
    },
    /// What the intermediate-update callback does at its next calls.
    Callback {
        request_early_return: bool,
        try_to_free: bool,
    },
}

/// The instance's options at instantiation and its calls.
#[derive(Arbitrary, Debug)]
struct Session {
    event_mode: bool,
    early_return: bool,
    intermediate_update: bool,
    calls: Vec<Call>,
}

/// Step sizes, valid and not.
const STEPS: [f64; 7] = [1e-6, 1e-5, 1e-4, 1e-3, 0.0, -1e-4, f64::NAN];

thread_local! {
    /// The instance the callback reads, and what it does.
    static PAUSED: Cell<(fmi3Instance, bool, bool)> = const { Cell::new((ptr::null_mut(), false, false)) };
}

/// A value reference: the table's, just beyond it, `time`, the structural parameter, the arrays.
fn vr(pick: u8) -> u32 {
    let n = variable_count();
    let extra = [
        n,
        fmi_export::fmi3::description::TIME_VALUE_REFERENCE,
        N_SECTIONS,
    ];
    let arrays = FMI3.arrays.len() as u32;
    let k = u32::from(pick) % (n + extra.len() as u32 + arrays);
    if k < n {
        k
    } else if k < n + extra.len() as u32 {
        extra[(k - n) as usize]
    } else {
        FMI3.arrays[(k - n - extra.len() as u32) as usize].vr
    }
}

/// The callback: reads `time` and the first array, asks for an early return or tries to free the
/// instance as the session said.
unsafe extern "C" fn on_update(
    _environment: fmi3InstanceEnvironment,
    _time: fmi3Float64,
    _set_requested: fmi3Boolean,
    _get_allowed: fmi3Boolean,
    _finished: fmi3Boolean,
    _can_return_early: fmi3Boolean,
    early_return_requested: *mut fmi3Boolean,
    _early_return_time: *mut fmi3Float64,
) {
    let (instance, request, free) = PAUSED.get();
    let refs = [
        fmi_export::fmi3::description::TIME_VALUE_REFERENCE,
        FMI3.arrays[0].vr,
    ];
    let mut values = [0.0; 1 + 1001];
    // SAFETY: the paused instance; as many values as given.
    unsafe {
        fmi::fmi3GetFloat64(
            instance,
            refs.as_ptr(),
            2,
            values.as_mut_ptr(),
            values.len(),
        );
        fmi::fmi3GetFloat64(instance, refs.as_ptr(), 1, values.as_mut_ptr(), 1);
        if free {
            fmi::fmi3FreeInstance(instance);
        }
        *early_return_requested = request;
    }
}

fuzz_target!(|session: Session| {
    let name = CString::new("fuzz3").unwrap_or_default();
    let token = CString::new(FMI3_TOKEN).unwrap_or_default();
    // SAFETY: live strings for the duration of the call; no logger (messages are dropped).
    let c = unsafe {
        fmi::fmi3InstantiateCoSimulation(
            name.as_ptr(),
            token.as_ptr(),
            ptr::null(),
            false,
            true,
            session.event_mode,
            session.early_return,
            ptr::null(),
            0,
            ptr::null_mut(),
            None,
            session.intermediate_update.then_some(on_update as _),
        )
    };
    if c.is_null() {
        return;
    }
    PAUSED.set((c, false, false));
    let mut time = 0.0;
    for call in session.calls.into_iter().take(48) {
        // SAFETY: a live instance; every buffer is valid for the count passed.
        unsafe {
            match call {
                Call::EnterConfiguration => {
                    fmi::fmi3EnterConfigurationMode(c);
                }
                Call::SetSections(n) => {
                    fmi::fmi3SetUInt64(c, &N_SECTIONS, 1, &u64::from(n), 1);
                }
                Call::ExitConfiguration => {
                    fmi::fmi3ExitConfigurationMode(c);
                }
                Call::EnterInitialization { start, stop } => {
                    time = start;
                    fmi::fmi3EnterInitializationMode(
                        c,
                        false,
                        0.0,
                        start,
                        stop.is_some(),
                        stop.unwrap_or(0.0),
                    );
                }
                Call::ExitInitialization => {
                    fmi::fmi3ExitInitializationMode(c);
                }
                Call::EnterEventMode => {
                    fmi::fmi3EnterEventMode(c);
                }
                Call::UpdateDiscreteStates => {
                    let mut flags = [false; 5];
                    let mut next = 0.0;
                    let [a, b, d, e, f] = &mut flags;
                    fmi::fmi3UpdateDiscreteStates(c, a, b, d, e, f, &mut next);
                }
                Call::EnterStepMode => {
                    fmi::fmi3EnterStepMode(c);
                }
                Call::DoStep { at_time, t, size } => {
                    let t = if at_time { time } else { t };
                    let (mut event, mut terminate, mut early, mut last) =
                        (false, false, false, 0.0);
                    let status = fmi::fmi3DoStep(
                        c,
                        t,
                        STEPS[usize::from(size) % STEPS.len()],
                        false,
                        &mut event,
                        &mut terminate,
                        &mut early,
                        &mut last,
                    );
                    if status == fmi3Status_fmi3OK {
                        time = last;
                    }
                }
                Call::GetFloat64 { picks, off_by_one } => {
                    let refs: Vec<u32> = picks.into_iter().take(8).map(vr).collect();
                    let mut values = vec![0.0; 8 * 1001 + 1];
                    let mut n = 0u64;
                    fmi::fmi3GetUInt64(c, &N_SECTIONS, 1, &mut n, 1);
                    let size: usize = refs
                        .iter()
                        .map(|r| {
                            if FMI3.array(*r).is_some() {
                                n.max(1) as usize
                            } else {
                                1
                            }
                        })
                        .sum::<usize>()
                        + usize::from(off_by_one);
                    fmi::fmi3GetFloat64(
                        c,
                        refs.as_ptr(),
                        refs.len(),
                        values.as_mut_ptr(),
                        size.min(values.len()),
                    );
                }
                Call::SetFloat64 {
                    pick,
                    value_pick,
                    raw,
                } => {
                    let r = vr(pick);
                    let value = value_for(r, value_pick, raw);
                    fmi::fmi3SetFloat64(c, &r, 1, &value, 1);
                }
                Call::SetInt64 { pick, value } => {
                    let r = vr(pick);
                    fmi::fmi3SetInt64(c, &r, 1, &value, 1);
                }
                Call::Terminate => {
                    fmi::fmi3Terminate(c);
                }
                Call::Reset => {
                    fmi::fmi3Reset(c);
                }
                Call::StateRoundTrip { flip } => {
                    let mut state: fmi3FMUState = ptr::null_mut();
                    if fmi::fmi3GetFMUState(c, &mut state) == fmi3Status_fmi3OK {
                        let mut size = 0usize;
                        fmi::fmi3SerializedFMUStateSize(c, state, &mut size);
                        let mut bytes = vec![0u8; size];
                        fmi::fmi3SerializeFMUState(c, state, bytes.as_mut_ptr(), size);
                        if let Some((at, mask)) = flip {
                            let at = usize::from(at) % bytes.len().max(1);
                            if let Some(b) = bytes.get_mut(at) {
                                *b ^= mask;
                            }
                        }
                        let mut restored: fmi3FMUState = ptr::null_mut();
                        if fmi::fmi3DeserializeFMUState(c, bytes.as_ptr(), size, &mut restored)
                            == fmi3Status_fmi3OK
                        {
                            fmi::fmi3SetFMUState(c, restored);
                            fmi::fmi3FreeFMUState(c, &mut restored);
                        }
                        fmi::fmi3FreeFMUState(c, &mut state);
                    }
                }
                Call::Callback {
                    request_early_return,
                    try_to_free,
                } => PAUSED.set((c, request_early_return, try_to_free)),
            }
        }
    }
    // SAFETY: a live instance, freed once.
    unsafe { fmi::fmi3FreeInstance(c) };
});
