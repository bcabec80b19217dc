#include "cli/slice_command.h"

#include "cli/cells_option.h"
#include "cli/command_line.h"
#include "slice/slicer.h"
#include "support/progress_line.h"
#include "surfaces/input_error.h"
#include "validate/block_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

namespace offsetgen {

void add_slice_command(CLI::App& app, SliceOptions& o) {
  auto* cmd = app.add_subcommand(
      "slice",
      "Cut a block of cells of a wall solid, or a part filled with it (--body) inside a skin, into a printer's\n"
      "layers straight from the closed form (no mesh):\n"
      "contours on the exact wall within --tolerance, as CLI (powder bed), SVG, or a Prusa SL1/SL1S archive\n"
      "(resin). docs/slice.md");
  add_wall_options(cmd, o);
  auto* cells = cmd->add_option("-c,--cells", o.cells, "Cells of the block from the origin: N, NX,NY,NZ or NXxNYxNZ")
                    ->capture_default_str();
  add_body_options(cmd, o)->excludes(cells);
  cmd->add_option("--cell-size", o.cell_size,
                  "Cell edge length in millimetres (a cube cell; a box cell X,Y,Z is refused: mesh and step take it)")
      ->capture_default_str();
  cmd->add_option("--layer-height", o.layer_height, "Layer height in millimetres (at most a cell)")
      ->capture_default_str();
  cmd->add_option("--first-layer", o.first_layer, "The first layer's height in millimetres (default --layer-height)");
  cmd->add_option("--tolerance", o.tolerance,
                  "The largest distance (mm) between a contour's chord and the exact wall in its layer")
      ->capture_default_str();
  cmd->add_option("-o,--output", o.output,
                  "Output: .cli (Common Layer Interface, binary), .svg (a group per layer), DIR/ (an SVG per layer), "
                  ".sl1 or .sl1s (Prusa resin archive)");
  cmd->add_flag("--cli-ascii", o.cli_ascii, "Write ASCII CLI instead of binary");
  cmd->add_option("--printer", o.printer,
                  "The resin printer's screen: sl1 (1440 x 2560 at 0.04725 mm) or sl1s "
                  "(1620 x 2560 at 0.05 mm); default from the extension");
  cmd->add_option("--layer-range", o.layer_range,
                  "Slice share I of N (counted from 0) of the layers into a part file -o NAME.EXT.part, for "
                  "--merge (docs/slice.md, a tall part over a Slurm array)");
  cmd->add_option("--merge", o.merge,
                  "Join the --layer-range parts, shares 0 to N-1 in order, into -o (the single run's bytes)")
      ->expected(1, -1);
  cmd->add_option("--hatch", o.hatch,
                  "CLI: hatch lines filling each layer, SPACING mm apart at ANGLE degrees (default 0) on layer 0, "
                  "turned ROTATE degrees more each layer (default 66.67): SPACING[,ANGLE[,ROTATE]]");
  cmd->add_option("--beam-offset", o.beam_offset,
                  "CLI: write the contours offset inward by this many mm (the beam's radius); hatches fill the "
                  "offset contours (default 0)");
  cmd->add_option("--center", o.center,
                  "SL1/SL1S: the part's centre on the printer's bed, X,Y in mm (default the bed's centre)");
  cmd->add_option("-j,--threads", o.threads, "Threads (default: one per hardware thread)");
  cmd->add_flag("-q,--quiet", o.quiet, "Print nothing on success");
  cmd->footer(
      "Exit status: 0 success, 2 usage or input error (no file is written then), 3 internal error or out of\n"
      "memory or disk, 130/143 interrupted by SIGINT/SIGTERM (the unfinished file removed).\n"
      "Examples: offsetgen slice --surface gyroid --density 0.2 --cells 2 --cell-size 8 --layer-height 0.05 -o g.cli\n"
      "          offsetgen slice --surface gyroid --density 0.2 --cells 6 --cell-size 8 -o gyroid.sl1\n"
      "          offsetgen slice --surface gyroid --density 0.25 --body part.stl --skin 1.5 --cell-size 6 -o part.sl1");
}

namespace {

int run_merge(const SliceOptions& o) {
  if (!o.surface.empty() || !o.expression.empty() || !o.layer_range.empty())
    throw InputError("--merge joins the parts of a run: give only the parts and -o");
  const slice::LayerMergeReport r = slice::merge_layer_parts(o.merge, o.output);
  if (!o.quiet)
    std::printf("offsetgen slice: %s written (%s, %.1f MB): %zu layers from %zu parts\n", o.output.c_str(),
                r.format.c_str(), double(r.bytes) / 1e6, r.layers, o.merge.size());
  return kExitOk;
}

}  // namespace

int run_slice_command(const SliceOptions& o) {
  if (!o.merge.empty()) return run_merge(o);
  slice::SliceRequest r;
  r.wall = wall_request(o);
  std::string cells = o.cells;
  std::replace(cells.begin(), cells.end(), ',', 'x');
  r.cells = parse_cells(cells);
  r.body = body_request(o);
  const std::array<double, 3> cell_size = parse_cell_size(o.cell_size);
  // The slicer's wall, its layers and the body's lattice are in cell units of one cell size; a box cell
  // would need the composed field in mm (as mesh and step use), which slice does not build.
  if (!cube_cell(cell_size))
    throw InputError(fmt::format(
        "--cell-size {}: slice takes a cube cell only (one size, MM); a box cell X,Y,Z is not sliced yet: write "
        "the part with offsetgen mesh --cell-size {} and slice that mesh",
        o.cell_size, o.cell_size));
  r.cell_size = cell_size[0];
  r.layer_height = o.layer_height;
  r.first_layer = o.first_layer;
  r.tolerance = o.tolerance;
  r.output = o.output;
  r.cli_ascii = o.cli_ascii;
  r.printer = o.printer;
  r.threads = o.threads;
  r.layer_range = o.layer_range;
  r.hatch = o.hatch;
  r.beam_offset = o.beam_offset;
  r.center = o.center;
  slice::validate(r);  // before anything is generated
  ProgressLine bar("[offsetgen slice]");
  const slice::SliceSummary summary = slice::run_slice(
      r, [&](const std::string& stage, double f) { bar.show(stage, f); },
      [&](const std::string& warning) {
        bar.clear();
        std::fprintf(stderr, "offsetgen slice: warning: %s\n", warning.c_str());
      });
  bar.clear();
  if (!o.quiet) std::fputs(slice::format_summary(summary).c_str(), stdout);
  return kExitOk;
}

}  // namespace offsetgen
