#include "check/progress.h"

#include <unistd.h>

#include <cstdio>

namespace offsetgen::check {

Progress::Progress() : enabled_(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { clear(); }

void Progress::update(const std::string& stage, const std::string& detail) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r\033[K[offsetgen check] %s: %s", stage.c_str(), detail.c_str());
  std::fflush(stderr);
  dirty_ = true;
}

void Progress::clear() {
  if (!enabled_ || !dirty_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  dirty_ = false;
}

}  // namespace offsetgen::check
