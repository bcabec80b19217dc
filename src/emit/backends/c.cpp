// The C target: a self-contained C99/C++ header, <prefix>.h, in double and/or float (f-suffixed
// names), with inline sin/cos helpers and the batch API (emit/c_batch.cpp). Skeletons: templates/c/.
#include "emit/backend.h"
#include "emit/c_batch.h"
#include "emit/c_family.h"
#include "emit/c_names.h"
#include "emit/emitted_api.h"
#include "emit/templates.h"
#include "offset/method.h"

#include <fmt/format.h>

#include <cmath>

namespace offsetgen {
namespace {

class CBackend final : public Backend {
 public:
  std::string name() const override { return "c"; }
  std::string extension() const override { return "h"; }
  std::string title() const override { return "C"; }
  std::string file_template() const override { return "c_header.h.in"; }
  std::string function_template() const override { return "c_function.in"; }

  std::string real_type(Precision p) const override { return p == Precision::Double ? "double" : "float"; }
  std::string local_decl(Precision p) const override { return "const " + real_type(p); }
  std::string bool_decl() const override { return "const int"; }
  std::string literal(double value, Precision p) const override {
    if (std::isnan(value)) return p == Precision::Double ? "nan(\"\")" : "nanf(\"\")";  // the density relations
    return c_family::literal(value, p);
  }
  std::string suffix(Precision p) const override { return p == Precision::Float ? "f" : ""; }
  std::string abs_name(Precision p) const override { return "fabs" + suffix(p); }
  std::string vector_type(int dims) const override { return fmt::format("[{}]", dims); }
  std::optional<std::string> reserved(const std::string& identifier) const override {
    return c_names::reserved(identifier);
  }
  std::vector<std::string> declared_identifiers(const std::string& prefix) const override {
    std::vector<std::string> names;
    for (const auto& suffix : function_suffixes()) {
      const std::string name = prefix + "_" + suffix;
      names.insert(names.end(), {name, name + "f", name + "_n", name + "f_n"});
    }
    names.push_back(prefix + "_glsl");  // offsetgen_generate(LANG glsl_string)
    names.push_back(guard_name(prefix, "h"));
    return names;
  }

  std::vector<std::string> input_names(const FileFacts& facts, const EmittedFunction& f) const override {
    return c_family::input_names(facts, f);
  }
  std::string parameters(const FileFacts& facts, const EmittedFunction& f, Precision p) const override {
    return c_family::parameters(facts, f, real_type(p));
  }
  std::string return_type(const FileFacts&, const EmittedFunction& f, Precision p) const override {
    return f.vector_result ? "void" : real_type(p);
  }
  std::string unused_parameter(const std::string& name) const override { return "(void)" + name + ";"; }
  std::string vector_return(const FileFacts&, const std::vector<std::string>& components) const override {
    return c_family::vector_return(components);
  }
  std::string finish_body(const FileFacts&, const std::string& body, Precision) const override {
    return rename_trig_calls(body, "offsetgen_");  // the inline helpers of templates/c/c_scalar_trig.in
  }

  std::string list_entry(const FileFacts& facts, const EmittedFunction& f, Precision p) const override {
    const std::string call =
        fmt::format("{} {}{}", return_type(facts, f, p), emitted_name(facts, f, p),
                    f.vector_result ? f.signature_doc.substr(0, f.signature_doc.size() - 1) + ", n)" : f.signature_doc);
    return fmt::format(" *   {:<42} {}\n", call, f.doc);
  }
  std::string ops_entry(const EmittedFunction& f) const override { return c_family::ops_entry(f); }
  std::string paragraph(const std::string& label, const std::string& text) const override {
    return c_family::paragraph(label, text);
  }
  std::string method_paragraph(const MethodFacts& m) const override { return c_family::method_paragraph(m); }
  std::string comment_paragraph(const std::string& text) const override { return c_family::comment_paragraph(text); }
  // The scalar functions call inline sin/cos helpers instead of libm's; they are defined once, ahead
  // of the functions of each precision that call them.
  std::string precision_section(const FileFacts&, const std::string& functions, Precision p) const override {
    const std::string f = suffix(p);
    if (functions.find("offsetgen_sin" + f + "(") == std::string::npos &&
        functions.find("offsetgen_cos" + f + "(") == std::string::npos)
      return functions;
    const auto sections = load_template_sections("c/c_scalar_trig.in", {"double", "float"});
    const std::string support =
        fmt::format(fmt::runtime(sections.at(p == Precision::Double ? "double" : "float")),
                    fmt::arg("range_double", kTrigRangeDouble), fmt::arg("range_float", kTrigRangeFloat));
    return support + functions;
  }
  std::string trailing_sections(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                                const std::vector<Precision>& precisions) const override {
    return emit_c_batch(facts, functions, precisions);  // the _n batch API (c_batch.h)
  }
};

}  // namespace

const Backend& c_backend() {
  static const CBackend instance;
  return instance;
}

}  // namespace offsetgen
