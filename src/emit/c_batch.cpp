#include "emit/c_batch.h"

#include "emit/printer.h"
#include "emit/templates.h"

#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

namespace offsetgen {
namespace {


bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string join(const std::vector<std::string>& parts, const char* separator) {
  std::string out;
  for (const auto& part : parts) out += (out.empty() ? "" : separator) + part;
  return out;
}

bool batched(const EmittedFunction& f) { return !f.vector_result && (f.suffix == "offset" || f.suffix == "shell"); }

// The bits of a range limit, for the helpers' integer comparison (templates/c/c_batch.in).
std::string double_bits(const char* value) {
  const double d = std::stod(value);
  std::uint64_t b = 0;
  std::memcpy(&b, &d, sizeof b);
  return fmt::format("0x{:016x}", b);
}

std::string float_bits(const char* value) {
  const float f = std::stof(value);
  std::uint32_t b = 0;
  std::memcpy(&b, &f, sizeof b);
  return fmt::format("0x{:08x}", b);
}

// Points per block of the batch loops: a multiple of every vector width up to AVX-512 (8 doubles,
// 16 floats), so that the block loop's constant trip count needs no remainder.
int block_size(Precision precision) { return precision == Precision::Double ? 8 : 16; }

bool identifier_start(const std::string& code, size_t i) { return i == 0 || !identifier_char(code[i - 1]); }

}  // namespace

std::string rename_calls(const std::string& code, const std::vector<std::string>& names, const std::string& prefix) {
  std::string out;
  out.reserve(code.size() + code.size() / 8);
  size_t i = 0;
  while (i < code.size()) {
    bool renamed = false;
    if (identifier_start(code, i)) {
      for (const auto& name : names) {
        if (code.compare(i, name.size(), name) != 0) continue;
        size_t end = i + name.size();
        if (end < code.size() && code[end] == 'f') ++end;  // the float spelling
        if (end < code.size() && code[end] == '(') {
          out += prefix;
          out.append(code, i, end - i);
          i = end;
          renamed = true;
          break;
        }
      }
    }
    if (!renamed) out += code[i++];
  }
  return out;
}

std::string rename_trig_calls(const std::string& code, const std::string& prefix) {
  return rename_calls(code, {"sin", "cos"}, prefix);
}

std::string emit_c_batch(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                         const std::vector<Precision>& precisions) {
  bool any = false;
  for (const auto& f : functions) any = any || batched(f);
  if (!any) return "";

  const auto sections = load_template_sections("c/c_batch.in", {"file", "support_double", "support_float", "function"});
  std::vector<std::string> coordinates = {"x", "y"};
  if (facts.dims == 3) coordinates.push_back("z");

  std::string list, support, rendered;
  for (Precision precision : precisions) {
    const Dialect d("c", precision);
    const std::string real = d.real_type();
    support += fmt::format(fmt::runtime(sections.at(precision == Precision::Double ? "support_double" : "support_float")),
                           fmt::arg("range_double", kTrigRangeDouble), fmt::arg("range_float", kTrigRangeFloat),
                           fmt::arg("range_double_bits", double_bits(kTrigRangeDouble)),
                           fmt::arg("range_float_bits", float_bits(kTrigRangeFloat)));
    for (const auto& f : functions) {
      if (!batched(f)) continue;
      std::vector<std::string> inputs = coordinates;
      inputs.push_back(f.extra_parameter);
      std::vector<std::string> elements, block_elements, array_params;
      for (const auto& input : inputs) {
        elements.push_back(input + "[i]");
        block_elements.push_back(input + "[i + j]");
        array_params.push_back(fmt::format("const {} *{}", real, input));
      }
      const PrintedBody printed = print_program(*f.program, d, block_elements);
      std::string body;
      for (const auto& line : printed.temporaries) body += "            " + line + "\n";
      body += fmt::format("            out[i + j] = {};\n", printed.outputs.at(0));

      const std::string scalar = facts.prefix + "_" + f.suffix + d.suffix();
      const std::string name = scalar + "_n";
      list += fmt::format(" *   void {}(n, {}, out)\n", name, join(inputs, ", "));
      rendered += fmt::format(
          fmt::runtime(sections.at("function")), fmt::arg("doc", f.doc), fmt::arg("scalar", scalar),
          fmt::arg("name", name), fmt::arg("call", join(elements, ", ")),
          fmt::arg("array_params", join(array_params, ", ")), fmt::arg("real", real),
          fmt::arg("body", rename_calls(body, {"sin", "cos", "sqrt"}, "offsetgen_batch_")),
          fmt::arg("block", block_size(precision)), fmt::arg("abs", d.abs_name()),
          fmt::arg("huge", precision == Precision::Double ? "HUGE_VAL" : "HUGE_VALF"));
    }
  }
  if (!list.empty()) list.pop_back();
  return fmt::format(fmt::runtime(sections.at("file")), fmt::arg("list", list), fmt::arg("support", support),
                     fmt::arg("functions", rendered), fmt::arg("range_double", kTrigRangeDouble),
                     fmt::arg("range_float", kTrigRangeFloat));
}

}  // namespace offsetgen
