//! The FMI 3 state machine against the standard's: every `fmi3*` function of an instance in every
//! state this test reaches, refused with fmi3Error where FMI 3.0 forbids it and never refused as
//! an illegal call where it allows it.

use fmi_export::{Call, Version};
use fmi_sys::fmi3::*;

use super::{ERROR, GUID, Instance3, fmu3};
use crate::harness::vr;

/// The FMI 3 states this test reaches. FMI 3 has no Error state of its own: a function that
/// returns fmi3Error leaves the FMU in Terminated (FMI 3.0.2 §2.3.1), so the instance's Error
/// state is checked against Terminated's row.
#[derive(Clone, Copy, Debug, PartialEq)]
enum S3 {
    Instantiated,
    ConfigurationMode,
    InitializationMode,
    EventMode,
    StepMode,
    Terminated,
    AfterError,
}

/// The states, among those this test reaches, in which FMI 3.0 Co-Simulation allows `call`,
/// transcribed from the standard's state descriptions (FMI 3.0.2 §2.3 "State Machine and
/// Semantics" and §4.2.1 "State Machine for Co-Simulation"), independently of the implementation's
/// table:
/// - super state FMU State Settable (every state): fmi3SetDebugLogging, fmi3Reset,
///   fmi3FreeInstance and the six FMU-state functions;
/// - Instantiated: fmi3Set{VariableType}, fmi3Get{VariableType} (start values),
///   fmi3EnterConfigurationMode (the FMU has structural parameters), fmi3EnterInitializationMode;
/// - Configuration Mode: fmi3Set{VariableType} (structural parameters), fmi3ExitConfigurationMode;
/// - Initialization Mode: fmi3Set/Get{VariableType}, fmi3GetDirectionalDerivative,
///   fmi3ExitInitializationMode;
/// - super state Initialized (Event and Step Mode): fmi3Terminate;
/// - Event Mode: fmi3Set/Get{VariableType}, fmi3GetDirectionalDerivative,
///   fmi3UpdateDiscreteStates, fmi3EnterStepMode (fmi3EnterConfigurationMode only with tunable
///   structural parameters, which the FMU has not);
/// - Step Mode: fmi3Set/Get{VariableType}, fmi3GetOutputDerivatives,
///   fmi3GetDirectionalDerivative, fmi3DoStep, fmi3EnterEventMode (only for an instance created
///   with eventModeUsed, which the Step Mode instance here is not);
/// - Terminated: fmi3Get{VariableType}, fmi3GetDirectionalDerivative, fmi3GetOutputDerivatives.
///
/// `get` and `set` stand for the fmi3Get/Set{VariableType} functions (`Call::Other` among them:
/// the types the FMU has no variable of).
fn fmi3_allows(call: Call) -> &'static [S3] {
    use S3::{
        AfterError as E, ConfigurationMode as K, EventMode as V, InitializationMode as I,
        Instantiated as N, StepMode as S, Terminated as T,
    };
    const EVERY: &[S3] = &[N, K, I, V, S, T, E];
    match call {
        Call::SetDebugLogging | Call::Reset => EVERY,
        Call::GetFmuState
        | Call::SetFmuState
        | Call::FreeFmuState
        | Call::SerializedFmuStateSize
        | Call::SerializeFmuState
        | Call::DeSerializeFmuState => EVERY,
        Call::EnterConfigurationMode => &[N],
        Call::ExitConfigurationMode => &[K],
        Call::EnterInitializationMode => &[N],
        Call::ExitInitializationMode => &[I],
        Call::Terminate => &[V, S],
        Call::UpdateDiscreteStates | Call::EnterStepMode => &[V],
        Call::DoStep => &[S],
        Call::EnterEventMode => &[],
        Call::GetReal
        | Call::GetInteger
        | Call::GetInt64
        | Call::GetBoolean
        | Call::GetString
        | Call::GetUInt64
        | Call::GetOther("fmi3GetFloat32") => &[N, I, V, S, T, E],
        Call::SetReal
        | Call::SetInteger
        | Call::SetInt64
        | Call::SetBoolean
        | Call::SetString
        | Call::SetUInt64
        | Call::SetOther("fmi3SetFloat32") => &[N, K, I, V, S],
        Call::GetDirectionalDerivative => &[I, V, S, T, E],
        Call::GetRealOutputDerivatives => &[S, T, E],
        _ => unreachable!("{call:?} is not checked here"),
    }
}

/// Where the implementation refuses a call the standard allows, on purpose, with the reason:
/// - no FMU state is taken or restored in Configuration Mode: the structural parameters set there
///   are not part of a run's state, and restoring would leave them unset;
/// - nothing is read in Instantiated: the model, and the size of its arrays, exist only after
///   Configuration Mode, and FMI 2 (whose table the two versions share) forbids reading there;
///   the start values are in the description.
fn deliberate(call: Call, s: S3) -> bool {
    match call {
        Call::GetFmuState
        | Call::SetFmuState
        | Call::FreeFmuState
        | Call::SerializedFmuStateSize
        | Call::SerializeFmuState
        | Call::DeSerializeFmuState => s == S3::ConfigurationMode,
        Call::GetReal
        | Call::GetInteger
        | Call::GetInt64
        | Call::GetBoolean
        | Call::GetString
        | Call::GetUInt64
        | Call::GetOther("fmi3GetFloat32") => s == S3::Instantiated,
        _ => false,
    }
}

/// Every instance function of the FMU's FMI 3 interface that this test calls.
const CALLS: [Call; 31] = [
    Call::SetDebugLogging,
    Call::Reset,
    Call::GetFmuState,
    Call::SetFmuState,
    Call::FreeFmuState,
    Call::SerializedFmuStateSize,
    Call::SerializeFmuState,
    Call::DeSerializeFmuState,
    Call::EnterConfigurationMode,
    Call::ExitConfigurationMode,
    Call::EnterInitializationMode,
    Call::ExitInitializationMode,
    Call::Terminate,
    Call::UpdateDiscreteStates,
    Call::EnterStepMode,
    Call::DoStep,
    Call::EnterEventMode,
    Call::GetReal,
    Call::GetInteger,
    Call::GetInt64,
    Call::GetBoolean,
    Call::GetString,
    Call::GetUInt64,
    Call::GetOther("fmi3GetFloat32"),
    Call::SetReal,
    Call::SetInteger,
    Call::SetInt64,
    Call::SetBoolean,
    Call::SetString,
    Call::SetUInt64,
    Call::SetOther("fmi3SetFloat32"),
];

/// An instance driven into `s` (Event Mode: created with eventModeUsed), with the rigid rod:
/// the state machine is the same for every model, and the rigid one builds at once.
fn in_state(s: S3) -> Instance3 {
    let (inst, _) = Instance3::try_new(GUID, s == S3::EventMode, false);
    let inst = inst.expect("instantiated");
    let f = fmu3();
    // SAFETY: a live instance.
    unsafe {
        if s != S3::ConfigurationMode {
            assert_eq!(f.fmi3SetInt64(inst.c, &vr("rod.formulation"), 1, &1, 1), 0);
        }
        match s {
            S3::Instantiated => {}
            S3::ConfigurationMode => assert_eq!(f.fmi3EnterConfigurationMode(inst.c), 0),
            S3::InitializationMode | S3::EventMode | S3::StepMode | S3::Terminated => {
                assert_eq!(
                    f.fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
                    0
                );
                if s != S3::InitializationMode {
                    assert_eq!(f.fmi3ExitInitializationMode(inst.c), 0);
                }
                if s == S3::Terminated {
                    assert_eq!(f.fmi3Terminate(inst.c), 0);
                }
            }
            S3::AfterError => assert_eq!(inst.do_step(0.0, 1e-4).0, ERROR),
        }
    }
    inst
}

/// Calls `call` on `inst` with harmless arguments (empty arrays, a valid FMU state and its bytes).
fn invoke(inst: &Instance3, call: Call, state: fmi3FMUState, bytes: &[u8]) -> fmi3Status {
    let f = fmu3();
    let c = inst.c;
    let vr: *const fmi3ValueReference = std::ptr::null();
    let mut size = 0usize;
    let mut buffer = vec![0u8; bytes.len()];
    let mut new_state: fmi3FMUState = std::ptr::null_mut();
    let (mut b, mut t) = ([false; 5], 0.0);
    let mut last = 0.0;
    // SAFETY: every pointer is valid for the element counts given (0 for the value arrays), and
    // `state`/`bytes` are a live state and its serialization from this FMU.
    let result = unsafe {
        match call {
            Call::SetDebugLogging => f.fmi3SetDebugLogging(c, false, 0, std::ptr::null()),
            Call::Reset => f.fmi3Reset(c),
            Call::GetFmuState => f.fmi3GetFMUState(c, &mut new_state),
            Call::SetFmuState => f.fmi3SetFMUState(c, state),
            Call::FreeFmuState => f.fmi3FreeFMUState(c, &mut new_state),
            Call::SerializedFmuStateSize => f.fmi3SerializedFMUStateSize(c, state, &mut size),
            Call::SerializeFmuState => {
                f.fmi3SerializeFMUState(c, state, buffer.as_mut_ptr(), buffer.len())
            }
            Call::DeSerializeFmuState => {
                f.fmi3DeserializeFMUState(c, bytes.as_ptr(), bytes.len(), &mut new_state)
            }
            Call::EnterConfigurationMode => f.fmi3EnterConfigurationMode(c),
            Call::ExitConfigurationMode => f.fmi3ExitConfigurationMode(c),
            Call::EnterInitializationMode => {
                f.fmi3EnterInitializationMode(c, false, 0.0, 0.0, false, 0.0)
            }
            Call::ExitInitializationMode => f.fmi3ExitInitializationMode(c),
            Call::Terminate => f.fmi3Terminate(c),
            Call::UpdateDiscreteStates => {
                let [a, b1, c1, d, e] = &mut b;
                f.fmi3UpdateDiscreteStates(c, a, b1, c1, d, e, &mut t)
            }
            Call::EnterStepMode => f.fmi3EnterStepMode(c),
            Call::DoStep => {
                let [a, b1, c1, ..] = &mut b;
                f.fmi3DoStep(c, 0.0, 1e-4, false, a, b1, c1, &mut last)
            }
            Call::EnterEventMode => f.fmi3EnterEventMode(c),
            Call::GetReal => f.fmi3GetFloat64(c, vr, 0, std::ptr::null_mut(), 0),
            Call::GetInteger => f.fmi3GetInt32(c, vr, 0, std::ptr::null_mut(), 0),
            Call::GetInt64 => f.fmi3GetInt64(c, vr, 0, std::ptr::null_mut(), 0),
            Call::GetBoolean => f.fmi3GetBoolean(c, vr, 0, std::ptr::null_mut(), 0),
            Call::GetString => f.fmi3GetString(c, vr, 0, std::ptr::null_mut(), 0),
            Call::GetUInt64 => f.fmi3GetUInt64(c, vr, 0, std::ptr::null_mut(), 0),
            Call::GetOther("fmi3GetFloat32") => f.fmi3GetFloat32(c, vr, 0, std::ptr::null_mut(), 0),
            Call::SetReal => f.fmi3SetFloat64(c, vr, 0, std::ptr::null(), 0),
            Call::SetInteger => f.fmi3SetInt32(c, vr, 0, std::ptr::null(), 0),
            Call::SetInt64 => f.fmi3SetInt64(c, vr, 0, std::ptr::null(), 0),
            Call::SetBoolean => f.fmi3SetBoolean(c, vr, 0, std::ptr::null(), 0),
            Call::SetString => f.fmi3SetString(c, vr, 0, std::ptr::null(), 0),
            Call::SetUInt64 => f.fmi3SetUInt64(c, vr, 0, std::ptr::null(), 0),
            Call::SetOther("fmi3SetFloat32") => f.fmi3SetFloat32(c, vr, 0, std::ptr::null(), 0),
            _ => unreachable!("{call:?} is not checked here"),
        }
    };
    if !new_state.is_null() {
        // SAFETY: a state this call allocated, freed once.
        unsafe { f.fmi3FreeFMUState(c, &mut new_state) };
    }
    result
}

/// Every function of [`CALLS`] in every state of [`S3`]: where FMI 3.0 forbids it
/// ([`fmi3_allows`]) it returns fmi3Error; where it allows it, it is not refused as an illegal
/// call, but for the refusals the implementation makes on purpose ([`deliberate`], each with its
/// reason), which are counted so that none comes or goes unnoticed.
#[test]
fn every_fmi3_function_in_every_state_as_the_standard_says() {
    let donor = in_state(S3::StepMode);
    let f = fmu3();
    let mut state: fmi3FMUState = std::ptr::null_mut();
    let mut size = 0usize;
    // SAFETY: a live instance; the state is freed at the end.
    let bytes = unsafe {
        assert_eq!(f.fmi3GetFMUState(donor.c, &mut state), 0);
        assert_eq!(f.fmi3SerializedFMUStateSize(donor.c, state, &mut size), 0);
        let mut bytes = vec![0u8; size];
        assert_eq!(
            f.fmi3SerializeFMUState(donor.c, state, bytes.as_mut_ptr(), size),
            0
        );
        bytes
    };
    let (mut forbidden, mut refused_on_purpose) = (0, 0);
    let mut wrong = Vec::new();
    for s in [
        S3::Instantiated,
        S3::ConfigurationMode,
        S3::InitializationMode,
        S3::EventMode,
        S3::StepMode,
        S3::Terminated,
        S3::AfterError,
    ] {
        for call in CALLS {
            let inst = in_state(s);
            let before = inst.messages().len();
            let status = invoke(&inst, call, state, &bytes);
            let messages = inst.messages();
            let name = call.name(Version::Fmi3);
            let illegal = format!("{name}: Illegal call sequence.");
            let refused = messages[before..].iter().any(|m| m.contains(&illegal));
            if !fmi3_allows(call).contains(&s) {
                forbidden += 1;
                if status != ERROR {
                    wrong.push(format!("{call:?} in {s:?} is forbidden, returned {status}"));
                }
                // the refusal says so, naming the function (after an error: and the error; Event
                // Mode in Step Mode: that the instance does not use it)
                let says = messages[before..].iter().any(|m| {
                    m.contains(&format!("{name}: Illegal call sequence"))
                        || m.contains(&format!(
                            "{name}: the instance was created with eventModeUsed = false"
                        ))
                });
                if !says {
                    wrong.push(format!(
                        "{call:?} in {s:?}: refused without saying why: {messages:?}"
                    ));
                }
            } else if deliberate(call, s) {
                refused_on_purpose += 1;
                if status != ERROR {
                    wrong.push(format!("{call:?} in {s:?}: no longer refused"));
                }
            } else if refused {
                wrong.push(format!("{call:?} in {s:?} is allowed: {messages:?}"));
            }
        }
    }
    // SAFETY: the donor's state, freed once.
    unsafe { f.fmi3FreeFMUState(donor.c, &mut state) };
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    println!("{forbidden} forbidden pairs, {refused_on_purpose} refused on purpose");
    // FMI 3.0 forbids 75 of these (function, state) pairs; the implementation refuses 13 more on
    // purpose: 6 FMU-state functions in Configuration Mode and 7 getters in Instantiated.
    assert_eq!((forbidden, refused_on_purpose), (75, 13));
}
