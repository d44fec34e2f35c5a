//! FMI 3.0 co-simulation over the same [`crate::Model`]s as FMI 2: the modelDescription.xml
//! ([`description`]) and, with the runtime, the `fmi3*` functions ([`crate::export_fmi3!`]).

pub mod description;
#[cfg(feature = "runtime")]
pub mod exports;

pub use fmi_core::interface;
