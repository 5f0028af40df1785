// Finding the maps of a benchmark corpus: every map YAML under a folder
// (recursively), and every PGM/PNG image there that no YAML names.
#ifndef LINEMAP_TOOLS_BENCH_CORPUS_H_
#define LINEMAP_TOOLS_BENCH_CORPUS_H_

#include <string>
#include <vector>

#include "linemap/status.h"

namespace linemap::bench {

struct CorpusMap {
  std::string path;  // the YAML, or the bare image
  std::string name;  // path relative to its corpus folder, without the extension
  bool bare_image = false;
};

// Maps under each folder in `dirs`, in that order; within a folder sorted by
// path. A YAML whose `image:` cannot be read is still listed (loading it then
// reports the problem); images it names are not listed as bare images.
StatusOr<std::vector<CorpusMap>> DiscoverCorpus(const std::vector<std::string>& dirs);

// The default corpus: the bundled maps (tests/data/maps of the source tree)
// and, when present, the shared maps: $LINEMAP_SHARED_MAPS, else ../shared/maps
// beside the source tree or beside the current directory.
std::vector<std::string> DefaultCorpusDirs();

// The image path a ROS map YAML names (resolved against the YAML's folder),
// or "" when the YAML has no readable `image:` key.
std::string YamlImagePath(const std::string& yaml_path);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_CORPUS_H_
