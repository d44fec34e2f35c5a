#!/usr/bin/env bash
# Re-runs the measurements of BENCHMARKS.md, each with the command its table names, and prints their
# tables. Without arguments every section runs (about an hour and a half on the benchmark machine,
# the fuzzing half an hour per target of it); with arguments only the named ones:
#
#   bash packaging/benchmarks.sh [fmu] [native] [impacts] [weight] [damping] [grid] [realtime] [integrators]
#                                [accuracy] [energy] [criterion] [modes] [bearings] [film] [coupling]
#                                [system] [dask] [space] [platforms] [fuzz]
#
# Needs the packaged FMU and the venv (the README's first command makes both). Figures vary with the
# machine's load: compare ratios within one table, measured in one run.
set -euo pipefail
cd "$(dirname "$0")/.."
py=.venv/bin/python
fmu=target/fmu/FlexibleSliderCrank.fmu
all=(fmu native impacts weight damping grid realtime integrators accuracy energy criterion modes bearings film coupling system dask space platforms fuzz)
sections=("$@")
[ ${#sections[@]} -eq 0 ] && sections=("${all[@]}")

[ -x "$py" ] && [ -f "$fmu" ] || { echo "run the README's first command first (venv and FMU)" >&2; exit 1; }
for s in "${sections[@]}"; do
  echo
  echo "== $s ($(date -u +%F))"
  case "$s" in
    fmu) "$py" -m fsc.benchmark "$fmu" ;;
    native) cargo run --release --quiet --example fmu_loop ;;
    impacts)
      cargo run --release --quiet --example impacts
      cargo run --release --quiet --example impacts 3e-3
      IMPACTS_QUADRATURE=sampled cargo run --release --quiet --example impacts ;;
    weight)
      for w in 0 1 2 4; do
        cargo run --release --quiet --example impacts 1e-2 "$w"
        "$py" -m fsc.benchmark "$fmu" --quick solver.impactErrorWeight="$w"
      done ;;
    damping)
      cargo run --release --quiet --example damped_rod
      # each damped rod against the undamped one, alternating, twenty runs per process
      TIMEFORMAT="%R s"
      for _ in 1 2 3 4 5 6 7; do
        for zeta in 0 0.01 0.02; do
          printf 'zeta %s ' "$zeta"
          { time target/release/examples/damped_rod time "$zeta" 20 >/dev/null 2>&1; } 2>&1
        done
      done ;;
    grid)
      cargo run --release --quiet --example communication_points
      # the FMU's library through the C master, 100 µs against 10 µs communication steps
      cargo build --release --quiet --lib
      gcc -O2 packaging/master/fmu_run.c -o target/fmu_run -ldl
      guid=$(sed -n 's/.*guid="\([^"]*\)".*/\1/p' modelDescription/modelDescription.xml)
      vrs=$("$py" -c 'import xml.etree.ElementTree as E; print(",".join(v.get("valueReference") for v in E.parse("modelDescription/modelDescription.xml").iter("ScalarVariable") if v.get("causality") == "output" and v.find("Real") is not None))')
      TIMEFORMAT="%R s"
      for set in 162=0 162=0.01 162=0.02 162=0,i15=3; do
        for step in 1e-4 1e-5; do
          printf '%s, step %s: ' "$set" "$step"
          { time FMU_RUN_SET=$set target/fmu_run target/release/libflexible_slider_crank.so "$guid" 0.024 "$step" "$vrs" - ; } 2>&1
        done
      done ;;
    realtime)
      # the real-time cases through fmpy; BASELINE=OTHER.fmu adds another build, in the same rounds
      "$py" -m fsc.benchmark "$fmu" --real-time ${BASELINE:+--baseline=$BASELINE} ;;
    integrators) cargo run --release --quiet --example integrators ;;
    accuracy) cargo run --release --quiet --example accuracy 1e-2 3e-2 ;;
    energy) cargo run --release --quiet --example energy_account ;;
    criterion)
      cargo bench --bench evaluation -- --warm-up-time 0.5 --measurement-time 2
      cargo bench --bench element -- --warm-up-time 0.5 --measurement-time 1
      cargo bench --bench step ;;
    modes) cargo run --release --quiet --example mode_study ;;
    bearings)
      cargo test --release --quiet --test validation_mechanism bearings -- --nocapture
      cargo run --release --quiet --example bearing_design ;;
    film)
      cargo run --release --quiet --example film_models
      cargo build --release --quiet --example simulate
      # the finite film against the short one, alternating, ten revolutions each
      TIMEFORMAT="%R s"
      for _ in 1 2 3 4 5 6 7 8 9 10 11; do
        for film in lubricated short; do
          printf '%s ' "$film"
          { time target/release/examples/simulate craigBampton "$film" 0.12 >/dev/null 2>&1; } 2>&1
        done
      done
      time "$py" -m fsc bearing-report studies/compressor.toml ;;
    coupling) "$py" -m fsc.coupling_benchmark "$fmu" ;;
    system) "$py" -m fsc.system ;;
    dask) "$py" -m fsc.sweep_benchmark "$fmu" ;;
    space)
      "$py" -m fsc.parameter_space
      "$py" -m fsc.parameter_space --listed ;;
    platforms) bash packaging/release.sh ;;
    fuzz) bash packaging/fuzz.sh 1800 ;;
    *) echo "unknown section $s (one of: ${all[*]})" >&2; exit 1 ;;
  esac
done
