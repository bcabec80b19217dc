// Host-shader assembly around a pasted offsetgen GLSL snippet, plus the bookkeeping that turns a
// compiler's line numbers back into snippet lines. Pure C++ (no GL), shared by the renderer and
// by the GLSL tests (tests/glsl), so both report errors the same way.
#pragma once

#include <string>
#include <vector>

namespace offsetgen::glsl {

// A full shader source made of: host prologue, the snippet byte for byte, host epilogue.
// Remembers where the snippet sits so compiler messages can point at snippet lines.
struct HostedSource {
  std::string text;          // what goes to the compiler
  std::string snippet;       // the snippet, verbatim
  int snippet_first_line{};  // 1-based line of `text` holding snippet line 1
  int snippet_line_count{};  // number of lines of the snippet

  // "snippet line 12: <text>" when host_line falls inside the snippet, else "host line 40: <text>".
  [[nodiscard]] std::string describe_line(int host_line) const;
};

// Assembles prologue + snippet + epilogue. A newline is added after the snippet only when it does
// not already end with one, so the snippet's own bytes are never altered.
HostedSource assemble(const std::string& prologue, const std::string& snippet, const std::string& epilogue);

// Line numbers referenced by a compiler log's errors (its warnings' when it has no error), in
// order of first appearance, deduplicated.
// Understands glslang ("ERROR: file:12: ...") and Mesa ("0:12(5): error: ...").
std::vector<int> referenced_lines(const std::string& log);

// The compiler log followed by one "  snippet line N: ..." / "  host line N: ..." per referenced
// line.
std::string annotate_log(const std::string& log, const HostedSource& source);

// One parameter of a GLSL function definition.
struct GlslParam {
  std::string qualifier;  // "", "in", "out", "inout" ("const" is dropped)
  std::string type;       // e.g. "vec3"
  std::string name;
};

// One top-level function definition found in a snippet.
struct GlslFunction {
  std::string return_type;  // e.g. "float" (precision qualifier stripped)
  std::string name;
  std::vector<GlslParam> params;
};

// Top-level function definitions of a snippet (prototypes without a body are skipped), in order.
// Comments and preprocessor lines are ignored; one entry per name (first definition wins).
std::vector<GlslFunction> scan_functions(const std::string& snippet);

// Float-typed declarations (function results, parameters, locals, globals of type float, vecN,
// matN) that do not say highp, as "snippet line N: <text>". A host may declare
// "precision mediump float;" and some drivers then really compute in fp16, so the contract puts
// highp on every float; llvmpipe computes mediump in fp32 and cannot catch a missing one.
std::vector<std::string> declarations_without_highp(const std::string& snippet);

// The snippet's text with comments replaced by spaces (newlines kept, so line numbers survive).
std::string strip_comments(const std::string& src);

// Reads a whole file; throws std::runtime_error naming the path when it cannot.
std::string read_text_file(const std::string& path);

}  // namespace offsetgen::glsl
