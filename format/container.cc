#include "format/container.h"

#include <algorithm>

#include "format/byte_io.h"
#include "format/deflate.h"

namespace linemap {
namespace {

bool IsLetter(std::uint8_t c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

std::uint32_t ChunkCrc(const std::uint8_t* type, const std::uint8_t* payload, std::size_t size) {
  std::uint32_t crc = Crc32(0, type, 4);
  return Crc32(crc, payload, size);
}

Status CheckHeader(ByteCursor* cursor, ContainerView* view) {
  auto sig = cursor->ReadBytes(kLmapSignature.size(), "file signature");
  if (!sig.ok() || !std::equal(kLmapSignature.begin(), kLmapSignature.end(), *sig)) {
    return CorruptError("not an .lmap file (bad signature)");
  }
  LINEMAP_ASSIGN_OR_RETURN(view->major, cursor->ReadU8("version"));
  LINEMAP_ASSIGN_OR_RETURN(view->minor, cursor->ReadU8("version"));
  if (view->major < kOldestFormatMajor || view->major > kFormatMajor) {
    return UnsupportedError("format version " + std::to_string(view->major) + "." +
                            std::to_string(view->minor) + " is not supported (this decoder reads " +
                            std::to_string(kOldestFormatMajor) + ".x to " +
                            std::to_string(kFormatMajor) + ".x)");
  }
  return Status::Ok();
}

}  // namespace

StatusOr<ContainerView> ParseContainer(const std::vector<std::uint8_t>& bytes,
                                       std::uint64_t max_chunk_bytes) {
  ByteCursor cursor(bytes);
  ContainerView view;
  LINEMAP_RETURN_IF_ERROR(CheckHeader(&cursor, &view));
  while (true) {
    const std::size_t offset = cursor.position();
    if (cursor.empty()) return CorruptError("file ends without an LEND chunk (truncated)");
    LINEMAP_ASSIGN_OR_RETURN(const std::uint8_t* type, cursor.ReadBytes(4, "chunk type"));
    if (!std::all_of(type, type + 4, IsLetter)) {
      return CorruptError("bad chunk type at byte " + std::to_string(offset));
    }
    const std::string name(reinterpret_cast<const char*>(type), 4);
    auto length_or = cursor.ReadVarint("chunk length");
    if (!length_or.ok()) return CorruptError("chunk " + name + " has a malformed length");
    const std::uint64_t length = *length_or;
    // Past the end of the file (the payload and its 4-byte CRC) is corrupt
    // whatever the limit; over the caller's limit, resource exhausted.
    if (cursor.remaining() < 4 || length > cursor.remaining() - 4) {
      return CorruptError("chunk " + name + " is truncated");
    }
    if (length > max_chunk_bytes) {
      return OverLimitError(Limit::kChunkBytes, "chunk " + name + " has " + std::to_string(length) +
                                                    " bytes, over the limit of " +
                                                    std::to_string(max_chunk_bytes));
    }
    auto payload = cursor.ReadBytes(static_cast<std::size_t>(length), "chunk payload");
    if (!payload.ok()) return CorruptError("chunk " + name + " is truncated");
    auto crc = cursor.ReadU32("chunk CRC");
    if (!crc.ok()) return CorruptError("chunk " + name + " is truncated");
    if (*crc != ChunkCrc(type, *payload, length)) {
      return CorruptError("chunk " + name + " at byte " + std::to_string(offset) +
                          " fails its CRC check");
    }
    if (name == "LEND") {
      if (length != 0) return CorruptError("chunk LEND is not empty");
      if (!cursor.empty()) return CorruptError("data after the LEND chunk");
      return view;
    }
    view.chunks.push_back(Chunk{name, *payload, length, offset});
  }
}

ContainerWriter::ContainerWriter(std::uint8_t major, std::uint8_t minor) {
  out_.assign(kLmapSignature.begin(), kLmapSignature.end());
  out_.push_back(major);
  out_.push_back(minor);
}

void ContainerWriter::AddChunk(const std::string& type, const std::vector<std::uint8_t>& payload) {
  ByteWriter w;
  w.PutBytes(std::string_view(type.data(), 4));
  w.PutVarint(payload.size());
  w.PutBytes(payload);
  const std::uint8_t* t = reinterpret_cast<const std::uint8_t*>(type.data());
  w.PutU32(ChunkCrc(t, payload.data(), payload.size()));
  out_.insert(out_.end(), w.bytes().begin(), w.bytes().end());
}

std::vector<std::uint8_t> ContainerWriter::Finish() {
  AddChunk("LEND", {});
  return std::move(out_);
}

}  // namespace linemap
