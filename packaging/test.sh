#!/usr/bin/env bash
# The README's second command: runs every test of the project — formatting, lints, documentation,
# unit and validation tests, FMI conformance through the built library, the Python tests of the
# release FMU through fmpy and libcosimpy, and the release FMU's binaries for every platform
# (packaging/release.sh; win64 under wine, linux64 on an older Debian, aarch64-linux under qemu-user,
# darwin64 inspected).
# Installs what it needs itself (packaging/bootstrap.sh, packaging/release.sh), so it works on a
# fresh Debian machine with Rust.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each step's marker carries the seconds since the command started, so that a run's log shows
# where its time went.
step() { echo "== [${SECONDS} s] $*"; }

bash packaging/bootstrap.sh
step "platform test tools: wine (win64 DLL), debootstrap (an older Debian for linux64), qemu-user and"
echo "   Debian's ARM64 C library (aarch64-linux)"
need=()
for p in wine wine64 debootstrap qemu-user libc6-arm64-cross libgcc-s1-arm64-cross; do dpkg -s "$p" >/dev/null 2>&1 || need+=("$p"); done
if [ ${#need[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi
# The older Debian root the linux64 binary is tested in, made while the steps below run (it takes
# network and disk, hardly any processor).
mkdir -p target/platform-tests
old_debian=target/platform-tests/bullseye
root_pid=""
if [ "$(id -u)" -eq 0 ] && [ ! -x "$old_debian/usr/bin/ldd" ]; then
  rm -rf "$old_debian"
  debootstrap --variant=minbase bullseye "$old_debian" http://deb.debian.org/debian \
    >target/platform-tests/debootstrap.log 2>&1 &
  root_pid=$!
fi
# The release binaries (four cross builds, the largest part of the command) build in the
# background at the lowest priority, on the processor time the steps below leave idle: a crate
# compiled alone, a test program's last minutes, rustdoc. Their own session, so that a failing
# step stops them too (the process group's kill below); the kernel then schedules the session as
# a group of its own (autogroup), which gets as much as the foreground whatever its processes'
# nice value, unless the group's own nice value is raised too.
step "release binaries: linux64 (glibc 2.28), win64, darwin64, aarch64-linux, in the background"
echo "   at the lowest priority (log: target/release-binaries.log)"
setsid bash -c '{ echo 19 >/proc/self/autogroup; } 2>/dev/null || true
  exec nice -n 19 bash packaging/release.sh --binaries-only' >target/release-binaries.log 2>&1 &
release_pid=$!
trap 'kill -- "-$release_pid" 2>/dev/null || true' EXIT
step "cargo fmt --check"
cargo fmt --all -- --check
step "cargo clippy --all-targets -D warnings"
cargo clippy --workspace --all-targets -- -D warnings
step "cargo doc (warnings are errors)"
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --quiet
# One development build of the FMUs' libraries, the packaging program and the test programs, which
# the steps below share: built with the tests' dev-dependencies, crates below the libraries get
# features those alone do not turn on, and cargo builds a crate once per feature set. So the packaging
# program runs from that build: `cargo run -p packaging` would build it, the libraries and every crate
# under them a second time.
step "development build: the FMUs' libraries, the packaging program, the test programs"
cargo build --workspace --lib --bins --tests
# The Rust tests' FMU: the libraries in the development profile (the release build below makes the
# optimized ones; both give the same results to the bit).
step "package the FMU (development build)"
target/debug/packaging
step "the user guide's Rust code (doc test, on the packaged FMU)"
cargo test --doc --quiet -p flexible-slider-crank
step "benches and examples compile"
cargo test --benches --examples --no-run --quiet
step "cargo test (unit, validation and FMI tests; two test programs at a time)"
# cargo runs its test programs one after another, and one made of a few long tests leaves a core
# idle. So cargo lists them (built above), and they run here two at a time, each from its package's
# folder (as cargo runs it), its output printed when it ends; any failure fails the step.
cargo test --workspace --lib --tests --no-run --quiet --message-format=json | .venv/bin/python -c '
import json, os, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m.get("executable") and m["profile"]["test"]:
        print(os.path.dirname(m["manifest_path"]), m["executable"])' >target/test-programs.txt
xargs -P 2 -L 1 bash -c 'cd "$0" && out=$("$1" 2>&1); status=$?
  printf "== %s\n%s\n" "$1" "$out"; exit "$status"' <target/test-programs.txt
step "fuzzing: state deserialization, fmi2* and fmi3* call sequences, 60 s each"
bash packaging/fuzz.sh 60
step "waiting for the release binaries"
if ! wait "$release_pid"; then
  cat target/release-binaries.log >&2
  exit 1
fi
grep -H '^real' target/cross/logs/*.log # each cross build's wall time
if [ -n "$root_pid" ] && ! wait "$root_pid"; then
  cat target/platform-tests/debootstrap.log >&2
  exit 1
fi
step "release FMU: linux64 (glibc 2.28), win64, darwin64; FMI 3 adds aarch64-linux"
target/debug/packaging --binaries target/cross/binaries
# pytest runs on the release FMUs, the optimized libraries that ship, in place of the development ones.
cp -R target/fmu/release/. target/fmu/
step "pytest (release FMU through fmpy and libcosimpy; release binaries on every platform)"
# Two worker processes, each taking whole test files (their module fixtures built once).
set +e
.venv/bin/python -m pytest -q -n 2 --dist loadfile packaging/python/tests
status=$?
set -e
if [ "$status" -eq 5 ]; then
  echo "pytest collected no tests" >&2
  exit 1
fi
step "done (pytest exit status $status)"
exit "$status"
