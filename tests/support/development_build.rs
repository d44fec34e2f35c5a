//! The workspace's development build, from which the tests load the FMUs' libraries and run the
//! packaging program. Shared by the FMI tests and the `fmi` crate's test.
//!
//! It builds the whole workspace's test programs, as `cargo test` does: the tests' dev-dependencies
//! turn on features of crates the libraries share, and cargo builds a crate once per feature set.
//! `cargo build --lib -p dc-motor` or `cargo run -p packaging` would compile the libraries and every
//! crate under them a second time, and replace the tests' `target/debug/lib*.so` with their own.

use std::path::PathBuf;
use std::process::Command;

/// Builds the libraries, the packaging program and the test programs (nothing to do when run from
/// `cargo test`, which built them), and returns the build's directory, `target/debug/`.
pub fn build() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let status = Command::new(env!("CARGO"))
        .current_dir(&root)
        .args([
            "build",
            "--quiet",
            "--workspace",
            "--lib",
            "--bins",
            "--tests",
        ])
        .status()
        .unwrap();
    assert!(status.success(), "the workspace's development build failed");
    root.join("target").join("debug")
}
