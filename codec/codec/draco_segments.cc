#include "codec/codec/draco_segments.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/point_cloud/point_cloud_builder.h>

#include <array>
#include <tuple>

namespace linemap {

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
  return std::vector<std::uint8_t>(buffer.data(), buffer.data() + buffer.size());
}

StatusOr<std::vector<LatticeSegment>> DecodeSegmentsDraco(const std::vector<std::uint8_t>& body,
                                                          int width, int height,
                                                          const DecodeLimits& limits) {
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(body.data()), body.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodePointCloudFromBuffer(&buffer);
  if (!decoded.ok()) {
    return CorruptError(std::string("Draco data is malformed: ") + decoded.status().error_msg());
  }
  const std::unique_ptr<draco::PointCloud>& cloud = decoded.value();
  if (cloud->num_points() > limits.max_segments) {
    return ResourceExhaustedError("more segments than the limit");
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
