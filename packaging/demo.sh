#!/usr/bin/env bash
# The README's first command: builds target/fmu/FlexibleSliderCrank.fmu and simulates its
# DefaultExperiment through fmpy, writing target/demo/demo.csv and target/demo/demo.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/bootstrap.sh
cargo run --release -p packaging
.venv/bin/python -m fsc.demo target/fmu/FlexibleSliderCrank.fmu target/demo
