//! The FMI-version-neutral core of the FMI layer: what a model states once and what its run
//! shares with every FMI version's export layer.
//!
//! - [`table`]: the variable table's types (value references, causality, variability, type, start
//!   and range) and [`description::Description`], everything a modelDescription.xml says, with
//!   [`description::check`]; [`interface`]: what FMI 3 adds to the table (capabilities, structural
//!   parameters, arrays).
//! - [`clock`]: the clock grid communication points are rounded to.
//! - [`codec`]: the little-endian byte codec of serialized states.
//! - [`signal`]: inputs given as polynomials of time over a communication step.
//! - [`number`]: the shortest round-trip decimal form of numbers in messages.
//!
//! No FMI version's C API is here: `fmi-export` renders both versions' modelDescription.xml from
//! the table and exports the `fmi2*` and `fmi3*` functions over a model. A model's run and physics
//! import only this crate.

pub mod clock;
pub mod codec;
pub mod description;
pub mod interface;
pub mod number;
pub mod signal;
pub mod table;
