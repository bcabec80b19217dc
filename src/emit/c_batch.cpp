#include "emit/c_batch.h"

#include "emit/printer.h"
#include "emit/templates.h"

#include <fmt/format.h>

#include <cctype>
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

}  // namespace

std::string rename_trig_calls(const std::string& code, const std::string& prefix) {
  std::string out;
  out.reserve(code.size() + code.size() / 8);
  size_t i = 0;
  while (i < code.size()) {
    bool at_word_start = i == 0 || !identifier_char(code[i - 1]);
    if (at_word_start && (code.compare(i, 3, "sin") == 0 || code.compare(i, 3, "cos") == 0)) {
      size_t end = i + 3;
      if (end < code.size() && code[end] == 'f') ++end;
      if (end < code.size() && code[end] == '(') {
        out += prefix;
        out.append(code, i, end - i);
        i = end;
        continue;
      }
    }
    out += code[i++];
  }
  return out;
}

std::string emit_c_batch(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                         const std::vector<Precision>& precisions) {
  bool any = false;
  for (const auto& f : functions) any = any || batched(f);
  if (!any) return "";

  const auto sections = load_template_sections("c_batch.in", {"file", "support_double", "support_float", "function"});
  std::vector<std::string> coordinates = {"x", "y"};
  if (facts.dims == 3) coordinates.push_back("z");

  std::string list, support, rendered;
  for (Precision precision : precisions) {
    const Dialect d{Language::C, precision};
    const std::string real = d.real_type();
    support +=
        fmt::format(fmt::runtime(sections.at(precision == Precision::Double ? "support_double" : "support_float")),
                    fmt::arg("range_double", kTrigRangeDouble), fmt::arg("range_float", kTrigRangeFloat));
    for (const auto& f : functions) {
      if (!batched(f)) continue;
      std::vector<std::string> inputs = coordinates;
      inputs.push_back(f.extra_parameter);
      std::vector<std::string> elements, array_params;
      for (const auto& input : inputs) {
        elements.push_back(input + "[i]");
        array_params.push_back(fmt::format("const {} *{}", real, input));
      }
      const PrintedBody printed = print_program(*f.program, d, elements);
      std::string body;
      for (const auto& line : printed.temporaries) body += "        " + line + "\n";
      body += fmt::format("        out[i] = {};\n", printed.outputs.at(0));

      const std::string scalar = facts.prefix + "_" + f.suffix + d.suffix();
      const std::string name = scalar + "_n";
      list += fmt::format(" *   void {}(n, {}, out)\n", name, join(inputs, ", "));
      rendered +=
          fmt::format(fmt::runtime(sections.at("function")), fmt::arg("doc", f.doc), fmt::arg("scalar", scalar),
                      fmt::arg("name", name), fmt::arg("call", join(elements, ", ")),
                      fmt::arg("array_params", join(array_params, ", ")), fmt::arg("real", real),
                      fmt::arg("body", rename_trig_calls(body, "offsetgen_batch_")), fmt::arg("abs", d.abs_name()),
                      fmt::arg("huge", precision == Precision::Double ? "HUGE_VAL" : "HUGE_VALF"));
    }
  }
  if (!list.empty()) list.pop_back();
  return fmt::format(fmt::runtime(sections.at("file")), fmt::arg("list", list), fmt::arg("support", support),
                     fmt::arg("functions", rendered), fmt::arg("range_double", kTrigRangeDouble),
                     fmt::arg("range_float", kTrigRangeFloat));
}

}  // namespace offsetgen
