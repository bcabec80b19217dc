// The emitted API, shared by every emitter: which functions a file holds, their parameters, docs
// and programs, plus the facts every file's header comment states.
#pragma once

#include "density/density_model.h"
#include "offset/method.h"
#include "offset/surface_programs.h"
#include "surfaces/surface.h"

#include <optional>
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
  bool takes_point = true;      // false: a function of extra_parameter alone (the density relations)
};

// `density`: the density relations (density/density_model.h), when the file has them.
std::vector<EmittedFunction> emitted_functions(const SurfacePrograms& programs, int dims, const MethodFacts& method,
                                               const density::DensityPrograms* density = nullptr);

struct FileFacts {
  std::string file_name;
  std::string prefix;
  std::string command;
  int dims = 3;
  const Surface* surface = nullptr;
  const MethodFacts* method = nullptr;
  std::string metadata_json;  // one line
  // Density (density/): the model when the file has the density functions, the --density of
  // _wall and its thickness, the --density-field of _graded.
  const density::DensityModel* density = nullptr;
  std::optional<double> wall_density, wall_thickness;
  std::optional<std::string> density_field;
};

// The paragraph on density a file's header comment states (no comment markers, one sentence per
// line); "" without density functions. `nan_note` (Backend::nan_note) ends the out-of-range sentence.
std::string density_paragraph(const FileFacts& facts, const std::string& nan_note);

std::string guard_name(const std::string& prefix, const std::string& extension);

// A paragraph wrapped to `width` columns: the first line starts with `first`, the others with `rest`.
std::string wrap_paragraph(const std::string& text, const std::string& first, const std::string& rest,
                           size_t width = 100);

}  // namespace offsetgen
