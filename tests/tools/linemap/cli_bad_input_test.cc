// Bad input to every command, run against the built CLI:
// each row gives one command a broken input; the command must print exactly
// one line on stderr that names the file, exit 2, and write nothing (the
// output folder is listed before and after). Output into a missing folder
// is a failure while writing: exit 1 or 2, still one line, nothing written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::RunCli;

// The commands that read a map, with {IN} for the map and {OUT} for a file in
// the output folder. Commands that read only .lmap files are marked.
struct Command {
  const char* name;
  std::vector<std::string> argv;
  bool lmap_only;
};

const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = {
      {"info", {"info", "{IN}"}, false},
      {"encode", {"encode", "{IN}", "-o", "{OUT}/out.lmap"}, false},
      {"lines", {"lines", "{IN}", "-o", "{OUT}/lines.csv"}, false},
      {"segment", {"segment", "{IN}", "-o", "{OUT}/seg.json"}, false},
      {"plan", {"plan", "{IN}", "--from", "1,1", "--to", "2,2", "--svg", "{OUT}/p.svg"}, false},
      {"eval_original", {"eval", "{IN}", "{GOOD}"}, false},
      {"eval_decoded", {"eval", "{GOOD}", "{IN}"}, false},
      {"decode", {"decode", "{IN}", "-o", "{OUT}/out.yaml"}, true},
      {"export", {"export", "{IN}", "-o", "{OUT}/out.svg"}, true},
  };
  return commands;
}

// One broken input: a file name (its extension decides how commands read it)
// and what to put there.
enum class Make { kNothing, kDirectory, kProcMem, kText, kCopy };
struct BadInput {
  const char* file;
  Make make;
  std::string contents;  // text, or the source file for kCopy
  bool for_maps;         // used with commands that read YAML / images
  bool for_lmap;         // used with .lmap-only commands
};

std::vector<BadInput> BadInputs() {
  const std::string maps = testing::BundledMapsDir();
  const std::string png = testing::SourceDir() + "/tests/fuzz/corpus/map_image/grey8.png";
  const std::string yaml_head = "image: " + maps + "/navtut/lse_arena.pgm\n";
  return {
      {"missing.yaml", Make::kNothing, "", true, false},
      {"missing.lmap", Make::kNothing, "", true, true},
      {"folder.yaml", Make::kDirectory, "", true, false},
      {"folder.lmap", Make::kDirectory, "", false, true},
      {"unreadable.yaml", Make::kProcMem, "", true, false},
      {"unreadable.lmap", Make::kProcMem, "", false, true},
      {"empty.yaml", Make::kText, "", true, false},
      {"empty.lmap", Make::kText, "", true, true},
      {"empty.pgm", Make::kText, "", true, false},
      {"png_renamed.lmap", Make::kCopy, png, true, true},
      {"not_a_map.pgm", Make::kText, "this is not an image\n", true, false},
      {"yaml_renamed.lmap", Make::kText, yaml_head + "resolution: 0.05\n", false, true},
      {"wrong_types.yaml", Make::kText,
       yaml_head + "resolution: fine\norigin: 3\nnegate: maybe\noccupied_thresh: high\n", true,
       false},
      {"negative_resolution.yaml", Make::kText,
       yaml_head + "resolution: -0.05\norigin: [0, 0, 0]\n", true, false},
      {"zero_resolution.yaml", Make::kText, yaml_head + "resolution: 0\norigin: [0, 0, 0]\n", true,
       false},
      {"image_missing.yaml", Make::kText,
       "image: nowhere.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n", true, false},
  };
}

void MakeInput(const BadInput& input, const std::string& path) {
  switch (input.make) {
    case Make::kNothing:
      break;
    case Make::kDirectory:
      fs::create_directories(path);
      break;
    case Make::kProcMem:
      // Opens fine but every read fails (root can read chmod 000 files).
      fs::create_symlink("/proc/self/mem", path);
      break;
    case Make::kText:
      testing::WriteFile(path, input.contents);
      break;
    case Make::kCopy:
      fs::copy_file(input.contents, path);
      break;
  }
}

std::vector<std::string> Substitute(const std::vector<std::string>& argv, const std::string& in,
                                    const std::string& out) {
  const std::string good = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  std::vector<std::string> result;
  for (std::string arg : argv) {
    for (const auto& [key, value] :
         {std::pair<std::string, std::string>{"{IN}", in}, {"{OUT}", out}, {"{GOOD}", good}}) {
      const auto at = arg.find(key);
      if (at != std::string::npos) arg.replace(at, key.size(), value);
    }
    result.push_back(arg);
  }
  return result;
}

std::string Joined(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) s += a + " ";
  return s;
}

// `io_failure`: exit 1 (failure while reading or writing) is accepted too.
void ExpectCleanFailure(const std::vector<std::string>& argv, const std::string& out_dir,
                        const std::string& named, bool io_failure) {
  const std::vector<std::string> before = testing::ListDir(out_dir);
  const CliResult r = RunCli(argv);
  const std::string where = Joined(argv) + "\nstderr: " + r.err;
  if (io_failure) {
    EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 2) << "exit " << r.exit_code << ": " << where;
  } else {
    EXPECT_EQ(r.exit_code, 2) << where;
  }
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << where;
  EXPECT_TRUE(r.err.ends_with("\n")) << where;
  EXPECT_NE(r.err.find(named), std::string::npos)
      << "stderr does not name " << named << ": " << where;
  EXPECT_EQ(testing::ListDir(out_dir), before) << where;
}

TEST(CliBadInput, EveryCommandRefusesEveryBrokenInput) {
  const std::string dir = testing::MakeTempDir("cli_bad_input");
  const std::string out_dir = dir + "/out";
  fs::create_directories(out_dir);
  testing::WriteFile(out_dir + "/keep.txt", "existing output folder content\n");
  int rows = 0;
  for (const BadInput& input : BadInputs()) {
    const std::string path = dir + "/" + input.file;
    MakeInput(input, path);
    for (const Command& command : Commands()) {
      if (!(command.lmap_only ? input.for_lmap : input.for_maps)) continue;
      SCOPED_TRACE(std::string(command.name) + " <- " + input.file);
      ExpectCleanFailure(Substitute(command.argv, path, out_dir), out_dir, input.file,
                         /*io_failure=*/false);
      ++rows;
    }
  }
  EXPECT_GT(rows, 90);
  fs::remove_all(dir);
}

TEST(CliBadInput, OutputIntoAMissingFolderWritesNothing) {
  const std::string dir = testing::MakeTempDir("cli_bad_output");
  const std::string map = testing::BundledMapsDir() + "/navtut/lse_arena.yaml";
  const std::string lmap = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const std::string missing = dir + "/no_such_folder";
  const std::vector<std::vector<std::string>> rows = {
      {"encode", map, "-o", missing + "/out.lmap"},  {"lines", map, "-o", missing + "/lines.csv"},
      {"segment", map, "-o", missing + "/seg.json"}, {"decode", lmap, "-o", missing + "/out.yaml"},
      {"export", lmap, "-o", missing + "/out.svg"},
  };
  for (const auto& argv : rows)
    ExpectCleanFailure(argv, dir, "no_such_folder", /*io_failure=*/true);
  EXPECT_FALSE(fs::exists(missing));
  fs::remove_all(dir);
}

TEST(CliBadInput, BenchRefusesAMissingCorpusFolder) {
  const std::string dir = testing::MakeTempDir("cli_bad_bench");
  ExpectCleanFailure({"bench", dir + "/no_corpus_here", "--md", dir + "/out.md"}, dir,
                     "no_corpus_here", /*io_failure=*/false);
  fs::remove_all(dir);
}

// A header claiming 100000 x 100000 cells is refused from the header, before
// any allocation, by every command that reads .lmap files; --max-cells
// lowers the limit for files that are otherwise fine.
TEST(CliBadInput, LmapLimitsOnTheCommandLine) {
  const std::string dir = testing::MakeTempDir("cli_limits");
  const std::string huge = testing::SourceDir() + "/tests/data/lmap/huge_dimensions.lmap";
  const std::string small = testing::SourceDir() + "/tests/data/lmap/lse_arena_lossy.lmap";
  const std::vector<std::vector<std::string>> commands = {
      {"info", "{IN}"},
      {"decode", "{IN}", "-o", "{OUT}/o.yaml"},
      {"export", "{IN}", "-o", "{OUT}/o.svg"},
      {"eval", "{IN}", "{IN}"},
      {"plan", "{IN}", "--from", "1,1", "--to", "2,2"},
  };
  for (const auto& command : commands) {
    ExpectCleanFailure(Substitute(command, huge, dir), dir, "huge_dimensions.lmap", false);
    std::vector<std::string> limited = Substitute(command, small, dir);
    limited.push_back("--max-cells");
    limited.push_back("100");
    ExpectCleanFailure(limited, dir, "lse_arena_lossy.lmap", false);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace linemap
