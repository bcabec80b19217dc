// What the C-family backends (C, CUDA, OpenCL C) print alike: C's scalar signatures and vector
// results (C and CUDA), C's floating literals and the ` * `-prefixed file comment (all three).
// One place, so that a change to the C header's conventions reaches its GPU cousins.
#pragma once

#include "emit/backend.h"

#include <string>
#include <vector>

namespace offsetgen::c_family {

// x, y[, z] for functions of the point, then the extra parameter (h, t), as the body reads them.
std::vector<std::string> input_names(const FileFacts& facts, const EmittedFunction& f);

// "double x, double y, double z, double h", the normal with ", double n[3]" appended.
std::string parameters(const FileFacts& facts, const EmittedFunction& f, const std::string& real);

// "    n[0] = ...;\n" per component: a vector result is written through the n[] parameter.
std::string vector_return(const std::vector<std::string>& components);

// A finite value as a C literal: 17 significant digits in double, float's 9 with an f suffix;
// negative values in parentheses. (NaN is each language's own.)
std::string literal(double value, Precision p);

// The file comment: a labelled paragraph, the method's paragraph, a plain paragraph, an ops line.
std::string paragraph(const std::string& label, const std::string& text);
std::string method_paragraph(const MethodFacts& m);
std::string comment_paragraph(const std::string& text);
std::string ops_entry(const EmittedFunction& f);

}  // namespace offsetgen::c_family
