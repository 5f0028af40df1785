#!/bin/bash
# The size-and-speed benchmark against netpbm: for every map under a folder (default ../shared/maps)
# prints the default (exact) .lmap size against netpbm's PNG-9 of the same
# trinary map, and the times of
# `linemap encode` / `linemap decode` against `pnmtopng -compression 9` /
# `pngtopnm` (best of 5 wall-clock runs; pngtopnm writes its PGM to a file,
# as decode does; dec_s is the default decode, which flushes both files to
# disk, dec_ns the same with --no-sync), plus the decoder's peak memory.
# Usage: tools/codec_benchmark.sh [MAPS_DIR] [LINEMAP_BINARY]
set -u
MAPS=${1:-$(dirname "$0")/../../shared/maps}
L=${2:-$(dirname "$0")/../build/linemap}
T=$(mktemp -d)
best() {  # best-of-5 wall time in seconds of "$@" with stdout to $OUT (default /dev/null)
  local b=999
  for _ in 1 2 3 4 5; do
    local s=$(date +%s.%N); "$@" >"${OUT:-/dev/null}" 2>/dev/null; local e=$(date +%s.%N)
    b=$(echo "$e - $s" | bc -l | awk -v b="$b" '{print ($1 < b) ? $1 : b}')
  done
  echo "$b"
}
printf "%-36s %8s %7s %7s %6s %6s %6s %6s %6s %6s %6s\n" map cells png9 lmap lmap/png enc_s png_s dec_s dec_ns unpng_s dec_MB
find "$MAPS" \( -name '*.yaml' -o -name '*.pgm' -o -name '*.png' \) | sort | while read -r m; do
  case "$m" in *.yaml) ;; *) [ -e "${m%.*}.yaml" ] && continue; grep -qs "$(basename "$m")" "$(dirname "$m")"/*.yaml && continue ;; esac
  n=$(echo "${m#$MAPS/}" | tr / _); n=${n%.*}
  "$L" encode "$m" -o "$T/$n.lmap" >/dev/null 2>&1 || continue
  "$L" decode "$T/$n.lmap" -o "$T/$n.tri.yaml" >/dev/null || continue
  pnmtopng -compression 9 "$T/$n.tri.pgm" > "$T/$n.png" 2>/dev/null
  cells=$("$L" info "$m" --json | python3 -c 'import json,sys; d=json.load(sys.stdin); print(d["width"]*d["height"])')
  png=$(stat -c %s "$T/$n.png"); lmap=$(stat -c %s "$T/$n.lmap")
  enc=$(best "$L" encode "$m" -o "$T/$n.t.lmap")
  pngt=$(OUT="$T/$n.t.png" best pnmtopng -compression 9 "$T/$n.tri.pgm")
  dec=$(best "$L" decode "$T/$n.lmap" -o "$T/$n.dec.yaml")
  decns=$(best "$L" decode "$T/$n.lmap" -o "$T/$n.dec.yaml" --no-sync)
  unpng=$(OUT="$T/$n.unpng.pgm" best pngtopnm "$T/$n.png")
  mem=$( { /usr/bin/time -f "%M" "$L" decode "$T/$n.lmap" -o "$T/$n.dec.yaml" >/dev/null; } 2>&1 | tail -1)
  python3 -c "
print('%-36s %8d %7d %7d %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f %6.1f' % ('$n', $cells, $png, $lmap, $lmap/$png,
  $enc, $pngt, $dec, $decns, $unpng, $mem/1024.0))"
done
rm -rf "$T"
