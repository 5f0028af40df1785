#!/usr/bin/env bash
# Installs the built project into a scratch prefix and builds a consumer
# project against it with find_package(linemap).
set -euo pipefail
build_dir=$1 source_dir=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch"
cmake --install "$build_dir" --prefix "$scratch/prefix" >/dev/null
cmake -S "$source_dir/tests/install/consumer" -B "$scratch/build" \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/build" >/dev/null
out=$("$scratch/build/consumer" "$source_dir/tests/data/maps/navtut/lse_arena.yaml")
[ "$out" = "80 x 60" ] || { echo "consumer printed '$out'"; exit 1; }
out=$("$scratch/build/decode_consumer" "$source_dir/tests/data/lmap/depot_v2.lmap")
[ "$out" = "604 x 307" ] || { echo "decode_consumer printed '$out'"; exit 1; }
# The decoder library holds no encoder: no line extractor, no segmentation
# (the full library defines all three; a failing nm fails the test).
symbols=$(nm -C "$scratch/prefix/lib"*/liblinemap_decode.a)
if grep -E " T linemap::(EncodeLmap|ExtractLines|SegmentMap)\(" <<<"$symbols"; then
  echo "liblinemap_decode.a defines encoder functions"; exit 1
fi
grep -q " T linemap::DecodeLmap(" <<<"$symbols" || { echo "liblinemap_decode.a lacks DecodeLmap"; exit 1; }
test -x "$scratch/prefix/bin/linemap"
echo "install + find_package(linemap), linemap::linemap_decode OK"
