// Progress lines for long runs, on stderr and only when stderr is a terminal (never in logs/pipes).
#pragma once

#include <string>

namespace offsetgen::check {

class Progress {
 public:
  Progress();  // enabled iff stderr is a tty
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void update(const std::string& stage, const std::string& detail);
  void clear();
  bool enabled() const { return enabled_; }

 private:
  bool enabled_;
  bool dirty_ = false;
};

}  // namespace offsetgen::check
