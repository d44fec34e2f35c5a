#!/usr/bin/env bash
# Coverage-guided fuzzing (libFuzzer through cargo-fuzz) of the FMU's state deserialization and of
# fmi2* and fmi3* call sequences, each target for a fixed time (seconds, default 60; the three
# targets at once) from the corpus kept in fuzz/corpus. New inputs go to a scratch directory,
# so a run leaves the repository as it was; a crash fails the run and leaves its input under
# fuzz/artifacts/. With --update-corpus the kept corpus is regenerated instead (one target at a
# time): the inputs of the run, the kept ones and (for fmu_state) states of the current format from
# examples/fuzz_seeds.rs, measured by libFuzzer's merge (their coverage features) and the 33 that
# cover the most features kept, chosen greedily (packaging/python/fsc/fuzz_corpus.py), so the
# repository tracks at most 99 inputs.
#
#   bash packaging/fuzz.sh [seconds] [--update-corpus]
#
# With the nightly toolchain the targets are built with the address sanitizer; without it (a machine
# with the stable toolchain only) they are built without a sanitizer, still coverage-guided. Installs
# cargo-fuzz if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
update=${2:-}
mkdir -p target

if rustup run nightly rustc --version >/dev/null 2>&1; then
  fuzz=(cargo +nightly fuzz)
  sanitizer=address
else
  fuzz=(cargo +stable fuzz)
  sanitizer=none
fi
# (unoptimized: it only runs cargo, and builds in 0.55× the processor time)
command -v cargo-fuzz >/dev/null 2>&1 || cargo install cargo-fuzz --locked --quiet --debug

cargo fmt --manifest-path fuzz/Cargo.toml --all -- --check
# (in the main target directory, whose checked dependencies it shares: fuzz/Cargo.toml repeats the
# main workspace's development profile; a check links nothing, so libfuzzer-sys is pointed at a
# library path instead of compiling libFuzzer's C++ sources, about 35 processor-seconds)
CUSTOM_LIBFUZZER_PATH=/nonexistent/libfuzzer.a CARGO_TARGET_DIR=target \
  cargo clippy --quiet --manifest-path fuzz/Cargo.toml --all-targets -- -D warnings
echo "== fuzz targets built with sanitizer: $sanitizer"
if ! "${fuzz[@]}" build -s "$sanitizer" --fuzz-dir fuzz >target/fuzz-build.log 2>&1; then
  cat target/fuzz-build.log >&2
  exit 1
fi
fuzz_target() {
  local target=$1 scratch merged status
  scratch=$(mktemp -d)
  echo "== fuzz $target for ${seconds} s"
  status=0
  "${fuzz[@]}" run -s "$sanitizer" --fuzz-dir fuzz "$target" "$scratch" "fuzz/corpus/$target" -- \
    -max_total_time="$seconds" -rss_limit_mb=4096 -print_final_stats=1 \
    >"target/fuzz-$target.log" 2>&1 || status=$?
  if [ "$status" -eq 0 ] && [ "$update" = "--update-corpus" ]; then
    # FMU states of the current format, so the corpus reaches past the version check.
    if [ "$target" = fmu_state ]; then
      cargo run --quiet --release --example fuzz_seeds -- "$scratch"
    fi
    merged=$(mktemp -d)
    "${fuzz[@]}" run -s "$sanitizer" --fuzz-dir fuzz "$target" "$merged" "$PWD/fuzz/corpus/$target" \
      "$scratch" -- -set_cover_merge=1 -merge_control_file="$merged.control" -rss_limit_mb=4096 \
      >"target/fuzz-$target-merge.log" 2>&1
    .venv/bin/python -m fsc.fuzz_corpus "$merged.control" "fuzz/corpus/$target" --limit 33
    rm -rf "$merged" "$merged.control"
  fi
  rm -rf "$scratch"
  grep -E "^(INFO: seed corpus|stat::number_of_executed_units|stat::new_units_added|Done)" \
    "target/fuzz-$target.log" || true
  if [ "$status" -ne 0 ]; then
    tail -n 60 "target/fuzz-$target.log" >&2
    echo "fuzz target $target failed (input under fuzz/artifacts/$target)" >&2
    exit 1
  fi
}

if [ "$update" = "--update-corpus" ]; then
  for target in fmu_state call_sequence fmi3_call_sequence; do fuzz_target "$target"; done
else
  # libFuzzer runs on one core: the three targets at once, each for its full time.
  pids=()
  for target in fmu_state call_sequence fmi3_call_sequence; do
    fuzz_target "$target" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid"; done
fi
