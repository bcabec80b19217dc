#include "support/interrupt_cleanup.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>

// The handler calls only async-signal-safe functions (unlink, unlinkat, openat, rmdir, close, write,
// _exit, and getdents64, a bare system call where opendir would allocate) and reads the registry with
// lock-free atomics. A signal between mkstemp and the
// registration, a few system calls, still leaves the temporary behind; nothing here can close that
// window without blocking the signals in every thread.
namespace offsetgen {
namespace {

// A slot's life: kFree -> kFilling -> kTracked (its owner's thread), then back to kFree by release(),
// or to kTaken by the handler. A taken slot is never freed or refilled: the process is ending, and the
// handler reads its path without a torn write from a thread that reuses it.
enum State : int { kFree, kFilling, kTracked, kTaken };
enum class Kind : unsigned char { kFile, kDirectory };
static_assert(std::atomic<int>::is_always_lock_free, "the handler reads the slots: they must not take a lock");

constexpr int kSlots = 32;  // a mesh writes one file at a time; check holds a few scratch directories
struct Slot {
  std::atomic<int> state{kFree};
  Kind kind = Kind::kFile;
  bool target_exists = false;
  char path[PATH_MAX] = {};
  char target[PATH_MAX] = {};  // as the user gave it, for the message (truncated if longer)
};
Slot slots[kSlots];  // zero-initialised static storage: no constructor runs, no page is touched at start

char command_name[64] = "offsetgen";
std::atomic<bool> handling{false};

int track(Kind kind, const std::string& path, const std::string& target, bool target_exists) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) continue;
    Slot& s = slots[i];
    s.kind = kind;
    s.target_exists = target_exists;
    std::memcpy(s.path, path.c_str(), path.size() + 1);
    const size_t n = std::min(target.size(), sizeof(s.target) - 1);
    std::memcpy(s.target, target.data(), n);
    s.target[n] = '\0';
    s.state.store(kTracked, std::memory_order_release);
    return i;
  }
  return -1;
}

// The handler's message, built without allocating (one handler runs at a time: `handling`).
char line[3 * PATH_MAX];
size_t line_size = 0;
void add(const char* text) {
  while (*text != '\0' && line_size < sizeof(line) - 1) line[line_size++] = *text++;
}

const char* file_name(const char* path) {
  const char* name = path;
  for (const char* p = path; *p != '\0'; ++p)
    if (*p == '/') name = p + 1;
  return name;
}

// Removes what directory `dir` holds, subdirectories up to `depth` levels down, without following
// symlinks (unlinkat removes a link, not its target). One buffer per level: no allocation.
constexpr int kDepth = 4;
alignas(dirent64) char entries[kDepth][4096];
void remove_entries(int dir, int depth) {
  for (;;) {
    const ssize_t n = ::getdents64(dir, entries[depth], sizeof(entries[depth]));
    if (n <= 0) return;
    for (ssize_t at = 0; at < n;) {
      const auto* e = reinterpret_cast<const dirent64*>(entries[depth] + at);
      at += e->d_reclen;
      if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
      if (::unlinkat(dir, e->d_name, 0) == 0 || errno != EISDIR || depth == 0) continue;
      const int sub = ::openat(dir, e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
      if (sub < 0) continue;
      remove_entries(sub, depth - 1);
      ::close(sub);
      ::unlinkat(dir, e->d_name, AT_REMOVEDIR);
    }
  }
}

// A few passes: a compiler this process started may still be writing into the directory.
bool remove_directory(const char* path) {
  for (int pass = 0; pass < 3; ++pass) {
    const int dir = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (dir < 0) return false;
    remove_entries(dir, kDepth - 1);
    ::close(dir);
    if (::rmdir(path) == 0) return true;
    if (errno != ENOTEMPTY && errno != EEXIST) return false;
  }
  return false;
}

void on_signal(int signo) {
  // A second signal, delivered to another thread while this one cleans up, waits for our _exit.
  if (handling.exchange(true)) {
    for (;;) ::pause();
  }
  add(command_name);
  add(signo == SIGINT ? ": interrupted (SIGINT)" : ": interrupted (SIGTERM)");
  // Take every tracked slot first (its kind and path are then stable), then remove files before
  // directories: a file's line comes first.
  bool taken[kSlots];
  for (int i = 0; i < kSlots; ++i) {
    int expected = kTracked;
    taken[i] = slots[i].state.compare_exchange_strong(expected, kTaken, std::memory_order_acquire);
  }
  const char* separator = ": ";
  for (int i = 0; i < kSlots; ++i) {
    const Slot& s = slots[i];
    if (!taken[i] || s.kind != Kind::kFile) continue;
    if (::unlink(s.path) != 0) continue;  // renamed just now: the output is complete, nothing to say
    add(separator);
    add("removed the unfinished ");
    add(file_name(s.path));
    add("; ");
    add(s.target);
    add(s.target_exists ? " is unchanged" : " was not written");
    separator = "; ";
  }
  for (int i = 0; i < kSlots; ++i) {
    const Slot& s = slots[i];
    if (!taken[i] || s.kind != Kind::kDirectory || !remove_directory(s.path)) continue;
    add(separator);
    add("removed the scratch directory ");
    add(s.path);
    separator = "; ";
  }
  line[line_size++] = '\n';
  for (size_t done = 0; done < line_size;) {
    const ssize_t n = ::write(STDERR_FILENO, line + done, line_size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  ::_exit(128 + signo);  // the shell's convention: 130 for SIGINT, 143 for SIGTERM
}

}  // namespace

void install_interrupt_cleanup(const char* command) {
  const size_t n = std::min(std::strlen(command), sizeof(command_name) - 1);
  std::memcpy(command_name, command, n);
  command_name[n] = '\0';
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);  // in this thread, one signal's cleanup at a time
  sigaddset(&action.sa_mask, SIGTERM);
  for (const int signo : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    if (::sigaction(signo, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(signo, &action, nullptr);
  }
}

RemovedOnInterrupt RemovedOnInterrupt::file(const std::string& temporary, const std::string& target,
                                            bool target_exists) {
  return RemovedOnInterrupt(track(Kind::kFile, temporary, target, target_exists));
}

RemovedOnInterrupt RemovedOnInterrupt::directory(const std::string& path) {
  return RemovedOnInterrupt(track(Kind::kDirectory, path, "", false));
}

RemovedOnInterrupt& RemovedOnInterrupt::operator=(RemovedOnInterrupt&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

void RemovedOnInterrupt::release() {
  if (slot_ < 0) return;
  int expected = kTracked;
  // Fails only when the handler took the slot: it is ending the process and owns the slot now.
  slots[slot_].state.compare_exchange_strong(expected, kFree, std::memory_order_acq_rel);
  slot_ = -1;
}

}  // namespace offsetgen
