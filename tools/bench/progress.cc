#include "tools/bench/progress.h"

#include <unistd.h>

#include <algorithm>

namespace linemap::bench {

ProgressBar::ProgressBar(std::size_t total, std::FILE* stream)
    : ProgressBar(total, stream, ::isatty(::fileno(stream)) == 1) {}

ProgressBar::ProgressBar(std::size_t total, std::FILE* stream, bool enabled)
    : total_(total), stream_(stream), enabled_(enabled) {}

ProgressBar::~ProgressBar() { Finish(); }

std::string ProgressBar::Render(std::size_t done, std::size_t total, const std::string& label,
                                int bar_width) {
  const std::size_t width = static_cast<std::size_t>(std::max(1, bar_width));
  const std::size_t filled = total == 0 ? width : std::min(width, done * width / total);
  // Appended piece by piece: GCC 12 at -O2 and above reports a false
  // -Wrestrict on chains of std::string operator+ (its bug 105329).
  std::string text = "[";
  text.append(filled, '#');
  text.append(width - filled, ' ');
  text += "] ";
  const std::string count = std::to_string(done) + "/" + std::to_string(total);
  const std::size_t count_width = 2 * std::to_string(total).size() + 1;
  text.append(count_width - std::min(count.size(), count_width), ' ');
  text += count;
  if (!label.empty()) {
    text += ' ';
    text += label;
  }
  return text;
}

void ProgressBar::Update(std::size_t done, const std::string& label) {
  if (!enabled_) return;
  std::string text = Render(done, total_, label.substr(0, 48), 30);
  const std::size_t width = text.size();
  if (width < last_width_) text += std::string(last_width_ - width, ' ');
  last_width_ = width;
  std::fprintf(stream_, "\r%s", text.c_str());
  std::fflush(stream_);
}

void ProgressBar::Finish() {
  if (!enabled_ || last_width_ == 0) return;
  std::fprintf(stream_, "\r%s\r", std::string(last_width_, ' ').c_str());
  std::fflush(stream_);
  last_width_ = 0;
}

}  // namespace linemap::bench
