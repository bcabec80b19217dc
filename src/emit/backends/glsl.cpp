// The GLSL target: a paste-safe snippet, <prefix>.glsl, for GLSL ES 3.00 (WebGL2), GLSL 3.30+ and
// Vulkan GLSL, in lygia's conventions (include guard, no #version, no precision statement, every
// float highp). Skeletons: templates/glsl/.
#include "emit/backend.h"
#include "emit/emitted_api.h"
#include "emit/glsl_names.h"
#include "emit/shader_trig.h"
#include "offset/method.h"

#include <fmt/format.h>

#include <cmath>

namespace offsetgen {
namespace {

class GlslBackend final : public Backend {
 public:
  std::string name() const override { return "glsl"; }
  std::string extension() const override { return "glsl"; }
  std::string title() const override { return "GLSL"; }
  std::string file_template() const override { return "glsl_snippet.glsl.in"; }
  std::string function_template() const override { return "glsl_function.in"; }
  std::vector<Precision> precisions(const std::vector<Precision>&) const override { return {Precision::Float}; }

  // highp everywhere: a host's `precision mediump float` cannot drop the snippet to fp16.
  std::string real_type(Precision) const override { return "highp float"; }
  // Not const: GLSL const needs a constant initialiser.
  std::string local_decl(Precision) const override { return "highp float"; }
  std::string bool_decl() const override { return "bool"; }
  std::string literal(double value, Precision) const override {
    return std::isnan(value) ? "intBitsToFloat(0x7fc00000)" : float_literal(value);  // NaN: the density relations
  }
  std::string vector_type(int dims) const override { return dims == 3 ? "vec3" : "vec2"; }
  std::string atan2_name(Precision) const override { return "atan"; }  // GLSL's two-argument atan
  std::optional<std::string> reserved(const std::string& identifier) const override {
    return glsl_names::reserved(identifier);
  }

  // sin and cos are the snippet's own (emit/shader_trig.h): the driver's may be off by 2e-4.
  std::vector<std::string> declared_identifiers(const std::string& prefix) const override {
    std::vector<std::string> names = Backend::declared_identifiers(prefix);
    for (const auto& name : own_trig_names(prefix)) names.push_back(name);
    return names;
  }
  std::string finish_body(const FileFacts& facts, const std::string& body, Precision) const override {
    return call_own_trig(body, facts.prefix);
  }
  std::string precision_section(const FileFacts& facts, const std::string& functions, Precision) const override {
    return with_own_trig(functions, facts.prefix, "glsl/glsl_trig.in");
  }

  std::string parameters(const FileFacts& facts, const EmittedFunction& f, Precision) const override {
    if (!f.takes_point) return "highp float " + f.extra_parameter;
    std::string params = "highp " + vector_type(facts.dims) + " p";
    if (!f.extra_parameter.empty()) params += ", highp float " + f.extra_parameter;
    return params;
  }
  std::string return_type(const FileFacts& facts, const EmittedFunction& f, Precision p) const override {
    return f.vector_result ? "highp " + vector_type(facts.dims) : real_type(p);
  }

  std::string list_entry(const FileFacts& facts, const EmittedFunction& f, Precision) const override {
    const std::string ret = f.vector_result ? vector_type(facts.dims) : "float";
    const std::string args = !f.takes_point ? "float " + f.extra_parameter
                                            : vector_type(facts.dims) + " p" +
                                                  (f.extra_parameter.empty() ? "" : ", float " + f.extra_parameter);
    return fmt::format("    - <{}> {}_{}(<{}>)\n", ret, facts.prefix, f.suffix, args);
  }
  std::string ops_entry(const EmittedFunction& f) const override {
    return fmt::format("    - {}: {}\n", f.suffix, count_ops(*f.program));
  }
  std::string paragraph(const std::string& label, const std::string& text) const override {
    return wrap_paragraph(label + ": " + text, "", "    ");
  }
  std::string method_paragraph(const MethodFacts& m) const override {
    return wrap_paragraph("Method: " + m.summary + " " + m.citation, "    ", "    ");
  }
  std::string comment_paragraph(const std::string& text) const override { return wrap_paragraph(text, "", "    "); }
  std::string nan_note() const override {
    return "GLSL returns intBitsToFloat(0x7fc00000), a NaN where the implementation keeps NaNs (desktop GL, "
           "Vulkan, llvmpipe); GLSL ES 3.00 leaves that value unspecified, so check the range on the host for "
           "WebGL.";
  }
};

}  // namespace

const Backend& glsl_backend() {
  static const GlslBackend instance;
  return instance;
}

}  // namespace offsetgen
