// Symmetry patches: a surface with mirror planes is cut by them into congruent pieces, and where four
// mirror planes bound a tetrahedron that one sheet of an offset surface crosses as a four-sided patch,
// that patch (fitted once) and its images under the group the four reflections generate are the whole
// sheet. A layout is data: the tetrahedron as two opposite edges (the lines that sample the patch run
// from one to the other), its four faces as mirror planes, and the region of the block the images fill.
//
// Plain C++ (no OpenCASCADE): the B-rep is assembled in wall_brep.cpp.
#pragma once

#include "step/bspline_fit.h"
#include "step/level_function.h"

#include <array>
#include <string>
#include <vector>

namespace offsetgen::step {

// The plane normal . p = offset, with normal's entries in {-1, 0, 1} (x = 1/2, x = y, x + y = 1/4, ...).
struct MirrorPlane {
  std::array<int, 3> normal{};
  double offset = 0;
};

// p -> q with q[a] = sign[a] * p[from[a]] + shift[a]: a signed permutation and a translation, the form
// of every symmetry of a cubic cell. The shifts are multiples of 1/8, exact in binary, so images of
// points on a mirror plane agree with their neighbours' to the last bit or within a few units of it.
struct Isometry {
  std::array<int, 3> from{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};
  Point shift{};
  Point apply(const Point& p) const;
  bool reverses() const;  // orientation reversing (an odd permutation times the signs' product)
  bool operator<(const Isometry& o) const;
};
Isometry compose(const Isometry& outer, const Isometry& inner);  // outer(inner(p))
Isometry reflection(const MirrorPlane& plane);

// lo < normal . p < hi
struct Slab {
  std::array<int, 3> normal{};
  double lo = 0, hi = 0;
};

struct PatchLayout {
  std::string surface;               // the catalog name
  std::string pieces;                // e.g. "48 per sheet and cell", for messages and the summary
  std::array<Point, 2> start;        // the lines start on the edge start[0] (v = 0) .. start[1] (v = 1)
  std::array<Point, 2> end;          // and end on the opposite edge end[0] (u = 0) .. end[1] (u = 1)
  std::array<MirrorPlane, 4> sides;  // the faces the patch's sides lie on: u = 0, u = 1, v = 0, v = 1
  // The region the patch's images fill, bounded by mirror planes, holding the block [0, cells]^3.
  std::vector<Slab> (*region)(const std::array<int, 3>& cells) = nullptr;
  // Whether that region is the block itself (its faces are mirror planes: the caps are the block's
  // faces); otherwise the block's box cuts the solid afterwards.
  bool region_is_block = false;
  // Whether --patches auto takes box patches all the same: where cutting the region to the block costs
  // more than box patches do in all (diamond, with fewer control points and the same deviation;
  // docs/step.md).
  bool auto_prefers_box_patches = false;

  Segment line(double u, double v) const;
  Point centroid() const;  // of the tetrahedron
};

// The layout of a catalog surface, or nullptr where there is none (yet).
const PatchLayout* find_patch_layout(const std::string& surface);
std::string patch_layout_surfaces();  // "schwarzp, diamond, ..."

// The points of the patch where the lines at (u, v) cross g = 0 (cell units). Throws InputError where
// a line does not cross exactly once: the offset surface is not the graph the layout needs there.
std::vector<Point> patch_points(const PatchLayout& layout, const LevelFunction& g,
                                const std::vector<std::array<double, 2>>& uv);
// On the m x m grid u = i/(m-1), v = j/(m-1), points[i * m + j].
std::vector<Point> patch_points(const PatchLayout& layout, const LevelFunction& g, int m);

// Puts a fitted patch's boundary control points on their mirror planes (to rounding; those of the form
// x = y hold bitwise already). Throws std::logic_error if one was off by more than rounding.
void snap_boundary(const PatchLayout& layout, CubicPatch& patch);

// The largest angle (radians) between the patch's normals on either side of its edges: the mirror
// image across each side's plane meets it there, and their normals differ by twice the angle between
// the normal and the plane (0 for the exact surface, which meets its mirror planes at right angles).
double normal_jump(const PatchLayout& layout, const CubicPatch& patch, int samples);

// One image of the patch in the region, and which of its sides lie on the region's boundary (a cap
// closes the wall there).
struct PatchImage {
  Isometry map;
  std::array<bool, 4> cap{};
};
// Every image of the tetrahedron inside the region, in a fixed order.
std::vector<PatchImage> region_images(const PatchLayout& layout, const std::array<int, 3>& cells);

}  // namespace offsetgen::step
