// Steps 2 and 3 of linemap's extractor: tracing edge cells into chains and
// splitting a chain into pieces within epsilon of their lines.
#include "codec/lines/edge_chains.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "tests/codec/lines/test_maps.h"

namespace linemap {
namespace {

using testing::DrawRoom;
using testing::FillBox;

TEST(LinemapChainsTest, EveryCellInExactlyOneChainOfNeighbours) {
  Grid grid(30, 30, Cell::kUnknown);
  DrawRoom(&grid, 2, 2, 27, 20);
  FillBox(&grid, 8, 8, 12, 9, Cell::kOccupied);
  const EdgeMap edges = ComputeEdgeMap(grid);
  const auto chains = lines_internal::TraceEdgeChains(edges, edges.is_edge);
  std::vector<int> seen(edges.is_edge.size(), 0);
  for (const auto& chain : chains) {
    for (std::size_t i = 0; i < chain.size(); ++i) {
      ++seen[chain[i]];
      if (i == 0) continue;
      const int dc = static_cast<int>(chain[i] % 30) - static_cast<int>(chain[i - 1] % 30);
      const int dr = static_cast<int>(chain[i] / 30) - static_cast<int>(chain[i - 1] / 30);
      EXPECT_LE(std::max(std::abs(dc), std::abs(dr)), 1);
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], edges.is_edge[i] ? 1 : 0);
}

TEST(LinemapSplitTest, StraightChainIsOnePieceAndACornerTwo) {
  // Cells (0..9, 0) then (9, 1..9): an L of 19 cells.
  std::vector<std::uint32_t> chain;
  const int width = 20;
  for (int c = 0; c < 10; ++c) chain.push_back(static_cast<std::uint32_t>(c));
  EXPECT_EQ(lines_internal::SplitChain(chain, width, 0.5), std::vector<int>{10});
  for (int r = 1; r < 10; ++r) chain.push_back(static_cast<std::uint32_t>(r * width + 9));
  const std::vector<int> pieces = lines_internal::SplitChain(chain, width, 0.5);
  ASSERT_EQ(pieces.size(), 2u);
  // The first piece may take the corner cell's neighbour only if it stays within 0.5.
  EXPECT_GE(pieces[0], 10);
  EXPECT_LE(pieces[0], 11);
}

}  // namespace
}  // namespace linemap
