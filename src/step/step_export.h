// `offsetgen step`: the wall of a block of cells as a STEP solid, its deviation from the exact wall
// measured before the file is written (docs/step.md).
#pragma once

#include "wall/wall_field.h"

#include <array>
#include <functional>
#include <string>

namespace offsetgen::step {

struct StepRequest {
  wall::WallRequest wall;
  std::array<int, 3> cells{1, 1, 1};
  double cell_size = 10;         // mm
  double tolerance = 0;          // mm: the largest distance allowed from the exact walls to the faces
  std::string output;            // .step / .stp
  int max_control_points = 40;   // per patch side; beyond it the tolerance is reported as out of reach
  std::string patches = "auto";  // "symmetry", "box", or "auto": symmetry where the surface has a layout
};

struct StepSummary {
  std::string surface;
  double thickness = 0;                     // cell units (a graded wall's at the origin)
  bool graded = false;                      // the thickness an expression of x, y, z
  std::string thickness_text;               // as given, for the summary and the file's header
  std::array<double, 2> thickness_range{};  // smallest and largest in the block (sampled)
  double thickness_limit = 0;               // cell units: 2 / the largest principal curvature
  int boxes_per_cell = 0;                   // the box route's boxes per cell side (0 on the symmetry route)
  std::string patches;                      // "symmetry patch", or "box patch (the largest; ...)"
  int patch_control_points =
      0;                 // per side of each symmetry patch (the larger of the two sheets), or of the largest box patch
  double fit_error = 0;  // mm: the largest |exact(u, v) - patch(u, v)| over the check grid
  double normal_jump = 0;   // degrees: the largest angle between the faces' normals across a patch edge
  long control_points = 0;  // over the whole file
  double control_points_per_cell = 0;
  int bspline_faces = 0, planar_faces = 0;
  bool valid = false, closed = false;
  int solids = 0;
  // The pieces the block cuts the wall into (1 for Schwarz P; diamond's block corners each cut off a
  // small tetrahedron of the wall): export's count, written into the header for check.
  int expected_solids = 1;
  double volume = 0;                                // mm^3, of the solid read back from the file
  double exact_volume = 0, exact_volume_error = 0;  // mm^3, column quadrature of the exact wall (standard error)
  double max_deviation = 0, mean_deviation = 0;     // mm, of the exact walls from the file's faces
  long deviation_points = 0;
  std::array<double, 3> worst_point{};
  long bytes = 0;
  bool written = false;  // false: a check failed, no file
  std::string failure;   // why, when not written
  // Wall-clock seconds of each stage, and the process's CPU seconds in all (on a shared machine the
  // wall clock also counts waiting for a core).
  double seconds_generate = 0, seconds_fit = 0, seconds_build = 0, seconds_write = 0, seconds_read = 0,
         seconds_check = 0, seconds_deviation = 0, seconds_volume = 0, seconds_total = 0, cpu_seconds = 0;
};

// Throws InputError for what the exporter does not cover or bad input (nothing is written then).
StepSummary export_step(const StepRequest& request, const std::function<void(const std::string&)>& progress);

std::string format_summary(const StepSummary& summary, const StepRequest& request);

// `offsetgen check part.step`: a file of `offsetgen step`, measured again against the walls its header
// names (offsetgen-metadata in FILE_DESCRIPTION): one valid closed solid, the exact walls within its
// tolerance of the faces, its volume against the exact wall volume. summary.written means it passed.
// Throws InputError for a file that is not a STEP file of offsetgen's.
struct StepCheck {
  StepRequest request;  // as the header gives it
  StepSummary summary;
};
StepCheck check_step_file(const std::string& path, const std::function<void(const std::string&)>& progress);
std::string format_check_summary(const StepCheck& check, const std::string& path);

}  // namespace offsetgen::step
