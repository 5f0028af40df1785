// Cell-for-cell agreement with nav2's classification on every real map,
// through an independent decoding path: netpbm (pngtopam / pamtopam) decodes
// the image to PAM, and the classification is recomputed here directly from
// nav2's map_io.cpp, in 16-bit quanta as GraphicsMagick's Q16 build hands
// them to nav2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "linemap/map_io.h"
#include "tests/testing/test_support.h"

namespace linemap {
namespace {

struct Pam {
  int width = 0, height = 0, depth = 0;
  unsigned maxval = 0;
  std::vector<unsigned> samples;
};

// GraphicsMagick reports a matte channel for PNG colour types 4 and 6 and
// for any tRNS chunk; pngtopam -alphapam adds an opaque alpha plane anyway.
bool PngHasAlpha(const std::string& path) {
  const std::string data = testing::ReadFile(path);
  if (data.size() < 33) return false;
  const unsigned color_type = static_cast<unsigned char>(data[25]);
  return color_type == 4 || color_type == 6 || data.find("tRNS") != std::string::npos;
}

bool HaveNetpbm() { return std::system("command -v pngtopam >/dev/null 2>&1") == 0; }

// Runs `command` and parses its PAM output.
bool ReadPam(const std::string& command, Pam* pam) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return false;
  std::string data;
  char buf[1 << 16];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), pipe)) > 0) data.append(buf, n);
  if (::pclose(pipe) != 0) return false;
  const std::size_t end = data.find("ENDHDR\n");
  if (data.rfind("P7\n", 0) != 0 || end == std::string::npos) return false;
  std::istringstream header(data.substr(3, end - 3));
  std::string key;
  while (header >> key) {
    if (key == "WIDTH")
      header >> pam->width;
    else if (key == "HEIGHT")
      header >> pam->height;
    else if (key == "DEPTH")
      header >> pam->depth;
    else if (key == "MAXVAL")
      header >> pam->maxval;
    else
      header.ignore(1 << 20, '\n');
  }
  const std::size_t count = static_cast<std::size_t>(pam->width) * pam->height * pam->depth;
  const std::size_t bytes = pam->maxval > 255 ? 2 : 1;
  std::size_t pos = end + 7;
  if (data.size() - pos < count * bytes) return false;
  pam->samples.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    unsigned v = static_cast<unsigned char>(data[pos++]);
    if (bytes == 2) v = (v << 8) | static_cast<unsigned char>(data[pos++]);
    pam->samples[i] = v;
  }
  return true;
}

Cell Nav2Classify(const Pam& pam, bool matte, std::size_t pixel, const MapMetadata& meta) {
  // Channels to 16-bit quanta, as GraphicsMagick Q16 scales them.
  auto quantum = [&](unsigned v) -> double {
    return pam.maxval == 65535 ? v : (v * 65535.0 + pam.maxval / 2) / pam.maxval;
  };
  const unsigned* s = pam.samples.data() + pixel * pam.depth;
  const bool grey = pam.depth <= 2;
  const bool alpha = matte && (pam.depth == 2 || pam.depth == 4);
  double r = quantum(s[0]), g = grey ? r : quantum(s[1]), b = grey ? r : quantum(s[2]);
  double sum = std::floor(r) + std::floor(g) + std::floor(b);
  double channels = 3;
  const double a = alpha ? std::floor(quantum(s[pam.depth - 1])) : 65535.0;
  if (meta.mode == MapMode::kTrinary && alpha) {
    sum += a;
    channels = 4;
  }
  const double shade = std::floor(sum / channels) / 65535.0;
  const double occ = meta.negate ? shade : 1.0 - shade;
  if (meta.mode == MapMode::kScale && a != 65535.0) return Cell::kUnknown;
  if (meta.occupied_thresh < occ) return Cell::kOccupied;
  if (occ < meta.free_thresh) return Cell::kFree;
  return Cell::kUnknown;
}

void ExpectAgreement(const std::string& map_path) {
  SCOPED_TRACE(map_path);
  StatusOr<Grid> grid = LoadRosMap(map_path);
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  std::string image = map_path;
  if (map_path.ends_with(".yaml")) {
    // The YAMLs in the corpus name their image beside them.
    const std::string text = testing::ReadFile(map_path);
    const std::size_t at = text.find("image:");
    std::string name = text.substr(at + 6, text.find('\n', at) - at - 6);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t\r") + 1);
    image = map_path.substr(0, map_path.find_last_of('/') + 1) + name;
  }
  const std::string command =
      (image.ends_with(".png") ? "pngtopam -alphapam '" : "pamtopam < '") + image + "' 2>/dev/null";
  Pam pam;
  ASSERT_TRUE(ReadPam(command, &pam)) << command;
  const bool matte = image.ends_with(".png") && PngHasAlpha(image);
  ASSERT_EQ(pam.width, grid->width());
  ASSERT_EQ(pam.height, grid->height());
  std::size_t mismatches = 0;
  for (int y = 0; y < pam.height; ++y) {
    for (int x = 0; x < pam.width; ++x) {
      const Cell expected =
          Nav2Classify(pam, matte, static_cast<std::size_t>(y) * pam.width + x, grid->meta);
      if (grid->at(x, pam.height - 1 - y) != expected) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST(Nav2AgreementTest, BundledMaps) {
  if (!HaveNetpbm()) GTEST_SKIP() << "netpbm is not installed";
  for (const std::string& yaml : testing::FindYamlFiles(testing::BundledMapsDir())) {
    ExpectAgreement(yaml);
  }
}

TEST(Nav2AgreementTest, EverySharedMap) {
  const std::string shared = testing::SharedMapsDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/maps is absent";
  if (!HaveNetpbm()) GTEST_SKIP() << "netpbm is not installed";
  int checked = 0;
  for (const std::string& yaml : testing::FindYamlFiles(shared)) {
    if (yaml.find("empty_room") != std::string::npos) continue;  // its image is missing
    ExpectAgreement(yaml);
    ++checked;
  }
  for (const std::string& image : testing::FindBareImages(shared)) {
    ExpectAgreement(image);
    ++checked;
  }
  EXPECT_GE(checked, 24);
}

}  // namespace
}  // namespace linemap
