// The WGSL target: <prefix>.wgsl, module-scope functions for WebGPU shaders (Dawn, wgpu/naga,
// browsers). f32 everywhere, vec2<f32>/vec3<f32> vectors, `let` temporaries, no globals. WGSL has no
// preprocessor, so there is no include guard: a file is pasted once per module, and a second copy
// is a redeclaration error that the WGSL compiler names. Skeletons: templates/wgsl/.
#include "emit/backend.h"
#include "emit/emitted_api.h"
#include "emit/shader_trig.h"
#include "offset/method.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

namespace offsetgen {
namespace {

// WGSL keywords and reserved words (W3C WGSL, "Keyword Summary" and "Reserved Words"), the union
// over the drafts since 2023 (binding_array left the list, non_coherent and noncoherent joined it).
// Dawn (npm webgpu 0.6.2) refuses every one of them as a function name except binding_array.
const std::set<std::string>& wgsl_keywords() {
  static const std::set<std::string> words = {
      // keywords
      "alias", "break", "case", "const", "const_assert", "continue", "continuing", "default", "diagnostic", "discard",
      "else", "enable", "false", "fn", "for", "if", "let", "loop", "override", "requires", "return", "struct", "switch",
      "true", "var", "while",
      // reserved words
      "NULL", "Self", "abstract", "active", "alignas", "alignof", "as", "asm", "asm_fragment", "async", "attribute",
      "auto", "await", "become", "binding_array", "cast", "catch", "class", "co_await", "co_return", "co_yield",
      "coherent", "column_major", "common", "compile", "compile_fragment", "concept", "const_cast", "consteval",
      "constexpr", "constinit", "crate", "debugger", "decltype", "delete", "demote", "demote_to_helper", "do",
      "dynamic_cast", "enum", "explicit", "export", "extends", "extern", "external", "fallthrough", "filter", "final",
      "finally", "friend", "from", "fxgroup", "get", "goto", "groupshared", "highp", "impl", "implements", "import",
      "inline", "instanceof", "interface", "layout", "lowp", "macro", "macro_rules", "match", "mediump", "meta", "mod",
      "module", "move", "mut", "mutable", "namespace", "new", "nil", "noexcept", "noinline", "nointerpolation",
      "non_coherent", "noncoherent", "noperspective", "null", "nullptr", "of", "operator", "package", "packoffset",
      "partition", "pass", "patch", "pixelfragment", "precise", "precision", "premerge", "priv", "protected", "pub",
      "public", "readonly", "ref", "regardless", "register", "reinterpret_cast", "require", "resource", "restrict",
      "self", "set", "shared", "sizeof", "smooth", "snorm", "static", "static_assert", "static_cast", "std",
      "subroutine", "super", "target", "template", "this", "thread_local", "throw", "trait", "try", "type", "typedef",
      "typeid", "typename", "typeof", "union", "unless", "unorm", "unsafe", "unsized", "use", "using", "varying",
      "virtual", "volatile", "wgsl", "where", "with", "writeonly", "yield"};
  return words;
}

// WGSL rejects a constant expression whose value is NaN ("value nan cannot be represented as
// 'f32'"), so a NaN is read from a `let`, which is not a constant expression.
constexpr const char* kNanBits = "_nan_bits";
constexpr const char* kNan = "bitcast<f32>(_nan_bits)";

class WgslBackend final : public Backend {
 public:
  std::string name() const override { return "wgsl"; }
  std::string extension() const override { return "wgsl"; }
  std::string title() const override { return "WGSL"; }
  std::string file_template() const override { return "wgsl_snippet.wgsl.in"; }
  std::string function_template() const override { return "wgsl_function.in"; }
  std::vector<Precision> precisions(const std::vector<Precision>&) const override { return {Precision::Float}; }

  std::string real_type(Precision) const override { return "f32"; }
  std::string local_decl(Precision) const override { return "let"; }
  std::string bool_decl() const override { return "let"; }
  // The f suffix makes every literal a concrete f32, as the C float variant computes, rather than an
  // AbstractFloat folded in higher precision.
  std::string literal(double value, Precision) const override {
    if (std::isnan(value)) return kNan;  // the density relations
    const std::string text = float_literal(value);
    return value < 0 ? text.substr(0, text.size() - 1) + "f)" : text + "f";
  }
  std::string select(const std::string& condition, const std::string& if_true,
                     const std::string& if_false) const override {
    return "select(" + if_false + ", " + if_true + ", " + condition + ")";
  }
  std::string vector_type(int dims) const override { return dims == 3 ? "vec3<f32>" : "vec2<f32>"; }
  std::optional<std::string> reserved(const std::string& identifier) const override {
    if (wgsl_keywords().count(identifier)) return "'" + identifier + "' is a WGSL keyword or reserved word";
    if (identifier.rfind("__", 0) == 0) return "WGSL identifiers must not begin with __";
    if (identifier == "_") return "a lone _ is not a WGSL identifier";
    return std::nullopt;
  }
  // Functions only: no guard, no macros.
  std::vector<std::string> declared_identifiers(const std::string& prefix) const override {
    std::vector<std::string> names;
    for (const auto& suffix : function_suffixes()) names.push_back(prefix + "_" + suffix);
    for (const auto& name : own_trig_names(prefix)) names.push_back(name);
    return names;
  }

  std::string parameters(const FileFacts& facts, const EmittedFunction& f, Precision) const override {
    if (!f.takes_point) return f.extra_parameter + ": f32";
    std::string params = "p: " + vector_type(facts.dims);
    if (!f.extra_parameter.empty()) params += ", " + f.extra_parameter + ": f32";
    return params;
  }
  // The file ends with the last function's closing brace (the function template ends in a blank line).
  // The snippet's own sin/cos (emit/shader_trig.h) ahead of the functions that call them.
  std::string precision_section(const FileFacts& facts, const std::string& functions, Precision) const override {
    const std::string all = with_own_trig(functions, facts.prefix, "wgsl/wgsl_trig.in");
    return all.size() >= 2 && all.compare(all.size() - 2, 2, "\n\n") == 0 ? all.substr(0, all.size() - 1) : all;
  }
  std::string finish_body(const FileFacts& facts, const std::string& body, Precision) const override {
    const std::string own = call_own_trig(body, facts.prefix);
    if (own.find(kNan) == std::string::npos) return own;
    return fmt::format("    let {} = 0x7fc00000u;\n", kNanBits) + own;
  }

  std::string list_entry(const FileFacts& facts, const EmittedFunction& f, Precision p) const override {
    return fmt::format("    - fn {}_{}({}) -> {}\n", facts.prefix, f.suffix, parameters(facts, f, p),
                       return_type(facts, f, p));
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
    return "WGSL returns bitcast<f32>(0x7fc00000u) read through a let (WGSL rejects a NaN constant), a quiet "
           "NaN; WGSL lets an implementation assume no NaNs and fold it away, so check the range on the host "
           "where that matters.";
  }
};

}  // namespace

const Backend& wgsl_backend() {
  static const WgslBackend instance;
  return instance;
}

}  // namespace offsetgen
