// What a powder-bed machine scans in a layer besides its contours (CLI only, docs/slice.md): the
// contours offset inward by the beam's radius (--beam-offset), and parallel hatch lines filling the
// solid inside them (--hatch SPACING[,ANGLE[,ROTATE]]), PySLM's habit of a hatch angle turned by ROTATE
// degrees from one layer to the next.
//
// The offset is Clipper's (libpolyclipping, round joins, arcs within a quarter of the tolerance, on a
// 1 nm grid). The hatches are cut here, exactly, by a scan line rule: line j of a layer is
// {p : p . n = (j + 1/2) SPACING}, n the unit normal of the hatch direction (so lines at angle 0 lie
// halfway between the block's sides when SPACING divides them); each edge of a loop crosses the lines
// whose offset lies in [its lower end, its upper end) (half-open, so a vertex on a line counts once), and
// the crossings along each line, sorted, pair up into the segments inside (even-odd, which for nested
// loops without crossings is the solid). Every endpoint is a point of a loop's edge (to rounding).
// Segments run back and forth (line j left to right along the hatch direction, line j + 1 right to
// left), lines in order of j.
#pragma once

#include "slice/layer_contours.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::slice {

struct HatchPattern {
  double spacing = 0;       // mm between neighbouring lines
  double angle = 0;         // degrees, layer 0's hatch direction from +x (counter-clockwise)
  double rotation = 66.67;  // degrees added on each layer
  // Layer k's hatch direction, degrees in [0, 180).
  double angle_of_layer(size_t layer) const;
};

// "SPACING[,ANGLE[,ROTATE]]" (mm, degrees, degrees); throws InputError for anything else or for a
// spacing <= 0, or numbers that are not finite.
HatchPattern parse_hatch(const std::string& text);

struct Hatch {
  Point2 start, end;  // mm
};

// The solid inside `loops` (outer loops counter-clockwise, holes clockwise, no two edges crossing)
// shrunk by `distance` mm (> 0), as loops of the same kind; loops of less than `min_area` mm^2 dropped.
// Round joins, arcs within `arc_tolerance` mm.
std::vector<Loop> offset_inward(const std::vector<Loop>& loops, double distance, double arc_tolerance, double min_area);

// The hatch segments filling `loops` at `angle` degrees, `spacing` mm apart (the rule above).
std::vector<Hatch> hatch_loops(const std::vector<Loop>& loops, double spacing, double angle);

// --beam-offset and --hatch for one layer: the loops offset in place (vertices recounted), the hatches
// returned.
struct ScanSetup {
  std::optional<HatchPattern> hatch;
  double beam_offset = 0;  // mm; 0: the contours as they are
  double tolerance = 0.005;
  double min_area = 0;
};
std::vector<Hatch> scan_layer(const ScanSetup& setup, size_t layer, LayerContours& contours);

}  // namespace offsetgen::slice
