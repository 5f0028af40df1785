#include "linemap/morphology.h"

#include <gtest/gtest.h>

#include <random>

namespace linemap {
namespace {

// "Set" cells get any non-zero byte, as the mask type allows.
BinaryMask RandomMask(std::mt19937* rng, int w, int h, double density) {
  BinaryMask mask(w, h);
  std::bernoulli_distribution on(density);
  std::uniform_int_distribution<int> value(1, 255);
  for (auto& b : mask.bits) b = on(*rng) ? static_cast<std::uint8_t>(value(*rng)) : 0;
  return mask;
}

StructuringElement RandomElement(std::mt19937* rng) {
  std::uniform_int_distribution<int> half(0, 3);
  StructuringElement element;
  element.width = 2 * half(*rng) + 1;
  element.height = 2 * half(*rng) + 1;
  element.on.assign(static_cast<std::size_t>(element.width) * element.height, 0);
  std::bernoulli_distribution on(0.5);
  for (auto& b : element.on) b = on(*rng);
  return element;
}

// The textbook definitions, one cell at a time; outside the mask is 0.
BinaryMask DirectDilate(const BinaryMask& a, const StructuringElement& e) {
  BinaryMask out(a.width, a.height);
  for (int r = 0; r < a.height; ++r) {
    for (int c = 0; c < a.width; ++c) {
      bool any = false;
      for (int dy = -e.height / 2; dy <= e.height / 2; ++dy) {
        for (int dx = -e.width / 2; dx <= e.width / 2; ++dx) {
          if (e.at(dx, dy) && a.get(c - dx, r - dy)) any = true;
        }
      }
      out.set(c, r, any);
    }
  }
  return out;
}

BinaryMask DirectErode(const BinaryMask& a, const StructuringElement& e) {
  BinaryMask out(a.width, a.height);
  for (int r = 0; r < a.height; ++r) {
    for (int c = 0; c < a.width; ++c) {
      bool all = true;
      for (int dy = -e.height / 2; dy <= e.height / 2; ++dy) {
        for (int dx = -e.width / 2; dx <= e.width / 2; ++dx) {
          if (e.at(dx, dy) && !a.get(c + dx, r + dy)) all = false;
        }
      }
      out.set(c, r, all);
    }
  }
  return out;
}

TEST(MorphologyTest, ElementsOfThePaper) {
  const StructuringElement cross = StructuringElement::Cross3();
  EXPECT_EQ(cross.on, (std::vector<std::uint8_t>{0, 1, 0, 1, 1, 1, 0, 1, 0}));
  const StructuringElement square = StructuringElement::Square(5);
  EXPECT_EQ(square.width, 5);
  EXPECT_EQ(square.on.size(), 25u);
  EXPECT_TRUE(square.at(-2, 2));
  EXPECT_TRUE(cross.Valid());
  StructuringElement even;
  even.width = 2;
  even.height = 1;
  even.on = {1, 1};
  EXPECT_FALSE(even.Valid());
}

TEST(MorphologyTest, SinglePointDilatesToTheElement) {
  BinaryMask mask(7, 7);
  mask.set(3, 3, true);
  const BinaryMask cross = Dilate(mask, StructuringElement::Cross3());
  EXPECT_EQ(cross.Count(), 5u);
  EXPECT_TRUE(cross.at(3, 4));
  EXPECT_FALSE(cross.at(4, 4));
  // An asymmetric element: the offset (+1, 0) moves the point to the right.
  StructuringElement right;
  right.width = 3;
  right.height = 1;
  right.on = {0, 0, 1};
  const BinaryMask moved = Dilate(mask, right);
  EXPECT_EQ(moved.Count(), 1u);
  EXPECT_TRUE(moved.at(4, 3));
}

TEST(MorphologyTest, ErosionEatsInFromTheEdges) {
  BinaryMask full(6, 4);
  for (auto& b : full.bits) b = 1;
  const BinaryMask eroded = Erode(full, StructuringElement::Square(3));
  EXPECT_EQ(eroded.Count(), 4u * 2u);  // cols 1..4, rows 1..2
  EXPECT_FALSE(eroded.at(0, 1));
  EXPECT_TRUE(eroded.at(1, 1));
}

TEST(MorphologyTest, MatchesDirectDefinitionOnRandomGrids) {
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> size(1, 150);  // crosses 64-bit word edges
  for (int trial = 0; trial < 60; ++trial) {
    const int w = size(rng), h = size(rng) % 40 + 1;
    const BinaryMask mask = RandomMask(&rng, w, h, trial % 2 ? 0.2 : 0.7);
    const StructuringElement element = RandomElement(&rng);
    ASSERT_EQ(Dilate(mask, element), DirectDilate(mask, element)) << "trial " << trial;
    ASSERT_EQ(Erode(mask, element), DirectErode(mask, element)) << "trial " << trial;
    ASSERT_EQ(Close(mask, element), DirectErode(DirectDilate(mask, element), element));
    ASSERT_EQ(Open(mask, element), DirectDilate(DirectErode(mask, element), element));
  }
}

TEST(MorphologyTest, FullRectanglesMatchDirectDefinition) {
  // Full rectangles larger than 3x3 take the separable path.
  std::mt19937 rng(4242);
  const StructuringElement elements[] = {StructuringElement::Square(5),
                                         StructuringElement::Square(7),
                                         {7, 3, std::vector<std::uint8_t>(21, 1)},
                                         {1, 9, std::vector<std::uint8_t>(9, 1)}};
  for (const StructuringElement& element : elements) {
    for (int trial = 0; trial < 6; ++trial) {
      const BinaryMask mask = RandomMask(&rng, 20 + 23 * trial, 5 + 7 * trial, 0.15 + 0.15 * trial);
      ASSERT_EQ(Dilate(mask, element), DirectDilate(mask, element));
      ASSERT_EQ(Erode(mask, element), DirectErode(mask, element));
    }
  }
}

TEST(MorphologyTest, CellWiseOperations) {
  BinaryMask a(3, 1), b(3, 1);
  a.bits = {1, 1, 0};
  b.bits = {0, 1, 1};
  EXPECT_EQ(Subtract(a, b).bits, (std::vector<std::uint8_t>{1, 0, 0}));
  EXPECT_EQ(Union(a, b).bits, (std::vector<std::uint8_t>{1, 1, 1}));
  EXPECT_EQ(Intersect(a, b).bits, (std::vector<std::uint8_t>{0, 1, 0}));
}

}  // namespace
}  // namespace linemap
