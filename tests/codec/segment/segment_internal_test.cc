// ForEachFlaggedCell (codec/segment/segment_internal.h): the cells of the
// flagged components, each once, whether it reads the components' boxes
// (small components) or the whole map (boxes larger than the map), against
// a plain scan of the labels.
#include "codec/segment/segment_internal.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "linemap/labeling.h"

namespace linemap::segment_internal {
namespace {

// The cells whose label is flagged, by a plain scan.
std::vector<int> FlaggedCells(const Labeling& labels, const std::vector<std::uint8_t>& flagged) {
  std::vector<int> count(labels.labels.size(), 0);
  for (std::size_t i = 0; i < labels.labels.size(); ++i) {
    count[i] = labels.labels[i] != 0 && flagged[labels.labels[i]] ? 1 : 0;
  }
  return count;
}

std::vector<int> Visits(const Labeling& labels, const std::vector<std::uint8_t>& flagged) {
  std::vector<int> count(labels.labels.size(), 0);
  ForEachFlaggedCell(labels, flagged, [&](std::size_t i) { ++count[i]; });
  return count;
}

// A deterministic speckle of small blobs, plus (when `frame`) a ring of
// cells along the map's rim: one component whose box is the whole map.
Labeling SpeckleLabels(int width, int height, bool frame) {
  BinaryMask mask(width, height);
  std::uint32_t state = 12345;
  for (int r = 1; r + 1 < height; ++r) {
    for (int c = 1; c + 1 < width; ++c) {
      state = state * 1103515245u + 12345u;
      if ((state >> 16) % 7 == 0) mask.set(c, r, true);
    }
  }
  if (frame) {
    for (int c = 0; c < width; ++c) {
      mask.set(c, 0, true);
      mask.set(c, height - 1, true);
    }
    for (int r = 0; r < height; ++r) {
      mask.set(0, r, true);
      mask.set(width - 1, r, true);
    }
  }
  return LabelComponents(mask, Connectivity::kEight);
}

TEST(ForEachFlaggedCellTest, SmallComponentsByTheirBoxes) {
  const Labeling labels = SpeckleLabels(61, 37, /*frame=*/false);
  ASSERT_GT(labels.components.size(), 10u);
  std::vector<std::uint8_t> flagged(labels.components.size() + 1, 0);
  for (std::size_t k = 1; k < flagged.size(); k += 2) flagged[k] = 1;
  ASSERT_GT(CellsInFlaggedBoxes(labels, flagged), 0u);  // the box path
  EXPECT_EQ(Visits(labels, flagged), FlaggedCells(labels, flagged));
}

TEST(ForEachFlaggedCellTest, BoxesLargerThanTheMapReadTheWholeMap) {
  const Labeling labels = SpeckleLabels(61, 37, /*frame=*/true);
  std::vector<std::uint8_t> flagged(labels.components.size() + 1, 1);
  flagged[0] = 0;
  ASSERT_EQ(CellsInFlaggedBoxes(labels, flagged), 0u);  // the whole-map path
  EXPECT_EQ(Visits(labels, flagged), FlaggedCells(labels, flagged));
}

TEST(ForEachFlaggedCellTest, NothingFlaggedVisitsNothing) {
  const Labeling labels = SpeckleLabels(20, 20, /*frame=*/true);
  const std::vector<std::uint8_t> flagged(labels.components.size() + 1, 0);
  EXPECT_EQ(Visits(labels, flagged), std::vector<int>(labels.labels.size(), 0));
}

}  // namespace
}  // namespace linemap::segment_internal
