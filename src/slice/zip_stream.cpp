#include "slice/zip_stream.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>
#include <zlib.h>

#include <limits>

namespace offsetgen::slice {
namespace {

constexpr uint16_t kDosTime = 0;           // 00:00:00
constexpr uint16_t kDosDate = 1 << 5 | 1;  // 1980-01-01

void put16(std::string& out, uint32_t v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>((v >> 8) & 0xff));
}
void put32(std::string& out, uint64_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

uint32_t crc_of(const std::string& s) {
  uLong crc = crc32(0L, Z_NULL, 0);
  size_t done = 0;
  while (done < s.size()) {
    const auto chunk = static_cast<uInt>(std::min<size_t>(s.size() - done, 1u << 30));
    crc = crc32(crc, reinterpret_cast<const Bytef*>(s.data() + done), chunk);
    done += chunk;
  }
  return static_cast<uint32_t>(crc);
}

}  // namespace

ZipStream::ZipStream(const std::string& path) : file_(path), path_(path) {}

void ZipStream::put_shared_fields(std::string& out, const Entry& e) {
  put16(out, 10);  // version needed: stored
  put16(out, 0);   // flags
  put16(out, 0);   // stored
  put16(out, kDosTime);
  put16(out, kDosDate);
  put32(out, e.crc);
  put32(out, e.size);
  put32(out, e.size);
  put16(out, static_cast<uint32_t>(e.name.size()));
  put16(out, 0);  // extra
}

std::string ZipStream::local_header(const Entry& e) const {
  std::string h;
  put32(h, 0x04034b50);
  put_shared_fields(h, e);
  h += e.name;
  return h;
}

size_t ZipStream::add(const std::string& name, const std::string& content) {
  if (entries_.size() >= 0xffff)
    throw InputError(fmt::format("{}: more than 65535 entries (layers) in one archive", path_));
  if (content.size() >= std::numeric_limits<uint32_t>::max() ||
      file_.size() + content.size() >= std::numeric_limits<uint32_t>::max())
    throw InputError(fmt::format("{}: the archive would pass 4 GiB (zip64 is not written)", path_));
  Entry e;
  e.name = name;
  e.crc = crc_of(content);
  e.size = static_cast<uint32_t>(content.size());
  e.offset = file_.size();
  file_.append(local_header(e));
  file_.append(content);
  entries_.push_back(e);
  return entries_.size() - 1;
}

void ZipStream::replace(size_t entry, const std::string& content) {
  Entry& e = entries_.at(entry);
  if (content.size() != e.size) throw std::logic_error("ZipStream::replace: the content's length changed");
  e.crc = crc_of(content);
  const std::string header = local_header(e);
  file_.overwrite(e.offset, header);
  file_.overwrite(e.offset + header.size(), content);
}

void ZipStream::finish() {
  const uint64_t start = file_.size();
  std::string dir;
  for (const Entry& e : entries_) {
    put32(dir, 0x02014b50);
    put16(dir, 20);  // made by: MS-DOS attributes, zip 2.0
    put_shared_fields(dir, e);
    put16(dir, 0);  // comment
    put16(dir, 0);  // disk
    put16(dir, 0);  // internal attributes
    put32(dir, 0);  // external attributes
    put32(dir, e.offset);
    dir += e.name;
  }
  const uint64_t directory = dir.size();
  put32(dir, 0x06054b50);  // the end record
  put16(dir, 0);
  put16(dir, 0);
  put16(dir, static_cast<uint32_t>(entries_.size()));
  put16(dir, static_cast<uint32_t>(entries_.size()));
  put32(dir, directory);
  put32(dir, start);
  put16(dir, 0);
  file_.append(dir);
  file_.commit();
}

}  // namespace offsetgen::slice
