// The machine-readable block every emitted file carries:
//   /* offsetgen-metadata {"format":1,"generator":...,"surface":...,"order":4,...} */
// Reading it is how `offsetgen check` knows what a file was made from; nothing else is needed.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::run {

struct FileMetadata {
  std::string language = "c";  // the backend's name (emit/backend.h): what runs the file (run/runner.h)
  int format = 1;
  std::string generator;                      // "offsetgen 0.1.0"
  std::string prefix;                         // function prefix, e.g. gyroid_o4
  std::optional<std::string> surface;         // catalog name, or
  std::optional<std::string> expression;      // user expression in cell coordinates
  std::map<std::string, std::string> params;  // --param values
  double scale = 1;                           // k of X = k x
  int dims = 3;
  std::string method = "richardson";     // the offset method (offset/method.h registry)
  int order = 1;                         // the order the file was built with
  int graded_order = 0;                  // order of its graded walls; 0 when not recorded
  std::optional<std::string> thickness;  // --thickness (total wall thickness), if any
  bool has_double = true;                // C precisions present
  bool has_float = false;
  double gradient_bound = 0;       // the safeguard's M (natural units)
  std::map<std::string, int> ops;  // per function, when present
  // Density (files generated with density functions; density/): the relations' limits as stated,
  // the --density of _wall and its thickness, the --density-field of _graded.
  bool has_density = false;
  double density_limit = 0, thickness_limit = 0, offset_limit = 0;
  double network_density_min = 0, network_density_max = 0;
  std::optional<double> wall_density, wall_thickness;
  std::optional<std::string> density_field;
  bool has_graded() const { return thickness.has_value() || density_field.has_value(); }  // a _graded function
  std::string json;  // the block's JSON text as found
};

// Parses the metadata out of a file's text. The language is the block's "language", a backend's name;
// files written before that field existed (C or GLSL) are told apart by their code, never by their name. Throws
// offsetgen::InputError saying that the file was not produced by offsetgen (no block) or that its
// block is damaged (bad JSON, missing or ill-typed fields), naming the problem.
FileMetadata parse_metadata(const std::string& text);

// Reads `path` and parses it. Throws InputError when the file cannot be read, or is a directory or
// another non-regular file.
FileMetadata read_metadata(const std::string& path, std::string* text_out = nullptr);

}  // namespace offsetgen::run
