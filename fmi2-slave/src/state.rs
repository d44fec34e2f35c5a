//! The FMI 2.0 co-simulation state machine (FMI 2.0.4 §4.2.4) as one table.
//!
//! `StepInProgress` and `StepCanceled` never occur: the FMU is synchronous (no `fmi2Pending`).

/// States of an instance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    /// After fmi2Instantiate or fmi2Reset.
    Instantiated,
    /// Between Enter- and ExitInitializationMode.
    InitializationMode,
    /// Ready for fmi2DoStep.
    StepComplete,
    /// fmi2DoStep returned fmi2Discard.
    StepFailed,
    /// After fmi2Terminate.
    Terminated,
    /// A call returned fmi2Error.
    Error,
}

/// The instance-bound FMI functions (GetTypesPlatform, GetVersion and Instantiate need none).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Call {
    SetDebugLogging,
    SetupExperiment,
    EnterInitializationMode,
    ExitInitializationMode,
    Terminate,
    Reset,
    GetReal,
    GetInteger,
    GetBoolean,
    GetString,
    SetReal,
    SetInteger,
    SetBoolean,
    SetString,
    GetFmuState,
    SetFmuState,
    FreeFmuState,
    SerializedFmuStateSize,
    SerializeFmuState,
    DeSerializeFmuState,
    GetDirectionalDerivative,
    SetRealInputDerivatives,
    GetRealOutputDerivatives,
    DoStep,
    CancelStep,
    GetStatus,
    GetRealStatus,
    GetIntegerStatus,
    GetBooleanStatus,
    GetStringStatus,
}

use State::{Error, InitializationMode, Instantiated, StepComplete, StepFailed, Terminated};

const ALL: &[State] = &[
    Instantiated,
    InitializationMode,
    StepComplete,
    StepFailed,
    Terminated,
    Error,
];

impl Call {
    /// The states in which the call is legal (FMI 2.0.4 table in §4.2.4; docs/fmi.md §1.3).
    pub fn allowed(self) -> &'static [State] {
        match self {
            Call::SetDebugLogging => ALL,
            Call::SetupExperiment | Call::EnterInitializationMode => &[Instantiated],
            Call::ExitInitializationMode => &[InitializationMode],
            Call::DoStep => &[StepComplete],
            Call::CancelStep => &[],
            Call::Terminate => &[StepComplete, StepFailed],
            Call::Reset
            | Call::GetFmuState
            | Call::SetFmuState
            | Call::FreeFmuState
            | Call::SerializedFmuStateSize
            | Call::SerializeFmuState
            | Call::DeSerializeFmuState => ALL,
            Call::GetReal
            | Call::GetInteger
            | Call::GetBoolean
            | Call::GetString
            | Call::GetDirectionalDerivative => &[
                InitializationMode,
                StepComplete,
                StepFailed,
                Terminated,
                Error,
            ],
            Call::SetReal
            | Call::SetInteger
            | Call::SetBoolean
            | Call::SetString
            | Call::SetRealInputDerivatives => &[Instantiated, InitializationMode, StepComplete],
            Call::GetRealOutputDerivatives => &[StepComplete, StepFailed, Terminated, Error],
            Call::GetStatus
            | Call::GetRealStatus
            | Call::GetIntegerStatus
            | Call::GetBooleanStatus
            | Call::GetStringStatus => &[StepComplete, StepFailed, Terminated],
        }
    }

    /// The C function name, for messages.
    pub fn name(self) -> String {
        let debug = format!("{self:?}");
        format!("fmi2{}", debug.replace("FmuState", "FMUstate"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_follow_the_c_api() {
        assert_eq!(Call::DoStep.name(), "fmi2DoStep");
        assert_eq!(Call::DeSerializeFmuState.name(), "fmi2DeSerializeFMUstate");
        assert_eq!(Call::GetFmuState.name(), "fmi2GetFMUstate");
    }

    #[test]
    fn do_step_only_after_initialisation() {
        assert_eq!(Call::DoStep.allowed(), &[StepComplete]);
        assert!(!Call::SetReal.allowed().contains(&Terminated));
    }
}
