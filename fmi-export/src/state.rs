//! The co-simulation state machine of FMI 2.0 (FMI 2.0.4 §4.2.4) and FMI 3.0 (FMI 3.0.2 §4.2.4) as
//! one table: FMI 3 adds Configuration, Event and Intermediate Update Mode and its own calls.
//!
//! `StepInProgress` and `StepCanceled` never occur: the FMU is synchronous (no `fmi2Pending`).

use crate::error::FmuError;

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

/// An instance's place in the state machine: its state, whether a caught panic poisoned it (only
/// Reset and FreeInstance are accepted then), and what put it in the Error or StepFailed state
/// (the first error, the discarded step), for the calls refused there. Every change of state is
/// one of this module's: [`Call::allowed`] says where a call may be made, [`Call::leads_to`] where
/// it goes when it succeeds.
#[derive(Clone, Debug, PartialEq)]
pub struct Machine {
    state: State,
    poisoned: bool,
    cause: Option<String>,
}

impl Default for Machine {
    /// Instantiated, not poisoned.
    fn default() -> Self {
        Self {
            state: Instantiated,
            poisoned: false,
            cause: None,
        }
    }
}

impl Machine {
    /// The state.
    pub fn state(&self) -> State {
        self.state
    }

    /// Whether `call` (of FMI `version`, named so in messages) may be made now: not on a
    /// poisoned instance but Reset, and only in a state where the table allows it (the refusal
    /// then names what put the instance there, if anything did).
    pub fn admit(&self, call: Call, version: Version) -> Result<(), FmuError> {
        if self.poisoned && call != Call::Reset {
            return Err(FmuError::Invalid(format!(
                "{}: the instance is unusable after an internal error; call {p}Reset or \
                 {p}FreeInstance",
                call.name(version),
                p = version.prefix()
            )));
        }
        if call.allowed().contains(&self.state) {
            return Ok(());
        }
        Err(match &self.cause {
            Some(cause) => FmuError::Invalid(format!(
                "Illegal call sequence. The instance is in the {:?} state since: {cause}",
                self.state
            )),
            None => FmuError::IllegalCall(call.name(version)),
        })
    }

    /// `call` succeeded: the state it leads to ([`Call::leads_to`]); out of Error and StepFailed
    /// the cause is forgotten.
    pub fn succeeded(&mut self, call: Call, how: Succeeded) {
        if call == Call::Reset {
            *self = Self::default();
            return;
        }
        if let Some(state) = call.leads_to(how) {
            self.state = state;
        }
        if !matches!(self.state, Error | StepFailed) {
            self.cause = None;
        }
    }

    /// A step was discarded (`message` says why): StepFailed.
    pub fn discarded(&mut self, message: String) {
        self.cause = Some(message);
        self.state = StepFailed;
    }

    /// A call failed (`message` says why): Error, its cause the first error.
    pub fn failed(&mut self, message: String) {
        if self.state != Error {
            self.cause = Some(message);
        }
        self.state = Error;
    }

    /// A call panicked (`message` names it): Error, poisoned.
    pub fn poison(&mut self, message: String) {
        self.poisoned = true;
        self.cause = Some(message);
        self.state = Error;
    }

    /// A restored FMU state's machine state (SetFMUState).
    pub fn restore(&mut self, state: State) {
        self.state = state;
        self.cause = None;
    }
}

/// How a call that changes state succeeded, where that decides the state it leads to.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Succeeded {
    /// FMI 3: the master uses Event Mode (eventModeUsed): initialization ends in Event Mode.
    pub event_mode: bool,
    /// FMI 3: the step paused inside for the master's intermediate update.
    pub paused: bool,
}

/// Every state (the logging switch and the refusals of what the FMU lacks work everywhere), in
/// an order where the table's sets of states are runs of it.
const EVERYWHERE: &[State] = &[
    ConfigurationMode,
    Instantiated,
    InitializationMode,
    StepComplete,
    StepFailed,
    Terminated,
    Error,
    EventMode,
    IntermediateUpdate,
];

/// Every state but Intermediate Update (where fmi3DoStep is under way).
const ALL: &[State] = EVERYWHERE.split_at(8).0;

/// Where an FMU state may be got, set and serialized: everywhere but Configuration Mode (whose
/// structural parameters are not a run's state) and Intermediate Update.
const FMU_STATE: &[State] = ALL.split_at(1).1;

/// Where values may be read: from Initialization Mode on.
const READ: &[State] = EVERYWHERE.split_at(2).1;

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
            Call::GetUInt64 => READ,
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
            | Call::GetOther(_) => READ,
            Call::GetDirectionalDerivative => FMU_STATE.split_at(1).1,
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

    /// The state a call that succeeded leads to (None: it stays where it is); `how` it succeeded
    /// decides where initialization ends (FMI 3's Event Mode) and whether a step paused inside
    /// (FMI 3's Intermediate Update Mode). Reset leads to Instantiated with every start value
    /// ([`Machine::succeeded`]).
    pub fn leads_to(self, how: Succeeded) -> Option<State> {
        match self {
            Call::EnterInitializationMode => Some(InitializationMode),
            Call::ExitInitializationMode if how.event_mode => Some(EventMode),
            Call::DoStep | Call::ResumeStep if how.paused => Some(IntermediateUpdate),
            Call::ExitInitializationMode
            | Call::EnterStepMode
            | Call::DoStep
            | Call::ResumeStep => Some(StepComplete),
            Call::Terminate => Some(Terminated),
            Call::EnterConfigurationMode => Some(ConfigurationMode),
            Call::Reset | Call::ExitConfigurationMode => Some(Instantiated),
            Call::EnterEventMode => Some(EventMode),
            _ => None,
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
