//! A model-independent FMI co-simulation FMU layer for FMI 2.0 and FMI 3.0.
//!
//! A model states its variables once, in a table of [`table::Variable`]s; its build script renders
//! both versions' modelDescription.xml from that table ([`build`]), and at run time it implements
//! [`Model`] — parameters, inputs, outputs, a step, a state codec — while this crate supplies
//! everything FMI. Its core knows no FMI version's C types: the instance ([`Instance`]) with its
//! state machine (one table for both versions, [`state`]), the experiment and the clock of the
//! communication steps ([`experiment`]), the argument checks ([`checks`]), the
//! master's logger, `catch_unwind` at the boundary ([`ffi`]), the version-free status
//! ([`Status`]) and the calls both versions make alike ([`calls`]). Two sibling clients turn their
//! version's C calls into calls of that core: [`fmi2`] (the 34 `fmi2*` functions,
//! [`export_fmi2!`]) and [`fmi3`] (the 75 `fmi3*` functions, [`export_fmi3!`]); neither calls the
//! other. The reference driver ([`reference`](mod@reference)) is a third client. It knows no physics: every model
//! of the workspace is built on it.
//!
//! # References
//! - Modelica Association (2023), Functional Mock-up Interface 2.0.4.
//! - Modelica Association (2024), Functional Mock-up Interface 3.0.2.

pub mod build;
pub mod fmi2;
pub mod fmi3;
mod xml;

pub use fmi_core::{clock, codec, description, interface, number, signal, table};

#[cfg(feature = "runtime")]
pub mod calls;
#[cfg(feature = "runtime")]
pub mod checks;
#[cfg(feature = "runtime")]
pub mod error;
#[cfg(feature = "runtime")]
pub mod experiment;
#[cfg(feature = "runtime")]
pub mod ffi;
#[cfg(feature = "runtime")]
pub mod instance;
#[cfg(feature = "runtime")]
pub mod logger;
#[cfg(feature = "runtime")]
pub mod model;
#[cfg(feature = "runtime")]
pub mod reference;
#[cfg(feature = "runtime")]
pub mod state;
#[cfg(feature = "runtime")]
pub mod status;

#[cfg(feature = "runtime")]
pub use error::FmuError;
#[cfg(feature = "runtime")]
pub use experiment::{Experiment, Step, StepOutcome};
#[cfg(feature = "runtime")]
pub use instance::Instance;
#[cfg(feature = "runtime")]
pub use logger::Logger;
#[cfg(feature = "runtime")]
pub use model::{Context, Model};
#[cfg(feature = "runtime")]
pub use state::{Call, State, Version};
#[cfg(feature = "runtime")]
pub use status::Status;
