//! The 34 `fmi2*` functions of a co-simulation FMU (FMI 2.0.4 §2.1, §4.2), generic over the
//! [`crate::Model`]; [`crate::export_fmi2!`] exports them under their C names. Each is a shim: pointers
//! become slices through [`crate::ffi`], the state machine is checked there, and the work happens
//! in the core ([`crate::calls`], [`crate::experiment`]), the [`crate::Instance`] and its model.

/// The C types of the FMI 2.0 headers, for [`crate::export_fmi2!`].
pub mod sys {
    pub use fmi_sys::fmi2::*;
}

mod codes;
mod export_macro;
mod fmu_state;
mod lifecycle;
mod step;
mod values;

pub use fmu_state::{
    fmi2DeSerializeFMUstate, fmi2FreeFMUstate, fmi2GetFMUstate, fmi2SerializeFMUstate,
    fmi2SerializedFMUstateSize, fmi2SetFMUstate,
};
pub use lifecycle::{
    fmi2EnterInitializationMode, fmi2ExitInitializationMode, fmi2FreeInstance,
    fmi2GetTypesPlatform, fmi2GetVersion, fmi2Instantiate, fmi2Reset, fmi2SetDebugLogging,
    fmi2SetupExperiment, fmi2Terminate,
};
pub use step::{
    fmi2CancelStep, fmi2DoStep, fmi2GetBooleanStatus, fmi2GetIntegerStatus, fmi2GetRealStatus,
    fmi2GetStatus, fmi2GetStringStatus,
};
pub use values::{
    fmi2GetBoolean, fmi2GetDirectionalDerivative, fmi2GetInteger, fmi2GetReal,
    fmi2GetRealOutputDerivatives, fmi2GetString, fmi2SetBoolean, fmi2SetInteger, fmi2SetReal,
    fmi2SetRealInputDerivatives, fmi2SetString,
};
