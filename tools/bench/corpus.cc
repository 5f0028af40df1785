#include "tools/bench/corpus.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>

namespace linemap::bench {
namespace fs = std::filesystem;
namespace {

std::string LowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool IsYaml(const fs::path& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".yaml" || ext == ".yml";
}

bool IsImage(const fs::path& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".pgm" || ext == ".png";
}

std::string Normal(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return (ec ? path : absolute).lexically_normal().string();
}

std::string NameIn(const fs::path& dir, const fs::path& file) {
  fs::path relative = file.lexically_relative(dir);
  if (relative.empty()) relative = file.filename();
  relative.replace_extension();
  return relative.generic_string();
}

std::string ExistingDir(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return "";
  const fs::path canonical = fs::weakly_canonical(dir, ec);
  return (ec ? dir : canonical).string();
}

}  // namespace

std::string YamlImagePath(const std::string& yaml_path) {
  try {
    const YAML::Node root = YAML::LoadFile(yaml_path);
    if (!root.IsMap() || !root["image"] || !root["image"].IsScalar()) return "";
    const fs::path image = root["image"].as<std::string>();
    if (image.is_absolute()) return Normal(image);
    return Normal(fs::path(yaml_path).parent_path() / image);
  } catch (const YAML::Exception&) {
    return "";
  }
}

StatusOr<std::vector<CorpusMap>> DiscoverCorpus(const std::vector<std::string>& dirs) {
  std::vector<CorpusMap> maps;
  for (const std::string& dir_text : dirs) {
    const fs::path dir = Normal(dir_text);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
      return NotFoundError(dir_text + ": not a folder");
    }
    std::vector<fs::path> yamls, images;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    if (ec) return IoError(dir_text + ": " + ec.message());
    for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (ec) return IoError(dir_text + ": " + ec.message());
      if (!it->is_regular_file(ec)) continue;
      if (IsYaml(it->path())) yamls.push_back(Normal(it->path()));
      if (IsImage(it->path())) images.push_back(Normal(it->path()));
    }
    std::set<std::string> named;
    for (const fs::path& yaml : yamls) named.insert(YamlImagePath(yaml.string()));
    std::vector<CorpusMap> found;
    for (const fs::path& yaml : yamls) found.push_back({yaml.string(), NameIn(dir, yaml), false});
    for (const fs::path& image : images) {
      if (!named.count(image.string())) found.push_back({image.string(), NameIn(dir, image), true});
    }
    std::sort(found.begin(), found.end(),
              [](const CorpusMap& a, const CorpusMap& b) { return a.path < b.path; });
    maps.insert(maps.end(), found.begin(), found.end());
  }
  return maps;
}

std::vector<std::string> DefaultCorpusDirs() {
  std::vector<std::string> dirs;
  const fs::path source = LINEMAP_SOURCE_DIR;
  if (std::string bundled = ExistingDir(source / "tests" / "data" / "maps"); !bundled.empty()) {
    dirs.push_back(bundled);
  }
  std::vector<fs::path> shared_candidates;
  if (const char* env = std::getenv("LINEMAP_SHARED_MAPS"); env && *env) {
    shared_candidates.push_back(env);
  }
  shared_candidates.push_back(source / ".." / "shared" / "maps");
  std::error_code ec;
  shared_candidates.push_back(fs::current_path(ec) / ".." / "shared" / "maps");
  for (const fs::path& candidate : shared_candidates) {
    if (std::string shared = ExistingDir(candidate); !shared.empty()) {
      dirs.push_back(shared);
      break;
    }
  }
  return dirs;
}

}  // namespace linemap::bench
