#include "format/pixel_classifier.h"

#include <cmath>

#include "format/image.h"

namespace linemap {

Cell ClassifyPixel(const std::uint16_t* samples, int channels, const MapMetadata& meta) {
  // GraphicsMagick hands nav2 R, G, B (grey images have R = G = B) and, for
  // images with a matte channel, an opacity; nav2 averages in
  // MaxRGB - opacity, which is the alpha value itself.
  const bool has_alpha = channels == 2 || channels == 4;
  const std::uint32_t r = samples[0];
  const std::uint32_t g = channels >= 3 ? samples[1] : samples[0];
  const std::uint32_t b = channels >= 3 ? samples[2] : samples[0];
  const std::uint32_t alpha = has_alpha ? samples[channels - 1] : kQuantumMax;

  double sum = static_cast<double>(r) + g + b;
  double count = 3.0;
  if (meta.mode == MapMode::kTrinary && has_alpha) {
    sum += alpha;
    count = 4.0;
  }
  // nav2 passes the double mean to ColorGray::scaleQuantumToDouble(Quantum),
  // which truncates it to a 16-bit quantum first.
  const auto mean_quantum = static_cast<std::uint16_t>(sum / count);
  const double shade = static_cast<double>(mean_quantum) / kQuantumMax;
  const double occ = meta.negate ? shade : 1.0 - shade;

  switch (meta.mode) {
    case MapMode::kTrinary:
      if (meta.occupied_thresh < occ) return Cell::kOccupied;
      if (occ < meta.free_thresh) return Cell::kFree;
      return Cell::kUnknown;
    case MapMode::kScale:
      if (alpha != kQuantumMax) return Cell::kUnknown;
      if (meta.occupied_thresh < occ) return Cell::kOccupied;
      if (occ < meta.free_thresh) return Cell::kFree;
      // nav2 keeps a 0..100 level here; a trinary grid has no place for it.
      return Cell::kUnknown;
    case MapMode::kRaw: {
      const double value = std::round(shade * 255.0);
      if (value == 0.0) return Cell::kFree;
      if (value == 100.0) return Cell::kOccupied;
      // 1..99 are levels a trinary grid cannot hold; above 100 nav2 says unknown.
      return Cell::kUnknown;
    }
  }
  return Cell::kUnknown;
}

Cell ClassifyGrey8(std::uint8_t grey, const MapMetadata& meta) {
  const std::uint16_t q = static_cast<std::uint16_t>(grey * 257);
  return ClassifyPixel(&q, 1, meta);
}

}  // namespace linemap
