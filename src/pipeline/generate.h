// The driver: one request through every stage. Resolve the surface, build the offset with the
// chosen method, lower it to programs, and hand them to the emitters. `check` uses the first three
// stages only (build_generation), so it never needs an emitter to find a surface.
#pragma once

#include "density/density_model.h"
#include "emit/backend.h"
#include "emit/emitted_api.h"
#include "offset/method.h"
#include "offset/surface_programs.h"
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
  std::optional<std::string> thickness;       // graded wall t(x, y, z), cell units (physical with a map)
  // A conforming lattice (surfaces/lattice_map.h): the lattice coordinates of a physical point, and
  // the box where its walls are built and its bounds taken (required with a map). A body's mesh sets
  // the clearance: sample points this close to the map's singular set lie where no wall is kept.
  std::string map;
  std::optional<Surface::Box> domain;
  double singular_clearance = 0;
  // Density (density/): the four density relations; --density adds _wall, the sheet of that
  // relative density; --density-field adds _graded with t(p) = thickness_for_density(rho(p)).
  // Either of the last two implies the first.
  bool density_functions = false;
  std::optional<double> density;
  std::optional<std::string> density_field;
  // What to emit.
  std::vector<std::string> languages = {"c"};  // backend names (emit/backend.h)
  std::vector<Precision> precisions = {Precision::Double};
  std::string command;                             // the exact command, for the banner
  std::map<std::string, std::string> file_names;   // language -> name printed in its banner (default <prefix>.<ext>)
  std::function<void(const std::string&)> notice;  // announces a long run with a time estimate; may be empty
};

struct Generation {
  Surface surface;
  std::unique_ptr<OffsetConstruction> construction;
  SurfacePrograms programs;
  std::string prefix;
  std::string metadata_json;  // the C header's block; each file's names its own language
  // With density functions: the model, the relations as programs, the _wall thickness.
  std::optional<density::DensityModel> density;
  std::optional<density::DensityPrograms> density_programs;
  std::optional<double> wall_thickness;
  std::optional<GiNaC::ex> graded_thickness;  // t(x, y, z) of _graded (--thickness or --density-field)
  std::map<std::string, std::string> files;   // language -> text, for the requested languages (generate())

  // The text of a requested language's file; throws std::out_of_range if it was not requested.
  const std::string& file(const std::string& language) const { return files.at(language); }
  const std::string& c_header() const { return file("c"); }
  const std::string& glsl_snippet() const { return file("glsl"); }

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

// Whether a request asks for the density functions (directly or through --density/--density-field).
bool wants_density(const GenerationRequest& request);

// The density model of a request's surface, with the request's densities checked: throws InputError
// when the surface has none (2D, not periodic) or a density is out of range.
density::DensityModel resolve_density(const GenerationRequest& request, const Surface& surface);

// The emitted functions of a generation (emit/emitted_api.h), density relations included.
std::vector<EmittedFunction> emitted_functions(const Generation& g);

// The default prefix of a request: <surface>_o<order>, with the order the method builds.
std::string default_prefix(const GenerationRequest& request);

}  // namespace offsetgen
