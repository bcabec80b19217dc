#include "step/step_request.h"

#include "emit/file_writer.h"
#include "surfaces/input_error.h"
#include "validate/block_checks.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace offsetgen::step {

Patches patches_from_name(const std::string& name) {
  if (name == "auto") return Patches::Auto;
  if (name == "symmetry") return Patches::Symmetry;
  if (name == "box") return Patches::Box;
  throw InputError(fmt::format("--patches {}: give auto, symmetry or box", name));
}

void validate_request(const StepRequest& r) {
  // STEP export takes no --density-field (a graded wall is --thickness EXPR).
  if (r.wall.thickness.empty() == !r.wall.generation.density.has_value())
    throw InputError(
        "give one of --thickness T (cell units; mm with a box cell) and --density R: each one sets the wall's "
        "thickness");
  if (r.max_control_points < 4) throw InputError("--max-control-points: a cubic patch needs at least 4 a side");
  if (!(r.tolerance > 0) || !std::isfinite(r.tolerance))
    throw InputError(
        fmt::format("--tolerance {}: give the largest deviation allowed, a positive length in mm", r.tolerance));
  check_block(r.cells, r.cell_size);
  // The density relations are of the cube cell's wall (docs/density.md); a box cell stretches the
  // cell differently along each axis, so no closed form gives the thickness of a density.
  if (!cube_cell(r.cell_size) && r.wall.generation.density)
    throw InputError(
        "--density needs a cube cell: with --cell-size X,Y,Z of unequal sides the cell is stretched differently "
        "along each axis and no closed-form density relation holds; give the wall as --thickness T (mm)");
  if (r.output.empty()) throw InputError("no output file: use -o part.step");
  const std::string ext = std::filesystem::path(r.output).extension().string();
  if (ext != ".step" && ext != ".stp" && ext != ".STEP" && ext != ".STP")
    throw InputError(fmt::format("-o '{}': STEP files end in .step or .stp", r.output));
  try {
    require_writable(r.output);  // an unwritable -o is the user's input, found before the long work
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

}  // namespace offsetgen::step
