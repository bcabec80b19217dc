#include "run/metadata.h"

#include "emit/backend.h"

#include "surfaces/surface.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace offsetgen::run {
namespace {

constexpr const char* kMarker = "offsetgen-metadata";
constexpr int kMaxSupportedOrder = 64;

[[noreturn]] void damaged(const std::string& what) {
  throw InputError(
      fmt::format("the offsetgen-metadata block is damaged: {}. Regenerate the file with "
                  "`offsetgen generate` (the command is in its banner).",
                  what));
}

using json = nlohmann::json;

const json& field(const json& j, const char* key) {
  auto it = j.find(key);
  if (it == j.end()) damaged(fmt::format("field \"{}\" is missing", key));
  return *it;
}

std::string string_field(const json& j, const char* key) {
  const json& v = field(j, key);
  if (!v.is_string()) damaged(fmt::format("field \"{}\" must be a string", key));
  return v.get<std::string>();
}

std::optional<std::string> optional_string_field(const json& j, const char* key) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return std::nullopt;
  if (!it->is_string()) damaged(fmt::format("field \"{}\" must be a string or null", key));
  return it->get<std::string>();
}

int int_field(const json& j, const char* key, int lo, int hi) {
  const json& v = field(j, key);
  if (!v.is_number_integer()) damaged(fmt::format("field \"{}\" must be an integer", key));
  if (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(hi))
    damaged(fmt::format("field \"{}\" = {} is outside {}..{}", key, v.get<unsigned long long>(), lo, hi));
  long long value = v.get<long long>();
  if (value < lo || value > hi) damaged(fmt::format("field \"{}\" = {} is outside {}..{}", key, value, lo, hi));
  return static_cast<int>(value);
}

double positive_number_field(const json& j, const char* key) {
  const json& v = field(j, key);
  if (!v.is_number()) damaged(fmt::format("field \"{}\" must be a number", key));
  double value = v.get<double>();
  if (!std::isfinite(value) || value <= 0) damaged(fmt::format("field \"{}\" must be a positive number", key));
  return value;
}

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

// "language": a backend's name (emit/backend.h). Older files lack it: a C header is the one with
// `static inline` functions, anything else is a GLSL snippet.
std::string file_language(const json& j, const std::string& text) {
  auto it = j.find("language");
  if (it == j.end() || it->is_null()) return text.find("static inline ") != std::string::npos ? "c" : "glsl";
  if (!it->is_string()) damaged("field \"language\" must be a string");
  const std::string language = *it;
  for (const Backend* b : backends())
    if (b->name() == language) return language;
  damaged(fmt::format("field \"language\" must be one of {}", backend_names()));
}

// The block's JSON text: after `/* offsetgen-metadata` up to `*/` on the same line, or the rest of a
// Python comment line `# offsetgen-metadata {...}` (NumPy modules).
std::string block_text(const std::string& text) {
  // A C-style comment, or a Python comment line (NumPy modules): `# offsetgen-metadata {...}`.
  const bool python = text.find(std::string("\n# ") + kMarker + " ") != std::string::npos;
  const std::string opener = std::string(python ? "\n# " : "/* ") + kMarker;
  auto start = text.find(opener);
  if (start == std::string::npos) {
    throw InputError(
        "this file was not produced by offsetgen: it has no `/* offsetgen-metadata {...} */` block, so "
        "there is no record of the surface and order it was made from. `offsetgen check` only checks "
        "files written by `offsetgen generate`.");
  }
  if (text.find(opener, start + opener.size()) != std::string::npos)
    damaged("the file holds more than one metadata block (two generated files pasted together?)");
  auto json_begin = start + opener.size();
  auto line_end = text.find('\n', json_begin);
  auto close = python ? (line_end == std::string::npos ? text.size() : line_end) : text.find("*/", json_begin);
  if (close == std::string::npos || (line_end != std::string::npos && close > line_end))
    damaged("the block does not end with `*/` on its line");
  return text.substr(json_begin, close - json_begin);
}

json parse_block(const std::string& body) {
  json j;
  try {
    j = json::parse(body);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for numbers beyond double
    damaged(fmt::format("its JSON does not parse ({})", e.what()));
  }
  if (!j.is_object()) damaged("its JSON is not an object");
  return j;
}

// Where the file comes from: format, generator, prefix, the surface or expression and its parameters.
void read_origin(const json& j, FileMetadata& m) {
  m.format = int_field(j, "format", 0, 1000);
  if (m.format != 1)
    throw InputError(
        fmt::format("the offsetgen-metadata block has format {}, but this offsetgen reads format 1; "
                    "use the offsetgen version that wrote the file",
                    m.format));
  m.generator = string_field(j, "generator");
  if (m.generator.rfind("offsetgen", 0) != 0) damaged("field \"generator\" does not name offsetgen");
  m.prefix = string_field(j, "prefix");
  if (!is_identifier(m.prefix)) damaged(fmt::format("field \"prefix\" = \"{}\" is not a C identifier", m.prefix));
  m.surface = optional_string_field(j, "surface");
  m.expression = optional_string_field(j, "expression");
  if (m.surface.has_value() == m.expression.has_value())
    damaged("exactly one of \"surface\" and \"expression\" must be given");
  if (auto it = j.find("params"); it != j.end() && !it->is_null()) {
    if (!it->is_object()) damaged("field \"params\" must be an object");
    for (auto p = it->begin(); p != it->end(); ++p) {
      if (!p.value().is_string()) damaged(fmt::format("parameter \"{}\" must be a string", p.key()));
      m.params[p.key()] = p.value().get<std::string>();
    }
  }
}

// What was built: scale, dimensions, method and order, thickness, precisions, the safeguard bound, ops.
void read_construction(const json& j, FileMetadata& m) {
  m.scale = positive_number_field(j, "scale");
  m.dims = int_field(j, "dims", 2, 3);
  // Files from before the method choice were all made by the paper's construction.
  m.method = optional_string_field(j, "method").value_or("richardson");
  m.order = int_field(j, "order", 1, kMaxSupportedOrder);
  if (auto graded = j.find("graded_order"); graded != j.end()) m.graded_order = int_field(j, "graded_order", 1, 64);
  m.thickness = optional_string_field(j, "thickness");
  const json& precisions = field(j, "precisions");
  if (!precisions.is_array() || precisions.empty()) damaged("field \"precisions\" must be a non-empty list");
  m.has_double = m.has_float = false;
  for (const auto& p : precisions) {
    if (p == "double") {
      m.has_double = true;
    } else if (p == "float") {
      m.has_float = true;
    } else {
      damaged("field \"precisions\" may only hold \"double\" and \"float\"");
    }
  }
  m.gradient_bound = positive_number_field(j, "gradient_bound");
  if (auto it = j.find("ops"); it != j.end() && !it->is_null()) {
    if (!it->is_object()) damaged("field \"ops\" must be an object");
    for (auto p = it->begin(); p != it->end(); ++p) {
      if (!p.value().is_number_unsigned() || p.value().get<unsigned long long>() > 1000000000ULL)
        damaged(fmt::format("ops of \"{}\" must be a count (an integer from 0 to 1e9)", p.key()));
      m.ops[p.key()] = static_cast<int>(p.value().get<unsigned long long>());
    }
  }
}

// The density relations' limits and the --density / --density-field of files with density functions.
void read_density(const json& j, FileMetadata& m) {
  auto it = j.find("density");
  if (it == j.end() || it->is_null()) return;
  if (!it->is_object()) damaged("field \"density\" must be an object");
  m.has_density = true;
  m.density_limit = positive_number_field(*it, "density_limit");
  m.thickness_limit = positive_number_field(*it, "thickness_limit");
  m.offset_limit = positive_number_field(*it, "offset_limit");
  const json& range = field(*it, "network_density_range");
  if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number())
    damaged("field \"network_density_range\" must be a list of two numbers");
  m.network_density_min = range[0].get<double>();
  m.network_density_max = range[1].get<double>();
  if (auto w = j.find("wall_density"); w != j.end() && !w->is_null()) {
    m.wall_density = positive_number_field(j, "wall_density");
    m.wall_thickness = positive_number_field(j, "wall_thickness");
  }
  m.density_field = optional_string_field(j, "density_field");
}

}  // namespace

FileMetadata parse_metadata(const std::string& text) {
  const std::string body = block_text(text);
  const json j = parse_block(body);
  FileMetadata m;
  m.language = file_language(j, text);
  m.json = body;
  // trim the surrounding spaces of the JSON text
  while (!m.json.empty() && std::isspace(static_cast<unsigned char>(m.json.front()))) m.json.erase(0, 1);
  while (!m.json.empty() && std::isspace(static_cast<unsigned char>(m.json.back()))) m.json.pop_back();
  read_origin(j, m);
  read_construction(j, m);
  read_density(j, m);
  // The header must actually define what the block describes.
  const std::string probe = m.prefix + "_offset";
  if (text.find(probe) == std::string::npos)
    damaged(fmt::format("the file does not define {} although its metadata names prefix \"{}\"", probe, m.prefix));
  return m;
}

FileMetadata read_metadata(const std::string& path, std::string* text_out) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status))
    throw InputError(
        fmt::format("'{}' is a directory; give one file written by `offsetgen generate` (a .h header "
                    "or a .glsl snippet)",
                    path));
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(
        fmt::format("'{}' is not a regular file (a device, FIFO or socket); give a header or GLSL "
                    "snippet written by `offsetgen generate`",
                    path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot read '{}'", path));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  if (text.find('\0') != std::string::npos)
    throw InputError(fmt::format("'{}' is a binary file, not a header or GLSL snippet written by offsetgen", path));
  FileMetadata m = parse_metadata(text);
  if (text_out) *text_out = std::move(text);
  return m;
}

}  // namespace offsetgen::run
