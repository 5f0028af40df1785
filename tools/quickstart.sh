#!/usr/bin/env bash
# Quick start: install, build, and run linemap on a map bundled with the project.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
MAP=tests/data/maps/nav2/depot.yaml
echo "== linemap info $MAP"
build/linemap info "$MAP"
