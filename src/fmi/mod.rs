//! The FMI 2.0 and FMI 3.0 co-simulation FMU of the slider-crank: [`instance::SliderCrankFmu`]
//! implements the [`fmi_export::Model`] of the model-independent FMI layer around
//! [`crate::Simulation`], which supplies the exported functions of both versions (one library
//! exports `fmi2*` and `fmi3*`), their state machine and the checks at the boundary.
//!
//! `fmi/` sees only `Simulation`, `Parameters`, `Outputs` and the variable table
//! ([`crate::variables`]), and no other module sees `fmi/`; there is no
//! global mutable state, so any number of instances may live in one process, on any thread.
//!
//! # References
//! - Modelica Association (2023), Functional Mock-up Interface 2.0.4.
//! - Modelica Association (2024), Functional Mock-up Interface 3.0.2.

pub mod instance;
mod instance_state;
pub mod model_description;
pub mod outputs;
pub mod snapshot;
mod step;

pub use model_description::{
    FMI3_SCALAR_TOKEN, FMI3_TOKEN, GUID, MODEL_DESCRIPTION, MODEL_DESCRIPTION_FMI3,
    MODEL_DESCRIPTION_FMI3_SCALAR, MODEL_IDENTIFIER, TERMINALS_AND_ICONS_FMI3,
};

fmi_export::export_fmi2!(instance::SliderCrankFmu);
fmi_export::export_fmi3!(instance::SliderCrankFmu);
