#include "body/body_files.h"

#include "support/point.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <system_error>

#ifdef OFFSETGEN_HAVE_LIB3MF
#include <Model/COM/NMR_DLLInterfaces.h>
#endif

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "binary STL and PLY are read by memcpy on a little-endian host");

namespace offsetgen::body {
namespace {

// Triangles are numbered with one bit to spare in body_topology.cpp.
constexpr size_t kMaxTriangles = (size_t(1) << 31) - 1;

[[noreturn]] void fail(const std::string& name, const std::string& where, const std::string& what) {
  throw InputError(fmt::format("{}: {}: {}", name, where, what));
}

// A token of the file for a message: printable ASCII, at most 40 characters.
std::string quoted(std::string_view token) {
  std::string out = "'";
  for (size_t i = 0; i < token.size() && i < 40; ++i) out += (token[i] >= 0x20 && token[i] < 0x7f) ? token[i] : '?';
  if (token.size() > 40) out += "...";
  return out + "'";
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

bool equals_nocase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

bool starts_with_nocase(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() && equals_nocase(text.substr(0, prefix.size()), prefix);
}

// std::from_chars, which is locale-free but refuses a leading '+'.
bool parse_number(std::string_view token, double& out) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), out);
  return ec == std::errc() && end == token.data() + token.size();
}

bool parse_integer(std::string_view token, int64_t& out) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), out);
  return ec == std::errc() && end == token.data() + token.size();
}

// Welds points by exact position (an open-addressing table of point indices) and collects triangles;
// polygons become fans.
class MeshBuilder {
 public:
  explicit MeshBuilder(const std::string& name) : name_(name) {}

  uint32_t point(Point p) {
    for (double& x : p)
      if (x == 0) x = 0;  // -0 and +0 are one position
    if (2 * (mesh_.points.size() + 1) > slots_.size()) grow();
    size_t i = hash(p) & mask_;
    for (; slots_[i] != 0; i = (i + 1) & mask_)
      if (mesh_.points[slots_[i] - 1] == p) return slots_[i] - 1;
    if (mesh_.points.size() >= std::numeric_limits<uint32_t>::max() - 1)
      throw InputError(
          fmt::format("{}: more than {} distinct points", name_, std::numeric_limits<uint32_t>::max() - 1));
    mesh_.points.push_back(p);
    slots_[i] = static_cast<uint32_t>(mesh_.points.size());
    return slots_[i] - 1;
  }

  // Corners already welded; a polygon of n corners gives n - 2 triangles (0, i, i + 1).
  void polygon(const uint32_t* corners, size_t n) {
    for (size_t i = 1; i + 1 < n; ++i) {
      if (mesh_.triangles.size() >= kMaxTriangles)
        throw InputError(fmt::format("{}: more than {} triangles", name_, kMaxTriangles));
      mesh_.triangles.push_back({corners[0], corners[i], corners[i + 1]});
    }
  }

  void reserve_triangles(size_t n) { mesh_.triangles.reserve(std::min(n, kMaxTriangles)); }

  BodyMesh finish() {
    if (mesh_.triangles.empty()) throw InputError(fmt::format("{}: no triangles", name_));
    return std::move(mesh_);
  }

 private:
  static uint64_t mix(uint64_t z) {  // splitmix64's finaliser
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  static uint64_t hash(const Point& p) {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (double x : p) {
      uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = mix(h ^ bits);
    }
    return h;
  }
  void grow() {
    slots_.assign(std::max<size_t>(64, 2 * slots_.size()), 0);
    mask_ = slots_.size() - 1;
    for (size_t j = 0; j < mesh_.points.size(); ++j) {
      size_t i = hash(mesh_.points[j]) & mask_;
      while (slots_[i] != 0) i = (i + 1) & mask_;
      slots_[i] = static_cast<uint32_t>(j + 1);
    }
  }

  const std::string& name_;
  BodyMesh mesh_;
  std::vector<uint32_t> slots_;  // 0: empty, else point index + 1
  size_t mask_ = 0;
};

// Points of an indexed file (PLY, OBJ) welded on first use, so unused ones are dropped.
class IndexedPoints {
 public:
  IndexedPoints(MeshBuilder& builder, const std::vector<Point>& points)
      : builder_(builder), points_(points), welded_(points.size(), kNone) {}
  uint32_t operator()(size_t i) {
    if (welded_[i] == kNone) welded_[i] = builder_.point(points_[i]);
    return welded_[i];
  }

 private:
  static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  MeshBuilder& builder_;
  const std::vector<Point>& points_;
  std::vector<uint32_t> welded_;
};

// ---- text ----

// Whitespace-separated tokens with the line each starts on.
class Tokens {
 public:
  explicit Tokens(std::string_view text, size_t start = 0) : text_(text), pos_(start) {}
  // The next token, empty at the end.
  std::string_view next() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    token_line_ = line_;
    const size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  std::string where() const { return fmt::format("line {}", token_line_); }
  void set_line(size_t line) { line_ = token_line_ = line; }
  size_t remaining() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t line_ = 1, token_line_ = 1;
};

// ---- STL ----

Point read_vertex(Tokens& tokens, const std::string& name) {
  Point p{};
  for (double& x : p) {
    const std::string_view token = tokens.next();
    if (!parse_number(token, x))
      fail(name, tokens.where(), fmt::format("expected 'vertex x y z', found {}", quoted(token)));
    if (!std::isfinite(x)) fail(name, tokens.where(), fmt::format("coordinate {} is not finite", quoted(token)));
  }
  return p;
}

BodyMesh parse_ascii_stl(std::string_view text, const std::string& name) {
  MeshBuilder builder(name);
  Tokens tokens(text);
  std::string_view token = tokens.next();
  if (!starts_with_nocase(token, "solid")) fail(name, tokens.where(), "expected 'solid'");
  tokens.skip_line();  // the solid's name
  std::vector<uint32_t> corners;
  for (;;) {
    token = tokens.next();
    if (token.empty()) fail(name, tokens.where(), "unexpected end of file: expected 'endsolid'");
    if (starts_with_nocase(token, "endsolid")) {
      tokens.skip_line();
      token = tokens.next();
      if (token.empty()) break;
      // Some exporters write one solid per part into one file: they are one body.
      if (!starts_with_nocase(token, "solid"))
        fail(name, tokens.where(), fmt::format("expected 'solid' or the end of the file, found {}", quoted(token)));
      tokens.skip_line();
      continue;
    }
    if (!equals_nocase(token, "facet"))
      fail(name, tokens.where(), fmt::format("expected 'facet' or 'endsolid', found {}", quoted(token)));
    token = tokens.next();
    if (equals_nocase(token, "normal")) {
      // The normal is not used (the order of the vertices decides); it may even be nan.
      for (int k = 0; k < 3; ++k) {
        double ignored;
        token = tokens.next();
        if (!parse_number(token, ignored))
          fail(name, tokens.where(), fmt::format("expected 'normal nx ny nz', found {}", quoted(token)));
      }
      token = tokens.next();
    }
    if (!equals_nocase(token, "outer") || !equals_nocase(tokens.next(), "loop"))
      fail(name, tokens.where(), "expected 'outer loop'");
    corners.clear();
    while (equals_nocase(token = tokens.next(), "vertex")) corners.push_back(builder.point(read_vertex(tokens, name)));
    if (!equals_nocase(token, "endloop"))
      fail(name, tokens.where(), fmt::format("expected 'vertex x y z' or 'endloop', found {}", quoted(token)));
    if (corners.size() < 3)
      fail(name, tokens.where(), fmt::format("a facet with {} vertices (it needs 3)", corners.size()));
    if (!equals_nocase(tokens.next(), "endfacet")) fail(name, tokens.where(), "expected 'endfacet'");
    builder.polygon(corners.data(), corners.size());
  }
  return builder.finish();
}

BodyMesh parse_binary_stl(std::string_view bytes, const std::string& name) {
  if (bytes.size() < 84)
    fail(name, fmt::format("byte {}", bytes.size()),
         fmt::format("truncated binary STL: {} bytes, less than its 80-byte header and facet count", bytes.size()));
  uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  const uint64_t needed = 84 + 50 * uint64_t(count);
  if (needed > bytes.size())
    fail(name, fmt::format("byte {}", bytes.size()),
         fmt::format("truncated binary STL: its count of {} facets needs {} bytes, the file has {}", count, needed,
                     bytes.size()));
  if (needed < bytes.size())
    fail(name, fmt::format("byte {}", needed),
         fmt::format("{} bytes after the last of the {} facets of this binary STL (damaged, or not an STL)",
                     bytes.size() - needed, count));
  MeshBuilder builder(name);
  builder.reserve_triangles(count);
  for (uint32_t i = 0; i < count; ++i) {
    const size_t offset = 84 + 50 * size_t(i);
    float record[12];  // normal, then three vertices
    std::memcpy(record, bytes.data() + offset, sizeof record);
    uint32_t corners[3];
    for (size_t v = 0; v < 3; ++v) {
      const Point p{record[3 + 3 * v], record[4 + 3 * v], record[5 + 3 * v]};
      for (size_t k = 0; k < 3; ++k)
        if (!std::isfinite(p[k]))
          fail(name, fmt::format("byte {}", offset + 12 + 12 * v + 4 * k),
               fmt::format("facet {}: a coordinate is not finite ({})", i, p[k]));
      corners[v] = builder.point(p);
    }
    builder.polygon(corners, 3);
  }
  return builder.finish();
}

BodyMesh parse_stl(std::string_view bytes, const std::string& name) {
  // A binary STL's 80-byte header may start with "solid" too (some exporters do that): the exact
  // size of a binary file decides first.
  if (bytes.size() >= 84) {
    uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (84 + 50 * uint64_t(count) == bytes.size()) return parse_binary_stl(bytes, name);
  }
  size_t start = 0;
  while (start < bytes.size() && is_space(bytes[start])) ++start;
  if (!starts_with_nocase(bytes.substr(start), "solid")) return parse_binary_stl(bytes, name);
  try {
    return parse_ascii_stl(bytes, name);
  } catch (const InputError&) {
    // Control bytes say it is a binary STL (of the wrong size) whose header says "solid".
    const std::string_view head = bytes.substr(0, 1024);
    const bool binary = std::any_of(head.begin(), head.end(), [](char c) {
      return (static_cast<unsigned char>(c) < 0x20 && !is_space(c)) || c == 0x7f;
    });
    if (binary) return parse_binary_stl(bytes, name);
    throw;
  }
}

// ---- PLY ----

enum class Scalar { I8, U8, I16, U16, I32, U32, F32, F64 };

size_t scalar_size(Scalar s) {
  switch (s) {
    case Scalar::I8:
    case Scalar::U8:
      return 1;
    case Scalar::I16:
    case Scalar::U16:
      return 2;
    case Scalar::I32:
    case Scalar::U32:
    case Scalar::F32:
      return 4;
    case Scalar::F64:
      return 8;
  }
  return 1;
}

bool is_integer(Scalar s) { return s != Scalar::F32 && s != Scalar::F64; }

bool scalar_from_name(std::string_view word, Scalar& out) {
  static const std::pair<const char*, Scalar> names[] = {
      {"char", Scalar::I8},   {"int8", Scalar::I8},     {"uchar", Scalar::U8},   {"uint8", Scalar::U8},
      {"short", Scalar::I16}, {"int16", Scalar::I16},   {"ushort", Scalar::U16}, {"uint16", Scalar::U16},
      {"int", Scalar::I32},   {"int32", Scalar::I32},   {"uint", Scalar::U32},   {"uint32", Scalar::U32},
      {"float", Scalar::F32}, {"float32", Scalar::F32}, {"double", Scalar::F64}, {"float64", Scalar::F64}};
  for (const auto& [n, s] : names)
    if (word == n) {
      out = s;
      return true;
    }
  return false;
}

struct PlyProperty {
  std::string name;
  bool list = false;
  Scalar count_type = Scalar::U8;
  Scalar type = Scalar::F32;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  size_t line = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  size_t data_start = 0;  // byte offset of the first byte after end_header's line
  size_t data_line = 0;   // line number of the first data line (ASCII)
};

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name) {
  PlyHeader header;
  size_t pos = 0, line_number = 0;
  bool have_format = false;
  for (;;) {
    if (pos >= bytes.size()) fail(name, fmt::format("line {}", line_number), "the header has no 'end_header'");
    const size_t end = std::min(bytes.find('\n', pos), bytes.size());
    const std::string_view line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    const std::string where = fmt::format("line {}", line_number);
    const std::vector<std::string_view> w = words(line);
    if (line_number == 1) {
      if (w.size() != 1 || w[0] != "ply") fail(name, where, "not a PLY file (it must start with 'ply')");
      continue;
    }
    if (w.empty()) continue;
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") {
      header.data_start = std::min(pos, bytes.size());
      header.data_line = line_number + 1;
      break;
    }
    if (w[0] == "format") {
      if (w.size() != 3) fail(name, where, "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if (w[1] == "ascii")
        header.format = PlyFormat::Ascii;
      else if (w[1] == "binary_little_endian")
        header.format = PlyFormat::LittleEndian;
      else if (w[1] == "binary_big_endian")
        header.format = PlyFormat::BigEndian;
      else
        fail(name, where, fmt::format("unknown PLY format {}", quoted(w[1])));
      have_format = true;
    } else if (w[0] == "element") {
      int64_t count = 0;
      if (w.size() != 3 || !parse_integer(w[2], count) || count < 0)
        fail(name, where, "expected 'element <name> <count>'");
      header.elements.push_back({std::string(w[1]), uint64_t(count), line_number, {}});
    } else if (w[0] == "property") {
      if (header.elements.empty()) fail(name, where, "a property before any element");
      PlyProperty property;
      if (w.size() == 5 && w[1] == "list") {
        property.list = true;
        if (!scalar_from_name(w[2], property.count_type) || !scalar_from_name(w[3], property.type))
          fail(name, where, fmt::format("unknown property type in {}", quoted(line)));
        if (!is_integer(property.count_type))
          fail(name, where, fmt::format("a list whose count is not an integer type: {}", quoted(line)));
        property.name = std::string(w[4]);
      } else if (w.size() == 3) {
        if (!scalar_from_name(w[1], property.type))
          fail(name, where, fmt::format("unknown property type {}", quoted(w[1])));
        property.name = std::string(w[2]);
      } else {
        fail(name, where, "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      }
      header.elements.back().properties.push_back(property);
    } else {
      fail(name, where, fmt::format("unknown header line {}", quoted(line)));
    }
  }
  if (!have_format) fail(name, "line 2", "the header has no 'format' line");
  return header;
}

// Reads the data section: scalars as int64 or double, each with where it is for messages.
class PlyAsciiReader {
 public:
  PlyAsciiReader(std::string_view bytes, const PlyHeader& header, const std::string& name)
      : tokens_(bytes, header.data_start), name_(name) {
    tokens_.set_line(header.data_line);
  }
  int64_t integer(Scalar) {
    const std::string_view token = next();
    int64_t value;
    if (!parse_integer(token, value))
      fail(name_, tokens_.where(), fmt::format("expected an integer, found {}", quoted(token)));
    return value;
  }
  double real(Scalar type) {
    if (is_integer(type)) return static_cast<double>(integer(type));
    const std::string_view token = next();
    double value;
    if (!parse_number(token, value))
      fail(name_, tokens_.where(), fmt::format("expected a number, found {}", quoted(token)));
    return value;
  }
  void skip(Scalar type) { real(type); }
  // Where a value is, for a message: taken before it is read (cheaply), named after (its line).
  size_t mark() const { return 0; }
  std::string at(size_t) const { return tokens_.where(); }
  // Each value is a token and a separator: at least two bytes.
  uint64_t capacity() const { return tokens_.remaining() / 2 + 1; }

 private:
  std::string_view next() {
    const std::string_view token = tokens_.next();
    if (token.empty()) fail(name_, tokens_.where(), "unexpected end of file in the PLY data");
    return token;
  }
  Tokens tokens_;
  const std::string& name_;
};

class PlyBinaryReader {
 public:
  PlyBinaryReader(std::string_view bytes, const PlyHeader& header, const std::string& name)
      : bytes_(bytes), pos_(header.data_start), swap_(header.format == PlyFormat::BigEndian), name_(name) {}
  int64_t integer(Scalar type) {
    switch (type) {
      case Scalar::I8:
        return load<int8_t>();
      case Scalar::U8:
        return load<uint8_t>();
      case Scalar::I16:
        return load<int16_t>();
      case Scalar::U16:
        return load<uint16_t>();
      case Scalar::I32:
        return load<int32_t>();
      case Scalar::U32:
        return load<uint32_t>();
      case Scalar::F32:
      case Scalar::F64:
        break;
    }
    fail(name_, at(pos_), "an integer of a floating-point type");  // the header check rules this out
  }
  double real(Scalar type) {
    if (type == Scalar::F32) return load<float>();
    if (type == Scalar::F64) return load<double>();
    return static_cast<double>(integer(type));
  }
  void skip(Scalar type) {
    require(scalar_size(type));
    pos_ += scalar_size(type);
  }
  size_t mark() const { return pos_; }
  std::string at(size_t mark) const { return fmt::format("byte {}", mark); }
  uint64_t capacity() const { return bytes_.size() - pos_; }

 private:
  void require(size_t n) {
    if (bytes_.size() - pos_ < n) fail(name_, at(pos_), "unexpected end of file in the PLY data");
  }
  template <typename T>
  T load() {
    require(sizeof(T));
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + pos_, sizeof(T));
    if (swap_) std::reverse(raw, raw + sizeof(T));
    pos_ += sizeof(T);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }
  std::string_view bytes_;
  size_t pos_;
  bool swap_;
  const std::string& name_;
};

struct PlyLayout {
  size_t vertex_element = SIZE_MAX, face_element = SIZE_MAX;
  size_t xyz[3] = {SIZE_MAX, SIZE_MAX, SIZE_MAX};  // property indices in the vertex element
  size_t indices = SIZE_MAX;                       // the list property in the face element
};

PlyLayout ply_layout(const PlyHeader& header, const std::string& name) {
  PlyLayout layout;
  for (size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    const std::string where = fmt::format("line {}", element.line);
    if (element.name == "vertex") {
      if (layout.vertex_element != SIZE_MAX) fail(name, where, "a second 'vertex' element");
      layout.vertex_element = e;
      for (size_t p = 0; p < element.properties.size(); ++p)
        for (size_t k = 0; k < 3; ++k)
          if (element.properties[p].name == std::string(1, char('x' + k))) {
            if (element.properties[p].list) fail(name, where, "the vertex coordinates are lists");
            layout.xyz[k] = p;
          }
      for (size_t k = 0; k < 3; ++k)
        if (layout.xyz[k] == SIZE_MAX)
          fail(name, where, fmt::format("the vertex element has no property '{}'", char('x' + k)));
    } else if (element.name == "face") {
      if (layout.face_element != SIZE_MAX) fail(name, where, "a second 'face' element");
      layout.face_element = e;
      for (size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.name == "vertex_indices" || property.name == "vertex_index") {
          if (!property.list || !is_integer(property.type))
            fail(name, where, fmt::format("'{}' must be a list of integers", property.name));
          layout.indices = p;
        }
      }
      if (layout.indices == SIZE_MAX) fail(name, where, "the face element has no 'vertex_indices' list");
    }
  }
  if (layout.vertex_element == SIZE_MAX) fail(name, "header", "no 'vertex' element");
  if (layout.face_element == SIZE_MAX) fail(name, "header", "no triangles (no 'face' element)");
  return layout;
}

template <typename Reader>
BodyMesh read_ply_data(Reader& reader, const PlyHeader& header, const PlyLayout& layout, const std::string& name) {
  const uint64_t vertex_count = header.elements[layout.vertex_element].count;
  if (vertex_count > std::numeric_limits<uint32_t>::max())
    fail(name, fmt::format("line {}", header.elements[layout.vertex_element].line),
         fmt::format("{} vertices, more than 32-bit indices reach", vertex_count));
  std::vector<Point> points;
  std::vector<uint32_t> corners;  // of every face, one after the other
  std::vector<size_t> face_ends;  // where each face's corners end in `corners`
  for (size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    if (element.properties.empty()) continue;
    // Every instance takes at least one value, so a count the data cannot hold is refused before
    // anything is allocated for it.
    if (element.count > reader.capacity())
      fail(name, fmt::format("line {}", element.line),
           fmt::format("{} {} elements, more than the rest of the file can hold", element.count, element.name));
    const bool is_vertex = e == layout.vertex_element, is_face = e == layout.face_element;
    if (is_vertex) points.reserve(element.count);
    if (is_face) face_ends.reserve(element.count);
    for (uint64_t i = 0; i < element.count; ++i) {
      Point p{};
      for (size_t q = 0; q < element.properties.size(); ++q) {
        const PlyProperty& property = element.properties[q];
        if (property.list) {
          const size_t mark = reader.mark();
          const int64_t n = reader.integer(property.count_type);
          if (n < 0) fail(name, reader.at(mark), fmt::format("a list of {} items", n));
          const bool indices = is_face && q == layout.indices;
          if (indices && n < 3) fail(name, reader.at(mark), fmt::format("face {}: {} vertices (a face needs 3)", i, n));
          for (int64_t j = 0; j < n; ++j) {
            if (!indices) {
              reader.skip(property.type);
              continue;
            }
            const size_t item_mark = reader.mark();
            const int64_t index = reader.integer(property.type);
            if (index < 0 || uint64_t(index) >= vertex_count)
              fail(name, reader.at(item_mark),
                   fmt::format("face {}: vertex index {} out of range (the file has {} vertices)", i, index,
                               vertex_count));
            corners.push_back(static_cast<uint32_t>(index));
          }
          if (indices) face_ends.push_back(corners.size());
        } else if (is_vertex && (q == layout.xyz[0] || q == layout.xyz[1] || q == layout.xyz[2])) {
          const size_t k = q == layout.xyz[0] ? 0 : q == layout.xyz[1] ? 1 : 2;
          const size_t mark = reader.mark();
          p[k] = reader.real(property.type);
          if (!std::isfinite(p[k]))
            fail(name, reader.at(mark), fmt::format("vertex {}: coordinate {} is not finite", i, char('x' + k)));
        } else {
          reader.skip(property.type);
        }
      }
      if (is_vertex) points.push_back(p);
    }
  }
  MeshBuilder builder(name);
  builder.reserve_triangles(corners.size() - 2 * face_ends.size());
  IndexedPoints welded(builder, points);
  std::vector<uint32_t> polygon;
  size_t begin = 0;
  for (size_t end : face_ends) {
    polygon.clear();
    for (size_t j = begin; j < end; ++j) polygon.push_back(welded(corners[j]));
    builder.polygon(polygon.data(), polygon.size());
    begin = end;
  }
  return builder.finish();
}

BodyMesh parse_ply(std::string_view bytes, const std::string& name) {
  const PlyHeader header = parse_ply_header(bytes, name);
  const PlyLayout layout = ply_layout(header, name);
  if (header.format == PlyFormat::Ascii) {
    PlyAsciiReader reader(bytes, header, name);
    return read_ply_data(reader, header, layout, name);
  }
  PlyBinaryReader reader(bytes, header, name);
  return read_ply_data(reader, header, layout, name);
}

// ---- OBJ ----

BodyMesh parse_obj(std::string_view text, const std::string& name) {
  std::vector<Point> points;
  std::vector<int64_t> corners;                      // 0-based, checked against the final count at the end
  std::vector<std::pair<size_t, size_t>> face_ends;  // (end in corners, line)
  size_t pos = 0, line_number = 0;
  while (pos < text.size()) {
    const size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    Tokens tokens(line);
    const std::string_view keyword = tokens.next();
    const auto where = [&] { return fmt::format("line {}", line_number); };
    if (keyword == "v") {
      Point p{};
      for (double& x : p) {
        const std::string_view token = tokens.next();
        if (!parse_number(token, x)) fail(name, where(), fmt::format("expected 'v x y z', found {}", quoted(token)));
        if (!std::isfinite(x)) fail(name, where(), fmt::format("coordinate {} is not finite", quoted(token)));
      }
      points.push_back(p);
    } else if (keyword == "f") {
      size_t n = 0;
      // A '#' starts a comment at the end of the line.
      for (std::string_view token = tokens.next(); !token.empty() && token[0] != '#'; token = tokens.next(), ++n) {
        // v, v/vt, v//vn or v/vt/vn: only the position index matters.
        const size_t slash = token.find('/');
        const std::string_view index_text = token.substr(0, slash);
        int64_t index;
        if (!parse_integer(index_text, index) || index == 0 ||
            (slash != std::string_view::npos && std::count(token.begin(), token.end(), '/') > 2))
          fail(name, where(),
               fmt::format("expected a face vertex 'v', 'v/vt', 'v//vn' or 'v/vt/vn', found {}", quoted(token)));
        // Negative indices count back from the last vertex so far (-1 is the last).
        if (index < -int64_t(points.size()))
          fail(name, where(),
               fmt::format("face vertex {} out of range ({} vertices before this line)", index, points.size()));
        corners.push_back(index < 0 ? int64_t(points.size()) + index : index - 1);
      }
      if (n < 3) fail(name, where(), fmt::format("a face with {} vertices (it needs 3)", n));
      face_ends.emplace_back(corners.size(), line_number);
    }
  }
  if (points.size() > std::numeric_limits<uint32_t>::max())
    throw InputError(fmt::format("{}: {} vertices, more than 32-bit indices reach", name, points.size()));
  MeshBuilder builder(name);
  builder.reserve_triangles(corners.size() - 2 * face_ends.size());
  IndexedPoints welded(builder, points);
  std::vector<uint32_t> polygon;
  size_t begin = 0;
  for (const auto& [end, line] : face_ends) {
    polygon.clear();
    for (size_t j = begin; j < end; ++j) {
      // Positive indices may point forward (some writers put vertices after faces).
      if (uint64_t(corners[j]) >= points.size())
        fail(name, fmt::format("line {}", line),
             fmt::format("face vertex {} out of range (the file has {} vertices)", corners[j] + 1, points.size()));
      polygon.push_back(welded(static_cast<size_t>(corners[j])));
    }
    builder.polygon(polygon.data(), polygon.size());
    begin = end;
  }
  return builder.finish();
}

// ---- 3MF ----

#ifdef OFFSETGEN_HAVE_LIB3MF

// Owns one lib3mf handle.
struct Handle {
  NMR::PLib3MFBase* p = nullptr;
  Handle() = default;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (p) NMR::lib3mf_release(p);
  }
};

// x' = m[.][0..2] . x + m[.][3], as lib3mf's MODELTRANSFORM.
using Affine = std::array<std::array<double, 4>, 3>;

Affine to_affine(const NMR::MODELTRANSFORM& t) {
  Affine m{};
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 4; ++j) m[i][j] = t.m_fFields[i][j];
  return m;
}

// outer after inner.
Affine compose(const Affine& outer, const Affine& inner) {
  Affine m{};
  for (size_t i = 0; i < 3; ++i) {
    for (size_t j = 0; j < 4; ++j) {
      double s = j == 3 ? outer[i][3] : 0.0;
      for (size_t k = 0; k < 3; ++k) s += outer[i][k] * inner[k][j];
      m[i][j] = s;
    }
  }
  return m;
}

double determinant(const Affine& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

class ThreeMfReader {
 public:
  ThreeMfReader(const std::string& name, MeshBuilder& builder) : name_(name), builder_(builder) {}

  void read(const std::string& bytes) {
    Handle reader;
    if (NMR::lib3mf_createmodel(reinterpret_cast<NMR::PLib3MFModel**>(&model_.p)) != LIB3MF_OK ||
        NMR::lib3mf_model_queryreader(model_.p, "3mf", reinterpret_cast<NMR::PLib3MFModelReader**>(&reader.p)) !=
            LIB3MF_OK)
      throw std::runtime_error("lib3mf: cannot create a model and its reader");
    std::vector<BYTE> buffer(bytes.begin(), bytes.end());
    if (NMR::lib3mf_reader_readfrombuffer(reader.p, buffer.data(), buffer.size()) != LIB3MF_OK)
      throw InputError(fmt::format("{}: not a readable 3MF file ({})", name_, last_error(reader.p)));
    DWORD unit = NMR::MODELUNIT_MILLIMETER;
    check(NMR::lib3mf_model_getunit(model_.p, &unit), "getunit");
    const double scale = unit == NMR::MODELUNIT_MICROMETER   ? 0.001
                         : unit == NMR::MODELUNIT_CENTIMETER ? 10.0
                         : unit == NMR::MODELUNIT_INCH       ? 25.4
                         : unit == NMR::MODELUNIT_FOOT       ? 304.8
                         : unit == NMR::MODELUNIT_METER      ? 1000.0
                                                             : 1.0;
    const Affine to_mm{{{scale, 0, 0, 0}, {0, scale, 0, 0}, {0, 0, scale, 0}}};

    Handle items;
    check(NMR::lib3mf_model_getbuilditems(model_.p, reinterpret_cast<NMR::PLib3MFModelBuildItemIterator**>(&items.p)),
          "getbuilditems");
    for (;;) {
      BOOL more = false;
      check(NMR::lib3mf_builditemiterator_movenext(items.p, &more), "movenext");
      if (!more) break;
      Handle item;
      check(NMR::lib3mf_builditemiterator_getcurrent(items.p, reinterpret_cast<NMR::PLib3MFModelBuildItem**>(&item.p)),
            "getcurrent");
      DWORD id = 0;
      check(NMR::lib3mf_builditem_getobjectresourceid(item.p, &id), "getobjectresourceid");
      NMR::MODELTRANSFORM transform;
      check(NMR::lib3mf_builditem_getobjecttransform(item.p, &transform), "getobjecttransform");
      add_object(id, compose(to_mm, to_affine(transform)), 0);
    }
  }

 private:
  static std::string last_error(NMR::PLib3MFBase* instance) {
    DWORD code = 0;
    LPCSTR message = nullptr;
    if (NMR::lib3mf_getlasterror(instance, &code, &message) != LIB3MF_OK || !message) return "lib3mf gave no reason";
    return fmt::format("{} (lib3mf error 0x{:x})", message, unsigned(code));
  }
  void check(LIB3MFRESULT result, const char* what) const {
    if (result != LIB3MF_OK)
      throw InputError(fmt::format("{}: lib3mf: {} failed (0x{:x})", name_, what, unsigned(result)));
  }

  void add_object(DWORD id, const Affine& transform, int depth) {
    if (depth > 32) throw InputError(fmt::format("{}: 3MF components nested more than 32 deep", name_));
    Handle mesh;
    // lib3mf answers OK with no object for an id of another kind.
    if (NMR::lib3mf_model_getmeshobjectbyid(model_.p, id, reinterpret_cast<NMR::PLib3MFModelMeshObject**>(&mesh.p)) ==
            LIB3MF_OK &&
        mesh.p) {
      add_mesh(mesh.p, id, transform);
      return;
    }
    Handle components;
    if (NMR::lib3mf_model_getcomponentsobjectbyid(
            model_.p, id, reinterpret_cast<NMR::PLib3MFModelComponentsObject**>(&components.p)) != LIB3MF_OK ||
        !components.p)
      throw InputError(fmt::format("{}: 3MF object {} is neither a mesh nor made of components", name_, id));
    DWORD count = 0;
    check(NMR::lib3mf_componentsobject_getcomponentcount(components.p, &count), "getcomponentcount");
    for (DWORD i = 0; i < count; ++i) {
      Handle component;
      check(NMR::lib3mf_componentsobject_getcomponent(components.p, i,
                                                      reinterpret_cast<NMR::PLib3MFModelComponent**>(&component.p)),
            "getcomponent");
      DWORD child = 0;
      check(NMR::lib3mf_component_getobjectresourceid(component.p, &child), "component getobjectresourceid");
      NMR::MODELTRANSFORM local;
      check(NMR::lib3mf_component_gettransform(component.p, &local), "component gettransform");
      add_object(child, compose(transform, to_affine(local)), depth + 1);
    }
  }

  void add_mesh(NMR::PLib3MFBase* mesh, DWORD id, const Affine& m) {
    DWORD vertex_count = 0, triangle_count = 0;
    check(NMR::lib3mf_meshobject_getvertexcount(mesh, &vertex_count), "getvertexcount");
    check(NMR::lib3mf_meshobject_gettrianglecount(mesh, &triangle_count), "gettrianglecount");
    std::vector<NMR::MODELMESHVERTEX> vertices(vertex_count);
    std::vector<NMR::MODELMESHTRIANGLE> triangles(triangle_count);
    if (vertex_count)
      check(NMR::lib3mf_meshobject_getvertices(mesh, vertices.data(), vertex_count, nullptr), "getvertices");
    if (triangle_count)
      check(NMR::lib3mf_meshobject_gettriangleindices(mesh, triangles.data(), triangle_count, nullptr),
            "gettriangleindices");
    std::vector<Point> points(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
      const auto& x = vertices[v].m_fPosition;
      for (size_t i = 0; i < 3; ++i) {
        points[v][i] = m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] + m[i][3];
        if (!std::isfinite(points[v][i]))
          throw InputError(fmt::format("{}: 3MF object {}: vertex {} is not finite", name_, id, v));
      }
    }
    // A mirroring transform turns the triangles inside out; reversing them keeps their facing.
    const bool mirrored = determinant(m) < 0;
    IndexedPoints welded(builder_, points);
    for (size_t t = 0; t < triangle_count; ++t) {
      uint32_t corners[3];
      for (size_t k = 0; k < 3; ++k) {
        const DWORD index = triangles[t].m_nIndices[k];
        if (index >= vertex_count)
          throw InputError(fmt::format("{}: 3MF object {}: triangle {}: vertex index {} out of range ({} vertices)",
                                       name_, id, t, index, vertex_count));
        corners[mirrored ? 2 - k : k] = welded(index);
      }
      builder_.polygon(corners, 3);
    }
  }

  const std::string& name_;
  MeshBuilder& builder_;
  Handle model_;
};

BodyMesh parse_3mf(const std::string& bytes, const std::string& name) {
  MeshBuilder builder(name);
  ThreeMfReader(name, builder).read(bytes);
  return builder.finish();
}

#else

BodyMesh parse_3mf(const std::string&, const std::string& name) {
  throw InputError(fmt::format(
      "{}: reading 3MF needs lib3mf, and this offsetgen was built without it (apt-get install lib3mf-dev and "
      "rebuild; .stl, .ply and .obj work)",
      name));
}

#endif

}  // namespace

#ifdef OFFSETGEN_HAVE_LIB3MF
bool can_read_3mf() { return true; }
#else
bool can_read_3mf() { return false; }
#endif

BodyFormat body_format_for_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".stl") return BodyFormat::Stl;
  if (ext == ".ply") return BodyFormat::Ply;
  if (ext == ".obj") return BodyFormat::Obj;
  if (ext == ".3mf") return BodyFormat::ThreeMf;
  if (ext.empty())
    throw InputError(fmt::format("body '{}': no extension to tell its format (use .stl, .ply, .obj or .3mf)", path));
  throw InputError(fmt::format("body '{}': unknown format '{}' (use .stl, .ply, .obj or .3mf)", path,
                               std::filesystem::path(path).extension().string()));
}

BodyMesh parse_body(const std::string& bytes, BodyFormat format, const std::string& name_for_messages) {
  switch (format) {
    case BodyFormat::Stl:
      return parse_stl(bytes, name_for_messages);
    case BodyFormat::Ply:
      return parse_ply(bytes, name_for_messages);
    case BodyFormat::Obj:
      return parse_obj(bytes, name_for_messages);
    case BodyFormat::ThreeMf:
      return parse_3mf(bytes, name_for_messages);
  }
  throw std::logic_error("parse_body: unknown format");
}

BodyMesh read_body_file(const std::string& path) {
  const BodyFormat format = body_format_for_path(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(fmt::format("body '{}' is a directory", path));
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(fmt::format("cannot read body '{}': {}", path, std::strerror(errno)));
  const std::streamoff size = in.tellg();
  std::string bytes(size > 0 ? static_cast<size_t>(size) : 0, '\0');
  in.seekg(0);
  if (size < 0 || !in.read(bytes.data(), size))
    throw InputError(fmt::format("cannot read body '{}': {}", path, std::strerror(errno)));
  return parse_body(bytes, format, path);
}

}  // namespace offsetgen::body
