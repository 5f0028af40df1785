// The anchors check of linemap bench: which maps the default .lmap 2.0 file
// wins and loses against each codec, and how the report prints it.
#include "tools/bench/anchors.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tools/bench/report.h"

namespace linemap::bench {
namespace {

MapResult Map(const std::string& name, double cells, double lmap, double png9, double jxl) {
  MapResult r;
  r.name = name;
  r.figures[key::kCells] = cells;
  r.figures[key::kLmapBytes] = lmap;
  r.figures[key::kPng9Bytes] = png9;
  if (jxl > 0) r.figures[key::kJxlBytes] = jxl;
  return r;
}

const AnchorOutcome& Outcome(const std::vector<AnchorOutcome>& outcomes, const char* figure) {
  for (const AnchorOutcome& o : outcomes) {
    if (o.anchor.figure == figure) return o;
  }
  ADD_FAILURE() << "no anchor " << figure;
  return outcomes.front();
}

std::vector<std::string> Names(const std::vector<const MapResult*>& maps) {
  std::vector<std::string> names;
  for (const MapResult* m : maps) names.push_back(m->name);
  return names;
}

TEST(BenchAnchorsTest, SubjectIsTheDefault2FileAndAllSixAnchorsAreChecked) {
  // The default file, layers included: not --raster-only.
  EXPECT_EQ(AnchorSubject().figure, std::string(key::kLmapBytes));
  EXPECT_EQ(std::string(key::kLmapBytes), "lmap2_bytes");
  std::vector<std::string> figures;
  for (const Anchor& a : SizeAnchors()) figures.push_back(a.figure);
  EXPECT_EQ(figures, (std::vector<std::string>{key::kPng9Bytes, key::kWebpBytes, key::kJbigBytes,
                                               key::kZstdBytes, key::kXzBytes, key::kJxlBytes}));
}

TEST(BenchAnchorsTest, WonLostAndSmallMapsLeftOut) {
  const std::vector<MapResult> results = {
      Map("small", 99999, 500, 100, 100),    // under 100,000 cells: not checked
      Map("won", 100000, 900, 1000, 901),    // smaller than both
      Map("tie", 250000, 1000, 1000, 2000),  // a tie with PNG-9 is a loss
      Map("no_jxl", 300000, 400, 1000, 0)};  // JPEG XL not measured here
  const std::vector<AnchorOutcome> outcomes = CheckAnchors(results);
  const AnchorOutcome& png = Outcome(outcomes, key::kPng9Bytes);
  EXPECT_EQ(Names(png.won), (std::vector<std::string>{"won", "no_jxl"}));
  EXPECT_EQ(Names(png.lost), (std::vector<std::string>{"tie"}));
  const AnchorOutcome& jxl = Outcome(outcomes, key::kJxlBytes);
  EXPECT_EQ(Names(jxl.won), (std::vector<std::string>{"won", "tie"}));
  EXPECT_TRUE(jxl.lost.empty());
  const AnchorOutcome& webp = Outcome(outcomes, key::kWebpBytes);
  EXPECT_TRUE(webp.won.empty() && webp.lost.empty());
}

TEST(BenchAnchorsTest, TablesCountWinsAndListLossesWithBothSizes) {
  const std::vector<MapResult> results = {Map("office", 3400000, 1679, 3000, 1022),
                                          Map("lab", 200000, 800, 1000, 900)};
  const std::vector<NamedTable> tables = AnchorTables(results);
  ASSERT_EQ(tables.size(), 2u);
  const std::string summary = tables[0].table.Text();
  EXPECT_NE(summary.find("PNG-9                2                2/2     0"), std::string::npos)
      << summary;
  // JPEG XL: lab won (800 < 900), office lost (1679 > 1022).
  EXPECT_NE(summary.find("JPEG XL lossless     2                1/2     1"), std::string::npos)
      << summary;
  const std::string losses = tables[1].table.Text();
  EXPECT_NE(losses.find("JPEG XL lossless  office  3400000             1679          1022"),
            std::string::npos)
      << losses;
  EXPECT_EQ(losses.find("lab"), std::string::npos);
}

// The compact file is compared with its own figure, and its table says it
// is a comparison, not the goal.
TEST(BenchAnchorsTest, CompactFileIsComparedOnItsOwnSizeNotAsTheGoal) {
  const std::vector<Anchor> subjects = ComparedSubjects();
  ASSERT_EQ(subjects.size(), 2u);
  EXPECT_EQ(subjects[0].figure, std::string(key::kLmapCompactBytes));
  EXPECT_EQ(subjects[1].figure, std::string(key::kLmapRasterCompactBytes));
  MapResult office = Map("office", 3400000, 1679, 3000, 1022);
  office.figures[key::kLmapCompactBytes] = 1000;    // beats JPEG XL where the default does not
  const std::vector<MapResult> results = {office};  // outcomes point into it
  const std::vector<AnchorOutcome> outcomes = CheckAnchors(results, subjects[0]);
  EXPECT_EQ(Names(Outcome(outcomes, key::kJxlBytes).won), (std::vector<std::string>{"office"}));
  const std::vector<NamedTable> tables = AnchorTables(results, subjects[0], /*goal=*/false);
  ASSERT_EQ(tables.size(), 1u);
  EXPECT_NE(tables[0].caption.find("not a goal"), std::string::npos) << tables[0].caption;
  EXPECT_EQ(tables[0].caption.find("goal:"), std::string::npos) << tables[0].caption;
  EXPECT_NE(AnchorTables(results)[0].caption.find("goal:"), std::string::npos);
}

TEST(BenchAnchorsTest, NoLossesTableWhenEveryMapIsWon) {
  const std::vector<NamedTable> tables = AnchorTables({Map("lab", 200000, 800, 1000, 900)});
  EXPECT_EQ(tables.size(), 1u);
}

TEST(BenchReportTest, ASizeColumnNoMapHasIsLeftOut) {
  MapResult with = Map("a", 200000, 800, 1000, 900);
  MapResult without = Map("a", 200000, 800, 1000, 0);
  auto sizes_header = [](const MapResult& r) {
    const std::vector<NamedTable> tables = PerMapTables({r});
    return tables.at(0).table.headers();
  };
  auto has = [](const std::vector<std::string>& headers, const std::string& h) {
    return std::find(headers.begin(), headers.end(), h) != headers.end();
  };
  EXPECT_TRUE(has(sizes_header(with), "JPEG XL"));
  EXPECT_FALSE(has(sizes_header(without), "JPEG XL"));
  EXPECT_TRUE(has(sizes_header(without), "PNG-9"));
}

}  // namespace
}  // namespace linemap::bench
