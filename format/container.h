// The .lmap container (spec/format.md sections "File structure" and
// "Chunks"): an 8-byte signature, a version (2 bytes), then chunks of
//   type (4 ASCII letters) | length (varint) | payload | CRC-32 of type+payload
// ending with the empty chunk "LEND". A chunk whose type starts with an
// upper-case letter is critical (a decoder that does not know it must
// refuse the file); a lower-case first letter marks an ancillary chunk that
// unknown-chunk-aware decoders skip (PNG's rule).
#ifndef LINEMAP_FORMAT_CONTAINER_H_
#define LINEMAP_FORMAT_CONTAINER_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "linemap/status.h"

namespace linemap {

inline constexpr std::array<std::uint8_t, 8> kLmapSignature = {0x8A, 'L',  'M',  'A',
                                                               'P',  0x0D, 0x0A, 0x1A};
// The version of a file of the 2.0 chunk set, the container's default; the
// encoder raises the minor to what a file holds (2.1 BLKS, 2.2 LAYR, 2.3
// model 12, spec/format.md 13). Decoders read majors 1 and 2.
inline constexpr std::uint8_t kFormatMajor = 2;
inline constexpr std::uint8_t kFormatMinor = 0;
inline constexpr std::uint8_t kOldestFormatMajor = 1;
inline constexpr std::size_t kFileHeaderSize = 10;  // signature + major + minor

struct Chunk {
  std::string type;                       // exactly 4 ASCII letters
  const std::uint8_t* payload = nullptr;  // points into the file bytes
  std::size_t size = 0;
  std::size_t offset = 0;  // of the chunk's type field in the file
  bool critical() const { return !type.empty() && type[0] >= 'A' && type[0] <= 'Z'; }
};

struct ContainerView {
  std::uint8_t major = 0;
  std::uint8_t minor = 0;
  std::vector<Chunk> chunks;  // in file order, without LEND
};

// Splits `bytes` into chunks, checking the signature, the version (major must
// be kOldestFormatMajor..kFormatMajor), type letters, lengths (<= max_chunk_bytes), every CRC, the
// final LEND and that nothing follows it. Errors name the chunk.
StatusOr<ContainerView> ParseContainer(const std::vector<std::uint8_t>& bytes,
                                       std::uint64_t max_chunk_bytes);

// Builds a file: signature, version, the chunks in order, LEND.
class ContainerWriter {
 public:
  // A file of version major.minor (default 2.0).
  explicit ContainerWriter(std::uint8_t major = kFormatMajor, std::uint8_t minor = kFormatMinor);
  void AddChunk(const std::string& type, const std::vector<std::uint8_t>& payload);
  // Appends LEND and returns the file.
  std::vector<std::uint8_t> Finish();

 private:
  std::vector<std::uint8_t> out_;
};

}  // namespace linemap

#endif  // LINEMAP_FORMAT_CONTAINER_H_
