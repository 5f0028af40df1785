// The .lmap decoder: spec/format.md section "Decoding". Integer-only from
// the header on; every read goes through the bounded ByteCursor and every
// count is checked against the limits before it is used.
#include <fstream>
#include <string>

#include "codec/cells/plane_coder.h"
#include "codec/layers/raster.h"
#include "codec/lmap/chunk_coding.h"
#include "codec/lmap/decoder_v2.h"
#include "codec/lmap/draco_segments.h"
#include "format/container.h"
#include "format/file_io.h"
#include "linemap/codec.h"

namespace linemap {
namespace {

// The critical chunks in their required order; each at most once.
constexpr const char* kCriticalOrder[] = {kRoomChunk,     kSegmentChunk, kBlobChunk,
                                          kOccupiedChunk, kFreeChunk,    kResidualChunk};
constexpr int kCriticalCount = 6;

int CriticalRank(const std::string& type) {
  for (int i = 0; i < kCriticalCount; ++i) {
    if (type == kCriticalOrder[i]) return i;
  }
  return -1;
}

const char* CoderName(PayloadCoder coder) {
  switch (coder) {
    case PayloadCoder::kRaw:
      return "raw";
    case PayloadCoder::kDeflate:
      return "deflate";
    case PayloadCoder::kDraco:
      return "draco";
  }
  return "?";
}

class Decoder {
 public:
  Decoder(const DecodeLimits& limits, LmapContents* out) : limits_(limits), out_(out) {}

  Status Run(const ContainerView& view) {
    out_->major = view.major;
    out_->minor = view.minor;
    if (view.chunks.empty() || view.chunks[0].type != kHeaderChunk) {
      return CorruptError("the first chunk is not LMHD");
    }
    int last_rank = -1;
    for (std::size_t i = 0; i < view.chunks.size(); ++i) {
      const Chunk& chunk = view.chunks[i];
      Status status = i == 0 ? ApplyHeader(chunk) : ApplyChunk(chunk, &last_rank);
      if (!status.ok()) return status.WithContext("chunk " + chunk.type);
    }
    out_->grid.mutable_cells() = std::move(canvas_);
    return Status::Ok();
  }

 private:
  Status ApplyHeader(const Chunk& chunk) {
    LINEMAP_ASSIGN_OR_RETURN(header_, ReadHeader(chunk.payload, chunk.size, limits_));
    out_->grid = Grid(0, 0);
    Grid grid(header_.width, header_.height, Cell::kUnknown);
    grid.meta = header_.meta;
    canvas_ = std::move(grid.mutable_cells());
    out_->grid = std::move(grid);
    out_->lossless = header_.lossless;
    out_->chunks.push_back({chunk.type, chunk.size, "header"});
    return Status::Ok();
  }

  Status ApplyChunk(const Chunk& chunk, int* last_rank) {
    if (chunk.type == kHeaderChunk) return CorruptError("a second LMHD chunk");
    const int rank = CriticalRank(chunk.type);
    if (rank < 0) {
      if (chunk.critical()) return UnsupportedError("unknown critical chunk");
      if (chunk.type != kMetadataChunk) {
        out_->chunks.push_back({chunk.type, chunk.size, "skipped"});
        return Status::Ok();  // unknown ancillary chunk: skipped
      }
    } else {
      if (rank <= *last_rank) return CorruptError("chunk out of order or repeated");
      *last_rank = rank;
    }
    PayloadCoder coder = PayloadCoder::kRaw;
    LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> body,
                             UnwrapPayload(chunk.payload, chunk.size, limits_, &coder));
    const bool planar =
        chunk.type == kFreeChunk || chunk.type == kOccupiedChunk || chunk.type == kResidualChunk;
    out_->chunks.push_back({chunk.type, chunk.size,
                            planar ? std::string("range+") + CoderName(coder) : CoderName(coder)});
    if (coder == PayloadCoder::kDraco && chunk.type != kSegmentChunk) {
      return CorruptError("only SEGS may use the Draco payload coder");
    }
    const int w = header_.width;
    const int h = header_.height;
    if (chunk.type == kMetadataChunk) {
      LINEMAP_ASSIGN_OR_RETURN(out_->metadata, ReadMetadata(body));
    } else if (chunk.type == kRoomChunk || chunk.type == kBlobChunk) {
      const bool room = chunk.type == kRoomChunk;
      LINEMAP_ASSIGN_OR_RETURN(std::vector<std::vector<CellIndex>> chains,
                               ReadChains(body, w, h, limits_));
      const Cell value = room ? Cell::kFree : Cell::kOccupied;
      for (const std::vector<CellIndex>& chain : chains) {
        FillChain(chain,
                  [&](int c, int r) { canvas_[static_cast<std::size_t>(r) * w + c] = value; });
      }
      (room ? out_->room_chains : out_->blob_outlines) = std::move(chains);
    } else if (chunk.type == kSegmentChunk) {
      if (coder == PayloadCoder::kDraco) {
        LINEMAP_ASSIGN_OR_RETURN(out_->segments, DecodeSegmentsDraco(body, w, h, limits_));
      } else {
        LINEMAP_ASSIGN_OR_RETURN(out_->segments, ReadSegments(body, w, h, limits_));
      }
      for (const LatticeSegment& s : out_->segments) {
        RasterizeSegment(s.a, s.b, [&](int c, int r) {
          canvas_[static_cast<std::size_t>(r) * w + c] = Cell::kOccupied;
        });
      }
    } else if (chunk.type == kFreeChunk) {
      LINEMAP_RETURN_IF_ERROR(DecodeFreePlane(body.data(), body.size(), w, h, &canvas_));
    } else if (chunk.type == kOccupiedChunk) {
      LINEMAP_RETURN_IF_ERROR(DecodeOccupiedPlane(body.data(), body.size(), w, h, &canvas_));
    } else if (chunk.type == kResidualChunk) {
      LINEMAP_RETURN_IF_ERROR(DecodeResidualPlane(body.data(), body.size(), w, h, &canvas_));
    }
    return Status::Ok();
  }

  const DecodeLimits& limits_;
  LmapContents* out_;
  HeaderFields header_;
  std::vector<Cell> canvas_;
};

}  // namespace

bool LooksLikeLmap(const std::vector<std::uint8_t>& bytes) {
  return bytes.size() >= kLmapSignature.size() &&
         std::equal(kLmapSignature.begin(), kLmapSignature.end(), bytes.begin());
}

bool IsLmapPath(const std::string& path) {
  if (path.ends_with(".lmap")) return true;
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> head(kLmapSignature.size(), 0);
  in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
  return in.gcount() == static_cast<std::streamsize>(head.size()) && LooksLikeLmap(head);
}

StatusOr<LmapContents> DecodeLmapContents(const std::vector<std::uint8_t>& bytes,
                                          const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(ContainerView view, ParseContainer(bytes, limits.max_chunk_bytes));
  LmapContents contents;
  if (view.major == 1) {
    Decoder decoder(limits, &contents);
    LINEMAP_RETURN_IF_ERROR(decoder.Run(view));
  } else {
    contents.major = view.major;
    contents.minor = view.minor;
    LINEMAP_RETURN_IF_ERROR(DecodeV2Contents(view, limits, &contents));
  }
  return contents;
}

StatusOr<Grid> DecodeLmapRegion(const std::vector<std::uint8_t>& bytes, const CellWindow& window,
                                const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(ContainerView view, ParseContainer(bytes, limits.max_chunk_bytes));
  if (view.major == 1) {
    LmapContents contents;
    Decoder decoder(limits, &contents);
    LINEMAP_RETURN_IF_ERROR(decoder.Run(view));
    const Grid& full = contents.grid;
    LINEMAP_RETURN_IF_ERROR(CheckWindow(window, full.width(), full.height()));
    Grid out = WindowGrid(full.meta, window);
    for (int r = window.row0; r < window.row1; ++r) {
      for (int c = window.col0; c < window.col1; ++c) {
        out.set(c - window.col0, r - window.row0, full.at(c, r));
      }
    }
    return out;
  }
  if (view.chunks.empty() || view.chunks[0].type != kHeaderChunk) {
    return CorruptError("the first chunk is not LMHD");
  }
  StatusOr<HeaderFields> header = ReadHeader(view.chunks[0].payload, view.chunks[0].size, limits);
  if (!header.ok()) return header.status().WithContext("chunk LMHD");
  LINEMAP_RETURN_IF_ERROR(CheckWindow(window, header->width, header->height));
  return DecodeV2Region(view, window, limits);
}

StatusOr<Grid> LoadLmapRegion(const std::string& path, const CellWindow& window,
                              const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  StatusOr<Grid> grid = DecodeLmapRegion(bytes, window, limits);
  if (!grid.ok()) return grid.status().WithContext("'" + path + "'");
  return grid;
}

StatusOr<Grid> DecodeLmap(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(ContainerView view, ParseContainer(bytes, limits.max_chunk_bytes));
  if (view.major >= 2 && !view.chunks.empty() && view.chunks[0].type == kHeaderChunk) {
    // The grid alone: the window path reads the layers' polygons without
    // making their chains (LmapContents would hold them all).
    StatusOr<HeaderFields> header = ReadHeader(view.chunks[0].payload, view.chunks[0].size, limits);
    if (!header.ok()) return header.status().WithContext("chunk LMHD");
    if (header->width > 0 && header->height > 0) {
      return DecodeV2Region(view, CellWindow{0, 0, header->width, header->height}, limits);
    }
  }
  LINEMAP_ASSIGN_OR_RETURN(LmapContents contents, DecodeLmapContents(bytes, limits));
  return std::move(contents.grid);
}

StatusOr<LmapContents> LoadLmapContents(const std::string& path, const DecodeLimits& limits) {
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  StatusOr<LmapContents> contents = DecodeLmapContents(bytes, limits);
  if (!contents.ok()) return contents.status().WithContext("'" + path + "'");
  return contents;
}

StatusOr<Grid> LoadLmap(const std::string& path, const DecodeLimits& limits) {
  // Through DecodeLmap: the grid alone, without the layers' chains.
  LINEMAP_ASSIGN_OR_RETURN(std::vector<std::uint8_t> bytes,
                           ReadFileBytes(path, limits.max_file_bytes));
  StatusOr<Grid> grid = DecodeLmap(bytes, limits);
  if (!grid.ok()) return grid.status().WithContext("'" + path + "'");
  return grid;
}

}  // namespace linemap
