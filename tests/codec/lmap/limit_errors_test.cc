// Every refusal over a caller-set limit says which limit (Status::limit()),
// through each reader, so that a front end can name the option that lifts
// it (lmap_server's ~max_segments) without reading the message's words.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "format/file_io.h"
#include "linemap/codec.h"
#include "linemap/lmap_vectors.h"
#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap::testing {
namespace {

std::string Fixture(const std::string& name) { return SourceDir() + "/tests/data/lmap/" + name; }

struct LimitCase {
  const char* file;
  std::function<void(DecodeLimits*)> tighten;
  Limit expected;
  const char* words;  // what the message says of it
};

void ExpectOver(const Status& status, const LimitCase& c) {
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.code(), StatusCode::kResourceExhausted) << status.message();
  EXPECT_EQ(status.limit(), c.expected) << status.message();
  EXPECT_NE(status.message().find(c.words), std::string::npos) << status.message();
  EXPECT_NE(status.message().find(c.file), std::string::npos) << status.message();
}

TEST(LimitErrorsTest, EachLimitIsNamedByEveryReader) {
  // depot_v2.lmap: 437 wall segments, 8 rooms and 33 furniture objects;
  // depot_lossy.lmap (1.0) has zlib-deflated chunks.
  const std::vector<LimitCase> cases = {
      {"depot_v2.lmap", [](DecodeLimits* l) { l->max_segments = 436; }, Limit::kSegments,
       "segment"},
      {"depot_v2.lmap", [](DecodeLimits* l) { l->max_objects = 32; }, Limit::kObjects, "object"},
      {"depot_v2.lmap", [](DecodeLimits* l) { l->max_chain_length = 3; }, Limit::kChainLength,
       "chain"},
      {"depot_v2.lmap", [](DecodeLimits* l) { l->max_cells = 185427; }, Limit::kCells, "cells"},
      {"depot_v2.lmap", [](DecodeLimits* l) { l->max_file_bytes = 100; }, Limit::kFileBytes,
       "bytes"},
      {"depot_v2.lmap", [](DecodeLimits* l) { l->max_chunk_bytes = 100; }, Limit::kChunkBytes,
       "chunk"},
      {"depot_lossy.lmap", [](DecodeLimits* l) { l->max_inflated_bytes = 100; },
       Limit::kInflatedBytes, "inflated"},
  };
  for (const LimitCase& c : cases) {
    SCOPED_TRACE(std::string(c.file) + ": " + c.words);
    DecodeLimits limits;
    c.tighten(&limits);
    ExpectOver(LoadLmap(Fixture(c.file), limits).status(), c);
    // The vector reader reads no cells: a cell limit is checked on the header.
    ExpectOver(LoadLmapVectors(Fixture(c.file), limits).status(), c);
  }
}

TEST(LimitErrorsTest, ImagesAndTheToleranceLimitAreNamed) {
  MapLoadOptions options;
  options.max_cells = 1000;
  const Status image = LoadRosMap(BundledMapsDir() + "/nav2/depot.yaml", options).status();
  EXPECT_EQ(image.code(), StatusCode::kResourceExhausted) << image.message();
  EXPECT_EQ(image.limit(), Limit::kCells) << image.message();

  StatusOr<Grid> depot = LoadRosMap(BundledMapsDir() + "/nav2/depot.yaml");
  ASSERT_TRUE(depot.ok());
  EncodeOptions encode;
  encode.tolerance_cells = 1;
  encode.max_tolerance_cells = 1000;
  const Status tolerance = EncodeLmap(*depot, encode).status();
  EXPECT_EQ(tolerance.code(), StatusCode::kResourceExhausted) << tolerance.message();
  EXPECT_EQ(tolerance.limit(), Limit::kToleranceCells) << tolerance.message();
}

TEST(LimitErrorsTest, ContextKeepsTheLimitAndOtherErrorsHaveNone) {
  const Status over = OverLimitError(Limit::kObjects, "12 rooms exceed the object limit of 11");
  const Status framed = over.WithContext("'a.lmap'").WithContext("chunk LAYR");
  EXPECT_EQ(framed.limit(), Limit::kObjects);
  EXPECT_EQ(framed.code(), StatusCode::kResourceExhausted);
  EXPECT_EQ(framed.message(), "chunk LAYR: 'a.lmap': 12 rooms exceed the object limit of 11");
  EXPECT_EQ(CorruptError("bad CRC").WithContext("'a.lmap'").limit(), Limit::kNone);
  EXPECT_EQ(Status::Ok().limit(), Limit::kNone);
  // A corrupt file is corrupt, not over a limit.
  const Status bad = LoadLmap(Fixture("bad_crc.lmap")).status();
  EXPECT_EQ(bad.code(), StatusCode::kCorrupt) << bad.message();
  EXPECT_EQ(bad.limit(), Limit::kNone);
}

}  // namespace
}  // namespace linemap::testing
