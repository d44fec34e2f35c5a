//! FMI 2.0 co-simulation over the crate's [`crate::Model`]s: the modelDescription.xml
//! ([`description`]) and, with the runtime, the `fmi2*` functions ([`crate::export_fmi2!`]), a
//! client of the version-free core beside [`crate::fmi3`].

pub mod description;
#[cfg(feature = "runtime")]
pub mod exports;
