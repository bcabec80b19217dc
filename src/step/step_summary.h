// What `offsetgen step` measured on the solid it wrote (or refused to write), and its summary.
#pragma once

#include "step/body_part.h"
#include "step/step_request.h"

#include <array>
#include <string>

namespace offsetgen::step {

// The route taken: which patches cut the sheets into faces (Patches::Auto resolved).
enum class Route { Symmetry, Box };

struct StepSummary {
  std::string surface;
  double thickness = 0;                     // cell units, or mm (a box cell); a graded wall's at the origin
  bool thickness_in_mm = false;             // a box cell's wall (step/cell_frame.h): its thickness, limit in mm
  bool graded = false;                      // the thickness an expression of x, y, z
  std::string thickness_text;               // as given, for the summary and the file's header
  std::array<double, 2> thickness_range{};  // smallest and largest in the block (sampled)
  double thickness_limit = 0;               // cell units (or mm): 2 / the largest principal curvature
  Route route = Route::Symmetry;            // export's (a file's header does not say)
  int boxes_per_cell = 0;                   // the box route's boxes per cell side (0 on the symmetry route)
  // Per side of each symmetry patch (the larger of the two sheets), or of the largest box patch.
  int patch_control_points = 0;
  double fit_error = 0;     // mm: the largest |exact(u, v) - patch(u, v)| over the check grid
  double normal_jump = 0;   // degrees: the largest angle between the faces' normals across a patch edge
  long control_points = 0;  // over the whole file
  double control_points_per_cell = 0;
  int bspline_faces = 0, planar_faces = 0;
  bool valid = false, closed = false;
  int solids = 0;
  // The pieces the block cuts the wall into (1 for Schwarz P; diamond's block corners each cut off a
  // small tetrahedron of the wall): export's count, written into the header for check.
  int expected_solids = 1;
  double volume = 0;                                // mm^3, of the solid measured (export: in memory; check: read back)
  double exact_volume = 0, exact_volume_error = 0;  // mm^3, column quadrature of the exact wall (standard error)
  double max_deviation = 0, mean_deviation = 0;     // mm, of the exact walls from the faces
  long deviation_points = 0;
  std::array<double, 3> worst_point{};
  long bytes = 0;
  bool passed = false;  // every check passed (export: and the file was written); else no file
  std::string failure;  // the check that failed, when not passed
  BodyPart body;        // --body: the body, the core and the trimmed part (path empty without one)
  // Wall-clock seconds of each stage, and the process's CPU seconds in all (on a shared machine the
  // wall clock also counts waiting for a core).
  double seconds_generate = 0, seconds_fit = 0, seconds_build = 0, seconds_write = 0, seconds_read = 0,
         seconds_check = 0, seconds_deviation = 0, seconds_volume = 0, seconds_total = 0, cpu_seconds = 0;
};

std::string format_summary(const StepSummary& summary, const StepRequest& request);

// The catalog name, or an expression's name (its --name) and F.
std::string surface_words(const GenerationRequest& generation);

// "0.1 cell (1 mm", or for a graded wall "0.05 + 0.05*x cell (0.5 to 1.5 mm in the block", or for a
// box cell's wall "1 mm (along the physical normal" or "0.75 + 0.05*x mm (0.75 to 1.25 mm in the
// block, along the physical normal" (the caller closes the bracket): export's and check's summaries.
std::string thickness_words(const StepSummary& summary, const std::array<double, 3>& cell_size);

}  // namespace offsetgen::step
