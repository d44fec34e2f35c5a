//! Coverage-guided fuzzing of fmi2* call sequences: up to two instances, any order of the calls
//! a co-simulation master can make, with value references and values chosen around each
//! variable's declared range. Whatever the sequence, every call must return a status (never
//! crash, hang or abort) and the instances must free cleanly.

#![no_main]

use arbitrary::Arbitrary;
use flexible_slider_crank_fuzz::{Instance, value_for, variable_count};
use libfuzzer_sys::fuzz_target;

/// One call of the master.
#[derive(Arbitrary, Debug)]
enum Call {
    Instantiate {
        guid_ok: bool,
        model_exchange: bool,
    },
    Free,
    Setup {
        tolerance: Option<f64>,
        start: f64,
        stop: Option<f64>,
    },
    EnterInitialization,
    ExitInitialization,
    Terminate,
    Reset,
    SetReal {
        vr: u8,
        pick: u8,
        raw: f64,
    },
    SetInteger {
        vr: u8,
        pick: u8,
        raw: f64,
    },
    SetBoolean {
        vr: u8,
        value: i32,
    },
    SetString {
        vr: u8,
        value: String,
    },
    GetAll {
        vrs: Vec<u8>,
    },
    Statuses,
    /// fmi2DoStep at the instance's time (or `t` itself) with one of a few step sizes.
    DoStep {
        at_time: bool,
        t: f64,
        size: u8,
        no_set_prior: bool,
    },
    CancelStep,
    SetInputDerivative {
        vr: u8,
        order: i8,
        value: f64,
    },
    GetOutputDerivative {
        vr: u8,
        order: i8,
    },
    DirectionalDerivative {
        unknown: u8,
        known: u8,
    },
    GetState {
        reuse: Option<u8>,
    },
    SetState {
        slot: u8,
    },
    FreeState {
        slot: u8,
    },
    /// Serialize a state and deserialize the bytes, optionally with one byte flipped.
    RoundTrip {
        slot: u8,
        flip: Option<(u16, u8)>,
    },
}

/// Which instance a call goes to, and the call.
#[derive(Arbitrary, Debug)]
struct Op {
    second: bool,
    call: Call,
}

/// Step sizes: from a hundredth of the default communication step to a whole default
/// experiment, plus the invalid ones.
const STEPS: [f64; 8] = [1e-6, 1e-5, 1e-4, 1e-3, 0.0, -1e-4, f64::NAN, f64::INFINITY];

/// A value reference: mostly one of the table's, sometimes just beyond it.
fn vr(x: u8) -> u32 {
    u32::from(x) % (variable_count() + 2)
}

fn apply(slots: &mut [Option<Instance>; 2], op: Op) {
    let slot = &mut slots[usize::from(op.second)];
    if let Call::Instantiate {
        guid_ok,
        model_exchange,
    } = op.call
    {
        *slot = Instance::new(if op.second { "b" } else { "a" }, guid_ok, model_exchange);
        return;
    }
    let Some(fmu) = slot.as_mut() else { return };
    match op.call {
        Call::Instantiate { .. } => {}
        Call::Free => *slot = None,
        Call::Setup {
            tolerance,
            start,
            stop,
        } => {
            fmu.setup(tolerance, start, stop);
        }
        Call::EnterInitialization => {
            fmu.enter_initialization();
        }
        Call::ExitInitialization => {
            fmu.exit_initialization();
        }
        Call::Terminate => {
            fmu.terminate();
        }
        Call::Reset => {
            fmu.reset();
        }
        Call::SetReal { vr: x, pick, raw } => {
            fmu.set_real(vr(x), value_for(vr(x), pick, raw));
        }
        Call::SetInteger { vr: x, pick, raw } => {
            let value = value_for(vr(x), pick, raw);
            fmu.set_integer(
                vr(x),
                value.clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32,
            );
        }
        Call::SetBoolean { vr: x, value } => {
            fmu.set_boolean(vr(x), value);
        }
        Call::SetString { vr: x, value } => {
            fmu.set_string(vr(x), &value);
        }
        Call::GetAll { vrs } => {
            let vrs: Vec<u32> = vrs.into_iter().take(16).map(vr).collect();
            fmu.get_all(&vrs);
        }
        Call::Statuses => fmu.statuses(),
        Call::DoStep {
            at_time,
            t,
            size,
            no_set_prior,
        } => {
            let t = if at_time { fmu.time().unwrap_or(t) } else { t };
            fmu.do_step(t, STEPS[usize::from(size) % STEPS.len()], no_set_prior);
        }
        Call::CancelStep => {
            fmu.cancel_step();
        }
        Call::SetInputDerivative {
            vr: x,
            order,
            value,
        } => {
            fmu.set_input_derivative(vr(x), i32::from(order), value);
        }
        Call::GetOutputDerivative { vr: x, order } => {
            fmu.get_output_derivative(vr(x), i32::from(order));
        }
        Call::DirectionalDerivative { unknown, known } => {
            fmu.directional_derivative(vr(unknown), vr(known));
        }
        Call::GetState { reuse } => {
            fmu.get_state(reuse.map(usize::from));
        }
        Call::SetState { slot } => {
            fmu.set_state(usize::from(slot));
        }
        Call::FreeState { slot } => {
            fmu.free_state(usize::from(slot));
        }
        Call::RoundTrip { slot, flip } => {
            if let Some(mut bytes) = fmu.serialize(usize::from(slot)) {
                if let Some((at, mask)) = flip {
                    let at = usize::from(at) % bytes.len().max(1);
                    if let Some(b) = bytes.get_mut(at) {
                        *b ^= mask;
                    }
                }
                fmu.deserialize(&bytes);
            }
        }
    }
}

fuzz_target!(|ops: Vec<Op>| {
    let mut slots: [Option<Instance>; 2] = [None, None];
    for op in ops.into_iter().take(64) {
        apply(&mut slots, op);
    }
});
