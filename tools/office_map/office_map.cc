// office_map: writes the generated office map of the huge-map measurements
// (README, "Huge maps in bounded memory") as a map YAML + PGM, so that they
// can be repeated:
//
//   office_map OUT.yaml [WIDTH HEIGHT]     (cells; default 20768 13612)
//
// The map is bench::GenerateOfficeMapOfSize(WIDTH, HEIGHT) (96-cell rooms, doors,
// furniture, speckle, 0.05 m/cell, the same cells on every platform: the
// square of the larger side cut from its origin), as in the bench's scaling
// table. Making the 20,768 x 13,612 map holds the square and the cut, about
// 0.7 GB, for a few seconds.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "linemap/map_io.h"
#include "tools/bench/synthetic.h"

namespace {

int Usage() {
  std::fprintf(stderr, "usage: office_map OUT.yaml [WIDTH HEIGHT]  (cells, 64..65536)\n");
  return 2;
}

bool ParseSide(const char* text, int* side) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 64 || v > 65536) return false;
  *side = static_cast<int>(v);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using linemap::Grid;
  if (argc != 2 && argc != 4) return Usage();
  int width = 20768, height = 13612;
  if (argc == 4 && (!ParseSide(argv[2], &width) || !ParseSide(argv[3], &height))) return Usage();
  const Grid map = linemap::bench::GenerateOfficeMapOfSize(width, height);
  const linemap::Status saved = linemap::SaveRosMap(argv[1], map);
  if (!saved.ok()) {
    std::fprintf(stderr, "office_map: %s\n", saved.ToString().c_str());
    return 1;
  }
  std::printf("wrote %s and its .pgm: %d x %d cells\n", argv[1], width, height);
  return 0;
}
