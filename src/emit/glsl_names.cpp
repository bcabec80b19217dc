#include "emit/glsl_names.h"

#include <cctype>
#include <set>

namespace offsetgen::glsl_names {
namespace {

// Keywords and reserved words of GLSL 4.60 and GLSL ES 3.00 (the union).
const std::set<std::string>& keywords() {
  static const std::set<std::string> words = {
      "active",     "asm",          "atomic_uint", "attribute",   "bool",         "break",
      "buffer",     "bvec2",        "bvec3",       "bvec4",       "case",         "cast",
      "centroid",   "class",        "coherent",    "common",      "const",        "continue",
      "default",    "discard",      "dmat2",       "dmat2x2",     "dmat2x3",      "dmat2x4",
      "dmat3",      "dmat3x2",      "dmat3x3",     "dmat3x4",     "dmat4",        "dmat4x2",
      "dmat4x3",    "dmat4x4",      "do",          "double",      "dvec2",        "dvec3",
      "dvec4",      "else",         "enum",        "extern",      "external",     "false",
      "filter",     "fixed",        "flat",        "float",       "for",          "fvec2",
      "fvec3",      "fvec4",        "goto",        "half",        "highp",        "hvec2",
      "hvec3",      "hvec4",        "if",          "iimage1D",    "iimage2D",     "iimage3D",
      "image1D",    "image2D",      "image3D",     "in",          "inline",       "inout",
      "input",      "int",          "interface",   "invariant",   "isampler1D",   "isampler2D",
      "isampler3D", "isamplerCube", "ivec2",       "ivec3",       "ivec4",        "layout",
      "long",       "lowp",         "mat2",        "mat2x2",      "mat2x3",       "mat2x4",
      "mat3",       "mat3x2",       "mat3x3",      "mat3x4",      "mat4",         "mat4x2",
      "mat4x3",     "mat4x4",       "mediump",     "namespace",   "noinline",     "noperspective",
      "out",        "output",       "partition",   "patch",       "precise",      "precision",
      "public",     "readonly",     "resource",    "restrict",    "return",       "sample",
      "sampler1D",  "sampler2D",    "sampler3D",   "samplerCube", "shared",       "short",
      "sizeof",     "smooth",       "static",      "struct",      "subroutine",   "superp",
      "switch",     "template",     "this",        "true",        "typedef",      "uimage1D",
      "uimage2D",   "uimage3D",     "uint",        "uniform",     "union",        "unsigned",
      "using",      "usampler1D",   "usampler2D",  "usampler3D",  "usamplerCube", "uvec2",
      "uvec3",      "uvec4",        "varying",     "vec2",        "vec3",         "vec4",
      "void",       "volatile",     "while",       "writeonly"};
  return words;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::optional<std::string> reserved(const std::string& identifier) {
  if (keywords().count(identifier)) return "'" + identifier + "' is a GLSL keyword or reserved word";
  if (starts_with(identifier, "gl_")) return "names beginning with gl_ are reserved in GLSL";
  if (starts_with(identifier, "GL_")) return "macro names beginning with GL_ are reserved in GLSL";
  if (identifier.find("__") != std::string::npos) return "names containing __ are reserved in GLSL";
  if (starts_with(lower(identifier), "webgl_") || starts_with(lower(identifier), "_webgl_"))
    return "names beginning with webgl_ or _webgl_ are reserved in WebGL";
  return std::nullopt;
}

}  // namespace offsetgen::glsl_names
