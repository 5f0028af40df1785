// What both consumer programs do with the map they load: print its size, or
// the error, and return the exit status.
#ifndef LINEMAP_TESTS_INSTALL_CONSUMER_PRINT_SIZE_H_
#define LINEMAP_TESTS_INSTALL_CONSUMER_PRINT_SIZE_H_

#include <cstdio>

#include "linemap/grid.h"
#include "linemap/status.h"

// `load` is called with the path given on the command line.
template <typename Load>
int PrintSize(int argc, char** argv, Load load) {
  if (argc < 2) return 2;
  const linemap::StatusOr<linemap::Grid> grid = load(argv[1]);
  if (!grid.ok()) {
    std::fprintf(stderr, "%s\n", grid.status().message().c_str());
    return 1;
  }
  std::printf("%d x %d\n", grid->width(), grid->height());
  return 0;
}

#endif  // LINEMAP_TESTS_INSTALL_CONSUMER_PRINT_SIZE_H_
