// A one-line progress bar on stderr, drawn only when stderr is a terminal
// (so logs and pipes stay clean).
#ifndef LINEMAP_TOOLS_BENCH_PROGRESS_H_
#define LINEMAP_TOOLS_BENCH_PROGRESS_H_

#include <cstdio>
#include <string>

namespace linemap::bench {

class ProgressBar {
 public:
  // `total` steps; enabled when `stream` is a terminal.
  ProgressBar(std::size_t total, std::FILE* stream = stderr);
  ProgressBar(std::size_t total, std::FILE* stream, bool enabled);
  ~ProgressBar();

  // Shows step `done` of `total` and what is being worked on.
  void Update(std::size_t done, const std::string& label);
  // Erases the bar (call before printing results).
  void Finish();

  bool enabled() const { return enabled_; }
  // The text of the bar, without the carriage return: "[####    ]  3/8 label".
  static std::string Render(std::size_t done, std::size_t total, const std::string& label,
                            int bar_width);

 private:
  std::size_t total_;
  std::FILE* stream_;
  bool enabled_;
  std::size_t last_width_ = 0;
};

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_PROGRESS_H_
