// Writing generated files: atomically, only when the bytes change, and never over anything that is
// not a regular file.
//
// The rules, for every file offsetgen writes (headers, snippets, check's --json and --plot):
//   - only regular files are written: a directory, device node, FIFO or socket is refused with a
//     message, and so is a path that leads into /dev or /proc (stdout is `-o -`, nothing else);
//   - a symlink is written through: its target gets the new bytes, the link stays;
//   - an existing file keeps its mode and owner; a new one gets 0666 less the umask;
//   - the new bytes go to a temporary file beside the target and are renamed over it, so a reader
//     never sees half a file. A file with other hard links, or whose owner this process cannot give
//     to a new file, is rewritten in place instead, so the links and the owner stay;
//   - a file that already holds exactly the new bytes is left alone (timestamp included), so build
//     systems do not rebuild dependants for nothing.
#pragma once

#include "support/interrupt_cleanup.h"

#include <string>
#include <vector>

namespace offsetgen {

// Writes `content` to `path` by the rules above. Returns true when the file was written. Throws
// std::runtime_error naming the path on failure.
bool write_file_if_changed(const std::string& path, const std::string& content);

// The same rules without the comparison, for large outputs such as meshes, where reading the old file
// back would cost as much as writing it: always writes.
void write_file(const std::string& path, const std::string& content);

// A large file written in pieces (a mesh streamed tile by tile): to a temporary file beside `path`,
// renamed over it by commit(), so a reader never sees half a file and a failed run leaves nothing
// (the destructor removes the temporary; so does a SIGINT or SIGTERM where the executable installed
// install_interrupt_cleanup). Only regular files, as above; an existing file's mode is
// kept. Errors (a full disk among them) throw std::runtime_error naming the path and the reason.
class StreamedFile {
 public:
  explicit StreamedFile(const std::string& path);
  ~StreamedFile();
  StreamedFile(const StreamedFile&) = delete;
  StreamedFile& operator=(const StreamedFile&) = delete;

  void append(const std::string& bytes);
  void overwrite(size_t offset, const std::string& bytes);  // within what was appended
  size_t size() const { return size_; }
  void commit();

 private:
  std::string path_, target_, temporary_;
  int fd_ = -1;
  size_t size_ = 0;
  RemovedOnInterrupt tracked_;  // the temporary, for a SIGINT or SIGTERM before commit()
};

// Throws std::runtime_error if `path` could not be written by write_file_if_changed (missing or
// read-only directory, not a regular file, a device path), without creating anything. Lets a run fail
// before its long work and before it writes its first file.
void require_writable(const std::string& path);

// Throws std::runtime_error when two of `paths` name the same file (also through symlinks, hard
// links or spellings such as ./a and a), which would make one output overwrite the other.
void require_distinct(const std::vector<std::string>& paths);

}  // namespace offsetgen
