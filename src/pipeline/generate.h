// The driver: one request through every stage. Resolve the surface, build the offset with the
// chosen method, lower it to programs, and hand them to the emitters. `check` uses the first three
// stages only (build_generation), so it never needs an emitter to find a surface.
#pragma once

#include "emit/dialect.h"
#include "lowering/surface_programs.h"
#include "offset/method.h"
#include "surfaces/surface.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen {

struct GenerationRequest {
  // What to build.
  std::string surface;                        // catalog name; empty when `expression` is given
  std::string expression;                     // user expression in x, y[, z]
  std::map<std::string, std::string> params;  // for `expression` and `thickness`
  std::string name;                           // prefix override (required stem for expressions)
  std::string method = kDefaultMethod;        // an offset method of the registry (offset/method.h)
  int order = 4;                              // as asked; the method may round it (projection: even)
  std::optional<std::string> thickness;       // graded wall t(x, y, z), cell units
  // What to emit.
  bool c = true;
  bool glsl = false;
  std::vector<Precision> precisions = {Precision::Double};
  std::string command;      // the exact command, for the banner
  std::string c_file_name;  // names printed in the banners
  std::string glsl_file_name;
  std::function<void(const std::string&)> notice;  // announces a long run with a time estimate; may be empty
};

struct Generation {
  Surface surface;
  std::unique_ptr<OffsetConstruction> construction;
  SurfacePrograms programs;
  std::string prefix;
  std::string metadata_json;  // the C header's block; the GLSL snippet's says "language":"glsl"
  std::string c_header;      // empty unless requested (generate())
  std::string glsl_snippet;  // empty unless requested (generate())

  const MethodFacts& method() const { return construction->facts(); }
  int order() const { return method().order; }
};

// Resolves, validates, builds and lowers. Throws InputError for bad input.
Generation build_generation(const GenerationRequest& request);

// build_generation, then the requested files.
Generation generate(const GenerationRequest& request);

// Just the surface of a request (catalog lookup or parse), validated.
Surface resolve_surface(const GenerationRequest& request);

// The method of a request, with its order checked: throws InputError for an unknown method or an
// order out of its range.
const OffsetMethod& resolve_method(const GenerationRequest& request);

// The default prefix of a request: <surface>_o<order>, with the order the method builds.
std::string default_prefix(const GenerationRequest& request);

}  // namespace offsetgen
