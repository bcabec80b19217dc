#include "emit/file_writer.h"

#include "support/interrupt_cleanup.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace offsetgen {
namespace fs = std::filesystem;

namespace {

constexpr int kMaxSymlinkHops = 40;  // as the kernel's ELOOP limit

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(fmt::format("cannot write '{}': {}", path, why));
}

const char* type_name(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Paths that stand for file descriptors or process state rather than files: writing "through" them
// would replace a system file or a descriptor's target. Stdout is `-o -`.
bool is_descriptor_path(const fs::path& p) {
  const std::string s = fs::absolute(p).lexically_normal().string();
  return s.rfind("/proc/", 0) == 0 || s.rfind("/dev/fd/", 0) == 0 || s == "/dev/stdout" || s == "/dev/stderr" ||
         s == "/dev/stdin" || s == "/dev/tty";
}

// Where the bytes of `given` go: the file at the end of its symlink chain.
struct Destination {
  fs::path path;
  bool exists = false;
  struct stat st {};
};

Destination resolve(const std::string& given) {
  if (given.empty()) fail(given, "the path is empty");
  Destination d;
  d.path = given;
  for (int hops = 0;; ++hops) {
    if (is_descriptor_path(d.path))
      fail(given, "it is a device or descriptor path, not a file; write to stdout with `-o -`");
    struct stat link {};
    if (::lstat(d.path.c_str(), &link) != 0) {
      if (errno == ENOENT) break;  // a new file (also the end of a dangling symlink)
      fail(given, std::strerror(errno));
    }
    if (!S_ISLNK(link.st_mode)) {
      d.exists = true;
      d.st = link;
      break;
    }
    if (hops == kMaxSymlinkHops) fail(given, "too many levels of symbolic links");
    std::error_code ec;
    const fs::path target = fs::read_symlink(d.path, ec);
    if (ec) fail(given, ec.message());
    d.path = target.is_absolute() ? target : d.path.parent_path() / target;
  }
  if (d.exists && !S_ISREG(d.st.st_mode))
    fail(given, fmt::format("it is {}; offsetgen writes only regular files{}", type_name(d.st.st_mode),
                            S_ISDIR(d.st.st_mode) ? "" : " (stdout is `-o -`)"));
  return d;
}

fs::path directory_of(const fs::path& path) {
  fs::path dir = path.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

// The process umask, read without changing it (umask(2) can only set it, which races with threads).
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8));
  }
  return 022;
}

bool write_all(int fd, const std::string& content) {
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// Rewrites the file itself: its inode, links, owner and mode stay.
void write_in_place(const std::string& given, const Destination& d, const std::string& content) {
  const int fd = ::open(d.path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) fail(given, std::strerror(errno));
  const bool ok = write_all(fd, content);
  const int err = errno;
  if (::close(fd) != 0 || !ok) fail(given, std::strerror(ok ? errno : err));
}

// Writes a temporary file beside the target and renames it over the target. Returns false (having
// removed the temporary) when the existing file's owner cannot be given to the new one.
bool write_by_rename(const std::string& given, const Destination& d, const std::string& content) {
  std::string tmp = (directory_of(d.path) / ("." + d.path.filename().string() + ".tmpXXXXXX")).string();
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) fail(given, std::strerror(errno));
  // Released on every way out, after the rename or the unlink.
  const RemovedOnInterrupt tracked = RemovedOnInterrupt::file(tmp, given, d.exists);
  auto abandon = [&](int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    return err;
  };
  if (d.exists && ::fchown(fd, d.st.st_uid, d.st.st_gid) != 0) {
    abandon(errno);
    return false;
  }
  const mode_t mode = d.exists ? (d.st.st_mode & 07777) : (0666 & ~current_umask());
  if (::fchmod(fd, mode) != 0 || !write_all(fd, content)) fail(given, std::strerror(abandon(errno)));
  if (::close(fd) != 0 || std::rename(tmp.c_str(), d.path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(given, std::strerror(err));
  }
  return true;
}

}  // namespace

void require_writable(const std::string& path) {
  const Destination d = resolve(path);
  const fs::path dir = directory_of(d.path);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail(path, fmt::format("directory '{}' does not exist", dir.string()));
  const bool dir_writable = ::access(dir.c_str(), W_OK) == 0;
  if (d.exists && ::access(d.path.c_str(), W_OK) != 0) fail(path, "the file is read-only");
  if (!d.exists && !dir_writable) fail(path, fmt::format("directory '{}' is not writable", dir.string()));
}

void require_distinct(const std::vector<std::string>& paths) {
  for (size_t i = 0; i < paths.size(); ++i) {
    for (size_t j = i + 1; j < paths.size(); ++j) {
      const Destination a = resolve(paths[i]), b = resolve(paths[j]);
      std::error_code ec;
      const bool same_name = fs::weakly_canonical(a.path, ec) == fs::weakly_canonical(b.path, ec);
      const bool same_file = a.exists && b.exists && a.st.st_dev == b.st.st_dev && a.st.st_ino == b.st.st_ino;
      if (same_name || same_file)
        throw std::runtime_error(
            fmt::format("'{}' and '{}' are the same file: one output would overwrite the other", paths[i], paths[j]));
    }
  }
}

bool write_file_if_changed(const std::string& path, const std::string& content) {
  const Destination d = resolve(path);
  if (d.exists) {
    std::ifstream existing(d.path, std::ios::binary);
    if (existing) {
      std::ostringstream old;
      old << existing.rdbuf();
      if (old.str() == content) return false;
    }
  }
  write_file(path, content);
  return true;
}

StreamedFile::StreamedFile(const std::string& path) : path_(path) {
  const Destination d = resolve(path);
  require_writable(path);
  target_ = d.path.string();
  temporary_ = (directory_of(d.path) / ("." + d.path.filename().string() + ".tmpXXXXXX")).string();
  fd_ = ::mkstemp(temporary_.data());
  if (fd_ < 0) fail(path, std::strerror(errno));
  tracked_ = RemovedOnInterrupt::file(temporary_, path, d.exists);
  const mode_t mode = d.exists ? (d.st.st_mode & 07777) : (0666 & ~current_umask());
  if (::fchmod(fd_, mode) != 0) {
    const int err = errno;  // the destructor does not run for a constructor that throws
    ::close(fd_);
    ::unlink(temporary_.c_str());
    fail(path, std::strerror(err));
  }
}

// tracked_ is released after this body, so after the unlink.
StreamedFile::~StreamedFile() {
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(temporary_.c_str());
  }
}

void StreamedFile::append(const std::string& bytes) {
  if (!write_all(fd_, bytes)) {
    const int err = errno;
    if (err == ENOSPC || err == EDQUOT)
      throw ResourceError(
          fmt::format("cannot write '{}': the disk is full after {:.1f} MB; free space there, or "
                      "write elsewhere (the partial file is removed)",
                      path_, double(size_) / 1e6));
    fail(path_, std::strerror(err));
  }
  size_ += bytes.size();
}

void StreamedFile::overwrite(size_t offset, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(path_, std::strerror(errno));
    done += static_cast<size_t>(n);
  }
}

void StreamedFile::commit() {
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 || std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int err = errno;
    ::unlink(temporary_.c_str());
    tracked_.release();
    fail(path_, std::strerror(err));
  }
  tracked_.release();
}

void write_file(const std::string& path, const std::string& content) {
  const Destination d = resolve(path);
  require_writable(path);
  const bool dir_writable = ::access(directory_of(d.path).c_str(), W_OK) == 0;
  const bool keep_links = d.exists && d.st.st_nlink > 1;
  if (!dir_writable || keep_links || !write_by_rename(path, d, content)) write_in_place(path, d, content);
}

}  // namespace offsetgen
