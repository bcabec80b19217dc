#include "step/step_export.h"

#include "emit/file_writer.h"
#include "run/process.h"
#include "step/body_sampling.h"
#include "step/body_solid.h"
#include "step/body_trim.h"
#include "step/cell_frame.h"
#include "step/exact_walls.h"
#include "step/measurement.h"
#include "step/patch_route.h"
#include "step/step_check.h"
#include "step/step_file.h"
#include "step/step_metadata.h"
#include "support/stopwatch.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <ctime>
#include <filesystem>
#include <future>
#include <optional>

namespace offsetgen::step {

// 40^3 points: the lattice in the holed box's core to about 0.5% (one standard error), beside the
// reading back.
constexpr int kSamplesPerSide = 40;

StepSummary export_step(const StepRequest& r, const std::function<void(const std::string&)>& progress) {
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  validate_request(r);
  if (r.body) validate_cad_body(*r.body, r.output);
  const PatchLayout* layout = choose_layout(r);

  StepSummary s;
  // With a body, the block is the cells over it: the body is read and its core offset before the walls.
  std::optional<CadBody> body;
  if (r.body) {
    say("reading the body" + std::string(r.body->skin > 0 ? ", offsetting its core" : ""));
    body = load_cad_body(*r.body, r.cell_size, s.body);
  }
  StepRequest block_request = r;
  if (body) block_request.cells = body->cells;
  const StepRequest& block = block_request;
  s.surface = surface_words(r.wall.generation);
  say("generating the wall's functions");
  wall::WallField field(framed_wall(r));
  wall::WallField::Worker worker(field);
  record_thickness(field, worker, block, s);
  if (body && s.graded)
    throw InputError("--body takes a uniform wall (--thickness T or --density R): a graded one is not trimmed yet");
  say("compiling them");
  field.compile();

  s.seconds_generate = seconds_since(start);
  const CellFrame frame = cell_frame(r);
  const auto inside_wall = [&field, &worker, &frame](const Point& p) {
    return inside_wall_at(field, worker, frame, p);
  };
  say(layout != nullptr ? "fitting the symmetry patches, building the solid"
                        : "cutting the wall into boxes, fitting their patches, building the solid");
  const WallBrep brep = fit_and_build_wall(layout, field, worker, block, inside_wall, s);
  s.control_points = brep.control_points;
  s.expected_solids = brep.solids;

  // The exact wall volume needs only the wall's functions: it runs alongside the writing and the checks.
  std::future<ExactVolume> exact_volume = start_exact_wall_volume(field, block, s);
  TopoDS_Shape part = brep.solid;
  if (body) {
    part = trim_by_body(brep.solid, *body, s.body, say);
  }
  say("writing STEP");
  auto t0 = Clock::now();
  const run::ScratchDir scratch("offsetgen-step");  // removed on exit (a loaded library's mapping stays)
  const std::filesystem::path file = scratch.path() / "wall.step";
  write_step(part, file.string(), body ? body_part_description(block, s) : file_description(block, s),
             /*pcurves=*/layout == nullptr);  // box patches' trimming curves are known exactly
  const std::string bytes = read_file_bytes(file.string());
  s.bytes = long(bytes.size());
  s.seconds_write = seconds_since(t0);

  // The solid is measured as it is in memory, not read back from the file (reading back is slow; the
  // tests read every file back, as `offsetgen check` does); the file must hold every solid and face
  // of it.
  say("measuring");
  if (body) {
    // A trimmed part is measured on the file read back: the booleans' result in memory integrates to a
    // volume 0.11% low (the sphere of docs/step.md), the file to the volume FreeCAD and the mesh route
    // find. Reading is one core's work for 10-13 s, so the block is measured meanwhile, on a thread of
    // its own: each works on its own shapes (the part read is new), and the block's Worker is its own.
    // The part's volume is also estimated without the booleans, to catch them when they go wrong.
    SampledPart sampled;
    std::future<void> block_measured = std::async(std::launch::async, [&] {
      wall::WallField::Worker block_worker(field);
      measure_solid(brep.solid, block, field, block_worker, exact_volume, s);
      const auto in_wall = [&](const Point& p) {
        const Point q{(p[0] - body->corner[0]) / frame.mm[0], (p[1] - body->corner[1]) / frame.mm[1],
                      (p[2] - body->corner[2]) / frame.mm[2]};
        return inside_wall_at(field, block_worker, frame, q);
      };
      sampled = sample_part_volume(*body, s.body.body_volume, s.body.core_volume, in_wall, kSamplesPerSide);
    });
    say("reading the part back, measuring it");
    BodyPart read_back = s.body;
    const auto t_read = Clock::now();
    measure_part(read_step(file.string()), read_back);
    read_back.seconds_read_back = seconds_since(t_read);
    block_measured.get();
    read_back.sampled_volume = sampled.volume;
    read_back.sampled_error = sampled.error;
    read_back.sampled_points = sampled.points;
    s.body = read_back;
    if (s.failure.empty()) s.failure = body_part_failure(s.body);
    if (s.failure.empty() && !part_volume_agrees(s.body.volume, sampled, s.body.body_volume))
      s.failure = fmt::format(
          "OpenCASCADE's booleans gave a wrong part: its volume {:.3f} mm^3 is not the {:.3f} mm^3 (standard error "
          "{:.2f}) sampled from the body, its core and the exact walls; try another --origin or --skin",
          s.body.volume, sampled.volume, sampled.error);
  } else {
    measure_solid(brep.solid, block, field, worker, exact_volume, s);
  }
  if (s.failure.empty()) s.failure = file_holds_the_solid(bytes, part);
  if (s.failure.empty()) {
    write_file(r.output, bytes);
    s.passed = true;
  }
  s.seconds_total = seconds_since(start);
  s.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return s;
}

}  // namespace offsetgen::step
