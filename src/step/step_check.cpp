#include "step/step_check.h"

#include "step/cell_frame.h"

#include "step/exact_walls.h"
#include "step/measurement.h"
#include "step/step_file.h"
#include "step/step_metadata.h"
#include "support/stopwatch.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>
#include <TopExp_Explorer.hxx>

#include <ctime>
#include <filesystem>
#include <future>
#include <stdexcept>

namespace offsetgen::step {
namespace {

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

}  // namespace

std::string file_holds_the_solid(const std::string& bytes, const TopoDS_Shape& solid) {
  size_t solids = 0, faces = 0;
  for (TopExp_Explorer e(solid, TopAbs_SOLID); e.More(); e.Next()) ++solids;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) ++faces;
  // A solid with inner shells (a skinned part's sealed pores) is a BREP_WITH_VOIDS.
  const size_t written_solids = occurrences(bytes, "MANIFOLD_SOLID_BREP(") + occurrences(bytes, "BREP_WITH_VOIDS("),
               written_faces = occurrences(bytes, "ADVANCED_FACE(");
  if (written_solids == solids && written_faces == faces) return "";
  return fmt::format("the STEP file holds {} solids and {} faces of the solid's {} and {} (STEPControl_Writer)",
                     written_solids, written_faces, solids, faces);
}

StepCheck check_step_file(const std::string& path, const std::function<void(const std::string&)>& progress) {
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(fmt::format("{}: no such file", path));
  const std::string bytes = read_file_bytes(path);
  if (bytes.rfind("ISO-10303-21;", 0) != 0)
    throw InputError(fmt::format("{}: not a STEP file (it does not begin with ISO-10303-21;)", path));
  say("reading the file");
  StepContents contents;
  try {
    contents = read_step_contents(path);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
  StepCheck check;
  StepSummary& s = check.summary;
  check.request = request_from_description(contents.description, path, s.expected_solids);
  s.surface = surface_words(check.request.wall.generation);
  s.bytes = long(bytes.size());
  s.seconds_read = seconds_since(start);

  say("generating the walls it was made from");
  auto t0 = Clock::now();
  wall::WallField field(framed_wall(check.request));
  wall::WallField::Worker worker(field);
  record_thickness(field, worker, check.request, s);
  field.compile();
  s.seconds_generate = seconds_since(t0);
  say("measuring");
  std::future<ExactVolume> exact_volume = start_exact_wall_volume(field, check.request, s);
  measure_solid(contents.shape, check.request, field, worker, exact_volume, s);
  s.passed = s.failure.empty();
  s.seconds_total = seconds_since(start);
  s.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return check;
}

std::string format_check_summary(const StepCheck& c, const std::string& path) {
  const StepSummary& s = c.summary;
  const StepRequest& r = c.request;
  std::string out = fmt::format(
      "offsetgen check: {}: {} wall, t = {}), {}x{}x{} cells of {} mm, tolerance {} mm (its header)\n", path, s.surface,
      thickness_words(s, r.cell_size), r.cells[0], r.cells[1], r.cells[2], cell_size_words(r.cell_size), r.tolerance);
  out += fmt::format("  faces: {} B-spline, {} planar; {} control points ({:.0f} per cell); {} bytes\n",
                     s.bspline_faces, s.planar_faces, s.control_points, s.control_points_per_cell, s.bytes);
  out += fmt::format("  {}  solid: {}, {} solid{} ({} expected), {}\n",
                     s.valid && s.closed && s.solids == s.expected_solids ? "PASS" : "FAIL",
                     s.valid ? "valid (BRepCheck_Analyzer)" : "NOT valid", s.solids, s.solids == 1 ? "" : "s",
                     s.expected_solids, s.closed ? "each one closed shell" : "NOT closed");
  out += fmt::format(
      "  {}  deviation of the exact walls from the faces, {} points: max {:.3g} mm, mean {:.3g} mm (tolerance {} mm)\n",
      s.max_deviation <= r.tolerance ? "PASS" : "FAIL", s.deviation_points, s.max_deviation, s.mean_deviation,
      r.tolerance);
  const double rel = s.exact_volume > 0 ? (s.volume - s.exact_volume) / s.exact_volume : 0;
  out += fmt::format(
      "  {}  volume: {:.6f} mm^3; exact wall {:.6f} mm^3 (column quadrature, standard error {:.2g}); difference "
      "{:+.3g}% (at most {}%)\n",
      volume_agrees(s) ? "PASS" : "FAIL", s.volume, s.exact_volume, s.exact_volume_error, 100 * rel,
      100 * kVolumeTolerance);
  out += fmt::format("  time: {:.2f} s, {:.2f} s of CPU\n", s.seconds_total, s.cpu_seconds);
  out += s.passed ? "offsetgen check: all checks passed\n" : "offsetgen check: FAILED: " + s.failure + "\n";
  return out;
}

}  // namespace offsetgen::step
