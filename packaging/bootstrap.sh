#!/usr/bin/env bash
# Idempotent set-up on a fresh Debian machine with Rust: the system packages the build needs
# (libclang for fmi-sys's bindgen, DejaVu fonts for the plots, venv support) and a Python venv
# (.venv) with the pinned FMI masters and test tools of packaging/python/requirements.txt and the
# repository's own Python package, fsc.
set -euo pipefail
cd "$(dirname "$0")/.."

need=()
dpkg -s libclang-dev >/dev/null 2>&1 || need+=(libclang-dev)
dpkg -s fonts-dejavu-core >/dev/null 2>&1 || need+=(fonts-dejavu-core)
python3 -c 'import ensurepip, venv' >/dev/null 2>&1 || need+=(python3-venv)
if [ ${#need[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  echo "== installing ${need[*]}"
  $sudo apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi

if [ ! -x .venv/bin/python ]; then
  echo "== creating .venv"
  python3 -m venv .venv
fi
.venv/bin/pip install -q --disable-pip-version-check -r packaging/python/requirements.txt
# The repository's Python tooling (packaging/python/fsc), editable: the tests import it.
.venv/bin/pip install -q --disable-pip-version-check -e packaging/python
