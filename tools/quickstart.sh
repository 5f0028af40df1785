#!/usr/bin/env bash
# Quick start: install what is missing, build, then map-save and map-load a
# map bundled with the project, with size and fidelity figures.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
MAP=tests/data/maps/nav2/depot.yaml
OUT=${TMPDIR:-/tmp}/linemap-quickstart
mkdir -p "$OUT"
echo "== linemap info $MAP"
build/linemap info "$MAP"
echo
echo "== linemap encode (map-save, lossy) -> $OUT/depot.lmap"
build/linemap encode "$MAP" -o "$OUT/depot.lmap"
echo
echo "== linemap decode (map-load) -> $OUT/depot_decoded.yaml + .pgm"
build/linemap decode "$OUT/depot.lmap" -o "$OUT/depot_decoded.yaml"
echo
echo "== linemap eval: the original against the decoded map"
build/linemap eval "$MAP" "$OUT/depot.lmap"
echo
echo "== linemap encode --lossless: exact round trip"
build/linemap encode "$MAP" --lossless -o "$OUT/depot_lossless.lmap"
