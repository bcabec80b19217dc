#include "emit/file_writer.h"

#include <fmt/format.h>

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

fs::path directory_of(const std::string& path) {
  fs::path dir = fs::path(path).parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

}  // namespace

void require_writable(const std::string& path) {
  fs::path dir = directory_of(path);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw std::runtime_error(fmt::format("cannot write '{}': directory '{}' does not exist", path, dir.string()));
  }
  if (access(dir.c_str(), W_OK) != 0) {
    throw std::runtime_error(fmt::format("cannot write '{}': directory '{}' is not writable", path, dir.string()));
  }
  if (fs::exists(path, ec) && (fs::is_directory(path, ec) || access(path.c_str(), W_OK) != 0)) {
    throw std::runtime_error(fmt::format("cannot write '{}': it is a directory or read-only", path));
  }
}

bool write_file_if_changed(const std::string& path, const std::string& content) {
  {
    std::ifstream existing(path, std::ios::binary);
    if (existing) {
      std::ostringstream old;
      old << existing.rdbuf();
      if (old.str() == content) return false;
    }
  }
  write_file_atomically(path, content);
  return true;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  require_writable(path);
  std::string tmp = (directory_of(path) / ("." + fs::path(path).filename().string() + ".tmpXXXXXX")).string();
  int fd = mkstemp(tmp.data());
  if (fd < 0) throw std::runtime_error(fmt::format("cannot write '{}': {}", path, std::strerror(errno)));
  FILE* file = fdopen(fd, "wb");
  bool ok = file && std::fwrite(content.data(), 1, content.size(), file) == content.size();
  ok = file && std::fflush(file) == 0 && ok;
  if (file) std::fclose(file);
  if (ok) {
    // mkstemp creates 0600; generated sources should read like any other file.
    fs::permissions(tmp,
                    fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read);
  }
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    int err = errno;
    std::remove(tmp.c_str());
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, std::strerror(err)));
  }
}

}  // namespace offsetgen
