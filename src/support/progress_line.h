// One progress line on stderr, redrawn in place, and only when stderr is a terminal (never in logs or
// pipes): "[offsetgen mesh] sampling the narrow band [#####     ]  50%".
#pragma once

#include <string>

namespace offsetgen {

class ProgressLine {
 public:
  explicit ProgressLine(std::string prefix);  // "[offsetgen check]"
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // The stage, with a bar when fraction is in [0, 1] (negative: no fraction known).
  void show(const std::string& stage, double fraction = -1);
  void clear();  // before other output on stderr
  bool enabled() const { return enabled_; }

 private:
  std::string prefix_, last_;
  bool enabled_;
};

}  // namespace offsetgen
