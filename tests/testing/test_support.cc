#include "tests/testing/test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace linemap::testing {
namespace fs = std::filesystem;

std::string SourceDir() { return LINEMAP_SOURCE_DIR; }

std::string BundledMapsDir() { return SourceDir() + "/tests/data/maps"; }

std::string SharedMapsDir() {
  const char* env = std::getenv("LINEMAP_SHARED_MAPS");
  const fs::path dir = env ? fs::path(env) : fs::path(SourceDir()) / ".." / "shared" / "maps";
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return fs::weakly_canonical(dir, ec).string();
  return "";
}

std::vector<std::string> FindYamlFiles(const std::string& dir) {
  std::vector<std::string> out;
  if (dir.empty()) return out;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".yaml" || ext == ".yml")) {
      out.push_back(entry.path().string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> FindBareImages(const std::string& dir) {
  std::vector<std::string> out;
  if (dir.empty()) return out;
  std::set<std::string> named;
  for (const std::string& yaml : FindYamlFiles(dir)) {
    std::ifstream in(yaml);
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("image:", 0) == 0) {
        std::string name = line.substr(6);
        name.erase(0, name.find_first_not_of(" \t\"'"));
        name.erase(name.find_last_not_of(" \t\r\"'") + 1);
        named.insert((fs::path(yaml).parent_path() / name).lexically_normal().string());
      }
    }
  }
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".pgm" && ext != ".png")) continue;
    const std::string path = entry.path().lexically_normal().string();
    if (!named.count(path)) out.push_back(path);
  }
  std::sort(out.begin(), out.end());
  return out;
}

Grid TiledMap(const Grid& map, int width, int height) {
  Grid tiled(width, height, Cell::kUnknown);
  tiled.meta = map.meta;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) tiled.set(c, r, map.at(c % map.width(), r % map.height()));
  }
  return tiled;
}

std::string MakeTempDir(const std::string& tag) {
  static std::atomic<int> counter{0};
  const char* env = std::getenv("LINEMAP_TEST_TMP");
  const fs::path base = env ? fs::path(env) : fs::temp_directory_path() / "linemap-tests";
  const fs::path dir =
      base / (tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

void WriteFile(const std::string& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary);
  out << contents;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool FileExists(const std::string& path) {
  std::error_code ec;
  return fs::exists(path, ec);
}

std::vector<std::string> ListDir(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir)) out.push_back(entry.path().filename());
  std::sort(out.begin(), out.end());
  return out;
}

CliResult RunCli(const std::vector<std::string>& args) {
  CliResult result;
  const std::string dir = MakeTempDir("cli");
  const std::string out_path = dir + "/stdout";
  const std::string err_path = dir + "/stderr";
  const pid_t pid = ::fork();
  if (pid == 0) {
    FILE* out = std::freopen(out_path.c_str(), "w", stdout);
    FILE* err = std::freopen(err_path.c_str(), "w", stderr);
    if (!out || !err) _exit(127);
    std::vector<char*> argv;
    std::string cli = LINEMAP_CLI_PATH;
    argv.push_back(cli.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(cli.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = ReadFile(out_path);
  result.err = ReadFile(err_path);
  fs::remove_all(dir);
  return result;
}

}  // namespace linemap::testing
