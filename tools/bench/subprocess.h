// Running a command-line tool (no shell) and scratch folders for its files.
// Used for comparators that must not be linked (JBIG-KIT is GPL).
#ifndef LINEMAP_TOOLS_BENCH_SUBPROCESS_H_
#define LINEMAP_TOOLS_BENCH_SUBPROCESS_H_

#include <string>
#include <string_view>
#include <vector>

#include "linemap/status.h"

namespace linemap::bench {

// Runs argv[0] (looked up in PATH) with stdin, stdout and stderr on
// /dev/null and returns its exit code. kNotFound when it cannot be started;
// kIoError when it dies from a signal.
StatusOr<int> RunSubprocess(const std::vector<std::string>& argv);

struct SubprocessRun {
  int exit_code = 0;
  // User + system CPU time of the process and its threads, in ms (from
  // wait4's rusage): comparable with the in-process CPU times of the bench,
  // but it includes the program's start-up and its file reads and writes.
  double cpu_ms = 0;
};

// RunSubprocess, also reporting the CPU time the process used.
StatusOr<SubprocessRun> RunSubprocessTimed(const std::vector<std::string>& argv);

// True when `tool` can be found in PATH (or is an executable path).
bool ToolAvailable(const std::string& tool);

// A fresh folder under $TMPDIR (or /tmp), removed with its contents on
// destruction.
class ScratchDir {
 public:
  static StatusOr<ScratchDir> Create(const std::string& tag);
  ScratchDir(ScratchDir&& other) noexcept;
  ScratchDir& operator=(ScratchDir&&) = delete;
  ScratchDir(const ScratchDir&) = delete;
  ~ScratchDir();
  const std::string& path() const { return path_; }
  // Writes `data` to `name` inside the folder, without the fsyncs of
  // WriteFileAtomic: scratch files need no durability, and fsync on a busy
  // disk would dominate the benchmark's wall time. Returns the full path.
  StatusOr<std::string> WriteScratchFile(const std::string& name, std::string_view data) const;

 private:
  explicit ScratchDir(std::string path) : path_(std::move(path)) {}
  std::string path_;
};

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_SUBPROCESS_H_
