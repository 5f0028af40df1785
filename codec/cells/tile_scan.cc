// The scan shared by the tile coder's encoder and decoder (spec/tile_coding.md
// "Scan": rows, super-blocks, blocks, then the runs of tile_cell_runs.h) and
// a tile's bytes around it (model byte, end marker). The scan, the bit
// coders (EncodeIo, DecodeIo) and all they inline are local to this one
// translation unit: given external linkage in a header, GCC inlined them and
// allocated the per-cell loops' registers differently (measured: model 3
// decoded about 5 % slower; model 12's cell loop was no longer inlined).
#include <algorithm>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "codec/cells/tile_cell_runs.h"
#include "codec/cells/tile_coder_internal.h"
#include "codec/cells/tile_contexts.h"
#include "codec/cells/tile_mixer.h"
#include "codec/cells/tile_range_coder.h"

namespace linemap::tile_coder_internal {
namespace {

// The first byte of a tile's data: bits 0-4 name the model the cells were
// coded with, bits 5-7 count the zero bytes dropped from the stream's end.
constexpr std::uint8_t kModelMask = 31;
constexpr int kDroppedShift = 5;

// Encoder and decoder share one scan (CodeTile) so that their contexts
// cannot drift apart; these adapters either code the known bit or decode it.
class EncodeIo {
 public:
  static constexpr bool kEncoding = true;
  int Code(TileBitModel* m, int bit) {
    enc_.Encode(m, bit);
    return bit;
  }
  int CodeP(std::uint32_t p0, int bit) {
    enc_.EncodeP(p0, bit);
    return bit;
  }
  TileRangeEncoder& encoder() { return enc_; }

 private:
  TileRangeEncoder enc_;
};

class DecodeIo {
 public:
  static constexpr bool kEncoding = false;
  DecodeIo(const std::uint8_t* data, std::size_t size) : dec_(data, size) {}
  int Code(TileBitModel* m, int /*bit*/) { return dec_.Decode(m); }
  int CodeP(std::uint32_t p0, int /*bit*/) { return dec_.DecodeP(p0); }
  const TileRangeDecoder& decoder() const { return dec_; }

 private:
  TileRangeDecoder dec_;
};

template <bool kMix, bool kLayer, typename Io, typename Mixer>
void CodeCellsIn(Io& io, TileModelTable& models, Mixer& mixer, const CellRows& rows, int begin,
                 int end) {
  if constexpr (kLayer && kMix) {
    CodeMixedLayerCellRun(io, models, mixer, rows.cur, rows.n1, rows.n2, rows.hint_below,
                          rows.hint_row, rows.hint_above, rows.width, rows.terms, begin, end);
  } else if constexpr (kLayer) {
    CodeLayerCellRun(io, models, rows.cur, rows.n1, rows.hint_below, rows.hint_row, rows.hint_above,
                     rows.width, *rows.term_bytes, begin, end);
  } else {
    CodeCellRun<kMix>(io, models, mixer, rows.cur, rows.n1, rows.n2, rows.hint_row, begin, end);
  }
}

// The decoder's state in a local for the run (see CodeTile): the cells
// are stored as bytes, which may alias any object, so a decoder reached
// through a reference would be reloaded from memory after every cell.
template <bool kMix, bool kLayer, typename Io, typename Mixer>
void CodeCells(Io& io, TileModelTable& models, Mixer& mixer, const CellRows& rows, int begin,
               int end) {
  if constexpr (Io::kEncoding) {
    CodeCellsIn<kMix, kLayer>(io, models, mixer, rows, begin, end);
  } else {
    Io local = io;
    CodeCellsIn<kMix, kLayer>(local, models, mixer, rows, begin, end);
    io = local;
  }
}

// The scan shared by encoder and decoder (spec "Scan"). `cells` is read by
// the encoder, `canvas` written by the decoder; `hints` is width*height.
template <bool kMix, bool kFlags, bool kLayer, typename Io>
void CodeTileScan(Io& io, const TileRows& t) {
  const int tw = t.width;
  const int th = t.height;
  const std::uint8_t* hints = t.hints;
  const int blocks = (tw + kBlockCells - 1) / kBlockCells;
  TileModelTable models(kLayer && kMix ? kMixedLayerModelCount
                        : kLayer       ? kLayerModelCount
                                       : kModelCount);
  // Model 12 mixes four predictions, models 1 and 3 two.
  using Mixer = std::conditional_t<kLayer && kMix, TileMixer<4>, TileMixer<2>>;
  Mixer mixer(kLayer && kMix ? kMixedLayerSets : kMix ? kMixerSets : 0);
  RowRing ring(tw);
  std::vector<std::uint8_t> above_state(static_cast<std::size_t>(blocks), kStateNone);
  std::vector<std::uint8_t> above_super(
      static_cast<std::size_t>((blocks + kSuperBlocks - 1) / kSuperBlocks), kStateNone);
  // Without layers every hint is zero: all rows read this one (the layer
  // context reads it for the rows outside the tile as well).
  const std::vector<std::uint8_t> zero_hints(
      hints == nullptr || kLayer ? static_cast<std::size_t>(tw) : 0, 0);
  const LayerTermBytes term_bytes(t.layer_terms);
  unsigned row_state = kStateNone;
  const int rows_end = Io::kEncoding ? th : t.rows_wanted;
  for (int r = 0; r < rows_end; ++r) {
    std::uint8_t* cur = ring.Row(r + 2);
    const std::uint8_t* n1 = ring.Row(r + 1);
    const std::uint8_t* n2 = ring.Row(r);
    const std::uint8_t* hint_row = hints ? hints + r * t.hint_stride : zero_hints.data();
    // The hints one row below (read only for r > 0: inside the tile). With
    // the hints in the canvas, that row's cells are not written yet.
    const std::uint8_t* hint_below =
        !hints || r == 0 ? zero_hints.data() : hint_row - t.hint_stride;
    if constexpr (Io::kEncoding) {
      std::memcpy(cur, t.cells + r * t.cell_stride, static_cast<std::size_t>(tw));
    }
    const std::uint8_t* hint_above =
        hints && r + 1 < th ? hint_row + t.hint_stride : zero_hints.data();
    const CellRows cell_rows{cur,           n1,         n2, hint_row, hint_below, hint_above, tw,
                             t.layer_terms, &term_bytes};
    const bool hints_same =
        r > 0 && (hints == nullptr || std::memcmp(hint_row, hint_below, tw) == 0);
    const unsigned row_ctx = row_state * 2 + (hints_same ? 1 : 0);
    const int row_copy =
        io.Code(&models[kRowModel + row_ctx], Io::kEncoding && std::memcmp(cur, n1, tw) == 0);
    if (row_copy) {
      if constexpr (!Io::kEncoding) std::memcpy(cur, n1, static_cast<std::size_t>(tw));
      std::fill(above_state.begin(), above_state.end(), kStateCopy);
      std::fill(above_super.begin(), above_super.end(), kStateCopy);
      row_state = kStateCopy;
    } else if (!kFlags) {
      CodeCells<kMix, kLayer>(io, models, mixer, cell_rows, 0, tw);
      row_state = kStateCoded;
    } else {
      unsigned left = kStateNone;
      unsigned super_left = kStateNone;
      for (int sb = 0; sb < blocks; sb += kSuperBlocks) {
        const int sb_end = std::min(sb + kSuperBlocks, blocks);
        const int s_begin = sb * kBlockCells;
        const int s_end = std::min(sb_end * kBlockCells, tw);
        const std::size_t s_len = static_cast<std::size_t>(s_end - s_begin);
        const std::size_t si = static_cast<std::size_t>(sb / kSuperBlocks);
        // Hints equal over the row are equal over each of its parts: no
        // comparison then (and likewise for a super-block's blocks).
        const bool super_hints_same =
            hints_same ||
            (r > 0 && (hints == nullptr ||
                       std::memcmp(hint_row + s_begin, hint_below + s_begin, s_len) == 0));
        const unsigned super_uniform =
            std::memcmp(n1 + s_begin - 1, n1 + s_begin, s_len + 1) == 0 ? 1u + n1[s_begin] : 0u;
        const unsigned super_ctx =
            ((above_super[si] * 3 + super_left) * 2 + (super_hints_same ? 1 : 0)) * 4 +
            super_uniform;
        const int super_copy =
            io.Code(&models[kSuperModel + super_ctx],
                    Io::kEncoding && std::memcmp(cur + s_begin, n1 + s_begin, s_len) == 0);
        super_left = super_copy ? kStateCopy : kStateCoded;
        above_super[si] = static_cast<std::uint8_t>(super_left);
        if (super_copy) {
          if constexpr (!Io::kEncoding) std::memcpy(cur + s_begin, n1 + s_begin, s_len);
          for (int b = sb; b < sb_end; ++b) above_state[b] = kStateCopy;
          left = kStateCopy;
          continue;
        }
        bool changed = false;
        for (int b = sb; b < sb_end; ++b) {
          const int begin = b * kBlockCells;
          const int end = std::min(begin + kBlockCells, tw);
          const std::size_t len = static_cast<std::size_t>(end - begin);
          const bool full = len == kBlockCells;
          const bool block_hints_same =
              super_hints_same ||
              (r > 0 &&
               (hints == nullptr || SameCells(hint_row + begin, hint_below + begin, len, full)));
          const unsigned above_right = b + 1 < blocks ? above_state[b + 1] : kStateNone;
          // Whether the row below is one value over the block and its two
          // neighbours (and which): a uniform area rarely starts a structure.
          // (n1[begin - 1 .. end] all equal each their right neighbour.)
          const unsigned uniform =
              SameCells(n1 + begin - 1, n1 + begin, len, full) && n1[end - 1] == n1[end]
                  ? 1u + n1[begin]
                  : 0u;
          const unsigned ctx =
              ((((above_state[b] * 3 + left) * 3 + above_right) * 2 + (block_hints_same ? 1 : 0)) *
                   4 +
               uniform);
          // The super-block differs, so when every block before the last was
          // equal, the last one differs: no decision.
          // Layer context: a block next to a drawn wall changes more often
          // than one in the open (LBLOCK; 0.6 % smaller at the tuning median
          // with the file's layers).
          const bool wall_near =
              kLayer && WallNearBlock(hint_below, hint_row, cell_rows.hint_above, begin, len, full);
          const int copy =
              b + 1 == sb_end && !changed
                  ? 0
                  : io.Code(&models[(wall_near ? kLayerBlockModel : kBlockModel) + ctx],
                            Io::kEncoding && SameCells(cur + begin, n1 + begin, len, full));
          if (copy) {
            if constexpr (!Io::kEncoding) {
              if (full) {
                std::memcpy(cur + begin, n1 + begin, kBlockCells);
              } else {
                std::memcpy(cur + begin, n1 + begin, len);
              }
            }
          } else {
            CodeCells<kMix, kLayer>(io, models, mixer, cell_rows, begin, end);
            changed = true;
          }
          left = copy ? kStateCopy : kStateCoded;
          above_state[b] = static_cast<std::uint8_t>(left);
        }
      }
      row_state = kStateCoded;
    }
    // The decoder writes a row's cells one row late, once the row above
    // it has read its hints: with the hints in the canvas (a tile decoded
    // over its hints), they are still there to read, not copied aside row
    // by row (1 % of the decode time over ../shared/maps).
    if constexpr (!Io::kEncoding) {
      if (r > 0) {
        std::memcpy(t.canvas + (r - 1) * t.canvas_stride, n1, static_cast<std::size_t>(tw));
      }
    }
  }
  if constexpr (!Io::kEncoding) {
    if (rows_end > 0) {
      std::memcpy(t.canvas + (rows_end - 1) * t.canvas_stride, ring.Row(rows_end + 1),
                  static_cast<std::size_t>(tw));
    }
  }
}

// The decoder's state is copied into a local for the scan: the cells and
// the models' counts are stored as bytes, which may alias any object, so
// a decoder reached through a reference would be reloaded from memory after
// every cell; a local whose address is never taken stays in registers
// (decode ~10 % faster).
template <bool kMix, bool kFlags, bool kLayer, typename Io>
void CodeTile(Io& io, const TileRows& t) {
  if constexpr (Io::kEncoding) {
    CodeTileScan<kMix, kFlags, kLayer>(io, t);
  } else {
    Io local = io;
    CodeTileScan<kMix, kFlags, kLayer>(local, t);
    io = local;
  }
}

// After the cells, 16 bits of a fixed value at probability 1/2 each: data
// cut short or altered decodes other cells, and then, but for a chance of
// 2^-16, another value here; the end check on the bytes read alone misses
// the truncations that happen to read as many bytes as the stream holds.
constexpr unsigned kEndMarker = 0xA55A;

template <typename Io>
unsigned CodeEndMarker(Io& io) {
  unsigned value = 0;
  for (int b = 15; b >= 0; --b) {
    value = value << 1 | static_cast<unsigned>(io.CodeP(1u << 15, (kEndMarker >> b) & 1));
  }
  return value;
}

// Runs the scan of `model` (models 0-3: bit 0 mixed, bit 1 every cell of
// a changed row, no block flags; models 4-11: block flags, layer context
// with the terms model - 4 drops).
template <typename Io>
void CodeTileAs(Io& io, TileRows rows, unsigned model) {
  switch (model) {
    case 0:
      return CodeTile<false, true, false>(io, rows);
    case 1:
      return CodeTile<true, true, false>(io, rows);
    case 2:
      return CodeTile<false, false, false>(io, rows);
    case 3:
      return CodeTile<true, false, false>(io, rows);
    case static_cast<unsigned>(TileModel::kMixedLayerAllCells):
      return CodeTile<true, false, true>(io, rows);
    default:
      rows.layer_terms = LayerTermsOf(model);
      return CodeTile<false, true, true>(io, rows);
  }
}

}  // namespace

// Codes the tile's cells and the end marker; returns the tile's bytes.
std::vector<std::uint8_t> EncodeTile(const TileRows& rows, TileModel model) {
  if (rows.width <= 0 || rows.height <= 0) return {};
  EncodeIo io;
  CodeTileAs(io, rows, static_cast<unsigned>(model));
  CodeEndMarker(io);
  const int dropped = io.encoder().Finish();
  std::vector<std::uint8_t> out;
  out.reserve(io.encoder().bytes().size() + 1);
  out.push_back(static_cast<std::uint8_t>(static_cast<unsigned>(model) | dropped << kDroppedShift));
  out.insert(out.end(), io.encoder().bytes().begin(), io.encoder().bytes().end());
  return out;
}

Status DecodeTile(const std::uint8_t* data, std::size_t size, const TileRows& rows) {
  if (rows.width == 0 || rows.height == 0) {
    if (size != 0) return CorruptError("tile cells: an empty tile has data");
    return Status::Ok();
  }
  if (rows.rows_wanted < 1 || rows.rows_wanted > rows.height) {
    return InvalidArgumentError("tile cells: rows wanted " + std::to_string(rows.rows_wanted) +
                                " of " + std::to_string(rows.height));
  }
  if (size == 0) return CorruptError("tile cells: no data");
  const unsigned model = data[0] & kModelMask;
  if (model > static_cast<unsigned>(TileModel::kMixedLayerAllCells)) {
    return CorruptError("tile cells: unknown model " + std::to_string(model));
  }
  DecodeIo io(data + 1, size - 1);
  CodeTileAs(io, rows, model);
  // A tile decoded in part ends before its end marker: the chunk's CRC has
  // checked its bytes, and the range decoder never reads past them.
  if (rows.rows_wanted < rows.height) return Status::Ok();
  if (CodeEndMarker(io) != kEndMarker) {
    return CorruptError("tile cells: range-coded data is malformed or truncated");
  }
  // Decoding must read every stored byte and imply exactly the zero bytes
  // the encoder dropped, so extra or missing bytes mean the data is corrupt.
  if (!io.decoder().EndsCleanly(data[0] >> kDroppedShift)) {
    return CorruptError("tile cells: range-coded data is malformed or truncated");
  }
  return Status::Ok();
}

}  // namespace linemap::tile_coder_internal
