#include "codec/lmap/draco_segments.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/point_cloud/point_cloud_builder.h>

#include <array>
#include <cstring>
#include <tuple>

namespace linemap {
namespace {

// Draco allocates its attribute buffers from the point count in its header
// before any of our checks could run, so the count is read and bounded
// first. Layout of a sequential point cloud (what EncodeSegmentsDraco
// writes): "DRACO", major, minor, encoder type (0 = point cloud), method
// (0 = sequential), flags (u16 LE), then the point count (int32 LE).
constexpr std::size_t kDracoPointCountOffset = 11;
constexpr std::uint16_t kDracoMetadataFlag = 0x8000;
constexpr std::uint64_t kMaxDracoPointsPerByte = 1024;

Status CheckDracoPointCount(const std::vector<std::uint8_t>& body, const DecodeLimits& limits) {
  if (body.size() < kDracoPointCountOffset + 4 || std::memcmp(body.data(), "DRACO", 5) != 0) {
    return CorruptError("Draco data is malformed: short or bad header");
  }
  if (body[7] != 0 || body[8] != 0) {
    return CorruptError("Draco data is not a sequential point cloud");
  }
  const std::uint16_t flags = static_cast<std::uint16_t>(body[9] | (body[10] << 8));
  if ((flags & kDracoMetadataFlag) != 0) return CorruptError("Draco data has metadata");
  std::uint32_t points = 0;
  for (int i = 3; i >= 0; --i) points = (points << 8) | body[kDracoPointCountOffset + i];
  // Entropy coding can pack very regular segments far below a bit each, so
  // the body-size bound is generous: it only stops tiny bodies that claim
  // millions of points (the allocation then stays within ~16 KiB per byte).
  // Over it the file breaks a format rule (corrupt); over the caller's limit
  // it is resource exhausted.
  // Draco reads the count as an int32: a negative one is never valid.
  if (points > 0x7FFFFFFF || points > kMaxDracoPointsPerByte * body.size()) {
    return CorruptError("Draco data claims " + std::to_string(points) +
                        " segments, more than its size allows");
  }
  if (points > limits.max_segments) {
    return OverLimitError(Limit::kSegments, "Draco data claims " + std::to_string(points) +
                                                " segments, over the limit of " +
                                                std::to_string(limits.max_segments));
  }
  return Status::Ok();
}

}  // namespace

std::vector<std::uint8_t> EncodeSegmentsDraco(const std::vector<LatticeSegment>& segments) {
  if (segments.empty()) return {};
  draco::PointCloudBuilder builder;
  builder.Start(static_cast<draco::PointIndex::ValueType>(segments.size()));
  const int att = builder.AddAttribute(draco::GeometryAttribute::GENERIC, 4, draco::DT_INT32);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const LatticeSegment& s = segments[i];
    const std::array<std::int32_t, 4> v = {s.a.col, s.a.row, s.b.col, s.b.row};
    builder.SetAttributeValueForPoint(att, draco::PointIndex(static_cast<std::uint32_t>(i)),
                                      v.data());
  }
  std::unique_ptr<draco::PointCloud> cloud = builder.Finalize(false);
  if (cloud == nullptr) return {};
  draco::Encoder encoder;
  encoder.SetEncodingMethod(draco::POINT_CLOUD_SEQUENTIAL_ENCODING);
  encoder.SetSpeedOptions(0, 0);  // best compression
  draco::EncoderBuffer buffer;
  if (!encoder.EncodePointCloudToBuffer(*cloud, &buffer).ok()) return {};
  // The decoder refuses denser claims; never write what it would refuse.
  if (segments.size() > kMaxDracoPointsPerByte * buffer.size()) return {};
  return std::vector<std::uint8_t>(buffer.data(), buffer.data() + buffer.size());
}

StatusOr<std::vector<LatticeSegment>> DecodeSegmentsDraco(const std::vector<std::uint8_t>& body,
                                                          int width, int height,
                                                          const DecodeLimits& limits) {
  LINEMAP_RETURN_IF_ERROR(CheckDracoPointCount(body, limits));
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(body.data()), body.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodePointCloudFromBuffer(&buffer);
  if (!decoded.ok()) {
    return CorruptError(std::string("Draco data is malformed: ") + decoded.status().error_msg());
  }
  // As in the varint form, nothing may follow the coded segments.
  if (buffer.remaining_size() != 0) return CorruptError("Draco data has trailing bytes");
  const std::unique_ptr<draco::PointCloud>& cloud = decoded.value();
  if (cloud->num_points() > limits.max_segments) {
    return OverLimitError(Limit::kSegments, "more segments than the limit");
  }
  if (cloud->num_attributes() != 1) return CorruptError("Draco data must hold one attribute");
  const draco::PointAttribute* att = cloud->attribute(0);
  if (att->attribute_type() != draco::GeometryAttribute::GENERIC || att->num_components() != 4 ||
      att->data_type() != draco::DT_INT32) {
    return CorruptError("Draco attribute is not 4 x int32");
  }
  std::vector<LatticeSegment> segments;
  segments.reserve(cloud->num_points());
  for (draco::PointIndex i(0); i < cloud->num_points(); ++i) {
    std::array<std::int32_t, 4> v{};
    if (!att->ConvertValue<std::int32_t, 4>(att->mapped_index(i), v.data())) {
      return CorruptError("Draco attribute value cannot be read");
    }
    const LatticeSegment s{{v[0], v[1]}, {v[2], v[3]}};
    const bool inside = s.a.col >= 0 && s.a.row >= 0 && s.b.col >= 0 && s.b.row >= 0 &&
                        s.a.col < width && s.b.col < width && s.a.row < height && s.b.row < height;
    if (!inside)
      return CorruptError("segment " + std::to_string(i.value()) + " lies outside the map");
    if (std::tie(s.b.row, s.b.col) < std::tie(s.a.row, s.a.col)) {
      return CorruptError("segment " + std::to_string(i.value()) + " is not canonical");
    }
    segments.push_back(s);
  }
  return segments;
}

}  // namespace linemap
