#include "emit/glsl_emitter.h"

#include "emit/dialect.h"
#include "emit/printer.h"
#include "emit/templates.h"

#include <fmt/format.h>

#include <sstream>

namespace offsetgen {
namespace {

std::string vector_type(int dims) { return dims == 3 ? "vec3" : "vec2"; }

std::string parameters(const FileFacts& facts, const EmittedFunction& f) {
  if (!f.takes_point) return "highp float " + f.extra_parameter;
  std::string params = "highp " + vector_type(facts.dims) + " p";
  if (!f.extra_parameter.empty()) params += ", highp float " + f.extra_parameter;
  return params;
}

std::string render_function(const std::string& skeleton, const FileFacts& facts, const EmittedFunction& f,
                            const Dialect& d) {
  std::vector<std::string> inputs = {"p.x", "p.y"};
  if (facts.dims == 3) inputs.push_back("p.z");
  if (!f.takes_point) inputs.clear();
  if (!f.extra_parameter.empty()) inputs.push_back(f.extra_parameter);
  PrintedBody printed = print_program(*f.program, d, inputs);
  std::string body;
  for (const auto& line : printed.temporaries) body += "    " + line + "\n";
  if (f.vector_result) {
    std::string components;
    for (const auto& out : printed.outputs) components += (components.empty() ? "" : ", ") + out;
    body += fmt::format("    return {}({});\n", vector_type(facts.dims), components);
  } else {
    body += fmt::format("    return {};\n", printed.outputs.at(0));
  }
  return fmt::format(fmt::runtime(skeleton), fmt::arg("doc", f.doc), fmt::arg("ops", count_ops(*f.program)),
                     fmt::arg("return_type", f.vector_result ? "highp " + vector_type(facts.dims) : "highp float"),
                     fmt::arg("name", facts.prefix + "_" + f.suffix), fmt::arg("params", parameters(facts, f)),
                     fmt::arg("body", body));
}

// The density paragraph as indented lines ending in a newline, or "" (emitted_api.h).
std::string density_comment(const FileFacts& facts) {
  std::string out, text = density_paragraph(facts, true), line;
  std::istringstream lines(text);
  while (std::getline(lines, line)) out += wrap_paragraph(line, "", "    ") + "\n";
  return out;
}

}  // namespace

std::string emit_glsl_snippet(const FileFacts& facts, const std::vector<EmittedFunction>& functions) {
  const std::string skeleton = load_template("glsl_function.in");
  const Dialect d{Language::Glsl, Precision::Float};
  std::string rendered, use_list, io_list, ops_list;
  for (const auto& f : functions) {
    rendered += render_function(skeleton, facts, f, d);
    std::string ret = f.vector_result ? vector_type(facts.dims) : "float";
    std::string args = !f.takes_point ? "float " + f.extra_parameter
                                      : vector_type(facts.dims) + " p" +
                                            (f.extra_parameter.empty() ? "" : ", float " + f.extra_parameter);
    use_list += fmt::format("    - <{}> {}_{}(<{}>)\n", ret, facts.prefix, f.suffix, args);
    ops_list += fmt::format("    - {}: {}\n", f.suffix, count_ops(*f.program));
  }
  io_list =
      "    - p: position in cell units (cell length L = 1; divide by L for other cells)\n"
      "    - h: offset distance in cell units, signed (h > 0 towards F > 0)\n"
      "    - t: total wall thickness in cell units (> 0)\n"
      "    - returns: _field and _offset in units of F, _shell in units of F squared (only its sign is\n"
      "      meaningful), _normal a unit vector";
  use_list.pop_back();
  ops_list.pop_back();
  const Surface& s = *facts.surface;
  const MethodFacts& m = *facts.method;
  auto paragraph = [](const std::string& label, const std::string& text) {
    return wrap_paragraph(label + " " + text, "", "    ");
  };
  const std::string method = wrap_paragraph("Method: " + m.summary + " " + m.citation, "    ", "    ");
  return fmt::format(fmt::runtime(load_template("glsl_snippet.glsl.in")), fmt::arg("file_name", facts.file_name),
                     fmt::arg("version", OFFSETGEN_VERSION), fmt::arg("command", facts.command),
                     fmt::arg("order", m.order), fmt::arg("title", s.title), fmt::arg("formula", s.formula),
                     fmt::arg("citation", s.citation), fmt::arg("method", method), fmt::arg("use_list", use_list),
                     fmt::arg("io_list", io_list), fmt::arg("prefix", facts.prefix),
                     fmt::arg("accuracy", paragraph("accuracy:", m.accuracy)),
                     fmt::arg("variable_thickness", paragraph("variable thickness:", m.variable_thickness)),
                     fmt::arg("safety", paragraph("safety:", m.safety) +
                                            (m.lipschitz.empty() ? "" : "\n" + paragraph("lipschitz:", m.lipschitz))),
                     fmt::arg("density", density_comment(facts)), fmt::arg("ops_list", ops_list),
                     fmt::arg("metadata", facts.metadata_json), fmt::arg("guard", guard_name(facts.prefix, "glsl")),
                     fmt::arg("functions", rendered));
}

}  // namespace offsetgen
