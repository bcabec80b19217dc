// The emitted API, shared by every emitter: which functions a file holds, their parameters, docs
// and programs, plus the facts every file's header comment states.
#pragma once

#include "lowering/surface_programs.h"
#include "offset/method.h"
#include "surfaces/surface.h"

#include <string>
#include <vector>

namespace offsetgen {

struct EmittedFunction {
  std::string suffix;  // "field", "offset", "shell", "normal", "graded"
  const Program* program = nullptr;
  std::string extra_parameter;  // "h", "t" or "" after the coordinates
  bool vector_result = false;   // the normal
  std::string doc;              // one line, no prefix
  std::string signature_doc;    // e.g. "(x, y, z, h)"
};

std::vector<EmittedFunction> emitted_functions(const SurfacePrograms& programs, int dims, const MethodFacts& method);

struct FileFacts {
  std::string file_name;
  std::string prefix;
  std::string command;
  int dims = 3;
  const Surface* surface = nullptr;
  const MethodFacts* method = nullptr;
  std::string metadata_json;  // one line
};

std::string guard_name(const std::string& prefix, const std::string& extension);

// A paragraph wrapped to `width` columns: the first line starts with `first`, the others with `rest`.
std::string wrap_paragraph(const std::string& text, const std::string& first, const std::string& rest,
                           size_t width = 100);

}  // namespace offsetgen
