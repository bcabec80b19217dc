#include "emit/c_emitter.h"

#include "emit/c_batch.h"
#include "emit/printer.h"
#include "emit/templates.h"

#include <fmt/format.h>

#include <sstream>

namespace offsetgen {
namespace {

std::string function_name(const FileFacts& facts, const EmittedFunction& f, const Dialect& d) {
  return facts.prefix + "_" + f.suffix + d.suffix();
}

std::string parameters(const FileFacts& facts, const EmittedFunction& f, const Dialect& d) {
  std::string real = d.real_type();
  if (!f.takes_point) return fmt::format("{} {}", real, f.extra_parameter);
  std::string params = fmt::format("{0} x, {0} y", real);
  if (facts.dims == 3) params += fmt::format(", {} z", real);
  if (!f.extra_parameter.empty()) params += fmt::format(", {} {}", real, f.extra_parameter);
  if (f.vector_result) params += fmt::format(", {} n[{}]", real, facts.dims);
  return params;
}

std::string render_function(const std::string& skeleton, const FileFacts& facts, const EmittedFunction& f,
                            const Dialect& d) {
  std::vector<std::string> inputs = {"x", "y"};
  if (facts.dims == 3) inputs.push_back("z");
  if (!f.takes_point) inputs.clear();
  if (!f.extra_parameter.empty()) inputs.push_back(f.extra_parameter);
  PrintedBody printed = print_program(*f.program, d, inputs);
  std::string body;
  // A function that does not read a parameter (x + y + z has a constant normal) says so, for
  // -Wunused-parameter.
  std::vector<bool> read(inputs.size(), false);
  for (NodeId id : schedule(*f.program))
    if (f.program->node(id).op == Op::Input) read[static_cast<size_t>(f.program->node(id).input)] = true;
  for (size_t i = 0; i < inputs.size(); ++i)
    if (!read[i]) body += fmt::format("    (void){};\n", inputs[i]);
  for (const auto& line : printed.temporaries) body += "    " + line + "\n";
  if (f.vector_result) {
    for (size_t i = 0; i < printed.outputs.size(); ++i) body += fmt::format("    n[{}] = {};\n", i, printed.outputs[i]);
  } else {
    body += fmt::format("    return {};\n", printed.outputs.at(0));
  }
  body = rename_trig_calls(body, "offsetgen_");  // the inline helpers of templates/c_scalar_trig.in
  return fmt::format(fmt::runtime(skeleton), fmt::arg("doc", f.doc), fmt::arg("ops", count_ops(*f.program)),
                     fmt::arg("return_type", f.vector_result ? "void" : d.real_type()),
                     fmt::arg("name", function_name(facts, f, d)), fmt::arg("params", parameters(facts, f, d)),
                     fmt::arg("body", body));
}

// The scalar functions call inline sin/cos helpers instead of libm's; they are defined once, ahead
// of the functions of each precision that call them.
std::string with_scalar_trig(const std::string& functions, Precision precision) {
  const std::string f = precision == Precision::Double ? "" : "f";
  if (functions.find("offsetgen_sin" + f + "(") == std::string::npos &&
      functions.find("offsetgen_cos" + f + "(") == std::string::npos)
    return functions;
  const auto sections = load_template_sections("c_scalar_trig.in", {"double", "float"});
  const std::string support =
      fmt::format(fmt::runtime(sections.at(precision == Precision::Double ? "double" : "float")),
                  fmt::arg("range_double", kTrigRangeDouble), fmt::arg("range_float", kTrigRangeFloat));
  return support + functions;
}

// The density paragraph as comment lines ending in a newline, or "" (emitted_api.h).
std::string density_comment(const FileFacts& facts) {
  std::string out, text = density_paragraph(facts, false), line;
  std::istringstream lines(text);
  while (std::getline(lines, line)) out += wrap_paragraph(line, " * ", " *   ") + "\n";
  return out;
}

}  // namespace

std::string emit_c_header(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                          const std::vector<Precision>& precisions) {
  const std::string skeleton = load_template("c_function.in");
  std::string rendered, function_list, ops_list;
  for (Precision precision : precisions) {
    Dialect d{Language::C, precision};
    std::string scalar_functions;
    for (const auto& f : functions) {
      scalar_functions += render_function(skeleton, facts, f, d);
      std::string call = fmt::format(
          "{} {}{}", f.vector_result ? "void" : d.real_type(), function_name(facts, f, d),
          f.vector_result ? f.signature_doc.substr(0, f.signature_doc.size() - 1) + ", n)" : f.signature_doc);
      function_list += fmt::format(" *   {:<42} {}\n", call, f.doc);
    }
    rendered += with_scalar_trig(scalar_functions, precision);
  }
  rendered += emit_c_batch(facts, functions, precisions);  // the _n batch API (c_batch.h)
  for (const auto& f : functions) ops_list += fmt::format(" *   {:<8} {}\n", f.suffix, count_ops(*f.program));
  function_list.pop_back();
  ops_list.pop_back();

  const Surface& s = *facts.surface;
  const MethodFacts& m = *facts.method;
  auto paragraph = [](const std::string& label, const std::string& text) {
    return wrap_paragraph(label + " " + text, " * ", " *   ");
  };
  const std::string method = wrap_paragraph(m.summary, " * Method:  ", " *          ") + "\n" +
                             wrap_paragraph(m.citation, " *          ", " *          ");
  return fmt::format(fmt::runtime(load_template("c_header.h.in")), fmt::arg("file_name", facts.file_name),
                     fmt::arg("version", OFFSETGEN_VERSION), fmt::arg("command", facts.command),
                     fmt::arg("order", m.order), fmt::arg("title", s.title), fmt::arg("formula", s.formula),
                     fmt::arg("citation", s.citation), fmt::arg("method", method),
                     fmt::arg("function_list", function_list), fmt::arg("prefix", facts.prefix),
                     fmt::arg("accuracy", paragraph("Accuracy:", m.accuracy)),
                     fmt::arg("variable_thickness", paragraph("Variable thickness:", m.variable_thickness)),
                     fmt::arg("safety", paragraph("Safety:", m.safety) +
                                            (m.lipschitz.empty() ? "" : "\n" + paragraph("Lipschitz:", m.lipschitz))),
                     fmt::arg("density", density_comment(facts)), fmt::arg("ops_list", ops_list),
                     fmt::arg("metadata", facts.metadata_json), fmt::arg("guard", guard_name(facts.prefix, "h")),
                     fmt::arg("functions", rendered));
}

}  // namespace offsetgen
