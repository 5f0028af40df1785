#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (ctest). Idempotent.
# Under CI (CI=true), or with LINEMAP_SANITIZE_TESTS=1, the whole suite runs a
# second time in build-asan/ under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
BUILD_DIR=${LINEMAP_BUILD_DIR:-build}
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)" --timeout 600

if [ "${CI:-}" = "true" ] || [ "${LINEMAP_SANITIZE_TESTS:-0}" = "1" ]; then
  echo "== the test suite again under ASan + UBSan (build-asan/)"
  LINEMAP_BUILD_DIR=build-asan bash tools/setup.sh -DCMAKE_BUILD_TYPE=Debug -DLINEMAP_SANITIZE=ON
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 900
fi

if [ "${CI:-}" = "true" ] || [ "${LINEMAP_FUZZ_SMOKE:-0}" = "1" ]; then
  echo "== fuzz smoke (libFuzzer, ASan + UBSan)"
  FUZZ_SECONDS=${FUZZ_SECONDS:-20} bash tools/fuzz_smoke.sh
fi
