// Rewrites of a printed function body (emit/render.cpp's finish_body) into a GPU language's fused
// math calls: one sincos for a sin and a cos of the same argument, rsqrt for a division by a
// square root. Used by the CUDA and OpenCL C backends.
#pragma once

#include <functional>
#include <string>

namespace offsetgen {

// The lines (indented, newline-terminated) that declare `sin_var` and `cos_var` from `argument`.
using SincosDeclaration =
    std::function<std::string(const std::string& argument, const std::string& sin_var, const std::string& cos_var)>;

// Every argument that `body` passes both to `sin_name` and to `cos_name` gets one sincos: `declare`'s
// lines go in before the first line calling either, and the calls become the variables
// _s<stem><k>, _c<stem><k> (a second fusion of other names, sinpi and cospi, takes another stem).
std::string fuse_sincos(const std::string& body, const std::string& sin_name, const std::string& cos_name,
                        const SincosDeclaration& declare, const std::string& stem = "");

// "1.0 / sqrt(e)" -> "rsqrt(e)", "a / sqrt(e)" -> "a * rsqrt(e)", and "_tB = 1.0 / _tA" where
// "_tA = sqrt(e)" -> "_tB = rsqrt(e)" (names as given: sqrtf, rsqrtf, ...).
std::string use_rsqrt(const std::string& body, const std::string& sqrt_name, const std::string& rsqrt_name);

}  // namespace offsetgen
