#include "emit/render.h"

#include "emit/dialect.h"
#include "emit/printer.h"
#include "emit/templates.h"

#include <fmt/format.h>

#include <deque>
#include <sstream>

namespace offsetgen {
namespace {

std::string render_function(const std::string& skeleton, const FileFacts& facts, const EmittedFunction& f,
                            const Dialect& d) {
  const Backend& b = *d.backend;
  const std::vector<std::string> inputs = b.input_names(facts, f);
  const PrintedBody printed = print_program(*f.program, d, inputs);
  std::string body = b.prologue(inputs);
  // A function that does not read a parameter (x + y + z has a constant normal) may have to say so
  // (C: -Wunused-parameter).
  std::vector<bool> read(inputs.size(), false);
  for (NodeId id : schedule(*f.program))
    if (f.program->node(id).op == Op::Input) read[static_cast<size_t>(f.program->node(id).input)] = true;
  for (size_t i = 0; i < inputs.size(); ++i) {
    const std::string statement = read[i] ? "" : b.unused_parameter(inputs[i]);
    if (!statement.empty()) body += "    " + statement + "\n";
  }
  for (const auto& line : printed.temporaries) body += "    " + line + "\n";
  if (f.vector_result)
    body += b.vector_return(facts, printed.outputs);
  else
    body += fmt::format("    return {};\n", printed.outputs.at(0));
  body = b.finish_body(facts, body, d.precision);
  return fmt::format(fmt::runtime(skeleton), fmt::arg("doc", f.doc), fmt::arg("ops", count_ops(*f.program)),
                     fmt::arg("return_type", b.return_type(facts, f, d.precision)),
                     fmt::arg("name", b.emitted_name(facts, f, d.precision)),
                     fmt::arg("params", b.parameters(facts, f, d.precision)), fmt::arg("body", body));
}

// The density paragraph as comment lines ending in a newline, or "" (emitted_api.h).
std::string density_comment(const Backend& b, const FileFacts& facts) {
  std::string out, line;
  std::istringstream lines(density_paragraph(facts, b.nan_note()));
  while (std::getline(lines, line)) out += b.comment_paragraph(line) + "\n";
  return out;
}

// The functions as `b` prints them: in half-turns where it has sinpi and cospi (their programs kept
// in `storage`), else as given.
std::vector<EmittedFunction> functions_for(const Backend& b, const std::vector<EmittedFunction>& given,
                                           std::deque<Program>& storage) {
  if (!b.half_turn_trig()) return given;
  std::vector<EmittedFunction> functions = given;
  for (auto& f : functions) {
    storage.push_back(in_half_turns(*f.program));
    f.program = &storage.back();
  }
  return functions;
}

}  // namespace

std::string render_file(const Backend& b, const FileFacts& facts, const std::vector<EmittedFunction>& given,
                        const std::vector<Precision>& precisions) {
  std::deque<Program> half_turn_programs;
  const std::vector<EmittedFunction> functions = functions_for(b, given, half_turn_programs);
  const std::string skeleton = load_template(b.name() + "/" + b.function_template());
  std::string rendered, function_list, ops_list;
  for (Precision precision : b.precisions(precisions)) {
    const Dialect d(b, precision);
    std::string section;
    for (const auto& f : functions) {
      section += render_function(skeleton, facts, f, d);
      function_list += b.list_entry(facts, f, precision);
    }
    rendered += b.precision_section(facts, section, precision);
  }
  rendered += b.trailing_sections(facts, functions, b.precisions(precisions));
  for (const auto& f : functions) ops_list += b.ops_entry(f);
  if (!function_list.empty()) function_list.pop_back();  // the last newline: the template has its own
  if (!ops_list.empty()) ops_list.pop_back();

  const Surface& s = *facts.surface;
  const MethodFacts& m = *facts.method;
  return fmt::format(fmt::runtime(load_template(b.name() + "/" + b.file_template())),
                     fmt::arg("file_name", facts.file_name), fmt::arg("version", OFFSETGEN_VERSION),
                     fmt::arg("command", facts.command), fmt::arg("order", m.order), fmt::arg("title", s.title),
                     fmt::arg("formula", s.formula), fmt::arg("citation", s.citation),
                     fmt::arg("method", b.method_paragraph(m)), fmt::arg("function_list", function_list),
                     fmt::arg("prefix", facts.prefix), fmt::arg("accuracy", b.paragraph("accuracy", m.accuracy)),
                     fmt::arg("variable_thickness", b.paragraph("variable thickness", m.variable_thickness)),
                     fmt::arg("safety", b.paragraph("safety", m.safety) +
                                            (m.lipschitz.empty() ? "" : "\n" + b.paragraph("lipschitz", m.lipschitz))),
                     fmt::arg("density", density_comment(b, facts)), fmt::arg("ops_list", ops_list),
                     fmt::arg("metadata", facts.metadata_json),
                     fmt::arg("guard", guard_name(facts.prefix, b.extension())), fmt::arg("functions", rendered));
}

}  // namespace offsetgen
