#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (ctest). Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
BUILD_DIR=${LINEMAP_BUILD_DIR:-build}
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)" --timeout 600
