#!/usr/bin/env bash
# Writes the version 2.x fixtures (tests/data/lmap/*_v2*.lmap) with the
# linemap built in BUILD (default build/), and the 2.x must-fail files
# (tests/data/bad/lmap_decode/v2_*.lmap) by editing one chunk of a valid
# file and recomputing its CRC. Run from the repository root; the tests
# check the fixtures against the source maps, not against this script.
# Files of earlier versions are kept as they were written and never
# rewritten: depot_v2_0.lmap and lse_arena_v2_0.lmap (2.0: WALL, ROOM,
# FURN), willow_v2_1_tolerance_1.lmap (2.1: BLKS), willow_v2_2_tolerance_1.lmap
# (2.2: BLKS in model 3 only); the 2.0 and 2.1 must-fail files are made from
# them.
set -euo pipefail
BUILD=${1:-build}
L=$BUILD/linemap
M=tests/data/maps
$L encode $M/navtut/lse_arena.yaml -o tests/data/lmap/lse_arena_v2.lmap --no-sync >/dev/null
$L encode $M/nav2/depot.yaml -o tests/data/lmap/depot_v2.lmap --no-sync >/dev/null
$L encode $M/nav2/depot.yaml -o tests/data/lmap/depot_v2_raster_only.lmap --raster-only \
  --no-sync >/dev/null
$L encode $M/nav2/depot.yaml -o tests/data/lmap/depot_v2_tiles_64.lmap --tile-size 64 \
  --no-sync >/dev/null
# Cells in blocks (BLKS), within a tolerance of 1 cell (2.3: models 3 and
# 12).
$L encode $M/turtlebot_apps/willow-2010-02-18-0.10.yaml \
  -o tests/data/lmap/willow_v2_3_tolerance_1.lmap --tolerance 1 \
  --no-sync >/dev/null
# Cells coded for size (2.3), in tiles of 64 cells: models 12, 3 and 4
# side by side (the script below checks that 12 and 3 occur).
$L encode $M/nav2/depot.yaml -o tests/data/lmap/depot_v2_3_compact_tiles_64.lmap --compact \
  --tile-size 64 --no-sync >/dev/null
# The layers in several sections (LAYR with boxes), tiles of 64 cells.
$L encode $M/nav2/depot.yaml -o tests/data/lmap/depot_v2_2_sections_64.lmap \
  --section-size 64 --tile-size 64 --no-sync >/dev/null
cp tests/data/lmap/willow_v2_1_tolerance_1.lmap tests/data/lmap/willow_v2_2_tolerance_1.lmap \
  tests/data/lmap/willow_v2_3_tolerance_1.lmap tests/data/lmap/depot_v2_3_compact_tiles_64.lmap \
  tests/data/lmap/depot_v2_0.lmap tests/data/lmap/depot_v2_2_sections_64.lmap \
  tests/fuzz/corpus/lmap_decode/
cp tests/data/lmap/depot_v2_2_sections_64.lmap tests/fuzz/corpus/lmap_vectors/
for f in lse_arena_v2 depot_v2; do
  mkdir -p tests/fuzz/corpus/lmap_vectors
  cp tests/data/lmap/$f.lmap tests/fuzz/corpus/lmap_decode/$f.lmap
  cp tests/data/lmap/$f.lmap tests/fuzz/corpus/lmap_vectors/$f.lmap
done
python3 - <<'PY'
import struct, zlib

def varint(v):
    out = bytearray()
    while True:
        b = v & 0x7F
        v >>= 7
        if v:
            out.append(b | 0x80)
        else:
            out.append(b)
            return bytes(out)

def read_varint(data, pos):
    v = shift = 0
    while True:
        b = data[pos]; pos += 1
        v |= (b & 0x7F) << shift; shift += 7
        if not b & 0x80:
            return v, pos

def parse(data):
    pos, chunks = 10, []
    while pos < len(data):
        t = data[pos:pos + 4]; n, p = read_varint(data, pos + 4)
        chunks.append([t, data[p:p + n]]); pos = p + n + 4
    return data[:10], chunks

def build(head, chunks):
    out = bytearray(head)
    for t, payload in chunks:
        out += t + varint(len(payload)) + payload
        out += struct.pack('<I', zlib.crc32(t + payload) & 0xFFFFFFFF)
    return bytes(out)

head, chunks = parse(open('tests/data/lmap/depot_v2_0.lmap', 'rb').read())
types = [c[0] for c in chunks]
bad = 'tests/data/bad/lmap_decode/'

def chunk(name):
    return chunks[types.index(name)]

def write(name, cs):
    open(bad + name, 'wb').write(build(head, cs))

# CELL payload: coder byte 0, then the tile side varint.
cell = chunk(b'CELL')
write('v2_tile_size_below_16.lmap',
      [c if c[0] != b'CELL' else [b'CELL', b'\x00' + varint(8) + cell[1][1 + len(varint(1024)):]]
       for c in chunks])
# One more byte after the tiles: the lengths no longer add up.
write('v2_tile_lengths_do_not_add_up.lmap',
      [c if c[0] != b'CELL' else [b'CELL', cell[1] + b'\x00'] for c in chunks])
# WALL after CELL.
order = [c for c in chunks if c[0] not in (b'WALL', b'LEND')]
order.insert(len(order), chunk(b'WALL'))
write('v2_wall_after_cell.lmap', [c for c in order if c[0] != b'LEND'] + [chunk(b'LEND')])
# A 1.0 chunk in a 2.0 file.
write('v2_segs_chunk_in_version_2.lmap',
      chunks[:1] + [[b'SEGS', b'\x00\x00']] + chunks[1:])
# A wall count of 2^40: more than the segment limit.
wall = chunk(b'WALL')
_, p = read_varint(wall[1], 1)
write('v2_wall_count_over_limit.lmap',
      [c if c[0] != b'WALL' else [b'WALL', b'\x00' + varint(1 << 40) + wall[1][p:]] for c in chunks])
# The WALL stream cut short.
write('v2_wall_stream_truncated.lmap',
      [c if c[0] != b'WALL' else [b'WALL', wall[1][:len(wall[1]) // 2]] for c in chunks])
# A room count of 2^26 and an empty stream: a stream reads zeros past its
# end, and zeros decode as the smallest room (one vertex), so only the
# object limit (2^20 by default) keeps a file of some 50 bytes (54 as the
# fuzz run's helper wrote it) from asking for 10 GB.
write('v2_room_count_over_object_limit.lmap',
      [c if c[0] != b'ROOM' else [b'ROOM', b'\x00' + varint(1 << 26)] for c in chunks])

# Version 2.1: BLKS payload: coder byte 0, block side u8, tile side varint.
head21, chunks21 = parse(open('tests/data/lmap/willow_v2_1_tolerance_1.lmap', 'rb').read())
blks = [c for c in chunks21 if c[0] == b'BLKS'][0]

def with_blks(payload):
    return build(head21, [c if c[0] != b'BLKS' else [b'BLKS', payload] for c in chunks21])

open(bad + 'v2_1_block_side_1.lmap', 'wb').write(with_blks(b'\x00\x01' + blks[1][2:]))
# Side 3 with the tile side of the side-2 file (1024): not a multiple.
open(bad + 'v2_1_tile_side_not_a_multiple_of_the_block_side.lmap', 'wb').write(
    with_blks(b'\x00\x03' + blks[1][2:]))
# Both forms of the cells: CELL (from the exact file) before BLKS.
both = [c for c in chunks21 if c[0] != b'BLKS' and c[0] != b'LEND'] + [chunk(b'CELL'), blks,
                                                                       [b'LEND', b'']]
open(bad + 'v2_1_cell_and_blks.lmap', 'wb').write(build(head21, both))

# Version 2.2: LAYR payload: coder byte 0, section side varint, the table,
# the streams.
head22, chunks22 = parse(open('tests/data/lmap/depot_v2_2_sections_64.lmap', 'rb').read())
layr = [c for c in chunks22 if c[0] == b'LAYR'][0]

def with_layr(payload, extra=()):
    out = []
    for c in chunks22:
        if c[0] == b'LAYR':
            out.extend(extra)
            out.append([b'LAYR', payload])
        else:
            out.append(c)
    return build(head22, out)

side, p = read_varint(layr[1], 1)
open(bad + 'v2_2_section_side_8.lmap', 'wb').write(with_layr(b'\x00' + varint(8) + layr[1][p:]))
# A side of 2^64 - 1: refused before a decoder cuts the map into bands of it.
open(bad + 'v2_2_section_side_2_64_minus_1.lmap', 'wb').write(
    with_layr(b'\x00' + varint((1 << 64) - 1) + layr[1][p:]))
# The 2.0 file's WALL before LAYR: the layers twice.
open(bad + 'v2_2_layr_and_wall.lmap', 'wb').write(with_layr(layr[1], [chunk(b'WALL')]))
# The first section with items gets a box one column narrower than its
# points: an item outside its section's box.
q = p
while True:
    counts = []
    for _ in range(3):
        v, q = read_varint(layr[1], q)
        counts.append(v)
    if sum(counts):
        break
c0, q = read_varint(layr[1], q)
r0, q = read_varint(layr[1], q)
dc_at = q
dc, q = read_varint(layr[1], q)
assert dc > 0
narrow = layr[1][:dc_at] + varint(dc - 1) + layr[1][q:]
assert len(varint(dc - 1)) == len(varint(dc))
open(bad + 'v2_2_item_outside_its_section_box.lmap', 'wb').write(with_layr(narrow))
# The table's checks (5.6), on the same first section with items: a box
# one column wider than the grid (c0 + dc = width); a B one larger, the
# streams unchanged (the B no longer add up to the bytes left); and the
# body cut a few bytes after S (fewer than 3n bytes for the n sections).
width, _ = read_varint(chunks22[0][1], 0)
q = dc_at + len(varint(dc))
assert len(varint(width - c0)) == len(varint(dc))
wide = layr[1][:dc_at] + varint(width - c0) + layr[1][q:]
open(bad + 'v2_2_section_box_outside_the_grid.lmap', 'wb').write(with_layr(wide))
dr, b_at = read_varint(layr[1], q)
b, q = read_varint(layr[1], b_at)
assert len(varint(b + 1)) == len(varint(b))
longer = layr[1][:b_at] + varint(b + 1) + layr[1][q:]
open(bad + 'v2_2_section_lengths_do_not_add_up.lmap', 'wb').write(with_layr(longer))
open(bad + 'v2_2_section_table_under_3_bytes_a_section.lmap', 'wb').write(
    with_layr(layr[1][:p + 6]))
# A table of one section (S = 1024 on depot) whose walls exceed the
# default segment limit (2^24 + 1) and whose rooms are 2^32: no limit makes
# 2^32 rooms readable (32-bit ids), so the file is corrupt, not over a
# limit that --max-segments would raise (all three counts are checked
# before the sums).
open(bad + 'v2_2_section_room_count_2_32_beside_walls_over_the_limit.lmap', 'wb').write(
    build(head22, [chunks22[0], [b'LAYR', b'\x00' + varint(1024) + varint((1 << 24) + 1) +
                               varint(1 << 32) + varint(0) + varint(0)], [b'LEND', b'']]))

# Version 2.3: the compact file's tiles name models 12 and 3; one named 13
# (reserved) must fail. CELL payload: coder byte 0, tile side, the index.
import math
head23, chunks23 = parse(open('tests/data/lmap/depot_v2_3_compact_tiles_64.lmap', 'rb').read())
cell23 = [c for c in chunks23 if c[0] == b'CELL'][0]
side, q = read_varint(cell23[1], 1)
lengths = []
for _ in range(math.ceil(604 / side) * math.ceil(307 / side)):
    n, q = read_varint(cell23[1], q)
    lengths.append(n)
models, at = set(), q
for n in lengths:
    if n:
        models.add(cell23[1][at] & 31)
    at += n
assert {3, 12} <= models, models
first = q  # the first tile's model byte (depot's first tile has cells)
assert lengths[0] > 0
body13 = bytearray(cell23[1])
body13[first] = (body13[first] & ~31) | 13
open(bad + 'v2_3_tile_model_13.lmap', 'wb').write(
    build(head23, [c if c[0] != b'CELL' else [b'CELL', bytes(body13)] for c in chunks23]))

# The tolerance file's metadata (its T) with a byte after its last entry:
# corrupt for every reader, the header-only one included.
head23t, chunks23t = parse(open('tests/data/lmap/willow_v2_3_tolerance_1.lmap', 'rb').read())
assert any(c[0] == b'meta' for c in chunks23t)
open(bad + 'v2_3_meta_trailing_bytes.lmap', 'wb').write(
    build(head23t, [c if c[0] != b'meta' else [b'meta', c[1] + b'\x00'] for c in chunks23t]))
# Its metadata with a count of entries above body size / 2 (4.3): 7 in a
# body of 13 bytes.
meta = [c for c in chunks23t if c[0] == b'meta'][0]
count, q = read_varint(meta[1], 1)
count = (len(meta[1]) - 1) // 2 + 1  # the body: the payload after its coder byte
assert len(varint(count)) == q - 1
open(bad + 'v2_meta_count_over_body_size.lmap', 'wb').write(
    build(head23t, [c if c[0] != b'meta' else [b'meta', b'\x00' + varint(count) + meta[1][q:]]
                    for c in chunks23t]))
# Its BLKS (one tile) with the first tile's block data length a one byte
# past the tile's end (6.4); the varint keeps its size.
blks = [c for c in chunks23t if c[0] == b'BLKS'][0]
width, q = read_varint(chunks23t[0][1], 0)
height, q = read_varint(chunks23t[0][1], q)
side, q = read_varint(blks[1], 2)
assert math.ceil(width / side) * math.ceil(height / side) == 1
n, q = read_varint(blks[1], q)
a, r = read_varint(blks[1], q)
assert len(varint(n - (r - q) + 1)) == r - q
open(bad + 'v2_1_block_data_past_the_tile.lmap', 'wb').write(
    build(head23t, [c if c[0] != b'BLKS' else [b'BLKS', blks[1][:q] + varint(n - (r - q) + 1) +
                                               blks[1][r:]] for c in chunks23t]))

# A file without cells must still hold valid layers: the 2.2 file's LAYR
# with the last byte of its stream set to 0 (a stream may not end in a zero
# byte), and no CELL chunk.
head2, chunks2 = parse(open('tests/data/lmap/depot_v2.lmap', 'rb').read())
nocell = []
for t, payload in chunks2:
    if t == b'CELL':
        continue
    nocell.append([t, payload[:-1] + b'\x00' if t == b'LAYR' else payload])
open(bad + 'v2_2_layr_stream_corrupt_without_cells.lmap', 'wb').write(build(head2, nocell))

# A grid of 0 columns by 5 rows has no tiles, but its cells' chunk must
# still be well formed. LMHD payload (no coder byte): width varint, height
# varint, the rest; the layers are left out (nothing lies in such a grid).
def empty_grid(head_chunk):
    width, q = read_varint(head_chunk[1], 0)
    height, q = read_varint(head_chunk[1], q)
    return [b'LMHD', varint(0) + varint(5) + head_chunk[1][q:]]

open(bad + 'v2_empty_grid_tile_size_5.lmap', 'wb').write(
    build(head2, [empty_grid(chunks2[0]), [b'CELL', b'\x00' + varint(5) + b'garbage'],
                  [b'LEND', b'']]))
open(bad + 'v2_1_empty_grid_block_side_0.lmap', 'wb').write(
    build(head21, [empty_grid(chunks21[0]), [b'BLKS', b'\x00\x00' + varint(16)],
                   [b'LEND', b'']]))

# The index of depot_v2.lmap's CELL (6.1; one tile of 1024 cells): a tile
# side of 65537; a tile length of 2^20, above the body size; and a body of
# the tile side 64 alone, where 10 x 5 tiles need at least 50 bytes.
cell = [c for c in chunks2 if c[0] == b'CELL'][0]
side, q = read_varint(cell[1], 1)
n, r = read_varint(cell[1], q)

def with_cell(payload):
    return build(head2, [c if c[0] != b'CELL' else [b'CELL', payload] for c in chunks2])

open(bad + 'v2_tile_size_65537.lmap', 'wb').write(with_cell(b'\x00' + varint(65537) + cell[1][q:]))
open(bad + 'v2_tile_length_over_body_size.lmap', 'wb').write(
    with_cell(cell[1][:q] + varint(1 << 20) + cell[1][r:]))
open(bad + 'v2_tile_count_over_bytes_left.lmap', 'wb').write(with_cell(b'\x00' + varint(64)))

# depot_v2.lmap's header (4.2): flag bit 5 (reserved) set; an origin
# (flag bit 4, its x and y after the resolution) of x NaN, then of y -inf.
def with_header(payload):
    return build(head2, [[b'LMHD', payload]] + chunks2[1:])

lmhd = chunks2[0][1]
_, q = read_varint(lmhd, 0)
_, q = read_varint(lmhd, q)  # the flags
assert not lmhd[q] & 0xF0

def with_origin(x, y):  # after the flags: the mode (1 byte), the resolution (8)
    return (lmhd[:q] + bytes([lmhd[q] | 0x10]) + lmhd[q + 1:q + 10] + struct.pack('<dd', x, y) +
            lmhd[q + 10:])

open(bad + 'v2_header_reserved_flag_bit_5.lmap', 'wb').write(
    with_header(lmhd[:q] + bytes([lmhd[q] | 0x20]) + lmhd[q + 1:]))
open(bad + 'v2_origin_x_nan.lmap', 'wb').write(with_header(with_origin(float('nan'), 0.0)))
open(bad + 'v2_origin_y_infinite.lmap', 'wb').write(with_header(with_origin(0.0, float('-inf'))))

# depot_v2.lmap's LAYR deflated (payload coder 1, 4.1) and cut short: the
# zlib stream is written by hand (one stored block, so that it does not
# depend on the zlib at hand) and loses its second half.
layr2 = [c for c in chunks2 if c[0] == b'LAYR'][0][1][1:]
assert len(layr2) < 65536
zstream = (b'\x78\x01\x01' + struct.pack('<HH', len(layr2), len(layr2) ^ 0xFFFF) + layr2 +
           struct.pack('>I', zlib.adler32(layr2)))
assert zlib.decompress(zstream) == layr2
open(bad + 'v2_2_layr_deflate_stream_truncated.lmap', 'wb').write(
    build(head2, [c if c[0] != b'LAYR' else
                  [b'LAYR', b'\x01' + varint(len(layr2)) + zstream[:len(zstream) // 2]]
                  for c in chunks2]))
PY
