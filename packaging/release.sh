#!/usr/bin/env bash
# The release build: target/fmu/release/FlexibleSliderCrank.fmu, DcMotor.fmu and LubricationCircuit.fmu,
# and the systems made of them (MotorCrank.ssp, motor-crank/OspSystemStructure.xml, LubeCrank.ssp,
# lube-crank/OspSystemStructure.xml), with stripped binaries for
#   binaries/linux64   x86_64 Linux, glibc 2.28 or later (RHEL/Rocky 8, Ubuntu 18.10, Debian 10 on)
#   binaries/win64     x86_64 Windows 10 or later
#   binaries/darwin64  macOS 11 or later, universal (x86_64 and arm64), ad-hoc signed
# and the FMI 3.0 twins in target/fmu/release/fmi3/ with the same libraries in FMI 3's platform folders
# (the universal binary's two slices apart: binaries/x86_64-darwin and binaries/aarch64-darwin), plus
# binaries/aarch64-linux (ARM64 Linux, glibc 2.28 or later), which FMI 2.0 cannot name,
# from this workspace, with this machine's Rust toolchain (rustup) and the Rust project's prebuilt
# standard library for each target (`rustup target add`), Debian packages, crates and PyPI packages:
#   - linux64 and aarch64-linux: linked by zig (PyPI `ziglang`) through cargo-zigbuild against
#     glibc 2.28's symbol versions;
#   - win64: linked by mingw-w64;
#   - darwin64: linked by zig, the two macOS slices merged by llvm-lipo.
# Where rustup's server cannot be reached, Debian's rustc-web builds win64, darwin64 and aarch64-linux
# instead (see the set-up below).
# Set-up needs the package registries and rustup's server; the builds then run offline. Paths are
# remapped, the DLL has no link time stamps and the zip's entries have fixed time stamps, so the same
# sources and the same toolchain give the same bytes.
#
#   bash packaging/release.sh                  # the binaries, then the FMUs and systems
#   bash packaging/release.sh --binaries-only  # the binaries only, in target/cross/binaries
#                                              # (then: cargo run -p packaging -- --binaries DIR)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
case ${1:-} in
  "") package=1 ;;
  --binaries-only) package=0 ;;
  *) echo "usage: bash packaging/release.sh [--binaries-only]" >&2; exit 2 ;;
esac
user_cargo_home=${CARGO_HOME:-$HOME/.cargo}

bash packaging/bootstrap.sh

# --- set-up: system packages and the targets' standard libraries -----------------------------
# Installs the Debian packages given that are not installed yet.
install_packages() {
  local need=() p sudo=""
  for p in "$@"; do dpkg -s "$p" >/dev/null 2>&1 || need+=("$p"); done
  [ ${#need[@]} -gt 0 ] || return 0
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  echo "== installing ${need[*]}"
  $sudo apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
}
install_packages gcc-mingw-w64-x86-64 clang llvm
targets=(x86_64-pc-windows-gnu x86_64-apple-darwin aarch64-apple-darwin aarch64-unknown-linux-gnu)
# The cross builds' compiler: the machine's, with rustup's prebuilt standard libraries (cross=()),
# or, where rustup's server cannot be reached, Debian's rustc-web (cross=(debian)), about 1.7× slower,
# which compiles std from its sources for win64 and darwin64 (build_std) and links Debian's prebuilt
# ARM64 std for aarch64-linux.
cross=()
build_std=()
std_remap=""
if ! timeout 300 rustup target add "${targets[@]}"; then
  echo "== rustup's standard libraries cannot be installed: Debian's Rust toolchain instead"
  install_packages libllvm22 libgit2-1.5 libcurl4 libssh2-1 libsqlite3-0
  rust_web=1.96
  # One fixed place for every checkout: cargo identifies the standard library's packages by their
  # absolute path, so a toolchain unpacked inside each checkout would make the binaries differ
  # between checkouts.
  toolchain=${XDG_CACHE_HOME:-$HOME/.cache}/flexible-slider-crank/rust-web-$rust_web
  mkdir -p "$(dirname "$toolchain")"
  exec 9>"$toolchain.lock"
  flock 9 # one unpacking at a time when several checkouts build at once
  if [ ! -x "$toolchain/usr/bin/cargo" ] || [ ! -d "$toolchain/usr/lib/rustlib/aarch64-unknown-linux-gnu/lib" ]; then
    echo "== unpacking Debian's Rust $rust_web toolchain into $toolchain"
    debs=$(mktemp -d)
    (cd "$debs" && apt-get download -qq rustc-web cargo-web rust-web-src \
      "libstd-rust-web-$rust_web" libstd-rust-web-dev 2>&1 | grep -v unsandboxed || true)
    # The ARM64 build of the same standard library (Debian's package of the same version for
    # arm64, from the same pool folder).
    arm64=$(apt-get download --print-uris libstd-rust-web-dev | cut -d"'" -f2 | sed 's/_amd64\.deb$/_arm64.deb/')
    python3 -c 'import sys, urllib.request; urllib.request.urlretrieve(sys.argv[1], sys.argv[2])' \
      "$arm64" "$debs/libstd-rust-web-dev-arm64.deb"
    rm -rf "$toolchain" && mkdir -p "$toolchain"
    for deb in "$debs"/*.deb; do dpkg-deb -x "$deb" "$toolchain"; done
    rm -rf "$debs"
  fi
  flock -u 9
  cross=(debian)
  # std without backtrace symbolization (a panic inside the FMU is caught and reported through
  # the master's logger); unwinding stays (catch_unwind at every fmi2 function needs it).
  build_std=(-Zbuild-std=std,panic_unwind -Zbuild-std-features=panic-unwind)
  std_remap="--remap-path-prefix=$toolchain/usr/lib/rustlib/src/rust=/rustc/$rust_web"
fi
# Debian's toolchain, for the fallback above.
debian() {
  env PATH="$toolchain/usr/bin:$PATH" RUSTC_BOOTSTRAP=1 \
    LD_LIBRARY_PATH="$toolchain/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$@"
}
zig_dir=$(.venv/bin/python -c 'import ziglang, os; print(os.path.dirname(ziglang.__file__))')
export PATH="$root/.venv/bin:$zig_dir:$PATH"
clang_include="$(clang -print-resource-dir)/include"

# --- set-up: every crate the offline builds compile ---------------------------------------------
# The builds run offline with a cargo home of their own, emptied and filled here at every run with
# exactly this workspace's crates (Cargo.lock): a crate that is not fetched here then fails the
# build on every machine, not only on one whose cargo cache happens to lack it. Fetching takes
# seconds.
out=$root/target/cross
cargo_home=$out/cargo-home
rm -rf "$cargo_home"
mkdir -p "$cargo_home"
echo "== fetching the crates of this workspace into $cargo_home"
CARGO_HOME=$cargo_home cargo fetch --locked --quiet
if [ ${#build_std[@]} -gt 0 ]; then # the standard library's own workspace's crates, which it compiles
  CARGO_HOME=$cargo_home debian cargo fetch --locked --quiet \
    --manifest-path "$toolchain/usr/lib/rustlib/src/rust/library/Cargo.toml"
fi

# --- builds: four jobs in parallel (each is mostly one serial chain of crates) ---------------
bin=$out/binaries
mkdir -p "$bin/linux64" "$bin/win64" "$bin/darwin64" "$bin/x86_64-darwin" "$bin/aarch64-darwin" \
  "$bin/aarch64-linux" "$out/logs"
export CARGO_HOME=$cargo_home
remap="--remap-path-prefix=$root=/build --remap-path-prefix=$cargo_home=/cargo $std_remap"
lib=(--offline --locked --quiet --release --lib -p flexible-slider-crank -p dc-motor -p lube-circuit)

linux64() {
  env CARGO_PROFILE_RELEASE_STRIP=symbols RUSTFLAGS="$remap" \
    "BINDGEN_EXTRA_CLANG_ARGS_x86_64-unknown-linux-gnu=-I$clang_include -I/usr/include/x86_64-linux-gnu -I/usr/include" \
    cargo zigbuild "${lib[@]}" --target x86_64-unknown-linux-gnu.2.28 --target-dir "$out/linux"
  cp "$out/linux/x86_64-unknown-linux-gnu/release/libflexible_slider_crank.so" "$bin/linux64/FlexibleSliderCrank.so"
  cp "$out/linux/x86_64-unknown-linux-gnu/release/libdc_motor.so" "$bin/linux64/DcMotor.so"
  cp "$out/linux/x86_64-unknown-linux-gnu/release/liblube_circuit.so" "$bin/linux64/LubricationCircuit.so"
}

# mingw-w64's linker stamps the time into the DLL unless told not to.
win64() {
  "${cross[@]}" env CARGO_PROFILE_RELEASE_STRIP=symbols RUSTFLAGS="$remap -C link-arg=-Wl,--no-insert-timestamp" \
    cargo build "${build_std[@]}" "${lib[@]}" --target x86_64-pc-windows-gnu --target-dir "$out/win"
  cp "$out/win/x86_64-pc-windows-gnu/release/flexible_slider_crank.dll" "$bin/win64/FlexibleSliderCrank.dll"
  cp "$out/win/x86_64-pc-windows-gnu/release/dc_motor.dll" "$bin/win64/DcMotor.dll"
  cp "$out/win/x86_64-pc-windows-gnu/release/lube_circuit.dll" "$bin/win64/LubricationCircuit.dll"
}

# zig's Mach-O linker exports every symbol of default visibility (it ignores rustc's export list,
# hence hidden by default: only the fmi2 functions stay exported), strips local symbols (-x) and
# signs the arm64 slice ad hoc; stripping after linking would break that signature. Hidden
# visibility is an unstable option of rustc (RUSTC_BOOTSTRAP lets the stable compiler take it).
darwin64() {
  local macos="-I$clang_include -I$zig_dir/lib/libc/include/any-darwin-any"
  "${cross[@]}" env CARGO_PROFILE_RELEASE_STRIP=false MACOSX_DEPLOYMENT_TARGET=11.0 RUSTC_BOOTSTRAP=1 \
    RUSTFLAGS="$remap -Zdefault-visibility=hidden -C link-arg=-Wl,-x" \
    "BINDGEN_EXTRA_CLANG_ARGS_x86_64-apple-darwin=$macos" "BINDGEN_EXTRA_CLANG_ARGS_aarch64-apple-darwin=$macos" \
    cargo zigbuild "${build_std[@]}" "${lib[@]}" --target-dir "$out/darwin" \
    --target x86_64-apple-darwin --target aarch64-apple-darwin
  for lib in flexible_slider_crank:FlexibleSliderCrank dc_motor:DcMotor lube_circuit:LubricationCircuit; do
    llvm-lipo-14 -create "$out/darwin/x86_64-apple-darwin/release/lib${lib%%:*}.dylib" \
      "$out/darwin/aarch64-apple-darwin/release/lib${lib%%:*}.dylib" \
      -output "$bin/darwin64/${lib##*:}.dylib"
    # FMI 3.0 names each architecture: the universal binary's slices, taken back out of it.
    for arch in x86_64:x86_64 arm64:aarch64; do
      llvm-lipo-14 "$bin/darwin64/${lib##*:}.dylib" -thin "${arch%%:*}" \
        -output "$bin/${arch##*:}-darwin/${lib##*:}.dylib"
    done
  done
}

# The same as linux64 for ARM64, bindgen reading zig's glibc headers for the target.
aarch64_linux() {
  local glibc="-I$clang_include -I$zig_dir/lib/libc/include/aarch64-linux-gnu"
  glibc="$glibc -I$zig_dir/lib/libc/include/generic-glibc -I$zig_dir/lib/libc/include/any-linux-any"
  "${cross[@]}" env CARGO_PROFILE_RELEASE_STRIP=symbols RUSTFLAGS="$remap" \
    "BINDGEN_EXTRA_CLANG_ARGS_aarch64-unknown-linux-gnu=$glibc" \
    cargo zigbuild "${lib[@]}" --target aarch64-unknown-linux-gnu.2.28 \
    --target-dir "$out/aarch64-linux"
  cp "$out/aarch64-linux/aarch64-unknown-linux-gnu/release/libflexible_slider_crank.so" \
    "$bin/aarch64-linux/FlexibleSliderCrank.so"
  cp "$out/aarch64-linux/aarch64-unknown-linux-gnu/release/libdc_motor.so" "$bin/aarch64-linux/DcMotor.so"
  cp "$out/aarch64-linux/aarch64-unknown-linux-gnu/release/liblube_circuit.so" "$bin/aarch64-linux/LubricationCircuit.so"
}

jobs=(linux64 win64 darwin64 aarch64_linux)
pids=()
for job in "${jobs[@]}"; do
  echo "== building $job (log: target/cross/logs/$job.log)"
  (time $job) >"$out/logs/$job.log" 2>&1 &
  pids+=($!)
done
failed=0
for i in "${!jobs[@]}"; do
  if ! wait "${pids[$i]}"; then
    job=${jobs[$i]}
    echo "== $job failed:" >&2
    cat "$out/logs/$job.log" >&2
    failed=1
  fi
done
[ "$failed" -eq 0 ]
[ "$package" -eq 1 ] || exit 0

# --- the FMU -----------------------------------------------------------------------------------
# The packaging program only zips the libraries built above (and computes the reference results
# in process, to the bit what the release libraries give): its development build serves.
export CARGO_HOME=$user_cargo_home
cargo run --quiet -p packaging -- --binaries "$bin"
