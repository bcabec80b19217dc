// `offsetgen slice`: a block of cells of a wall solid, or a body filled with it, as a printer's layers, cut straight
// from the closed form (no mesh): each layer's contours (layer_contours.h) written as CLI (binary or ASCII), SVG, or a
// Prusa SL1/SL1S archive (layer_writer.h). Layers are cut at mid-height, PrusaSlicer's way: layer 0 at first_layer / 2,
// layer k >= 1 at first_layer + (k - 1/2) layer_height, every layer whose cut lies inside the block. Layers are worked
// on a few threads at a time and written in order, so the memory is a few layers' and the bytes do not depend on the
// threads.
#pragma once

#include "body/body_request.h"
#include "slice/layer_writer.h"
#include "wall/wall_field.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace offsetgen::slice {

struct SliceRequest {
  wall::WallRequest wall;
  std::array<int, 3> cells{1, 1, 1};  // the block [0, NX] x [0, NY] x [0, NZ] cells from the origin
  // A body filled with the lattice (inside a skin) instead of the block: its layers are cut from its
  // lowest point up, x and y in the body's own millimetres.
  std::optional<body::BodyRequest> body;
  double cell_size = 10;              // mm
  double layer_height = 0.05;         // mm
  std::optional<double> first_layer;  // mm; default layer_height
  double tolerance = 0.005;           // mm: the largest chord deviation from the exact contour
  std::string output;                 // .cli, .svg, .sl1, .sl1s
  bool cli_ascii = false;             // ASCII CLI instead of binary
  std::string printer;                // "sl1" or "sl1s"; default from the extension
  int threads = 0;                    // 0: one per hardware thread
  int pixels_per_cell = 0;            // the marching grid; 0: the thinnest wall spans 3 pixels
  // --layer-range I/N: share I (from 0) of N near-equal contiguous runs of the layers, written to a
  // part file (output NAME.EXT.part, EXT the format) that merge_layer_parts joins; empty: all layers.
  std::string layer_range;
  // CLI only (slice/scan_paths.h): --hatch SPACING[,ANGLE[,ROTATE]] ("": none) and --beam-offset MM.
  std::string hatch;
  std::optional<double> beam_offset;
  // SL1/SL1S only: --center X,Y, where the part's centre sits on the bed (mm); "": the bed's centre.
  std::string center;
};

struct SliceSummary {
  std::string output, format, surface, wall;
  std::array<int, 3> cells{};
  std::string body;  // with --body: its file, triangles, box and skin, in a line; else empty
  double cell_size = 0, layer_height = 0, first_layer = 0, tolerance = 0;
  int pixels_per_cell = 0;
  std::string share;  // "I/N: layers A to B of T" for a --layer-range share, else empty
  size_t layers = 0, loops = 0, vertices = 0, tiny_loops = 0, unverified_chords = 0;
  double tiny_area = 0;      // mm^2
  double max_deviation = 0;  // mm: the largest chord deviation measured
  size_t file_bytes = 0;
  std::string scan;  // --hatch / --beam-offset in words, else empty
  size_t hatches = 0;
  double hatch_length = 0;  // mm
  size_t samples = 0, refine_evaluations = 0;
  double generate_seconds = 0, compile_seconds = 0, slice_seconds = 0;
  size_t peak_memory_bytes = 0;  // the process's peak resident memory
};

// Called with a stage and a fraction in [0, 1] (negative: unknown).
using SliceProgress = std::function<void(const std::string& stage, double fraction)>;

SliceFormat format_for_output(const SliceRequest& request);
// Throws InputError for bad input before anything is generated or written.
void validate(const SliceRequest& request);
// `warn` hears of a body whose size looks like other units.
SliceSummary run_slice(const SliceRequest& request, const SliceProgress& progress = {},
                       const body::BodyWarning& warn = {});
std::string format_summary(const SliceSummary& summary);

// "X,Y" (mm, finite) -> {X, Y}; throws InputError otherwise.
std::array<double, 2> parse_center(const std::string& text);

// "I/N" -> {I, N} with 0 <= I < N (as mesh's --tile-range); throws InputError otherwise.
std::pair<int, int> parse_layer_range(const std::string& text);
// Layers [first, end) of share `index` of `count` of `layers` layers.
std::pair<size_t, size_t> layer_share(size_t layers, int index, int count);

struct LayerMergeReport {
  std::string format;
  size_t layers = 0, bytes = 0;
};
// Joins the part files of shares 0 .. N-1 of one request, given in order, into `output` (its extension
// the parts' format): the bytes the run without --layer-range writes. Throws InputError, writing
// nothing, for parts of different requests, a share missing, doubled or out of order, or a damaged part.
LayerMergeReport merge_layer_parts(const std::vector<std::string>& parts, const std::string& output);

}  // namespace offsetgen::slice
