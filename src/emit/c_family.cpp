#include "emit/c_family.h"

#include "emit/emitted_api.h"
#include "offset/method.h"

#include <fmt/format.h>

namespace offsetgen::c_family {

std::vector<std::string> input_names(const FileFacts& facts, const EmittedFunction& f) {
  std::vector<std::string> inputs;
  if (f.takes_point) inputs = {"x", "y"};
  if (f.takes_point && facts.dims == 3) inputs.push_back("z");
  if (!f.extra_parameter.empty()) inputs.push_back(f.extra_parameter);
  return inputs;
}

std::string parameters(const FileFacts& facts, const EmittedFunction& f, const std::string& real) {
  if (!f.takes_point) return fmt::format("{} {}", real, f.extra_parameter);
  std::string params = fmt::format("{0} x, {0} y", real);
  if (facts.dims == 3) params += fmt::format(", {} z", real);
  if (!f.extra_parameter.empty()) params += fmt::format(", {} {}", real, f.extra_parameter);
  if (f.vector_result) params += fmt::format(", {} n[{}]", real, facts.dims);
  return params;
}

std::string vector_return(const std::vector<std::string>& components) {
  std::string lines;
  for (size_t i = 0; i < components.size(); ++i) lines += fmt::format("    n[{}] = {};\n", i, components[i]);
  return lines;
}

std::string literal(double value, Precision p) {
  if (p == Precision::Float) {
    std::string text = float_literal(value);
    return value < 0 ? text.substr(0, text.size() - 1) + "f)" : text + "f";
  }
  const std::string text = floating_form(fmt::format("{:.17g}", value));
  return value < 0 ? "(" + text + ")" : text;
}

std::string paragraph(const std::string& label, const std::string& text) {
  std::string capitalised = label;
  capitalised[0] = static_cast<char>(capitalised[0] - 'a' + 'A');
  return wrap_paragraph(capitalised + ": " + text, " * ", " *   ");
}

std::string method_paragraph(const MethodFacts& m) {
  return wrap_paragraph(m.summary, " * Method:  ", " *          ") + "\n" +
         wrap_paragraph(m.citation, " *          ", " *          ");
}

std::string comment_paragraph(const std::string& text) { return wrap_paragraph(text, " * ", " *   "); }

std::string ops_entry(const EmittedFunction& f) {
  return fmt::format(" *   {:<8} {}\n", f.suffix, count_ops(*f.program));
}

}  // namespace offsetgen::c_family
