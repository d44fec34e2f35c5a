//! FMI 2.0 conformance of the built shared library, loaded through fmi-sys's `Fmi2Binding`
//! (libloading): exported symbols, instantiation checks, the state machine, argument checks, range
//! errors naming the variable, logging of `%` and `#`, reset, FMU state (bit-exact, corrupted bytes
//! rejected), interleaved instances and threads, and FMU = library (docs/fmi.md §3); the DC motor's
//! and the lubrication circuit's FMUs through the same calls.

// Test code: a failed unwrap is a failed test, with its message; calling a C API needs unsafe.
#![allow(clippy::unwrap_used, clippy::expect_used, unsafe_code)]

mod circuit;
mod conformance;
#[path = "../support/development_build.rs"]
mod development_build;
mod fmi3;
mod harness;
mod instances;
mod motor;
mod state_machine;
mod strings;
