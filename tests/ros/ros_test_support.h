// Helpers for the ROS 1 tests: a real rosmaster on a free port of
// 127.0.0.1 (never a robot's 11311), child processes (the nodes, rostopic)
// that are stopped by process id when the test ends or dies, and this test
// process as a ROS node of its own.
#ifndef LINEMAP_TESTS_ROS_ROS_TEST_SUPPORT_H_
#define LINEMAP_TESTS_ROS_ROS_TEST_SUPPORT_H_

#include <sys/types.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace linemap::testing {

// A child process with stdout and stderr in files. The child gets SIGKILL
// when this process dies (PR_SET_PDEATHSIG), so a crashed test leaves
// nothing running; the destructor stops it (SIGINT, then SIGKILL).
class ChildProcess {
 public:
  // Runs `argv` (argv[0] a path) with `env` added to this environment.
  ChildProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env,
               const std::string& log_dir, const std::string& tag);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  // The exit code (128 + signal when killed) once it ended within
  // `seconds`; nullopt if it is still running.
  std::optional<int> Wait(double seconds);
  // Sends `signal` and waits up to 5 s; SIGKILL after that.
  int Stop(int signal);
  std::string Stdout() const;
  std::string Stderr() const;

 private:
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
  std::string out_path_;
  std::string err_path_;
};

// A rosmaster on a free port of 127.0.0.1, with its logs in a scratch
// folder; stopped with the object.
class RosMaster {
 public:
  RosMaster();
  const std::string& uri() const { return uri_; }
  // ROS_MASTER_URI, ROS_IP / ROS_HOSTNAME (127.0.0.1), ROS_HOME and ROS_LOG_DIR
  // for a child node.
  std::vector<std::string> Env() const;
  const std::string& scratch() const { return scratch_; }
  bool running() const { return process_ != nullptr; }

 private:
  std::string scratch_;
  std::string uri_;
  std::unique_ptr<ChildProcess> process_;
};

// The master shared by the tests of this process, started on first use;
// this process joins it as a ROS node (ros::init with __master) the first
// time. ROS allows one ros::init per process, hence one master per process
// (ctest runs each test in a process of its own).
RosMaster& SharedMaster();

// A TCP port on 127.0.0.1 that nothing listens on (bound, then released).
int FreePort();

// Polls `done` every 10 ms, spinning ROS callbacks, for up to `seconds`.
bool WaitFor(const std::function<bool()>& done, double seconds);

// Seconds on a monotonic clock.
double Now();

// Paths of the programs under test.
std::string LmapServerPath();
std::string LmapSaverPath();
std::string RostopicPath();

}  // namespace linemap::testing

#endif  // LINEMAP_TESTS_ROS_ROS_TEST_SUPPORT_H_
