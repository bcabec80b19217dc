// A zip archive written entry by entry into a StreamedFile (emit/file_writer.h): stored entries (the
// PNGs are compressed already), CRC-32 from zlib, every time stamp 1980-01-01 00:00 and no extra fields,
// so the bytes depend on the contents alone. One entry may be rewritten in place later with content
// of the same length (SL1's config.ini holds totals known only at the end). No zip64: at most 65535
// entries and 4 GiB.
#pragma once

#include "emit/file_writer.h"

#include <cstdint>
#include <string>
#include <vector>

namespace offsetgen::slice {

class ZipStream {
 public:
  explicit ZipStream(const std::string& path);
  // Returns the entry's number.
  size_t add(const std::string& name, const std::string& content);
  void replace(size_t entry, const std::string& content);  // same length as before
  void finish();                                           // the central directory, then the rename
  size_t bytes() const { return file_.size(); }

 private:
  struct Entry {
    std::string name;
    uint32_t crc = 0, size = 0;
    uint64_t offset = 0;
  };
  std::string local_header(const Entry& e) const;
  // The fields a local header and the central directory's record share, from "version needed" to
  // the extra field's length.
  static void put_shared_fields(std::string& out, const Entry& e);
  StreamedFile file_;
  std::string path_;
  std::vector<Entry> entries_;
};

}  // namespace offsetgen::slice
