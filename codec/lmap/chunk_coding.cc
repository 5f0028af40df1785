#include "codec/lmap/chunk_coding.h"

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <tuple>

#include "format/deflate.h"

namespace linemap {
namespace {

// 8-neighbour steps, direction d = 0..7 counter-clockwise from east (rows
// grow upwards, as grid rows do).
constexpr int kStepCol[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kStepRow[8] = {0, 1, 1, 1, 0, -1, -1, -1};

bool Before(CellIndex p, CellIndex q) { return std::tie(p.row, p.col) < std::tie(q.row, q.col); }

// A finite, positive binary64 bit pattern (checked without floating point).
bool IsPositiveFinite(std::uint64_t bits) {
  const std::uint64_t exponent = (bits >> 52) & 0x7FF;
  return (bits >> 63) == 0 && exponent != 0x7FF && (bits & ~(std::uint64_t{1} << 63)) != 0;
}
bool IsFinite(std::uint64_t bits) { return ((bits >> 52) & 0x7FF) != 0x7FF; }

}  // namespace

std::vector<std::uint8_t> WrapPayload(const std::vector<std::uint8_t>& body, bool allow_deflate) {
  std::vector<std::uint8_t> raw;
  raw.reserve(body.size() + 1);
  raw.push_back(static_cast<std::uint8_t>(PayloadCoder::kRaw));
  raw.insert(raw.end(), body.begin(), body.end());
  if (!allow_deflate || body.empty()) return raw;
  ByteWriter deflated;
  deflated.PutU8(static_cast<std::uint8_t>(PayloadCoder::kDeflate));
  deflated.PutVarint(body.size());
  deflated.PutBytes(DeflateBytes(body.data(), body.size()));
  if (deflated.size() < raw.size()) return deflated.bytes();
  return raw;
}

StatusOr<std::vector<std::uint8_t>> UnwrapPayload(const std::uint8_t* payload, std::size_t size,
                                                  const DecodeLimits& limits, PayloadCoder* coder) {
  ByteCursor cursor(payload, size);
  LINEMAP_ASSIGN_OR_RETURN(std::uint8_t kind, cursor.ReadU8("payload coder"));
  switch (kind) {
    case static_cast<std::uint8_t>(PayloadCoder::kRaw): {
      *coder = PayloadCoder::kRaw;
      return std::vector<std::uint8_t>(payload + 1, payload + size);
    }
    case static_cast<std::uint8_t>(PayloadCoder::kDeflate): {
      *coder = PayloadCoder::kDeflate;
      auto inflated = cursor.ReadVarint("inflated size");
      if (!inflated.ok()) return inflated.status();
      // Deflate expands at most ~1032:1; a larger claim is corrupt whatever
      // the limit, so it is checked first.
      if (*inflated > 1032 * std::uint64_t{cursor.remaining()} + 64) {
        return CorruptError("inflated size is impossible for the deflate data");
      }
      if (*inflated > limits.max_inflated_bytes) {
        return OverLimitError(Limit::kInflatedBytes, "inflated size " + std::to_string(*inflated) +
                                                         " is over the limit of " +
                                                         std::to_string(limits.max_inflated_bytes));
      }
      const std::size_t at = cursor.position();
      return InflateBytes(payload + at, size - at, static_cast<std::size_t>(*inflated));
    }
    case static_cast<std::uint8_t>(PayloadCoder::kDraco):
      // Only SEGS bodies may be Draco-coded; the caller checks.
      *coder = PayloadCoder::kDraco;
      return std::vector<std::uint8_t>(payload + 1, payload + size);
    default:
      // Reserved for later minor versions: well-formed, just not known here.
      return UnsupportedError("unknown payload coder " + std::to_string(kind));
  }
}

namespace {
constexpr char kDracoOutsideSegs[] = "the Draco payload coder is for SEGS only";
}  // namespace

StatusOr<std::vector<std::uint8_t>> UnwrapV2Payload(const std::uint8_t* payload, std::size_t size,
                                                    const DecodeLimits& limits,
                                                    PayloadCoder* coder) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> body,
                           UnwrapPayload(payload, size, limits, coder));
  if (*coder == PayloadCoder::kDraco) return CorruptError(kDracoOutsideSegs);
  return body;
}

Status CheckV2PayloadCoder(const std::uint8_t* payload, std::size_t size) {
  ByteCursor cursor(payload, size);
  LINEMAP_ASSIGN_OR_RETURN(std::uint8_t kind, cursor.ReadU8("payload coder"));
  if (kind == static_cast<std::uint8_t>(PayloadCoder::kDraco)) {
    return CorruptError(kDracoOutsideSegs);
  }
  if (kind != static_cast<std::uint8_t>(PayloadCoder::kRaw) &&
      kind != static_cast<std::uint8_t>(PayloadCoder::kDeflate)) {
    return UnsupportedError("unknown payload coder " + std::to_string(kind));
  }
  return Status::Ok();
}

// The default thresholds are not stored (header flag bit 2 clear).
constexpr std::uint64_t kDefaultOccupiedBits = 0x3FE4CCCCCCCCCCCDull;  // 0.65
constexpr std::uint64_t kDefaultFreeBits = 0x3FC916872B020C4Aull;      // 0.196

enum HeaderFlag : std::uint8_t {
  kFlagNegate = 1,
  kFlagLossless = 2,
  kFlagThresholds = 4,  // occupied and free thresholds follow
  kFlagYaw = 8,         // origin yaw follows (else 0)
  kFlagOrigin = 16,     // origin x and y follow (else both +0.0)
  kFlagsKnown = 31,
};

std::vector<std::uint8_t> WriteHeader(const HeaderFields& h) {
  const std::uint64_t occ = std::bit_cast<std::uint64_t>(h.meta.occupied_thresh);
  const std::uint64_t fre = std::bit_cast<std::uint64_t>(h.meta.free_thresh);
  const std::uint64_t yaw = std::bit_cast<std::uint64_t>(h.meta.origin.yaw);
  const bool thresholds = occ != kDefaultOccupiedBits || fre != kDefaultFreeBits;
  std::uint8_t flags = 0;
  if (h.meta.negate) flags |= kFlagNegate;
  if (h.lossless) flags |= kFlagLossless;
  if (thresholds) flags |= kFlagThresholds;
  if (yaw != 0) flags |= kFlagYaw;
  const std::uint64_t ox = std::bit_cast<std::uint64_t>(h.meta.origin.x);
  const std::uint64_t oy = std::bit_cast<std::uint64_t>(h.meta.origin.y);
  if (ox != 0 || oy != 0) flags |= kFlagOrigin;
  ByteWriter w;
  w.PutVarint(static_cast<std::uint64_t>(h.width));
  w.PutVarint(static_cast<std::uint64_t>(h.height));
  w.PutU8(flags);
  w.PutU8(static_cast<std::uint8_t>(h.meta.mode));
  w.PutU64(std::bit_cast<std::uint64_t>(h.meta.resolution));
  if (flags & kFlagOrigin) {
    w.PutU64(ox);
    w.PutU64(oy);
  }
  if (flags & kFlagYaw) w.PutU64(yaw);
  if (flags & kFlagThresholds) {
    w.PutU64(occ);
    w.PutU64(fre);
  }
  return w.bytes();
}

StatusOr<HeaderFields> ReadHeader(const std::uint8_t* data, std::size_t size,
                                  const DecodeLimits& limits) {
  ByteCursor c(data, size);
  HeaderFields h;
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t width, c.ReadVarintAtMost(0x7FFFFFFF, "width"));
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t height, c.ReadVarintAtMost(0x7FFFFFFF, "height"));
  std::uint64_t cells = 0;
  if (!CheckedMul(width, height, &cells) || cells > limits.max_cells) {
    return OverLimitError(Limit::kCells, "map of " + std::to_string(width) + " x " +
                                             std::to_string(height) +
                                             " cells is over the limit of " +
                                             std::to_string(limits.max_cells) + " cells");
  }
  LINEMAP_ASSIGN_OR_RETURN(std::uint8_t flags, c.ReadU8("flags"));
  LINEMAP_ASSIGN_OR_RETURN(std::uint8_t mode, c.ReadU8("mode"));
  if ((flags & ~kFlagsKnown) != 0) return CorruptError("reserved header flags are set");
  if (mode > 2) return CorruptError("unknown pixel mode " + std::to_string(mode));
  std::uint64_t bits[6] = {0, 0, 0, 0, kDefaultOccupiedBits, kDefaultFreeBits};
  LINEMAP_ASSIGN_OR_RETURN(bits[0], c.ReadU64("resolution"));
  if (flags & kFlagOrigin) {
    LINEMAP_ASSIGN_OR_RETURN(bits[1], c.ReadU64("origin x"));
    LINEMAP_ASSIGN_OR_RETURN(bits[2], c.ReadU64("origin y"));
  }
  if (flags & kFlagYaw) {
    LINEMAP_ASSIGN_OR_RETURN(bits[3], c.ReadU64("origin yaw"));
  }
  if (flags & kFlagThresholds) {
    LINEMAP_ASSIGN_OR_RETURN(bits[4], c.ReadU64("occupied threshold"));
    LINEMAP_ASSIGN_OR_RETURN(bits[5], c.ReadU64("free threshold"));
  }
  if (!IsPositiveFinite(bits[0])) return CorruptError("resolution is not a positive number");
  constexpr const char* kNames[6] = {"resolution", "origin x",           "origin y",
                                     "origin yaw", "occupied threshold", "free threshold"};
  for (int i = 1; i < 6; ++i) {
    if (!IsFinite(bits[i])) return CorruptError(std::string(kNames[i]) + " is not finite");
  }
  if (!c.empty()) return CorruptError("header has trailing bytes");
  h.width = static_cast<int>(width);
  h.height = static_cast<int>(height);
  h.meta.resolution = std::bit_cast<double>(bits[0]);
  h.meta.origin = Pose2D{std::bit_cast<double>(bits[1]), std::bit_cast<double>(bits[2]),
                         std::bit_cast<double>(bits[3])};
  h.meta.occupied_thresh = std::bit_cast<double>(bits[4]);
  h.meta.free_thresh = std::bit_cast<double>(bits[5]);
  h.meta.mode = static_cast<MapMode>(mode);
  h.meta.negate = (flags & kFlagNegate) != 0;
  h.lossless = (flags & kFlagLossless) != 0;
  return h;
}

std::vector<std::uint8_t> WriteMetadata(
    const std::vector<std::pair<std::string, std::string>>& entries) {
  ByteWriter w;
  w.PutVarint(entries.size());
  for (const auto& [key, value] : entries) {
    w.PutVarint(key.size());
    w.PutBytes(key);
    w.PutVarint(value.size());
    w.PutBytes(value);
  }
  return w.bytes();
}

StatusOr<std::vector<std::pair<std::string, std::string>>> ReadMetadata(
    const std::vector<std::uint8_t>& body) {
  ByteCursor c(body);
  // Each entry needs at least 2 bytes, which bounds the count.
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t count, c.ReadVarintAtMost(body.size() / 2, "entry count"));
  std::vector<std::pair<std::string, std::string>> entries;
  for (std::uint64_t i = 0; i < count; ++i) {
    std::string text[2];
    for (std::string& t : text) {
      LINEMAP_ASSIGN_OR_RETURN(std::uint64_t n, c.ReadVarintAtMost(c.remaining(), "text length"));
      LINEMAP_ASSIGN_OR_RETURN(const std::uint8_t* p, c.ReadBytes(n, "text"));
      t.assign(reinterpret_cast<const char*>(p), n);
    }
    entries.emplace_back(std::move(text[0]), std::move(text[1]));
  }
  if (!c.empty()) return CorruptError("metadata has trailing bytes");
  return entries;
}

std::optional<int> ToleranceCellsOf(
    int major, bool lossless, const std::vector<std::pair<std::string, std::string>>& metadata) {
  if (major < 2 || lossless) return std::nullopt;
  for (auto entry = metadata.rbegin(); entry != metadata.rend(); ++entry) {
    if (entry->first != kToleranceMetadataKey) continue;
    const std::string& text = entry->second;
    // Plain decimal only: no sign, no spaces, no leading zero, at most ten
    // digits (so the sum below cannot overflow before the range check).
    if (text.empty() || text.size() > 10 || text[0] == '0') return std::nullopt;
    std::int64_t value = 0;
    for (char ch : text) {
      if (ch < '0' || ch > '9') return std::nullopt;
      value = value * 10 + (ch - '0');
    }
    if (value > std::numeric_limits<int>::max()) return std::nullopt;
    return static_cast<int>(value);
  }
  return std::nullopt;
}

StatusOr<std::vector<LatticeSegment>> ReadSegments(const std::vector<std::uint8_t>& body, int width,
                                                   int height, const DecodeLimits& limits) {
  ByteCursor c(body);
  // Each segment takes at least 4 bytes: a larger count is impossible for the
  // body (corrupt); the caller's limit is checked second (resource exhausted).
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t count,
                           c.ReadVarintAtMost(body.size() / 4, "segment count"));
  if (count > limits.max_segments) {
    return OverLimitError(Limit::kSegments, "segment count " + std::to_string(count) +
                                                " is over the limit of " +
                                                std::to_string(limits.max_segments));
  }
  std::vector<LatticeSegment> segments;
  segments.reserve(count);
  CellIndex prev{0, 0};
  for (std::uint64_t i = 0; i < count; ++i) {
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t drow, c.ReadVarintAtMost(height, "segment row"));
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t col, c.ReadVarintAtMost(width, "segment column"));
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t length_rows, c.ReadVarintAtMost(height, "segment rows"));
    LINEMAP_ASSIGN_OR_RETURN(std::int64_t dcol, c.ReadSignedVarint("segment columns"));
    // In 64 bits and checked before narrowing: near 2^31 cells a sum of two
    // in-range fields can wrap an int to a negative position.
    const std::int64_t arow = std::int64_t{prev.row} + static_cast<std::int64_t>(drow);
    const std::int64_t acol = static_cast<std::int64_t>(col) + (drow == 0 ? prev.col : 0);
    const std::int64_t brow = arow + static_cast<std::int64_t>(length_rows);
    // |dcol| > width puts b outside anyway; the test keeps acol + dcol from
    // overflowing.
    const bool dcol_ok = dcol >= -std::int64_t{width} && dcol <= width;
    const std::int64_t bcol = dcol_ok ? acol + dcol : -1;
    if (arow < 0 || arow >= height || acol < 0 || acol >= width || brow < 0 || brow >= height ||
        bcol < 0 || bcol >= width) {
      return CorruptError("segment " + std::to_string(i) + " lies outside the map");
    }
    LatticeSegment s;
    s.a = CellIndex{static_cast<int>(acol), static_cast<int>(arow)};
    s.b = CellIndex{static_cast<int>(bcol), static_cast<int>(brow)};
    if (Before(s.b, s.a)) return CorruptError("segment " + std::to_string(i) + " is not canonical");
    segments.push_back(s);
    prev = s.a;
  }
  if (!c.empty()) return CorruptError("segment data has trailing bytes");
  return segments;
}

StatusOr<std::vector<std::vector<CellIndex>>> ReadChains(const std::vector<std::uint8_t>& body,
                                                         int width, int height,
                                                         const DecodeLimits& limits) {
  ByteCursor c(body);
  LINEMAP_ASSIGN_OR_RETURN(std::uint64_t count, c.ReadVarintAtMost(body.size() / 3, "chain count"));
  if (count > 0 && (width == 0 || height == 0)) return CorruptError("chain in an empty map");
  std::vector<std::vector<CellIndex>> chains;
  std::uint64_t total = 0;
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::string name = "chain " + std::to_string(k);
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t length, c.ReadVarint("chain length"));
    // Steps past the body are corrupt; past the caller's limit, resource
    // exhausted (total <= limit here, so the subtraction cannot wrap).
    if (length == 0 || length - 1 > c.remaining()) return CorruptError(name + " has a bad length");
    if (length > limits.max_chain_length - total) {
      return OverLimitError(Limit::kChainLength, name +
                                                     " takes the chain cells over the limit of " +
                                                     std::to_string(limits.max_chain_length));
    }
    total += length;
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t col, c.ReadVarintAtMost(width - 1, "chain column"));
    LINEMAP_ASSIGN_OR_RETURN(std::uint64_t row, c.ReadVarintAtMost(height - 1, "chain row"));
    std::vector<CellIndex> chain;
    chain.reserve(length);
    chain.push_back(CellIndex{static_cast<int>(col), static_cast<int>(row)});
    int dir = 0;
    for (std::uint64_t i = 1; i < length; ++i) {
      LINEMAP_ASSIGN_OR_RETURN(std::uint8_t delta, c.ReadU8("chain step"));
      if (delta > 7) return CorruptError(name + " has a bad step code");
      dir = (dir + delta) % 8;
      const CellIndex p = chain.back();
      const CellIndex q{p.col + kStepCol[dir], p.row + kStepRow[dir]};
      if (q.col < 0 || q.row < 0 || q.col >= width || q.row >= height) {
        return CorruptError(name + " leaves the map");
      }
      chain.push_back(q);
    }
    const CellIndex first = chain.front();
    const CellIndex last = chain.back();
    if (std::abs(first.col - last.col) > 1 || std::abs(first.row - last.row) > 1) {
      return CorruptError(name + " is not closed");
    }
    chains.push_back(std::move(chain));
  }
  if (!c.empty()) return CorruptError("chain data has trailing bytes");
  return chains;
}

}  // namespace linemap
