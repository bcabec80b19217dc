// The CUDA target: <prefix>.cuh, a header for .cu files with __host__ __device__ functions in double
// and float (f-suffixed names, as in the C header), written with CUDA's own math (sincospi and sinpi/
// cospi for the trig of 2 pi x, sincos for a sin and a cos of the same argument, rsqrt for a division
// by a square root), and a batch kernel
// <prefix>_offset_kernel (and <prefix>_offsetf_kernel). Skeletons: templates/cuda/.
#include "emit/backend.h"
#include "emit/c_family.h"
#include "emit/c_names.h"
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

// What the CUDA toolkit declares in every .cu file beyond C++ (cuda_runtime.h, the built-in
// variables and vector types): a header declaring one of these would not compile or would shadow it.
std::optional<std::string> cuda_reserved(const std::string& identifier) {
  static const std::set<std::string> builtins = {"threadIdx",   "blockIdx",     "blockDim", "gridDim",
                                                 "warpSize",    "dim3",         "half",     "half2",
                                                 "nv_bfloat16", "nv_bfloat162", "texture",  "surface"};
  if (builtins.count(identifier)) return "'" + identifier + "' is a CUDA built-in name";
  static const std::regex vector_type(
      "(make_)?(char|uchar|short|ushort|int|uint|long|ulong|longlong|ulonglong|float|double)[1-4]");
  if (std::regex_match(identifier, vector_type)) return "'" + identifier + "' is a CUDA vector type or its maker";
  static const std::regex runtime_api("(cuda|cu|cublas|cufft|curand|nv)[A-Z].*|CUDA_.*|CUDART_.*|__.*");
  if (std::regex_match(identifier, runtime_api))
    return "'" + identifier + "' is in a namespace the CUDA toolkit reserves (cuda*, cu*, CUDA_*, CUDART_*, __*)";
  return std::nullopt;
}

bool batched(const EmittedFunction& f) { return f.suffix == "offset" && f.takes_point && !f.vector_result; }

class CudaBackend final : public Backend {
 public:
  std::string name() const override { return "cuda"; }
  std::string extension() const override { return "cuh"; }
  std::string title() const override { return "CUDA"; }
  std::string file_template() const override { return "cuda_header.cuh.in"; }
  std::string function_template() const override { return "cuda_function.in"; }
  // GPU code wants float, and double where its accuracy matters: both, always.
  std::vector<Precision> precisions(const std::vector<Precision>&) const override {
    return {Precision::Double, Precision::Float};
  }

  std::string real_type(Precision p) const override { return p == Precision::Double ? "double" : "float"; }
  std::string local_decl(Precision p) const override { return "const " + real_type(p); }
  std::string bool_decl() const override { return "const bool"; }
  std::string literal(double value, Precision p) const override {
    if (std::isnan(value)) return p == Precision::Double ? "nan(\"\")" : "nanf(\"\")";  // the density relations
    return c_family::literal(value, p);
  }
  std::string suffix(Precision p) const override { return p == Precision::Float ? "f" : ""; }
  std::string abs_name(Precision p) const override { return "fabs" + suffix(p); }
  std::string vector_type(int dims) const override { return fmt::format("[{}]", dims); }
  std::optional<std::string> reserved(const std::string& identifier) const override {
    if (auto why = c_names::reserved(identifier)) return why;  // C++ keywords and reserved names
    return cuda_reserved(identifier);
  }
  std::vector<std::string> declared_identifiers(const std::string& prefix) const override {
    std::vector<std::string> names;
    for (const auto& suffix : function_suffixes()) {
      const std::string name = prefix + "_" + suffix;
      names.insert(names.end(), {name, name + "f"});
    }
    names.insert(names.end(), {prefix + "_offset_kernel", prefix + "_offsetf_kernel", guard_name(prefix, "cuh")});
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
  bool half_turn_trig() const override { return true; }  // sinpi, cospi, sincospi (and the f forms)
  std::string finish_body(const FileFacts&, const std::string& body, Precision p) const override {
    const std::string f = suffix(p), real = real_type(p);
    // One sincos (sincospi) per argument of both a sin and a cos (a sinpi and a cospi).
    auto fuse = [&](const std::string& text, const std::string& kind, const std::string& stem) {
      return fuse_sincos(
          text, "sin" + kind + f, "cos" + kind + f,
          [&](const std::string& argument, const std::string& s, const std::string& c) {
            return fmt::format("    {} {}, {};\n    sincos{}{}({}, &{}, &{});\n", real, s, c, kind, f, argument, s, c);
          },
          stem);
    };
    return use_rsqrt(fuse(fuse(body, "pi", "p"), "", ""), "sqrt" + f, "offsetgen_rsqrt" + f);
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
  std::string nan_note() const override {
    return "CUDA returns nan(\"\") (nanf(\"\") in float); code compiled with -use_fast_math may not keep NaNs, "
           "so check the range on the host where that matters.";
  }
  // The rsqrt helper, once, ahead of the functions of each precision that call it.
  std::string precision_section(const FileFacts&, const std::string& functions, Precision p) const override {
    if (functions.find("offsetgen_rsqrt" + suffix(p) + "(") == std::string::npos) return functions;
    const auto sections = load_template_sections("cuda/cuda_support.in", {"rsqrt_double", "rsqrt_float"});
    return fmt::format(fmt::runtime(sections.at(p == Precision::Double ? "rsqrt_double" : "rsqrt_float"))) + functions;
  }
  std::string trailing_sections(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                                const std::vector<Precision>& precisions) const override {
    const auto sections = load_template_sections("cuda/cuda_support.in", {"kernels", "kernel"});
    std::string list, kernels;
    for (const auto& f : functions) {
      if (!batched(f)) continue;
      for (Precision p : precisions) {
        std::vector<std::string> coordinates = {"x", "y"};
        if (facts.dims == 3) coordinates.push_back("z");
        std::string array_params, call, args;
        for (const auto& c : coordinates) {
          array_params += fmt::format("{}const {} *__restrict__ {}", array_params.empty() ? "" : ", ", real_type(p), c);
          call += c + "[i], ";
          args += c + ", ";
        }
        call += f.extra_parameter;
        const std::string scalar = emitted_name(facts, f, p);
        const std::string name = scalar + "_kernel";
        list += fmt::format(" *   {}<<<blocks, threads>>>(n, {}{}, out)   ({})\n", name, args, f.extra_parameter,
                            real_type(p));
        kernels +=
            fmt::format(fmt::runtime(sections.at("kernel")), fmt::arg("name", name),
                        fmt::arg("array_params", array_params), fmt::arg("real", real_type(p)),
                        fmt::arg("extra", f.extra_parameter), fmt::arg("scalar", scalar), fmt::arg("call", call));
      }
    }
    if (list.empty()) return "";
    list.pop_back();
    return fmt::format(fmt::runtime(sections.at("kernels")), fmt::arg("list", list), fmt::arg("prefix", facts.prefix),
                       fmt::arg("kernels", kernels));
  }
};

}  // namespace

const Backend& cuda_backend() {
  static const CudaBackend instance;
  return instance;
}

}  // namespace offsetgen
