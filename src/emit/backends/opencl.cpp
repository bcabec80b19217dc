// The OpenCL C target: <prefix>.cl, program source for OpenCL C 1.2 and later, with the functions
// and a batch kernel in float (f-suffixed names: <prefix>_offsetf, <prefix>_offsetf_kernel) and, where
// the device reports cl_khr_fp64, in double (the C header's names). float3/double3 points, OpenCL's
// own math (sinpi and cospi for the trig of 2 pi x, sincos, rsqrt). Skeletons: templates/opencl/.
#include "emit/backend.h"
#include "emit/c_family.h"
#include "emit/call_rewrites.h"
#include "emit/emitted_api.h"
#include "emit/templates.h"
#include "offset/method.h"

#include <fmt/format.h>

#include <cmath>
#include <regex>
#include <set>

namespace offsetgen {
namespace {

// OpenCL C's keywords beyond C99's, its address space and access qualifiers, built-in scalar, image
// and other opaque types, and C99's keywords (OpenCL C 3.0, sections 6.1-6.8).
const std::set<std::string>& opencl_words() {
  static const std::set<std::string> words = {
      // C99
      "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum", "extern",
      "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return", "short", "signed",
      "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void", "volatile", "while", "_Bool",
      "_Complex", "_Imaginary",
      // OpenCL C qualifiers
      "__global", "global", "__local", "local", "__constant", "constant", "__private", "private", "__generic",
      "generic", "__kernel", "kernel", "__read_only", "read_only", "__write_only", "write_only", "__read_write",
      "read_write", "uniform", "pipe", "__attribute__",
      // built-in and reserved types
      "bool", "uchar", "ushort", "uint", "ulong", "half", "quad", "size_t", "ptrdiff_t", "intptr_t", "uintptr_t",
      "image1d_t", "image1d_array_t", "image1d_buffer_t", "image2d_t", "image2d_array_t", "image2d_depth_t",
      "image2d_array_depth_t", "image3d_t", "sampler_t", "event_t", "queue_t", "ndrange_t", "clk_event_t",
      "reserve_id_t", "cl_mem_fence_flags", "memory_scope", "memory_order", "atomic_int", "atomic_uint", "atomic_long",
      "atomic_ulong", "atomic_float", "atomic_double", "atomic_flag", "complex", "imaginary",
      // the macros every OpenCL C compiler defines that an identifier could spell
      "NAN", "INFINITY", "HUGE_VAL", "HUGE_VALF", "MAXFLOAT", "FLT_MAX", "DBL_MAX", "M_PI", "M_PI_F"};
  return words;
}

bool batched(const EmittedFunction& f) { return f.suffix == "offset" && f.takes_point && !f.vector_result; }

class OpenclBackend final : public Backend {
 public:
  std::string name() const override { return "opencl"; }
  std::string extension() const override { return "cl"; }
  std::string title() const override { return "OpenCL C"; }
  std::string file_template() const override { return "opencl_source.cl.in"; }
  std::string function_template() const override { return "opencl_function.in"; }
  // float everywhere, double where cl_khr_fp64 exists (guarded in the file): both, float first.
  std::vector<Precision> precisions(const std::vector<Precision>&) const override {
    return {Precision::Float, Precision::Double};
  }

  std::string real_type(Precision p) const override { return p == Precision::Double ? "double" : "float"; }
  std::string local_decl(Precision p) const override { return "const " + real_type(p); }
  std::string bool_decl() const override { return "const bool"; }
  // An unsuffixed floating literal is a double in OpenCL C: float literals carry f.
  std::string literal(double value, Precision p) const override {
    if (std::isnan(value)) return p == Precision::Double ? "(double)NAN" : "NAN";  // the density relations
    return c_family::literal(value, p);
  }
  std::string suffix(Precision p) const override { return p == Precision::Float ? "f" : ""; }
  // OpenCL's math built-ins are overloaded: one name for float and double.
  std::string function(Fn fn, Precision) const override { return offsetgen::function_name(fn); }
  std::string sqrt_name(Precision) const override { return "sqrt"; }
  std::string abs_name(Precision) const override { return "fabs"; }
  std::string pow_name(Precision) const override { return "pow"; }
  std::string atan2_name(Precision) const override { return "atan2"; }
  std::string vector_type(int dims) const override { return dims == 3 ? "float3" : "float2"; }
  std::optional<std::string> reserved(const std::string& identifier) const override {
    if (opencl_words().count(identifier)) return "'" + identifier + "' is an OpenCL C keyword, qualifier or type";
    static const std::regex vector_or_matrix(
        "(bool|char|uchar|short|ushort|int|uint|long|ulong|half|float|double|quad)(2|3|4|8|16)(x(2|3|4|8|16))?");
    if (std::regex_match(identifier, vector_or_matrix))
      return "'" + identifier + "' is an OpenCL C vector type (or a reserved matrix type)";
    if (identifier.rfind("__", 0) == 0 ||
        (identifier.size() > 1 && identifier[0] == '_' && std::isupper(static_cast<unsigned char>(identifier[1]))))
      return "names beginning with __ or _ and a capital are the OpenCL C implementation's";
    if (identifier.rfind("cl_", 0) == 0 || identifier.rfind("CL_", 0) == 0)
      return "names beginning with cl_ or CL_ are OpenCL's (extensions, macros)";
    return std::nullopt;
  }
  std::vector<std::string> declared_identifiers(const std::string& prefix) const override {
    std::vector<std::string> names;
    for (const auto& suffix : function_suffixes()) {
      const std::string name = prefix + "_" + suffix;
      names.insert(names.end(), {name, name + "f"});
    }
    names.insert(names.end(), {prefix + "_offset_kernel", prefix + "_offsetf_kernel", guard_name(prefix, "cl")});
    return names;
  }

  std::string parameters(const FileFacts& facts, const EmittedFunction& f, Precision p) const override {
    const std::string real = real_type(p);
    if (!f.takes_point) return real + " " + f.extra_parameter;
    std::string params = fmt::format("{}{} p", real, facts.dims);
    if (!f.extra_parameter.empty()) params += fmt::format(", {} {}", real, f.extra_parameter);
    return params;
  }
  std::string return_type(const FileFacts& facts, const EmittedFunction& f, Precision p) const override {
    return f.vector_result ? fmt::format("{}{}", real_type(p), facts.dims) : real_type(p);
  }
  // The vector's type depends on the precision, which only finish_body knows: a placeholder till then.
  std::string vector_return(const FileFacts& facts, const std::vector<std::string>& components) const override {
    std::string list;
    for (const auto& c : components) list += (list.empty() ? "" : ", ") + c;
    return fmt::format("    return ({}{})({});\n", kRealPlaceholder, facts.dims, list);
  }
  bool half_turn_trig() const override { return true; }  // sinpi, cospi (OpenCL C 1.0)
  std::string finish_body(const FileFacts&, const std::string& body, Precision p) const override {
    const std::string real = real_type(p);
    std::string text =
        fuse_sincos(body, "sin", "cos", [&](const std::string& argument, const std::string& s, const std::string& c) {
          return fmt::format("    {0} {1};\n    const {0} {2} = sincos({3}, &{1});\n", real, c, s, argument);
        });
    text = use_rsqrt(text, "sqrt", "rsqrt");
    for (size_t at = text.find(kRealPlaceholder); at != std::string::npos; at = text.find(kRealPlaceholder))
      text.replace(at, std::string(kRealPlaceholder).size(), real);
    return text;
  }

  std::string list_entry(const FileFacts& facts, const EmittedFunction& f, Precision p) const override {
    const std::string call =
        fmt::format("{} {}({})", return_type(facts, f, p), emitted_name(facts, f, p), parameters(facts, f, p));
    return fmt::format(" *   {:<52} {}\n", call, f.doc);
  }
  std::string ops_entry(const EmittedFunction& f) const override { return c_family::ops_entry(f); }
  std::string paragraph(const std::string& label, const std::string& text) const override {
    return c_family::paragraph(label, text);
  }
  std::string method_paragraph(const MethodFacts& m) const override { return c_family::method_paragraph(m); }
  std::string comment_paragraph(const std::string& text) const override { return c_family::comment_paragraph(text); }
  std::string nan_note() const override {
    return "OpenCL C returns NAN ((double)NAN in double); a program built with -cl-fast-relaxed-math or "
           "-cl-finite-math-only may not keep NaNs, so check the range on the host where that matters.";
  }
  // The double functions exist only where the device has cl_khr_fp64.
  std::string precision_section(const FileFacts&, const std::string& functions, Precision p) const override {
    if (p == Precision::Float) return functions;
    const auto sections = load_template_sections("opencl/opencl_support.in", {"double_begin", "double_end"});
    return sections.at("double_begin") + functions + sections.at("double_end");
  }
  std::string trailing_sections(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                                const std::vector<Precision>& precisions) const override {
    const auto sections =
        load_template_sections("opencl/opencl_support.in", {"double_begin", "double_end", "kernels", "kernel"});
    std::string list, kernels;
    for (const auto& f : functions) {
      if (!batched(f)) continue;
      for (Precision p : precisions) {
        const std::string real = real_type(p);
        std::vector<std::string> coordinates = {"x", "y"};
        if (facts.dims == 3) coordinates.push_back("z");
        std::string array_params, point, args;
        for (const auto& c : coordinates) {
          array_params += fmt::format("{}__global const {} *{}", array_params.empty() ? "" : ", ", real, c);
          point += (point.empty() ? "" : ", ") + c + "[i]";
          args += c + ", ";
        }
        const std::string scalar = emitted_name(facts, f, p);
        const std::string name = scalar + "_kernel";
        list += fmt::format(" *   __kernel {}(ulong n, {}{}, out)   ({}{})\n", name, args, f.extra_parameter, real,
                            p == Precision::Double ? ", cl_khr_fp64" : "");
        const std::string kernel = fmt::format(
            fmt::runtime(sections.at("kernel")), fmt::arg("name", name), fmt::arg("array_params", array_params),
            fmt::arg("real", real), fmt::arg("extra", f.extra_parameter), fmt::arg("scalar", scalar),
            fmt::arg("call", fmt::format("({}{})({}), {}", real, facts.dims, point, f.extra_parameter)));
        kernels += p == Precision::Double ? sections.at("double_begin") + kernel + sections.at("double_end") : kernel;
      }
    }
    if (list.empty()) return "";
    list.pop_back();
    return fmt::format(fmt::runtime(sections.at("kernels")), fmt::arg("list", list), fmt::arg("kernels", kernels));
  }

 private:
  static constexpr const char* kRealPlaceholder = "@OFFSETGEN_REAL@";
};

}  // namespace

const Backend& opencl_backend() {
  static const OpenclBackend instance;
  return instance;
}

}  // namespace offsetgen
