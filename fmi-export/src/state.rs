//! The co-simulation state machine of FMI 2.0 (FMI 2.0.4 §4.2.4) and FMI 3.0 (FMI 3.0.2 §4.2.4) as
//! one table: FMI 3 adds Configuration, Event and Intermediate Update Mode and its own calls.
//!
//! `StepInProgress` and `StepCanceled` never occur: the FMU is synchronous (no `fmi2Pending`).

/// States of an instance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    /// After instantiation or Reset.
    Instantiated,
    /// FMI 3: between Enter- and ExitConfigurationMode, where structural parameters are set.
    ConfigurationMode,
    /// Between Enter- and ExitInitializationMode.
    InitializationMode,
    /// Ready for DoStep (FMI 3: Step Mode).
    StepComplete,
    /// DoStep returned Discard (FMI 2's StepFailed).
    StepFailed,
    /// After Terminate.
    Terminated,
    /// A call returned Error.
    Error,
    /// FMI 3 with eventModeUsed: after an event (and after initialization), until
    /// fmi3EnterStepMode.
    EventMode,
    /// FMI 3: inside fmi3DoStep, while the master's intermediate-update callback runs.
    IntermediateUpdate,
}

/// The FMI version an instance was created through (the names of its calls in messages).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Version {
    /// fmi2Instantiate.
    Fmi2,
    /// fmi3InstantiateCoSimulation.
    Fmi3,
}

impl Version {
    /// The prefix of its C function names.
    pub fn prefix(self) -> &'static str {
        match self {
            Version::Fmi2 => "fmi2",
            Version::Fmi3 => "fmi3",
        }
    }
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
    /// fmi3GetInt64: the switches, FMI 3 Enumerations.
    GetInt64,
    /// fmi3SetInt64.
    SetInt64,
    /// fmi3EnterConfigurationMode.
    EnterConfigurationMode,
    /// fmi3ExitConfigurationMode.
    ExitConfigurationMode,
    /// fmi3GetUInt64: the structural parameters.
    GetUInt64,
    /// fmi3SetUInt64.
    SetUInt64,
    /// fmi3EnterEventMode.
    EnterEventMode,
    /// fmi3UpdateDiscreteStates.
    UpdateDiscreteStates,
    /// fmi3EnterStepMode.
    EnterStepMode,
    /// fmi3DoStep going on after the master's intermediate-update callback.
    ResumeStep,
    /// A getter of an FMI 3 type the FMU has no variable of (named: "fmi3GetFloat32"): the state
    /// rule of every getter; it refuses every value reference.
    GetOther(&'static str),
    /// A setter of an FMI 3 type the FMU has no variable of: the state rule of every setter.
    SetOther(&'static str),
    /// A call with no state rule of its own, named for messages: FMI 3's functions of the
    /// capabilities the FMU does not have (clocks, model exchange, scheduled execution, adjoint
    /// derivatives, variable dependencies), which refuse every non-empty request.
    Other(&'static str),
}

use State::{
    ConfigurationMode, Error, EventMode, InitializationMode, Instantiated, IntermediateUpdate,
    StepComplete, StepFailed, Terminated,
};

/// Every state: the logging switch and the refusals of what the FMU lacks work everywhere.
const EVERYWHERE: &[State] = &[
    Instantiated,
    ConfigurationMode,
    InitializationMode,
    StepComplete,
    StepFailed,
    Terminated,
    Error,
    EventMode,
    IntermediateUpdate,
];

/// Every state but Intermediate Update (where fmi3DoStep is under way).
const ALL: &[State] = &[
    Instantiated,
    ConfigurationMode,
    InitializationMode,
    StepComplete,
    StepFailed,
    Terminated,
    Error,
    EventMode,
];

/// Where an FMU state may be got, set and serialized: everywhere but Configuration Mode (whose
/// structural parameters are not a run's state).
const FMU_STATE: &[State] = &[
    Instantiated,
    InitializationMode,
    StepComplete,
    StepFailed,
    Terminated,
    Error,
    EventMode,
];

impl Call {
    /// The states in which the call is legal (FMI 2.0.4 table in §4.2.4; docs/fmi.md §1.3).
    pub fn allowed(self) -> &'static [State] {
        match self {
            Call::SetDebugLogging | Call::Other(_) => EVERYWHERE,
            Call::SetupExperiment | Call::EnterInitializationMode => &[Instantiated],
            Call::ExitInitializationMode => &[InitializationMode],
            Call::DoStep => &[StepComplete],
            Call::CancelStep => &[],
            Call::Terminate => &[StepComplete, StepFailed, EventMode],
            Call::Reset => ALL,
            Call::EnterConfigurationMode => &[Instantiated],
            Call::ExitConfigurationMode => &[ConfigurationMode],
            Call::GetUInt64 => &[
                InitializationMode,
                StepComplete,
                StepFailed,
                Terminated,
                Error,
                EventMode,
                IntermediateUpdate,
            ],
            Call::ResumeStep => &[IntermediateUpdate],
            Call::EnterEventMode => &[StepComplete],
            Call::UpdateDiscreteStates | Call::EnterStepMode => &[EventMode],
            Call::GetFmuState
            | Call::SetFmuState
            | Call::FreeFmuState
            | Call::SerializedFmuStateSize
            | Call::SerializeFmuState
            | Call::DeSerializeFmuState => FMU_STATE,
            Call::GetReal
            | Call::GetInteger
            | Call::GetBoolean
            | Call::GetString
            | Call::GetInt64
            | Call::GetOther(_) => &[
                InitializationMode,
                StepComplete,
                StepFailed,
                Terminated,
                Error,
                EventMode,
                IntermediateUpdate,
            ],
            Call::GetDirectionalDerivative => &[
                InitializationMode,
                StepComplete,
                StepFailed,
                Terminated,
                Error,
                EventMode,
            ],
            // FMI 3 sets structural parameters in Configuration Mode, and only them there
            // (checked per variable).
            Call::SetReal
            | Call::SetInteger
            | Call::SetBoolean
            | Call::SetString
            | Call::SetInt64
            | Call::SetUInt64
            | Call::SetOther(_) => &[
                Instantiated,
                ConfigurationMode,
                InitializationMode,
                StepComplete,
                EventMode,
            ],
            Call::SetRealInputDerivatives => {
                &[Instantiated, InitializationMode, StepComplete, EventMode]
            }
            Call::GetRealOutputDerivatives => &[StepComplete, StepFailed, Terminated, Error],
            Call::GetStatus
            | Call::GetRealStatus
            | Call::GetIntegerStatus
            | Call::GetBooleanStatus
            | Call::GetStringStatus => &[StepComplete, StepFailed, Terminated],
        }
    }

    /// The C function name in FMI `version`, for messages.
    pub fn name(self, version: Version) -> String {
        let debug = format!("{self:?}");
        match (version, self) {
            (_, Call::Other(name) | Call::GetOther(name) | Call::SetOther(name)) => {
                name.to_string()
            }
            (Version::Fmi2, _) => format!("fmi2{}", debug.replace("FmuState", "FMUstate")),
            (Version::Fmi3, Call::SetupExperiment) => "fmi3EnterInitializationMode".into(),
            (Version::Fmi3, Call::ResumeStep) => "fmi3DoStep".into(),
            (Version::Fmi3, Call::GetRealOutputDerivatives) => "fmi3GetOutputDerivatives".into(),
            (Version::Fmi3, _) => format!(
                "fmi3{}",
                debug
                    .replace("Real", "Float64")
                    .replace("Integer", "Int32")
                    .replace("FmuState", "FMUState")
                    .replace("DeSerialize", "Deserialize")
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_follow_the_c_api() {
        let fmi2 = |call: Call| call.name(Version::Fmi2);
        assert_eq!(fmi2(Call::DoStep), "fmi2DoStep");
        assert_eq!(fmi2(Call::DeSerializeFmuState), "fmi2DeSerializeFMUstate");
        assert_eq!(fmi2(Call::GetFmuState), "fmi2GetFMUstate");
        let fmi3 = |call: Call| call.name(Version::Fmi3);
        assert_eq!(fmi3(Call::GetReal), "fmi3GetFloat64");
        assert_eq!(fmi3(Call::SetInteger), "fmi3SetInt32");
        assert_eq!(fmi3(Call::DeSerializeFmuState), "fmi3DeserializeFMUState");
        assert_eq!(fmi3(Call::SetupExperiment), "fmi3EnterInitializationMode");
        assert_eq!(fmi3(Call::Other("fmi3SetClock")), "fmi3SetClock");
    }

    #[test]
    fn do_step_only_after_initialisation() {
        assert_eq!(Call::DoStep.allowed(), &[StepComplete]);
        assert!(!Call::SetReal.allowed().contains(&Terminated));
    }
}
