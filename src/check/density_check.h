// `offsetgen check` on a file with density functions (density/, docs/density.md): the emitted
// relations against the model's own (robust) solutions, NaN out of range, and the volume fraction
// of the emitted solids measured by column integration (volume_fraction.h) against the requested
// density: the sheet _shell(p, thickness_for_density(rho)), the network offset(p,
// offset_for_density(rho)) < 0, _wall, and for a density field the fraction of every cell of a
// block against the field's mean over that cell.
#pragma once

#include "density/density_model.h"
#include "numeric/volume_fraction.h"
#include "run/c_library.h"
#include "run/metadata.h"

#include <ginac/ginac.h>
#include <nlohmann/json.hpp>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::check {

struct DensityCheckOptions {
  std::vector<double> sheet = {0.05, 0.1, 0.2, 0.3};  // densities of the sheet (those within rho_max run)
  std::vector<double> network = {0.2, 0.5, 0.8};      // densities of the network solid (within its range)
  double tolerance = 2e-4;                            // |measured - requested| per density
  double cell_tolerance = 2e-4;                       // per cell of a density field's block
  std::array<int, 3> block = {2, 2, 2};               // cells of the density field's block
  numeric::VolumeFractionOptions sampling;
  std::function<void(const std::string&)> progress;  // may be empty
};

struct DensityRow {
  std::string solid;  // "sheet", "network", "wall"
  double requested = 0;
  double parameter = 0;  // t (sheet, wall) or h (network), from the emitted inverse
  numeric::VolumeFraction measured;
  double deviation = 0;  // measured - requested
};

struct DensityCellRow {
  std::array<int, 3> cell{};
  double requested = 0;  // mean of rho over the cell
  numeric::VolumeFraction measured;
  double deviation = 0;
};

struct DensityReport {
  double tolerance = 0, cell_tolerance = 0;
  // The emitted relations against the model: largest relative difference over the valid range, and
  // whether every out-of-range argument gave NaN.
  double max_relation_error = 0;
  std::string worst_relation;
  bool has_float = false;  // the float relations were compared too
  double max_float_relation_error = 0;
  std::string worst_float_relation;
  int nan_failures = 0;
  std::vector<std::string> nan_failure_examples;
  std::vector<DensityRow> rows;
  std::vector<std::string> skipped;  // densities beyond the validity limits, with why
  std::optional<std::string> field;  // the density field, when the file has one
  std::array<int, 3> block{};
  std::vector<DensityCellRow> cells;
  numeric::VolumeFractionOptions sampling;
};

// `model`: the density model of the file's surface (the rebuilt reference's); `density_field`: rho(x)
// of the file's _graded, when it has one.
DensityReport measure_density(const run::LoadedFunctions& functions, const run::FileMetadata& meta,
                              const density::DensityModel& model, const std::optional<GiNaC::ex>& density_field,
                              const DensityCheckOptions& options);

// The report's density section (lines ending in newlines) and its JSON.
std::string format_density(const DensityReport& report);
nlohmann::ordered_json density_json(const DensityReport& report);

}  // namespace offsetgen::check
