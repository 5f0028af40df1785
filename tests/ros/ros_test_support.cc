#include "tests/ros/ros_test_support.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <ros/master.h>
#include <ros/ros.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>

#include "tests/testing/test_support.h"

extern char** environ;

namespace linemap::testing {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool WaitFor(const std::function<bool()>& done, double seconds) {
  const double deadline = Now() + seconds;
  while (!done()) {
    if (Now() > deadline) return false;
    if (ros::isInitialized()) ros::spinOnce();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv,
                           const std::vector<std::string>& env, const std::string& log_dir,
                           const std::string& tag)
    : out_path_(log_dir + "/" + tag + ".stdout"), err_path_(log_dir + "/" + tag + ".stderr") {
  // Everything the child needs is made before fork(): this process runs
  // ROS threads, so the child may only make async-signal-safe calls.
  std::map<std::string, std::string> merged;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    const std::size_t eq = entry.find('=');
    if (eq != std::string::npos) merged[entry.substr(0, eq)] = entry.substr(eq + 1);
  }
  for (const std::string& entry : env) {
    const std::size_t eq = entry.find('=');
    merged[entry.substr(0, eq)] = entry.substr(eq + 1);
  }
  std::vector<std::string> env_strings;
  for (const auto& [key, value] : merged) env_strings.push_back(key + "=" + value);
  std::vector<char*> envp;
  for (std::string& s : env_strings) envp.push_back(s.data());
  envp.push_back(nullptr);
  std::vector<std::string> args = argv;
  std::vector<char*> argvp;
  for (std::string& s : args) argvp.push_back(s.data());
  argvp.push_back(nullptr);
  const int out = ::open(out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int err = ::open(err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the test died before prctl
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::execve(argvp[0], argvp.data(), envp.data());
    ::_exit(127);
  }
  ::close(out);
  ::close(err);
  if (pid_ < 0) throw std::runtime_error("fork failed");
}

ChildProcess::~ChildProcess() {
  if (!exit_code_) Stop(SIGINT);
}

std::optional<int> ChildProcess::Wait(double seconds) {
  if (exit_code_) return exit_code_;
  const double deadline = Now() + seconds;
  while (true) {
    int status = 0;
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_) {
      exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      return exit_code_;
    }
    if (Now() > deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

int ChildProcess::Stop(int signal) {
  if (exit_code_) return *exit_code_;
  ::kill(pid_, signal);
  if (std::optional<int> code = Wait(5.0)) return *code;
  ::kill(pid_, SIGKILL);
  return Wait(5.0).value_or(-1);
}

std::string ChildProcess::Stdout() const { return ReadFile(out_path_); }
std::string ChildProcess::Stderr() const { return ReadFile(err_path_); }

int FreePort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof(address);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    ::close(fd);
    throw std::runtime_error("no free port on 127.0.0.1");
  }
  const int port = ntohs(address.sin_port);
  ::close(fd);
  return port;
}

namespace {

// True once something accepts connections on 127.0.0.1:port.
bool Listening(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  ::close(fd);
  return ok;
}

}  // namespace

RosMaster::RosMaster() : scratch_(MakeTempDir("rosmaster")) {
  // A port that a robot's master (11311) never has, free a moment ago; if
  // another process takes it meanwhile, the master fails and the next port
  // is tried.
  for (int attempt = 0; attempt < 5 && !process_; ++attempt) {
    const int port = FreePort();
    uri_ = "http://127.0.0.1:" + std::to_string(port) + "/";
    auto master = std::make_unique<ChildProcess>(
        std::vector<std::string>{LINEMAP_ROSMASTER_PATH, "--core", "-p", std::to_string(port), "-w",
                                 "2"},
        Env(), scratch_, "rosmaster-" + std::to_string(attempt));
    const bool up = WaitFor([&] { return Listening(port) || master->Wait(0).has_value(); }, 20.0);
    if (up && !master->Wait(0)) process_ = std::move(master);
  }
  if (!process_) throw std::runtime_error("rosmaster did not start (logs in " + scratch_ + ")");
}

std::vector<std::string> RosMaster::Env() const {
  return {"ROS_MASTER_URI=" + uri_, "ROS_IP=127.0.0.1", "ROS_HOSTNAME=127.0.0.1",
          "ROS_HOME=" + scratch_, "ROS_LOG_DIR=" + scratch_ + "/log"};
}

RosMaster& SharedMaster() {
  static RosMaster* master = [] {
    auto* m = new RosMaster();
    ros::M_string remappings = {{"__master", m->uri()}, {"__ip", "127.0.0.1"}};
    ros::init(remappings, "linemap_ros_test",
              ros::init_options::AnonymousName | ros::init_options::NoSigintHandler |
                  ros::init_options::NoRosout);
    ros::start();
    // At exit: leave ROS, then stop the master (its destructor).
    std::atexit([] {
      ros::shutdown();
      delete master;
    });
    return m;
  }();
  return *master;
}

std::string LmapServerPath() { return LINEMAP_LMAP_SERVER_PATH; }
std::string LmapSaverPath() { return LINEMAP_LMAP_SAVER_PATH; }
std::string RostopicPath() { return LINEMAP_ROSTOPIC_PATH; }

}  // namespace linemap::testing
