#!/usr/bin/env bash
# Quick start: install what is missing, build, then map-save and map-load a
# map bundled with the project, and show what the saved file holds.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
MAP=tests/data/maps/nav2/depot.yaml
OUT=${TMPDIR:-/tmp}/linemap-quickstart
mkdir -p "$OUT"
echo "== linemap info $MAP"
build/linemap info "$MAP"
echo
echo "== linemap encode (map-save: exact, with walls, rooms and furniture) -> $OUT/depot.lmap"
build/linemap encode "$MAP" -o "$OUT/depot.lmap"
echo
echo "== linemap info: the file's layers and chunks"
build/linemap info "$OUT/depot.lmap"
echo
echo "== linemap decode (map-load) -> $OUT/depot_decoded.yaml + .pgm"
build/linemap decode "$OUT/depot.lmap" -o "$OUT/depot_decoded.yaml"
echo
echo "== linemap eval: cell for cell, and the walls the RM-Line paper's way"
build/linemap eval "$MAP" "$OUT/depot.lmap"
echo
echo "== linemap export: the layers over the map -> $OUT/depot.svg (open it in a browser)"
build/linemap export "$OUT/depot.lmap" -o "$OUT/depot.svg"
echo
echo "== linemap encode --raster-only: an exact file of the cells alone (with --compact too: the smallest)"
build/linemap encode "$MAP" --raster-only -o "$OUT/depot_cells.lmap"
