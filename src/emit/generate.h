// The whole pipeline for one request: surface -> offset model -> programs -> C / GLSL text.
#pragma once

#include "emit/dialect.h"
#include "lowering/surface_programs.h"
#include "offset/offset_model.h"
#include "surfaces/surface.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen {

constexpr int kMaxOrder = 12;

struct GenerationRequest {
  std::string surface;                        // catalog name; empty when `expression` is given
  std::string expression;                     // user expression in x, y[, z]
  std::map<std::string, std::string> params;  // for `expression` and `thickness`
  std::string name;                           // prefix override (required stem for expressions)
  int order = 4;
  bool c = true;
  bool glsl = false;
  std::vector<Precision> precisions = {Precision::Double};
  std::optional<std::string> thickness;       // graded wall t(x, y, z), cell units
  std::string command;                        // the exact command, for the banner
  std::string c_file_name;                    // names printed in the banners
  std::string glsl_file_name;
  std::function<void(const std::string&)> notice;  // announces a long run with a time estimate; may be empty
};

struct Generation {
  Surface surface;
  OffsetModel model;
  SurfacePrograms programs;
  std::string prefix;
  std::string c_header;       // empty unless requested
  std::string glsl_snippet;   // empty unless requested
  std::string metadata_json;  // the C header's block; the GLSL snippet's says "language":"glsl"
};

// Resolves the surface (catalog or expression), validates every input, builds and lowers the
// offset, and renders the requested files. Throws InputError for bad input.
Generation generate(const GenerationRequest& request);

// Just the surface of a request (catalog lookup or parse), validated.
Surface resolve_surface(const GenerationRequest& request);

}  // namespace offsetgen
