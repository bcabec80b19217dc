#include "step/step_export.h"

#include "emit/file_writer.h"
#include "run/process.h"
#include "step/cell_frame.h"
#include "step/exact_walls.h"
#include "step/measurement.h"
#include "step/patch_route.h"
#include "step/step_check.h"
#include "step/step_file.h"
#include "step/step_metadata.h"
#include "support/stopwatch.h"

#include <ctime>
#include <filesystem>
#include <future>

namespace offsetgen::step {

StepSummary export_step(const StepRequest& r, const std::function<void(const std::string&)>& progress) {
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  validate_request(r);
  const PatchLayout* layout = choose_layout(r);

  StepSummary s;
  s.surface = surface_words(r.wall.generation);
  say("generating the wall's functions");
  wall::WallField field(framed_wall(r));
  wall::WallField::Worker worker(field);
  record_thickness(field, worker, r, s);
  say("compiling them");
  field.compile();

  s.seconds_generate = seconds_since(start);
  const CellFrame frame = cell_frame(r);
  const auto inside_wall = [&field, &worker, &frame](const Point& p) {
    return inside_wall_at(field, worker, frame, p);
  };
  say(layout != nullptr ? "fitting the symmetry patches, building the solid"
                        : "cutting the wall into boxes, fitting their patches, building the solid");
  const WallBrep brep = fit_and_build_wall(layout, field, worker, r, inside_wall, s);
  s.control_points = brep.control_points;
  s.expected_solids = brep.solids;

  // The exact wall volume needs only the wall's functions: it runs alongside the writing and the checks.
  std::future<ExactVolume> exact_volume = start_exact_wall_volume(field, r, s);
  say("writing STEP");
  auto t0 = Clock::now();
  const run::ScratchDir scratch("offsetgen-step");  // removed on exit (a loaded library's mapping stays)
  const std::filesystem::path file = scratch.path() / "wall.step";
  write_step(brep.solid, file.string(), file_description(r, s),
             /*pcurves=*/layout == nullptr);  // box patches' trimming curves are known exactly
  const std::string bytes = read_file_bytes(file.string());
  s.bytes = long(bytes.size());
  s.seconds_write = seconds_since(t0);

  // The solid is measured as it is in memory, not read back from the file (reading back is slow; the
  // tests read every file back, as `offsetgen check` does); the file must hold every solid and face
  // of it.
  say("measuring");
  measure_solid(brep.solid, r, field, worker, exact_volume, s);
  if (s.failure.empty()) s.failure = file_holds_the_solid(bytes, brep.solid);
  if (s.failure.empty()) {
    write_file(r.output, bytes);
    s.passed = true;
  }
  s.seconds_total = seconds_since(start);
  s.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return s;
}

}  // namespace offsetgen::step
