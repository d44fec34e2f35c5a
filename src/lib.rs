//! Flexible slider-crank mechanism with a clearance joint: a planar ANCF connecting rod, reduced by
//! Craig–Bampton component mode synthesis.
//!
//! Modules follow the physics: [`quadrature`] → [`ancf`] (element and rod) → [`reduction`]
//! (Craig–Bampton) → [`integrator`] (error-controlled time stepping). The variable table
//! ([`variables`]) lies below both the physics (whose parameters it names and bounds) and the FMI
//! adapter ([`fmi`]), which no other module imports.
//!
//! # References
//! - D. Sun, G. Chen, Y. Shi, T. Wang, R. Sun (2015), Model reduction of a flexible multibody system
//!   with clearance, Mech. Mach. Theory 85, 106–115.
//! - R. R. Craig, M. C. C. Bampton (1968), Coupling of substructures for dynamic analyses, AIAA J. 6.

pub mod ancf;
pub mod error;
pub mod fmi;
pub mod integrator;
pub mod joint;
pub mod linalg;
pub mod load_table;
pub mod math;
pub mod mechanism;
pub mod params;
pub mod quadrature;
pub mod reduction;
pub mod simulation;
pub mod variables;

pub use params::Parameters;
pub use simulation::{Input, InputSignal, Inputs, Outputs, Simulation, Snapshot};

pub use error::ModelError;

/// The user guide's Rust code, compiled and run by `cargo test --doc` (after the FMU is packaged).
#[cfg(doctest)]
#[doc = include_str!("../docs/guide/masters.md")]
struct GuideSnippets;
