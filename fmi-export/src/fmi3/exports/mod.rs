//! The `fmi3*` functions of a co-simulation FMU (FMI 3.0 §2.3, §4), generic over the same
//! [`crate::Model`] as FMI 2's; [`crate::export_fmi3!`] exports them under their C names. Each
//! checks its own pointer arguments and calls the core: [`crate::calls`] for what FMI 2 does alike,
//! the instance and the model for what only FMI 3 has; the instance's [`crate::Version`] names the
//! calls in its messages.

/// The C types of the FMI 3.0 headers, for [`crate::export_fmi3!`].
pub mod sys {
    pub use fmi_sys::fmi3::*;
}

mod arrays;
mod codes;
mod events;
mod export_macro;
mod export_other_types;
mod export_unsupported;
mod export_values;
mod lifecycle;
mod step;
mod values;

pub use arrays::{
    fmi3EnterConfigurationMode, fmi3ExitConfigurationMode, fmi3GetUInt64, fmi3SetUInt64,
};
pub use events::{fmi3EnterEventMode, fmi3EnterStepMode, fmi3UpdateDiscreteStates};
pub use lifecycle::{
    fmi3EnterInitializationMode, fmi3ExitInitializationMode, fmi3FreeInstance, fmi3GetVersion,
    fmi3InstantiateCoSimulation, fmi3Reset, fmi3SetDebugLogging, fmi3Terminate, instantiate_other,
    unsupported,
};
pub use step::{
    fmi3DeserializeFMUState, fmi3DoStep, fmi3FreeFMUState, fmi3GetDirectionalDerivative,
    fmi3GetFMUState, fmi3GetOutputDerivatives, fmi3SerializeFMUState, fmi3SerializedFMUStateSize,
    fmi3SetFMUState,
};
pub use values::{
    fmi3GetBoolean, fmi3GetFloat64, fmi3GetInt32, fmi3GetInt64, fmi3GetString, fmi3SetBoolean,
    fmi3SetFloat64, fmi3SetInt32, fmi3SetInt64, fmi3SetString, no_variable_of_type,
};
