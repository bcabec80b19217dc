// What an interrupted run leaves behind: nothing. Ctrl-C (SIGINT) or a scheduler's SIGTERM (Slurm at a
// job's time limit) would otherwise end the process without running destructors, leaving the
// temporary file beside the output (hundreds of MB for a mesh) and the compile scratch directories.
//
// The files being written register here while they exist; the handler that an executable installs
// removes them, says so on stderr in one line, and exits 128 + the signal (130, 143). The registry is
// fixed-size storage the handler reads with atomics only: a signal handler may not allocate or lock.
#pragma once

#include <string>

namespace offsetgen {

// Installs the handler for SIGINT and SIGTERM; `command` ("offsetgen mesh") starts its message. A
// signal the parent left ignored (nohup, a background job of a script) stays ignored.
void install_interrupt_cleanup(const char* command);

// A temporary file or scratch directory the handler removes if a signal ends the process while this
// is held. Not tracked (removed by nothing) when the registry is full or a path too long.
class RemovedOnInterrupt {
 public:
  // `temporary` is renamed over `target` (the path as the user gave it, for the message) when done.
  static RemovedOnInterrupt file(const std::string& temporary, const std::string& target, bool target_exists);
  // A directory of our own (mkdtemp): its entries are removed too, then the directory.
  static RemovedOnInterrupt directory(const std::string& path);

  RemovedOnInterrupt() = default;
  RemovedOnInterrupt(RemovedOnInterrupt&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }
  RemovedOnInterrupt& operator=(RemovedOnInterrupt&& other) noexcept;
  RemovedOnInterrupt(const RemovedOnInterrupt&) = delete;
  RemovedOnInterrupt& operator=(const RemovedOnInterrupt&) = delete;
  ~RemovedOnInterrupt() { release(); }

  // Stops tracking. Call it after the rename or removal, not before: a signal in between then finds
  // the path gone (and says nothing about it) rather than leaving the temporary behind.
  void release();

 private:
  explicit RemovedOnInterrupt(int slot) : slot_(slot) {}
  int slot_ = -1;
};

}  // namespace offsetgen
