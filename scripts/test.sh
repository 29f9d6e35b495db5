#!/usr/bin/env bash
# Builds (if needed) and runs every test: core unit tests, filter tests,
# Python-wrapping and ParaView-plugin tests.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
VTK_SMP_BACKEND_IN_USE=STDThread ctest --output-on-failure -j"$(nproc)"
