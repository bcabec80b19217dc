#include "step/step_summary.h"

#include "step/cell_frame.h"

#include <fmt/format.h>

namespace offsetgen::step {

std::string surface_words(const GenerationRequest& g) {
  return g.expression.empty() ? g.surface : fmt::format("{} (F = {})", g.name, g.expression);
}

std::string thickness_words(const StepSummary& s, const std::array<double, 3>& cell_sizes) {
  if (s.thickness_in_mm && !s.graded) return fmt::format("{} mm (along the physical normal", s.thickness_text);
  if (s.thickness_in_mm)
    return fmt::format("{} mm ({:.4g} to {:.4g} mm in the block, along the physical normal", s.thickness_text,
                       s.thickness_range[0], s.thickness_range[1]);
  const double cell_size = cell_sizes[0];
  if (!s.graded) return fmt::format("{} cell ({} mm", s.thickness_text, s.thickness * cell_size);
  return fmt::format("{} cell ({:.4g} to {:.4g} mm in the block", s.thickness_text, s.thickness_range[0] * cell_size,
                     s.thickness_range[1] * cell_size);
}

std::string format_summary(const StepSummary& s, const StepRequest& r) {
  const std::array<int, 3>& cells = s.body.path.empty() ? r.cells : s.body.cells;  // --body: the block over it
  std::string out = fmt::format(
      "offsetgen step: {}: {} wall, t = {}; curvature limit {:.4f} {}), {}x{}x{} cells of {} mm\n",
      s.passed ? r.output + " written" : "no file written", s.surface, thickness_words(s, r.cell_size),
      s.thickness_limit, s.thickness_in_mm ? "mm" : "cell", cells[0], cells[1], cells[2], cell_size_words(r.cell_size));
  const std::string patches = s.route == Route::Symmetry
                                  ? "symmetry patch"
                                  : fmt::format("box patch (the largest; boxes of 1/{} cell)", s.boxes_per_cell);
  // Box patches meet at edges traced on the boxes' faces: no mirror plane makes their normals agree.
  out += fmt::format(
      "  faces: {} B-spline (bicubic, {}x{} control points per {}), {} planar; {} control points "
      "({:.0f} per cell){}; {} bytes; {}\n",
      s.bspline_faces, s.patch_control_points, s.patch_control_points, patches, s.planar_faces, s.control_points,
      s.control_points_per_cell, s.graded ? ", each image fitted on its own (graded)" : "", s.bytes,
      s.graded || s.route == Route::Box
          ? "C0 edges"
          : fmt::format("largest normal jump across a patch edge {:.3f} degrees (C0 edges)", s.normal_jump));
  out += fmt::format("  {}: {}, {} solid{}, {}{}\n", s.body.path.empty() ? "solid" : "lattice block (before the trim)",
                     s.valid ? "valid (BRepCheck_Analyzer)" : "NOT valid", s.solids, s.solids == 1 ? "" : "s",
                     s.closed ? "each one closed shell" : "NOT closed",
                     s.expected_solids == 1 ? ""
                                            : fmt::format(" (the block cuts the wall into {} pieces: the surface "
                                                          "crosses two of its corners)",
                                                          s.expected_solids));
  out += fmt::format(
      "  deviation of the exact walls from the faces, {} points measured: max {:.3g} mm, mean {:.3g} mm "
      "(tolerance {} mm; fit check {:.3g} mm)\n",
      s.deviation_points, s.max_deviation, s.mean_deviation, r.tolerance, s.fit_error);
  const double rel = s.exact_volume > 0 ? (s.volume - s.exact_volume) / s.exact_volume : 0;
  out += fmt::format(
      "  volume: {:.6f} mm^3; exact wall {:.6f} mm^3 (column quadrature, standard error {:.2g}); difference "
      "{:+.3g}%\n",
      s.volume, s.exact_volume, s.exact_volume_error, 100 * rel);
  out += format_body_part(s.body);
  out += fmt::format(
      "  time: {:.2f} s, {:.2f} s of CPU (generate and compile {:.2f}, fit {:.2f}, build {:.2f}, write {:.2f}, "
      "check {:.2f}, deviation {:.2f}; exact volume {:.2f} alongside the last three)\n",
      s.seconds_total, s.cpu_seconds, s.seconds_generate, s.seconds_fit, s.seconds_build, s.seconds_write,
      s.seconds_check, s.seconds_deviation, s.seconds_volume);
  if (!s.passed) out += "  check failed: " + s.failure + "\n";
  return out;
}

}  // namespace offsetgen::step
