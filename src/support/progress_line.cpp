#include "support/progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace offsetgen {

ProgressLine::ProgressLine(std::string prefix) : prefix_(std::move(prefix)), enabled_(::isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::show(const std::string& stage, double fraction) {
  if (!enabled_) return;
  std::string line = prefix_ + " " + stage;
  if (fraction >= 0) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kWidth);
    char percent[8];
    std::snprintf(percent, sizeof(percent), "%3.0f%%", 100 * std::clamp(fraction, 0.0, 1.0));
    line += " [" + std::string(static_cast<size_t>(filled), '#') +
            std::string(static_cast<size_t>(kWidth - filled), ' ') + "] " + percent;
  }
  if (line == last_) return;
  last_ = line;
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
  std::fflush(stderr);
}

void ProgressLine::clear() {
  if (!enabled_ || last_.empty()) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  last_.clear();
}

}  // namespace offsetgen
