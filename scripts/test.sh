#!/usr/bin/env bash
# Builds (if needed) and runs every test: core unit tests, filter tests,
# Python-wrapping and ParaView-plugin tests, then the core under the
# sanitizers with a short fuzzing campaign.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
VTK_SMP_BACKEND_IN_USE=STDThread ctest --output-on-failure -j"$(nproc)"

# The core again, built with clang under AddressSanitizer and
# UndefinedBehaviorSanitizer: its unit tests and a short, seeded libFuzzer
# campaign (Testing/Fuzz). Only the VTK-free core: ParaView's libraries are not
# built with the sanitizers.
cd ..
{
  CC=clang CXX=clang++ cmake -S . -B build-sanitize -G Ninja -DTPC_CORE_ONLY=ON -DTPC_SANITIZE=ON \
    -DTPC_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo && cmake --build build-sanitize
} > build/sanitize-build.log 2>&1 || { tail -50 build/sanitize-build.log; exit 1; }
rm -f build/sanitize-build.log
cd build-sanitize
ctest --output-on-failure -j"$(nproc)"
