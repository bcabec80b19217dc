#include "step/symmetry_patch.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <stdexcept>
#include <tuple>

namespace offsetgen::step {
namespace {

// Scan points per line: the surface crosses each line once, and a second crossing closer than
// 1/kSteps of the line would be a fold far beyond the curvature limit.
constexpr int kSteps = 64;

double dot(const std::array<int, 3>& n, const Point& p) { return n[0] * p[0] + n[1] * p[1] + n[2] * p[2]; }

// Schwarz P (cos X + cos Y + cos Z): the cube's mirror planes. The tetrahedron x >= y >= z >= 0,
// x <= 1/2; the lines run from the 4-fold axis x = y = 1/2 to the x axis. 48 per sheet and cell, and
// the block's faces are mirror planes.
std::vector<Slab> schwarzp_region(const std::array<int, 3>& cells) {
  return {{{1, 0, 0}, 0, double(cells[0])}, {{0, 1, 0}, 0, double(cells[1])}, {{0, 0, 1}, 0, double(cells[2])}};
}

// Schwarz D (the catalog's form): mirror planes x - y = k/2 and x + y = 1/4 + k/2 (and the same for
// the other two pairs), those of Fd-3m. They bound tetrahedra of 1/96 of the cell, with F = -sqrt 2
// at the ends of one edge (A, C) and +sqrt 2 at those of the opposite one (B, D): each sheet crosses
// it as a four-sided patch. The cube's faces are no mirror planes, so the region is the smallest
// polyhedron of mirror planes half a mirror spacing beyond the block, cut to the block afterwards.
// Half a mirror spacing: the region's faces then stay clear of the block's edges, which the planes
// x - y = N and x + y = -1/4 would otherwise touch (a degenerate contact for the boolean).
constexpr double kMargin = 0.5;

std::vector<Slab> diamond_region(const std::array<int, 3>& cells) {
  std::vector<Slab> slabs;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = a + 1; b < 3; ++b) {
      std::array<int, 3> minus{}, plus{};
      minus[a] = plus[a] = plus[b] = 1;
      minus[b] = -1;
      slabs.push_back({minus, -double(cells[b]) - kMargin, double(cells[a]) + kMargin});
      slabs.push_back({plus, -0.25 - kMargin, double(cells[a] + cells[b]) + 0.25 + kMargin});
    }
  return slabs;
}

const std::vector<PatchLayout>& layouts() {
  static const std::vector<PatchLayout> all = [] {
    PatchLayout p;
    p.surface = "schwarzp";
    p.pieces = "48 per sheet and cell";
    p.start = {Point{0.5, 0.5, 0}, Point{0.5, 0.5, 0.5}};
    p.end = {Point{0, 0, 0}, Point{0.5, 0, 0}};
    p.sides = {MirrorPlane{{1, -1, 0}, 0}, MirrorPlane{{1, 0, 0}, 0.5}, MirrorPlane{{0, 0, 1}, 0},
               MirrorPlane{{0, 1, -1}, 0}};
    p.region = schwarzp_region;
    p.region_is_block = true;

    PatchLayout d;
    d.surface = "diamond";
    d.pieces = "96 per sheet and cell";
    d.start = {Point{0.125, 0.125, 0.125}, Point{0.375, -0.125, -0.125}};  // B .. D
    d.end = {Point{-0.125, -0.125, -0.125}, Point{0.125, 0.125, -0.375}};  // A .. C
    d.sides = {MirrorPlane{{0, 1, -1}, 0}, MirrorPlane{{1, 1, 0}, 0.25}, MirrorPlane{{1, -1, 0}, 0},
               MirrorPlane{{0, 1, 1}, -0.25}};
    d.region = diamond_region;
    d.auto_prefers_box_patches = true;
    // Neovius and I-WP have the cube's mirror planes too (Pm-3m, Im-3m), so Schwarz P's tetrahedron
    // O(0,0,0) X(1/2,0,0) M(1/2,1/2,0) R(1/2,1/2,1/2), but their signs at its vertices pair other
    // edges. Neovius: F = 13, -1, 1, -13 at O, X, M, R, and F < 0 along XR, F > 0 along OM; I-WP:
    // F = 3, -5, -5, 3, and F < 0 along XM, F > 0 along OR. The lines run between those edges.
    PatchLayout n = p;
    n.surface = "neovius";
    n.start = {Point{0.5, 0, 0}, Point{0.5, 0.5, 0.5}};  // X .. R
    n.end = {Point{0, 0, 0}, Point{0.5, 0.5, 0}};        // O .. M
    n.sides = {MirrorPlane{{0, 1, -1}, 0}, MirrorPlane{{1, 0, 0}, 0.5}, MirrorPlane{{0, 0, 1}, 0},
               MirrorPlane{{1, -1, 0}, 0}};
    PatchLayout w = p;
    w.surface = "iwp";
    w.start = {Point{0.5, 0, 0}, Point{0.5, 0.5, 0}};  // X .. M
    w.end = {Point{0, 0, 0}, Point{0.5, 0.5, 0.5}};    // O .. R
    w.sides = {MirrorPlane{{0, 0, 1}, 0}, MirrorPlane{{1, 0, 0}, 0.5}, MirrorPlane{{0, 1, -1}, 0},
               MirrorPlane{{1, -1, 0}, 0}};
    // F-RD (Fm-3m): the face-centred group's mirrors are the cube's and x + y = 1/2 (and the like),
    // which bound the tetrahedron O(0,0,0) X(1/2,0,0) Q(1/4,1/4,0) Q'(1/4,1/4,1/4), 1/192 of the cell.
    // F = 1, -7, 1, -3 at O, X, Q, Q', with F < 0 along XQ' and F > 0 along OQ.
    PatchLayout f = p;
    f.surface = "frd";
    f.pieces = "192 per sheet and cell";
    f.start = {Point{0.5, 0, 0}, Point{0.25, 0.25, 0.25}};  // X .. Q'
    f.end = {Point{0, 0, 0}, Point{0.25, 0.25, 0}};         // O .. Q
    f.sides = {MirrorPlane{{0, 1, -1}, 0}, MirrorPlane{{1, 1, 0}, 0.5}, MirrorPlane{{0, 0, 1}, 0},
               MirrorPlane{{1, -1, 0}, 0}};
    return std::vector<PatchLayout>{p, d, n, w, f};
  }();
  return all;
}

Point along(const std::array<Point, 2>& edge, double t) {
  return {edge[0][0] + t * (edge[1][0] - edge[0][0]), edge[0][1] + t * (edge[1][1] - edge[0][1]),
          edge[0][2] + t * (edge[1][2] - edge[0][2])};
}

bool inside(const std::vector<Slab>& region, const Point& p) {
  return std::all_of(region.begin(), region.end(), [&p](const Slab& s) {
    const double d = dot(s.normal, p);
    return s.lo < d && d < s.hi;
  });
}

}  // namespace

Point Isometry::apply(const Point& p) const {
  Point q{};
  for (size_t a = 0; a < 3; ++a) q[a] = sign[a] * p[static_cast<size_t>(from[a])] + shift[a];
  return q;
}

bool Isometry::reverses() const {
  int parity = 0;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = a + 1; b < 3; ++b)
      if (from[a] > from[b]) ++parity;
  for (int s : sign) parity += s < 0 ? 1 : 0;
  return parity % 2 == 1;
}

bool Isometry::operator<(const Isometry& o) const {
  return std::tie(from, sign, shift) < std::tie(o.from, o.sign, o.shift);
}

Isometry compose(const Isometry& outer, const Isometry& inner) {
  Isometry g;
  for (size_t a = 0; a < 3; ++a) {
    const auto k = static_cast<size_t>(outer.from[a]);
    g.from[a] = inner.from[k];
    g.sign[a] = outer.sign[a] * inner.sign[k];
    g.shift[a] = outer.sign[a] * inner.shift[k] + outer.shift[a];
  }
  return g;
}

Isometry reflection(const MirrorPlane& plane) {
  std::vector<size_t> axes;
  for (size_t a = 0; a < 3; ++a)
    if (plane.normal[a] != 0) axes.push_back(a);
  Isometry r;
  if (axes.size() == 1) {  // x_a = d / n_a: x_a -> 2 x_a0 - x_a
    const size_t a = axes[0];
    r.sign[a] = -1;
    r.shift[a] = 2 * plane.offset / plane.normal[a];
    return r;
  }
  if (axes.size() != 2) throw std::logic_error("a mirror plane of a cubic cell has one or two nonzero normal entries");
  // n_a x_a + n_b x_b = d, n = +-1: swap the two coordinates, with the signs and shifts that fix the plane.
  const size_t a = axes[0], b = axes[1];
  const int na = plane.normal[a], nb = plane.normal[b];
  r.from[a] = static_cast<int>(b);
  r.from[b] = static_cast<int>(a);
  r.sign[a] = -na * nb;
  r.sign[b] = -na * nb;
  r.shift[a] = plane.offset * na;
  r.shift[b] = plane.offset * nb;
  return r;
}

Segment PatchLayout::line(double u, double v) const {
  const Point a = along(start, v), b = along(end, u);
  Segment s{};
  for (size_t k = 0; k < 3; ++k) {
    s.a[k] = a[k];
    s.b[k] = b[k];
  }
  return s;
}

Point PatchLayout::centroid() const {
  Point c{};
  for (size_t k = 0; k < 3; ++k) c[k] = 0.25 * (start[0][k] + start[1][k] + end[0][k] + end[1][k]);
  return c;
}

const PatchLayout* find_patch_layout(const std::string& surface) {
  for (const PatchLayout& layout : layouts())
    if (layout.surface == surface) return &layout;
  return nullptr;
}

std::string patch_layout_surfaces() {
  std::string names;
  for (const PatchLayout& layout : layouts()) names += (names.empty() ? "" : ", ") + layout.surface;
  return names;
}

std::vector<Point> patch_points(const PatchLayout& layout, const LevelFunction& g,
                                const std::vector<std::array<double, 2>>& uv) {
  std::vector<Segment> segments;
  segments.reserve(uv.size());
  for (const auto& [u, v] : uv) segments.push_back(layout.line(u, v));
  const std::vector<std::vector<double>> roots = segment_roots(g, segments, kSteps);
  std::vector<Point> points(uv.size());
  for (size_t i = 0; i < uv.size(); ++i) {
    if (roots[i].size() != 1)
      throw InputError(
          fmt::format("the offset surface crosses the line of the {} symmetry patch at (u, v) = ({:.3f}, {:.3f}) {} "
                      "times, not once: at this thickness the wall is not the graph the patch layout needs (reduce "
                      "--thickness, or try --patches box, which fits each piece where it lies)",
                      layout.surface, uv[i][0], uv[i][1], roots[i].size()));
    const Segment& s = segments[i];
    const double t = roots[i][0];
    for (size_t a = 0; a < 3; ++a) points[i][a] = s.a[a] + t * (s.b[a] - s.a[a]);
  }
  return points;
}

std::vector<Point> patch_points(const PatchLayout& layout, const LevelFunction& g, int m) {
  std::vector<std::array<double, 2>> uv;
  uv.reserve(static_cast<size_t>(m * m));
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) uv.push_back({double(i) / (m - 1), double(j) / (m - 1)});
  return patch_points(layout, g, uv);
}

namespace {

// The control points of side k of a patch: u = 0, u = 1, v = 0, v = 1.
std::vector<Point*> side_points(CubicPatch& patch, size_t k) {
  const int n = patch.n;
  std::vector<Point*> out;
  for (int t = 0; t < n; ++t) {
    if (k == 0) out.push_back(&patch.at(0, t));
    if (k == 1) out.push_back(&patch.at(n - 1, t));
    if (k == 2) out.push_back(&patch.at(t, 0));
    if (k == 3) out.push_back(&patch.at(t, n - 1));
  }
  return out;
}

}  // namespace

void snap_boundary(const PatchLayout& layout, CubicPatch& patch) {
  for (size_t k = 0; k < 4; ++k) {
    const MirrorPlane& plane = layout.sides[k];
    size_t last = 0;
    for (size_t a = 0; a < 3; ++a)
      if (plane.normal[a] != 0) last = a;
    for (Point* p : side_points(patch, k)) {
      if (std::fabs(dot(plane.normal, *p) - plane.offset) > 1e-12)
        throw std::logic_error(
            fmt::format("{} patch: a boundary control point is off its mirror plane", layout.surface));
      double rest = plane.offset;
      for (size_t a = 0; a < 3; ++a)
        if (a != last) rest -= plane.normal[a] * (*p)[a];
      (*p)[last] = rest / plane.normal[last];
    }
  }
  for (size_t k = 0; k < 4; ++k)
    for (Point* p : side_points(patch, k))
      if (std::fabs(dot(layout.sides[k].normal, *p) - layout.sides[k].offset) > 1e-15)
        throw std::logic_error(fmt::format("{} patch: a corner is off one of its planes", layout.surface));
}

double normal_jump(const PatchLayout& layout, const CubicPatch& patch, int samples) {
  constexpr double kStep = 1e-6;
  auto normal_at = [&patch](double u, double v) {
    auto d = [&patch](double u0, double v0, double u1, double v1) {
      const Point a = patch.evaluate(u0, v0), b = patch.evaluate(u1, v1);
      return Point{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    };
    const double u0 = std::max(0.0, u - kStep), u1 = std::min(1.0, u + kStep);
    const double v0 = std::max(0.0, v - kStep), v1 = std::min(1.0, v + kStep);
    const Point du = d(u0, v, u1, v), dv = d(u, v0, u, v1);
    Point n{du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    const double length = std::hypot(n[0], n[1], n[2]);
    for (double& c : n) c /= length;
    return n;
  };
  double worst = 0;
  for (int k = 0; k <= samples; ++k) {
    const double t = double(k) / samples;
    const std::array<std::array<double, 2>, 4> at{{{0, t}, {1, t}, {t, 0}, {t, 1}}};
    for (size_t e = 0; e < 4; ++e) {
      const auto& m = layout.sides[e].normal;
      const double length = std::sqrt(double(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]));
      const Point n = normal_at(at[e][0], at[e][1]);
      const double sine = std::fabs(n[0] * m[0] + n[1] * m[1] + n[2] * m[2]) / length;
      worst = std::max(worst, 2 * std::asin(std::min(1.0, sine)));
    }
  }
  return worst;
}

namespace {

// Whether the tetrahedron's image comes nearer the block [0, cells]^3 than `margin` along every axis
// (its bounding box against the block's, so a few tetrahedra just beyond a corner pass too).
bool near_block(const PatchLayout& layout, const Isometry& map, const std::array<int, 3>& cells, double margin) {
  Point lo{}, hi{};
  bool first = true;
  for (const Point& vertex : {layout.start[0], layout.start[1], layout.end[0], layout.end[1]}) {
    const Point p = map.apply(vertex);
    for (size_t a = 0; a < 3; ++a) {
      lo[a] = first ? p[a] : std::min(lo[a], p[a]);
      hi[a] = first ? p[a] : std::max(hi[a], p[a]);
    }
    first = false;
  }
  for (size_t a = 0; a < 3; ++a)
    if (hi[a] <= -margin || lo[a] >= cells[a] + margin) return false;
  return true;
}

}  // namespace

std::vector<PatchImage> region_images(const PatchLayout& layout, const std::array<int, 3>& cells) {
  const std::vector<Slab> region = layout.region(cells);
  std::array<Isometry, 4> mirror;
  for (size_t k = 0; k < 4; ++k) mirror[k] = reflection(layout.sides[k]);
  const Point c = layout.centroid();
  // Where the region is larger than the block, only the tetrahedra that reach into the block are
  // kept: the box cuts the rest off anyway. The caps on their outer faces then lie at least
  // kBlockClearance outside the block, never in a plane of its box.
  constexpr double kBlockClearance = 1e-4;
  auto wanted = [&](const Isometry& map) {
    return inside(region, map.apply(c)) && (layout.region_is_block || near_block(layout, map, cells, kBlockClearance));
  };
  if (!wanted(Isometry{}))
    throw std::logic_error(layout.surface + ": the patch's own tetrahedron is not in the region");
  // Breadth first from the identity through the faces: the tetrahedra tile space, and those inside the
  // convex region (and reaching into the convex block) are connected through faces, so the search
  // finds all of them.
  std::vector<PatchImage> images{PatchImage{Isometry{}, {}}};
  std::set<Isometry> seen{Isometry{}};
  for (size_t i = 0; i < images.size(); ++i)
    for (size_t k = 0; k < 4; ++k) {
      const Isometry next = compose(images[i].map, mirror[k]);
      if (!wanted(next)) {
        images[i].cap[k] = true;
        continue;
      }
      if (seen.insert(next).second) images.push_back(PatchImage{next, {}});
    }
  return images;
}

}  // namespace offsetgen::step
