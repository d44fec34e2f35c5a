//! A model-independent FMI 2.0 co-simulation slave.
//!
//! A model states its variables once, in a table of [`table::Variable`]s; its build script renders
//! modelDescription.xml from that table ([`description`]), and at run time it implements
//! [`Model`] — parameters, inputs, outputs, a step, a state codec — while this crate supplies
//! everything FMI: the 34 exported functions ([`export_fmi2!`]), the state machine of FMI 2.0.4
//! §4.2.4, argument checks, the master's logger, `catch_unwind` at the boundary and the framing of
//! serialized states. It knows no physics: every model of the workspace is built on it.
//!
//! # References
//! - Modelica Association (2023), Functional Mock-up Interface 2.0.4.

pub mod build;
pub mod description;
pub mod fmi3;

pub use fmi_core::{clock, codec, number, signal, table};

#[cfg(feature = "slave")]
mod callback;
#[cfg(feature = "slave")]
pub mod checks;
#[cfg(feature = "slave")]
pub mod error;
#[cfg(feature = "slave")]
pub mod exports;
#[cfg(feature = "slave")]
pub mod ffi;
#[cfg(feature = "slave")]
pub mod logger;
#[cfg(feature = "slave")]
pub mod model;
#[cfg(feature = "slave")]
pub mod reference;
#[cfg(feature = "slave")]
pub mod state;

#[cfg(feature = "slave")]
pub use error::FmuError;
#[cfg(feature = "slave")]
pub use logger::Logger;
#[cfg(feature = "slave")]
pub use model::{Instance, Model, StepOutcome};
#[cfg(feature = "slave")]
pub use state::{Call, State, Version};
