#include <cstdio>

#include "linemap/codec.h"
#include "linemap/grid.h"

// Loads an .lmap file with the decoder library alone and prints its size.
int main(int argc, char** argv) {
  if (argc < 2) return 2;
  linemap::StatusOr<linemap::Grid> grid = linemap::LoadLmap(argv[1]);
  if (!grid.ok()) {
    std::fprintf(stderr, "%s\n", grid.status().message().c_str());
    return 1;
  }
  std::printf("%d x %d\n", grid->width(), grid->height());
  return 0;
}
