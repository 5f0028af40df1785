// Helpers shared by the test suites: where the maps are, scratch folders,
// running the built CLI.
#ifndef LINEMAP_TESTS_TESTING_TEST_SUPPORT_H_
#define LINEMAP_TESTS_TESTING_TEST_SUPPORT_H_

#include <cstdint>
#include <string>
#include <vector>

#include "linemap/grid.h"

namespace linemap::testing {

// The project's source folder.
std::string SourceDir();
// Maps shipped with the project (tests/data/maps).
std::string BundledMapsDir();
// ../shared/maps beside the project, or "" when it is absent.
std::string SharedMapsDir();

// Every map YAML under `dir` (recursive, sorted).
std::vector<std::string> FindYamlFiles(const std::string& dir);
// Every PGM/PNG under `dir` that no YAML there names (recursive, sorted).
std::vector<std::string> FindBareImages(const std::string& dir);

// A fresh empty folder for one test, removed by nobody (it lives under the
// build tree or /tmp).
std::string MakeTempDir(const std::string& tag);

void WriteFile(const std::string& path, const std::string& contents);
std::string ReadFile(const std::string& path);
bool FileExists(const std::string& path);
std::vector<std::string> ListDir(const std::string& dir);

// A width x height map of copies of `map` side by side (its metadata):
// maps larger than a layer block (2048 cells, the side of their layer
// sections) with walls, rooms and furniture in every block.
Grid TiledMap(const Grid& map, int width, int height);

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};
// Runs the built `linemap` binary with `args` (no shell involved).
CliResult RunCli(const std::vector<std::string>& args);

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_TESTING_TEST_SUPPORT_H_
