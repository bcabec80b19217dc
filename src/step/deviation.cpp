#include "step/deviation.h"

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>

namespace offsetgen::step {
namespace {

// splitmix64: a fixed, portable sequence in [0, 1).
struct Jitter {
  uint64_t state;
  double next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
  }
};

}  // namespace

std::vector<Point> exact_surface_points(const LevelFunction& g, const std::array<int, 3>& cells, int lines, int steps,
                                        uint64_t seed) {
  Jitter jitter{seed};
  std::vector<Point> points;
  for (size_t axis = 0; axis < 3; ++axis) {
    const size_t a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const int n1 = cells[a1] * lines, n2 = cells[a2] * lines;
    std::vector<Segment> segments;
    for (int i = 0; i < n1; ++i)
      for (int j = 0; j < n2; ++j) {
        Segment s{};
        s.a[a1] = s.b[a1] = (i + jitter.next()) / lines;
        s.a[a2] = s.b[a2] = (j + jitter.next()) / lines;
        s.a[axis] = 0;
        s.b[axis] = cells[axis];
        segments.push_back(s);
      }
    const auto roots = segment_roots(g, segments, steps * cells[axis]);
    for (size_t k = 0; k < segments.size(); ++k)
      for (double t : roots[k]) {
        Point p{};
        for (size_t a = 0; a < 3; ++a) p[a] = segments[k].a[a] + t * (segments[k].b[a] - segments[k].a[a]);
        points.push_back(p);
      }
  }
  return points;
}

Deviation measure_deviation(const TopoDS_Shape& shape, const std::vector<Point>& points, double cell_size,
                            double reach) {
  // A face: its box, and a grid of its points whose nearest gives the projection its start (Newton
  // from there, ShapeAnalysis_Surface::NextValueOfUV, which falls back to a global search).
  constexpr int kGrid = 9;
  struct Candidate {
    Bnd_Box box;
    std::unique_ptr<ShapeAnalysis_Surface> surface;
    std::vector<std::pair<gp_Pnt2d, gp_Pnt>> grid;
  };
  std::vector<Candidate> faces;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    if (surface->DynamicType() != STANDARD_TYPE(Geom_BSplineSurface)) continue;
    Candidate c;
    BRepBndLib::Add(face, c.box);
    c.box.Enlarge(reach);
    c.surface = std::make_unique<ShapeAnalysis_Surface>(surface);
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    surface->Bounds(u0, u1, v0, v1);
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        const gp_Pnt2d uv(u0 + (u1 - u0) * i / (kGrid - 1), v0 + (v1 - v0) * j / (kGrid - 1));
        c.grid.emplace_back(uv, surface->Value(uv.X(), uv.Y()));
      }
    faces.push_back(std::move(c));
  }
  Deviation d;
  double sum = 0;
  for (const Point& q : points) {
    const gp_Pnt p(q[0] * cell_size, q[1] * cell_size, q[2] * cell_size);
    double best = reach;
    for (Candidate& c : faces) {
      if (c.box.IsOut(p)) continue;
      const auto start = std::min_element(c.grid.begin(), c.grid.end(), [&p](const auto& a, const auto& b) {
        return a.second.SquareDistance(p) < b.second.SquareDistance(p);
      });
      c.surface->NextValueOfUV(start->first, p, 1e-3 * Precision::Confusion());
      best = std::min(best, c.surface->Gap());
    }
    sum += best;
    if (best > d.max || d.points == 0) {
      d.max = best;
      d.worst = {p.X(), p.Y(), p.Z()};
    }
    ++d.points;
  }
  d.mean = d.points ? sum / double(d.points) : 0;
  return d;
}

}  // namespace offsetgen::step
