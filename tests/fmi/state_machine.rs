//! The state machine: every function in every state where FMI 2.0.4 forbids it is an error, and
//! calls refused after an error name the first one.

use fmi_export::{Call, State, Version};
use fmi_sys::fmi2::*;

use crate::harness::{Instance, fmu, vr};

const OK: fmi2Status = fmi2Status_fmi2OK;
const ERROR: fmi2Status = fmi2Status_fmi2Error;

/// Every call in a state where it is illegal returns fmi2Error with "Illegal call sequence."
/// and does not crash; FreeInstance works afterwards; NULL components are errors.
#[test]
fn illegal_calls_are_errors() {
    type Check = (&'static str, fn(&Instance) -> fmi2Status);
    let before_init: &[Check] = &[
        ("fmi2DoStep", |i| i.do_step(0.0, 1e-4)),
        ("fmi2ExitInitializationMode", |i| i.exit()),
        ("fmi2Terminate", |i| i.terminate()),
        ("fmi2GetReal", |i| i.get_real(vr("slider.position")).0),
        // SAFETY: live instance.
        ("fmi2CancelStep", |i| unsafe { fmu().fmi2CancelStep(i.c) }),
    ];
    for (name, call) in before_init {
        let inst = Instance::new(&format!("illegal-{name}"));
        assert_eq!(call(&inst), ERROR, "{name} in Instantiated");
        assert!(
            inst.last_message()
                .contains(&format!("{name}: Illegal call sequence.")),
            "{:?}",
            inst.messages()
        );
    }
    let after_init: &[Check] = &[
        ("fmi2SetupExperiment", |i| i.setup(0.0, None)),
        ("fmi2EnterInitializationMode", |i| i.enter()),
        ("fmi2SetReal", |i| i.set_real(vr("rod.length"), 0.2)),
        ("fmi2SetInteger", |i| i.set_integer(vr("rod.nModes"), 2)),
    ];
    for (name, call) in after_init {
        let inst = Instance::new(&format!("late-{name}"));
        inst.initialize();
        assert_eq!(call(&inst), ERROR, "{name} in StepComplete");
        assert!(!inst.last_message().is_empty());
        // After an error only reset/free/get: DoStep is illegal now.
        assert_eq!(inst.do_step(0.0, 1e-4), ERROR);
        assert_eq!(inst.reset(), OK, "reset after error");
    }
    // SAFETY: NULL components are rejected before any dereference.
    unsafe {
        assert_eq!(fmu().fmi2DoStep(std::ptr::null_mut(), 0.0, 1e-4, 0), ERROR);
        assert_eq!(fmu().fmi2Reset(std::ptr::null_mut()), ERROR);
        fmu().fmi2FreeInstance(std::ptr::null_mut());
    }
}

/// Calls `call` on `inst` with harmless arguments (empty arrays, a valid FMU state).
fn invoke(inst: &Instance, call: Call, state: fmi2FMUstate, bytes: &[u8]) -> fmi2Status {
    let f = fmu();
    let c = inst.c;
    let (mut real, mut int, mut status) = (0.0, 0, 0);
    let mut string: fmi2String = std::ptr::null();
    let mut size = 0usize;
    let mut buffer = vec![0u8; bytes.len()];
    let mut new_state: fmi2FMUstate = std::ptr::null_mut();
    let null_vr: *const fmi2ValueReference = std::ptr::null();
    // SAFETY: every pointer is valid for the element counts given (0 for the value arrays), and
    // `state`/`bytes` are a live state and its serialization from this FMU.
    let result = unsafe {
        match call {
            Call::SetDebugLogging => f.fmi2SetDebugLogging(c, 0, 0, std::ptr::null()),
            Call::SetupExperiment => f.fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0),
            Call::EnterInitializationMode => f.fmi2EnterInitializationMode(c),
            Call::ExitInitializationMode => f.fmi2ExitInitializationMode(c),
            Call::Terminate => f.fmi2Terminate(c),
            Call::Reset => f.fmi2Reset(c),
            Call::GetReal => f.fmi2GetReal(c, null_vr, 0, std::ptr::null_mut()),
            Call::GetInteger => f.fmi2GetInteger(c, null_vr, 0, std::ptr::null_mut()),
            Call::GetBoolean => f.fmi2GetBoolean(c, null_vr, 0, std::ptr::null_mut()),
            Call::GetString => f.fmi2GetString(c, null_vr, 0, std::ptr::null_mut()),
            Call::SetReal => f.fmi2SetReal(c, null_vr, 0, std::ptr::null()),
            Call::SetInteger => f.fmi2SetInteger(c, null_vr, 0, std::ptr::null()),
            Call::SetBoolean => f.fmi2SetBoolean(c, null_vr, 0, std::ptr::null()),
            Call::SetString => f.fmi2SetString(c, null_vr, 0, std::ptr::null()),
            Call::GetFmuState => f.fmi2GetFMUstate(c, &mut new_state),
            Call::SetFmuState => f.fmi2SetFMUstate(c, state),
            Call::FreeFmuState => f.fmi2FreeFMUstate(c, &mut new_state),
            Call::SerializedFmuStateSize => f.fmi2SerializedFMUstateSize(c, state, &mut size),
            Call::SerializeFmuState => {
                f.fmi2SerializeFMUstate(c, state, buffer.as_mut_ptr().cast(), buffer.len())
            }
            Call::DeSerializeFmuState => {
                f.fmi2DeSerializeFMUstate(c, bytes.as_ptr().cast(), bytes.len(), &mut new_state)
            }
            Call::GetDirectionalDerivative => f.fmi2GetDirectionalDerivative(
                c,
                null_vr,
                0,
                null_vr,
                0,
                std::ptr::null(),
                std::ptr::null_mut(),
            ),
            Call::SetRealInputDerivatives => {
                f.fmi2SetRealInputDerivatives(c, null_vr, 0, std::ptr::null(), std::ptr::null())
            }
            Call::GetRealOutputDerivatives => f.fmi2GetRealOutputDerivatives(
                c,
                null_vr,
                0,
                std::ptr::null(),
                std::ptr::null_mut(),
            ),
            Call::DoStep => f.fmi2DoStep(c, 0.0, 1e-4, 0),
            Call::CancelStep => f.fmi2CancelStep(c),
            Call::GetStatus => f.fmi2GetStatus(c, fmi2StatusKind_fmi2DoStepStatus, &mut status),
            Call::GetRealStatus => {
                f.fmi2GetRealStatus(c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut real)
            }
            Call::GetIntegerStatus => {
                f.fmi2GetIntegerStatus(c, fmi2StatusKind_fmi2PendingStatus, &mut int)
            }
            Call::GetBooleanStatus => {
                f.fmi2GetBooleanStatus(c, fmi2StatusKind_fmi2Terminated, &mut int)
            }
            Call::GetStringStatus => {
                f.fmi2GetStringStatus(c, fmi2StatusKind_fmi2PendingStatus, &mut string)
            }
            Call::GetInt64
            | Call::SetInt64
            | Call::EnterConfigurationMode
            | Call::ExitConfigurationMode
            | Call::GetUInt64
            | Call::SetUInt64
            | Call::EnterEventMode
            | Call::UpdateDiscreteStates
            | Call::EnterStepMode
            | Call::ResumeStep
            | Call::Other(_)
            | Call::GetOther(_)
            | Call::SetOther(_) => {
                unreachable!("{call:?} has no FMI 2 function")
            }
        }
    };
    if !new_state.is_null() {
        // SAFETY: a state this call allocated, freed once.
        unsafe { f.fmi2FreeFMUstate(c, &mut new_state) };
    }
    result
}

const CALLS: [Call; 30] = [
    Call::SetDebugLogging,
    Call::SetupExperiment,
    Call::EnterInitializationMode,
    Call::ExitInitializationMode,
    Call::Terminate,
    Call::Reset,
    Call::GetReal,
    Call::GetInteger,
    Call::GetBoolean,
    Call::GetString,
    Call::SetReal,
    Call::SetInteger,
    Call::SetBoolean,
    Call::SetString,
    Call::GetFmuState,
    Call::SetFmuState,
    Call::FreeFmuState,
    Call::SerializedFmuStateSize,
    Call::SerializeFmuState,
    Call::DeSerializeFmuState,
    Call::GetDirectionalDerivative,
    Call::SetRealInputDerivatives,
    Call::GetRealOutputDerivatives,
    Call::DoStep,
    Call::CancelStep,
    Call::GetStatus,
    Call::GetRealStatus,
    Call::GetIntegerStatus,
    Call::GetBooleanStatus,
    Call::GetStringStatus,
];

/// An instance driven into `state` (StepFailed: by a step the work limit discards), with the rigid
/// rod: the state machine is the same for every model, and the rigid one builds at once.
fn in_state(name: &str, state: State) -> Instance {
    let inst = Instance::new(name);
    assert_eq!(inst.set_integer(vr("rod.formulation"), 1), OK);
    match state {
        State::Instantiated => {}
        State::InitializationMode => {
            assert_eq!(inst.setup(0.0, None), OK);
            assert_eq!(inst.enter(), OK);
        }
        State::StepComplete => inst.initialize(),
        State::Terminated => {
            inst.initialize();
            assert_eq!(inst.terminate(), OK);
        }
        State::Error => assert_eq!(inst.do_step(0.0, 1e-4), ERROR),
        State::StepFailed => {
            let limit = vr("solver.maxStepsPerInterval");
            assert_eq!(inst.set_integer(limit, 1), OK);
            inst.initialize();
            assert_eq!(inst.do_step(0.0, 1e-3), fmi2Status_fmi2Discard);
        }
        State::ConfigurationMode | State::EventMode | State::IntermediateUpdate => {
            unreachable!("FMI 3 only (tests/fmi/fmi3.rs)")
        }
    }
    inst
}

/// A call refused in the Error state names the error that put the instance there.
#[test]
fn calls_after_an_error_name_the_first_error() {
    let inst = Instance::new("first-error");
    assert_eq!(inst.set_real(vr("rod.length"), -1.0), ERROR);
    let first = inst.last_message();
    assert!(first.contains("rod.length"), "{first}");
    assert_eq!(inst.do_step(0.0, 1e-4), ERROR);
    let refused = inst.last_message();
    assert!(
        refused.contains("fmi2DoStep: Illegal call sequence.") && refused.contains(&first),
        "{refused}"
    );
    // SAFETY: live instance.
    assert_eq!(unsafe { fmu().fmi2Reset(inst.c) }, fmi2Status_fmi2OK);
    assert_eq!(inst.do_step(0.0, 1e-4), ERROR);
    assert!(
        !inst.last_message().contains("since"),
        "{}",
        inst.last_message()
    );
}

/// After a discarded step every refused call names the discard that put the instance in the
/// StepFailed state, with its reason, once (no doubled function name); the number format is the
/// one of every message (the shortest round-trip decimal).
#[test]
fn calls_after_a_discard_name_the_discard() {
    let inst = Instance::new("discard");
    assert_eq!(
        inst.set_integer(vr("solver.maxStepsPerInterval"), 5),
        fmi2Status_fmi2OK
    );
    inst.initialize();
    assert_eq!(inst.do_step(0.0, 1e-3), fmi2Status_fmi2Discard);
    let discard = inst.last_message();
    assert!(
        discard.starts_with("fmi2DoStep: step discarded")
            && !discard.contains("fmi2DoStep: fmi2DoStep"),
        "{discard}"
    );
    assert_eq!(inst.do_step(0.0, 1e-4), ERROR);
    let refused = inst.last_message();
    assert!(
        refused.contains("Illegal call sequence. The instance is in the StepFailed state since: fmi2DoStep: step discarded")
            && refused.contains("solver.maxStepsPerInterval = 5"),
        "{refused}"
    );
    assert!(
        !refused.contains("e0") && !refused.contains("e-0"),
        "{refused}"
    );
}

/// The states, among those this test reaches, in which FMI 2.0 Co-Simulation allows `call`:
/// transcribed from the standard's table of the calling sequence (FMI 2.0.4, §4.2.4; the same
/// table as the masks of the Modelica Association's Reference FMUs), independently of the
/// implementation's own table. StepInProgress and StepCanceled are not reached (the FMU never
/// returns fmi2Pending).
fn fmi2_allows(call: Call) -> &'static [State] {
    use State::{Error as E, InitializationMode as I, Instantiated as N, StepComplete as C};
    use State::{StepFailed as F, Terminated as T};
    match call {
        Call::SetDebugLogging | Call::Reset => &[N, I, C, F, T, E],
        Call::GetFmuState
        | Call::SetFmuState
        | Call::FreeFmuState
        | Call::SerializedFmuStateSize
        | Call::SerializeFmuState
        | Call::DeSerializeFmuState => &[N, I, C, F, T, E],
        Call::SetupExperiment | Call::EnterInitializationMode => &[N],
        Call::ExitInitializationMode => &[I],
        Call::Terminate => &[C, F],
        Call::DoStep => &[C],
        Call::GetReal | Call::GetInteger | Call::GetBoolean | Call::GetString => &[I, C, F, T, E],
        Call::GetDirectionalDerivative => &[I, C, F, T, E],
        Call::SetReal | Call::SetInteger | Call::SetBoolean | Call::SetString => &[N, I, C],
        Call::SetRealInputDerivatives => &[N, I, C],
        Call::GetRealOutputDerivatives => &[C, F, T, E],
        Call::CancelStep => &[],
        Call::GetStatus
        | Call::GetRealStatus
        | Call::GetIntegerStatus
        | Call::GetBooleanStatus
        | Call::GetStringStatus => &[C, F, T],
        _ => unreachable!("{call:?} has no FMI 2 function"),
    }
}

/// Every instance function in every reachable state: where the FMI 2 state machine forbids it
/// ([`fmi2_allows`], the standard's table) it returns fmi2Error with "fmi2X: Illegal call
/// sequence." and no crash; where the table allows it, it is not refused as illegal (it may still
/// report something else, such as a status that is not pending). 30 functions × 6 states.
#[test]
fn every_function_in_every_illegal_state_is_an_error() {
    let donor = in_state("donor", State::StepComplete);
    let state = donor.get_state();
    let bytes = donor.serialize(state);
    let mut checked = 0;
    for s in [
        State::Instantiated,
        State::InitializationMode,
        State::StepComplete,
        State::StepFailed,
        State::Terminated,
        State::Error,
    ] {
        for call in CALLS {
            let inst = in_state(&format!("sm-{s:?}-{call:?}"), s);
            let before = inst.messages().len();
            let status = invoke(&inst, call, state, &bytes);
            let messages = inst.messages();
            let illegal = format!("{}: Illegal call sequence.", call.name(Version::Fmi2));
            let refused = messages[before..].iter().any(|m| m.contains(&illegal));
            if fmi2_allows(call).contains(&s) {
                assert!(!refused, "{call:?} in {s:?} is allowed: {messages:?}");
                continue;
            }
            assert_eq!(status, ERROR, "{call:?} in {s:?}");
            assert!(refused, "{call:?} in {s:?}: {messages:?}");
            checked += 1;
        }
    }
    println!("{checked} illegal (function, state) pairs checked");
    // The FMI 2 table forbids 67 (function, state) pairs among these six states.
    assert_eq!(checked, 67);
    donor.free_state(state);
}
