#include "tools/bench/subprocess.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

extern char** environ;

namespace linemap::bench {
namespace fs = std::filesystem;

StatusOr<int> RunSubprocess(const std::vector<std::string>& argv) {
  LINEMAP_ASSIGN_OR_RETURN(const SubprocessRun run, RunSubprocessTimed(argv));
  return run.exit_code;
}

StatusOr<SubprocessRun> RunSubprocessTimed(const std::vector<std::string>& argv) {
  if (argv.empty()) return InvalidArgumentError("no command to run");
  std::vector<std::string> copy = argv;
  std::vector<char*> args;
  for (std::string& a : copy) args.push_back(a.data());
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int err = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) {
    return NotFoundError(argv[0] + ": cannot run: " + std::strerror(err)).WithErrno(err);
  }
  int status = 0;
  struct rusage usage {};
  while (::wait4(pid, &status, 0, &usage) < 0) {
    if (const int err = errno; err != EINTR) {
      return IoError(argv[0] + ": wait4 failed: " + std::strerror(err)).WithErrno(err);
    }
  }
  if (WIFEXITED(status)) {
    // posix_spawnp reports a missing program as exit code 127 from the child.
    if (WEXITSTATUS(status) == 127) return NotFoundError(argv[0] + ": not found");
    const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
    return SubprocessRun{WEXITSTATUS(status), ms(usage.ru_utime) + ms(usage.ru_stime)};
  }
  return IoError(argv[0] + ": killed by signal " + std::to_string(WTERMSIG(status)));
}

bool ToolAvailable(const std::string& tool) {
  if (tool.find('/') != std::string::npos) return ::access(tool.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (!dir.empty() && ::access((dir + "/" + tool).c_str(), X_OK) == 0) return true;
  }
  return false;
}

StatusOr<ScratchDir> ScratchDir::Create(const std::string& tag) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/linemap-" + tag + "-XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr) {
    const int err = errno;
    return IoError("cannot create a scratch folder " + pattern + ": " + std::strerror(err))
        .WithErrno(err);
  }
  return ScratchDir(pattern);
}

ScratchDir::ScratchDir(ScratchDir&& other) noexcept : path_(std::move(other.path_)) {
  other.path_.clear();
}

StatusOr<std::string> ScratchDir::WriteScratchFile(const std::string& name,
                                                   std::string_view data) const {
  const std::string path = path_ + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    const int err = errno;
    return IoError(path + ": " + std::strerror(err)).WithErrno(err);
  }
  const bool written = std::fwrite(data.data(), 1, data.size(), f) == data.size();
  if (std::fclose(f) != 0 || !written) return IoError(path + ": write failed");
  return path;
}

ScratchDir::~ScratchDir() {
  if (path_.empty()) return;
  std::error_code ec;
  fs::remove_all(path_, ec);
}

}  // namespace linemap::bench
