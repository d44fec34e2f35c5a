#!/usr/bin/env bash
# The README's second command: runs every test of the project — formatting, lints, documentation,
# unit and validation tests, FMI conformance through the built library, and the Python tests of the
# packaged FMU through fmpy and libcosimpy. Installs what it needs itself (packaging/bootstrap.sh),
# so it works on a fresh Debian machine with Rust.
set -euo pipefail
cd "$(dirname "$0")/.."

bash packaging/bootstrap.sh
echo "== cargo fmt --check"
cargo fmt --all -- --check
echo "== cargo clippy --all-targets -D warnings"
cargo clippy --workspace --all-targets -- -D warnings
echo "== cargo doc (warnings are errors)"
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --quiet
echo "== package the FMU (release build)"
cargo run --release --quiet -p packaging
cargo build --release --quiet --example simulate
echo "== benches and examples compile"
cargo test --benches --examples --no-run --quiet
echo "== cargo test (unit, validation and FMI tests)"
cargo test --workspace --lib --tests
echo "== pytest (packaged FMU through fmpy and libcosimpy)"
set +e
.venv/bin/python -m pytest -q packaging/python
status=$?
set -e
if [ "$status" -eq 5 ]; then
  echo "pytest collected no tests" >&2
  exit 1
fi
exit "$status"
