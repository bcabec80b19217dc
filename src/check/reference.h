// The symbolic model behind a file, rebuilt from its metadata with the core pipeline
// (GenerationRequest -> Generation), plus consistency checks between the two.
#pragma once

#include "lowering/program.h"
#include "pipeline/generate.h"
#include "run/metadata.h"

#include <ginac/ginac.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::check {

struct Reference {
  Generation generation;              // surface, offset model, programs (what the file should hold)
  std::vector<std::string> warnings;  // file vs regeneration mismatches that do not stop the check
};

// Throws InputError when the metadata names something the current offsetgen cannot rebuild (unknown
// surface, expression that does not parse, ...), saying that the metadata is the problem.
std::unique_ptr<Reference> rebuild_reference(const run::FileMetadata& meta);

// A wall thickness t(x) in cell units as a double-precision program (inputs x, y[, z]; output "t").
class ThicknessFunction {
 public:
  ThicknessFunction(const GiNaC::ex& t_cell, int dims);
  ThicknessFunction(const ThicknessFunction&) = delete;
  ThicknessFunction& operator=(const ThicknessFunction&) = delete;
  double operator()(const double* p);
  const GiNaC::ex& expression() const { return expression_; }

 private:
  GiNaC::ex expression_;
  int dims_;
  Program program_;
  std::unique_ptr<Evaluator> evaluator_;
  std::vector<double> inputs_;
};

// Parses a --thickness expression for the surface of `meta` (parameters: the file's, then `extra`).
// Throws InputError with the column when it does not parse.
GiNaC::ex parse_thickness(const std::string& text, const run::FileMetadata& meta,
                          const std::map<std::string, std::string>& extra);

}  // namespace offsetgen::check
