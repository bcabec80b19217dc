// The HLSL target: a paste-safe snippet, <prefix>.hlsl, for Shader Model 5+ (DXC, FXC, glslang's
// HLSL front end; Unity and Unreal shaders). float everywhere, float2/float3 vectors, an include
// guard, no globals at all (so nothing `static` can clash when two snippets meet). Skeletons:
// templates/hlsl/.
#include "emit/backend.h"
#include "emit/emitted_api.h"
#include "emit/shader_trig.h"
#include "offset/method.h"

#include <fmt/format.h>

#include <cmath>
#include <regex>
#include <set>

namespace offsetgen {
namespace {

// HLSL keywords and reserved words (Microsoft's "Keywords" and "Reserved words" pages, SM 6.x).
const std::set<std::string>& hlsl_keywords() {
  static const std::set<std::string> words = {"AppendStructuredBuffer",
                                              "asm",
                                              "asm_fragment",
                                              "auto",
                                              "BlendState",
                                              "bool",
                                              "break",
                                              "Buffer",
                                              "ByteAddressBuffer",
                                              "case",
                                              "catch",
                                              "cbuffer",
                                              "centroid",
                                              "char",
                                              "class",
                                              "column_major",
                                              "compile",
                                              "compile_fragment",
                                              "CompileShader",
                                              "const",
                                              "const_cast",
                                              "continue",
                                              "ComputeShader",
                                              "ConsumeStructuredBuffer",
                                              "default",
                                              "delete",
                                              "DepthStencilState",
                                              "DepthStencilView",
                                              "discard",
                                              "do",
                                              "double",
                                              "DomainShader",
                                              "dword",
                                              "dynamic_cast",
                                              "else",
                                              "enum",
                                              "explicit",
                                              "export",
                                              "extern",
                                              "false",
                                              "float",
                                              "for",
                                              "friend",
                                              "fxgroup",
                                              "GeometryShader",
                                              "goto",
                                              "groupshared",
                                              "half",
                                              "HullShader",
                                              "if",
                                              "in",
                                              "inline",
                                              "inout",
                                              "InputPatch",
                                              "int",
                                              "interface",
                                              "line",
                                              "lineadj",
                                              "linear",
                                              "LineStream",
                                              "long",
                                              "matrix",
                                              "min10float",
                                              "min12int",
                                              "min16float",
                                              "min16int",
                                              "min16uint",
                                              "mutable",
                                              "namespace",
                                              "new",
                                              "nointerpolation",
                                              "noperspective",
                                              "NULL",
                                              "operator",
                                              "out",
                                              "OutputPatch",
                                              "packoffset",
                                              "pass",
                                              "pixelfragment",
                                              "PixelShader",
                                              "point",
                                              "PointStream",
                                              "precise",
                                              "private",
                                              "protected",
                                              "public",
                                              "RasterizerState",
                                              "register",
                                              "reinterpret_cast",
                                              "RenderTargetView",
                                              "return",
                                              "row_major",
                                              "RWBuffer",
                                              "RWByteAddressBuffer",
                                              "RWStructuredBuffer",
                                              "RWTexture1D",
                                              "RWTexture1DArray",
                                              "RWTexture2D",
                                              "RWTexture2DArray",
                                              "RWTexture3D",
                                              "sample",
                                              "sampler",
                                              "SamplerComparisonState",
                                              "SamplerState",
                                              "shared",
                                              "short",
                                              "signed",
                                              "sizeof",
                                              "snorm",
                                              "stateblock",
                                              "stateblock_state",
                                              "static",
                                              "static_cast",
                                              "string",
                                              "struct",
                                              "StructuredBuffer",
                                              "switch",
                                              "tbuffer",
                                              "technique",
                                              "technique10",
                                              "technique11",
                                              "template",
                                              "texture",
                                              "Texture1D",
                                              "Texture1DArray",
                                              "Texture2D",
                                              "Texture2DArray",
                                              "Texture2DMS",
                                              "Texture2DMSArray",
                                              "Texture3D",
                                              "TextureCube",
                                              "TextureCubeArray",
                                              "this",
                                              "throw",
                                              "triangle",
                                              "triangleadj",
                                              "TriangleStream",
                                              "true",
                                              "try",
                                              "typedef",
                                              "typename",
                                              "uint",
                                              "uniform",
                                              "union",
                                              "unorm",
                                              "unsigned",
                                              "using",
                                              "vector",
                                              "vertexfragment",
                                              "VertexShader",
                                              "virtual",
                                              "void",
                                              "volatile",
                                              "while"};
  return words;
}

class HlslBackend final : public Backend {
 public:
  std::string name() const override { return "hlsl"; }
  std::string extension() const override { return "hlsl"; }
  std::string title() const override { return "HLSL"; }
  std::string file_template() const override { return "hlsl_snippet.hlsl.in"; }
  std::string function_template() const override { return "hlsl_function.in"; }
  std::vector<Precision> precisions(const std::vector<Precision>&) const override { return {Precision::Float}; }

  std::string real_type(Precision) const override { return "float"; }
  std::string local_decl(Precision) const override { return "float"; }
  std::string bool_decl() const override { return "bool"; }
  // An unsuffixed floating literal is a float in HLSL (a `1.0L` would be double).
  std::string literal(double value, Precision) const override {
    return std::isnan(value) ? "asfloat(0x7fc00000u)" : float_literal(value);  // NaN: the density relations
  }
  std::string vector_type(int dims) const override { return dims == 3 ? "float3" : "float2"; }
  std::optional<std::string> reserved(const std::string& identifier) const override {
    if (hlsl_keywords().count(identifier)) return "'" + identifier + "' is an HLSL keyword or reserved word";
    static const std::regex vector_or_matrix(
        "(bool|int|uint|dword|half|float|double|min10float|min16float|min12int|min16int|min16uint|int16_t|"
        "uint16_t|int64_t|uint64_t|float16_t|float64_t)[1-4](x[1-4])?");
    if (std::regex_match(identifier, vector_or_matrix)) return "'" + identifier + "' is an HLSL type name";
    // DXC is a C++ front end: names with a double underscore are the implementation's.
    if (identifier.find("__") != std::string::npos) return "names containing __ are reserved in HLSL (DXC)";
    if (identifier.rfind("SV_", 0) == 0) return "names beginning with SV_ are HLSL system-value semantics";
    return std::nullopt;
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
    return with_own_trig(functions, facts.prefix, "hlsl/hlsl_trig.in");
  }

  std::string parameters(const FileFacts& facts, const EmittedFunction& f, Precision) const override {
    if (!f.takes_point) return "float " + f.extra_parameter;
    std::string params = vector_type(facts.dims) + " p";
    if (!f.extra_parameter.empty()) params += ", float " + f.extra_parameter;
    return params;
  }

  std::string list_entry(const FileFacts& facts, const EmittedFunction& f, Precision) const override {
    const std::string args = !f.takes_point ? "float " + f.extra_parameter
                                            : vector_type(facts.dims) + " p" +
                                                  (f.extra_parameter.empty() ? "" : ", float " + f.extra_parameter);
    return fmt::format("    - <{}> {}_{}(<{}>)\n", f.vector_result ? vector_type(facts.dims) : "float", facts.prefix,
                       f.suffix, args);
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
    return "HLSL returns asfloat(0x7fc00000u), a quiet NaN; a compiler that assumes no NaNs (fast math) may "
           "fold it away, so check the range on the host where that matters.";
  }
};

}  // namespace

const Backend& hlsl_backend() {
  static const HlslBackend instance;
  return instance;
}

}  // namespace offsetgen
