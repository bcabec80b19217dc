#include "emit/backend.h"

#include "emit/emitted_api.h"
#include "surfaces/surface.h"

#include <fmt/format.h>

#include <algorithm>

namespace offsetgen {

// Each backend file defines its one instance (emit/backends/<name>.cpp).
const Backend& c_backend();
const Backend& glsl_backend();
const Backend& hlsl_backend();
const Backend& wgsl_backend();
const Backend& cuda_backend();
const Backend& opencl_backend();
const Backend& numpy_backend();

const std::vector<const Backend*>& backends() {
  static const std::vector<const Backend*> all = {&c_backend(),    &glsl_backend(), &hlsl_backend(),
                                                  &wgsl_backend(), &cuda_backend(), &opencl_backend(),
                                                  &numpy_backend()};
  return all;
}

std::string backend_names(const char* separator) {
  std::string names;
  for (const Backend* b : backends()) names += (names.empty() ? "" : separator) + b->name();
  return names;
}

const Backend& backend(const std::string& name) {
  for (const Backend* b : backends())
    if (b->name() == name) return *b;
  throw InputError(fmt::format("unknown language '{}': expected {} (or all)", name, backend_names()));
}

std::vector<const Backend*> parse_languages(const std::string& list) {
  if (list == "all") return backends();
  std::vector<bool> wanted(backends().size(), false);
  size_t start = 0;
  while (true) {
    const size_t comma = list.find(',', start);
    const std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty())
      throw InputError(
          fmt::format("--lang '{}': empty language name; expected a comma list of {}, or all", list, backend_names()));
    const Backend& b = backend(name);
    wanted[static_cast<size_t>(std::find(backends().begin(), backends().end(), &b) - backends().begin())] = true;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  std::vector<const Backend*> chosen;
  for (size_t i = 0; i < wanted.size(); ++i)
    if (wanted[i]) chosen.push_back(backends()[i]);
  return chosen;
}

std::string floating_form(std::string text) {
  if (text.find_first_of(".ni") != std::string::npos) return text;  // has a point, or inf/nan
  auto e = text.find_first_of("eE");
  if (e == std::string::npos) return text + ".0";
  return text.substr(0, e) + ".0" + text.substr(e);
}

std::string float_literal(double value) {
  const std::string text = floating_form(fmt::format("{:.9g}", static_cast<double>(static_cast<float>(value))));
  return value < 0 ? "(" + text + ")" : text;
}

// --- Defaults shared by the shader backends ----------------------------------------------------

const std::vector<std::string>& function_suffixes() {
  static const std::vector<std::string> suffixes = {"field",   "offset",  "shell",
                                                    "normal",  "graded",  "wall",
                                                    "density", "thickness_for_density", "network_density",
                                                    "offset_for_density"};
  return suffixes;
}

std::vector<std::string> Backend::declared_identifiers(const std::string& prefix) const {
  std::vector<std::string> names;
  for (const auto& suffix : function_suffixes()) names.push_back(prefix + "_" + suffix);
  names.push_back(guard_name(prefix, extension()));
  return names;
}

std::vector<std::string> Backend::input_names(const FileFacts& facts, const EmittedFunction& f) const {
  std::vector<std::string> inputs;
  if (f.takes_point) inputs = {"p.x", "p.y"};
  if (f.takes_point && facts.dims == 3) inputs.push_back("p.z");
  if (!f.extra_parameter.empty()) inputs.push_back(f.extra_parameter);
  return inputs;
}

std::string Backend::return_type(const FileFacts& facts, const EmittedFunction& f, Precision p) const {
  return f.vector_result ? vector_type(facts.dims) : real_type(p);
}

std::string Backend::emitted_name(const FileFacts& facts, const EmittedFunction& f, Precision p) const {
  return facts.prefix + "_" + f.suffix + suffix(p);
}

std::string Backend::vector_return(const FileFacts& facts, const std::vector<std::string>& components) const {
  std::string list;
  for (const auto& c : components) list += (list.empty() ? "" : ", ") + c;
  return fmt::format("    return {}({});\n", vector_type(facts.dims), list);
}

}  // namespace offsetgen
