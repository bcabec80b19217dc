#include "step/deviation.h"

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
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

// The distance from p to the surface over its whole parameter rectangle, by Newton's method on the
// squared distance from `start`, each step clipped to the rectangle (a variable at its bound and
// pushed outward stays there). A general point-surface search (ShapeAnalysis_Surface's fallback when
// its Newton leaves the rectangle) builds a grid per call: it was most of the deviation's time, and
// the start, the nearest of a grid of the face, is close enough for Newton. The result is a point of
// the face, so never below the true distance.
double distance_in_rectangle(const Geom_BSplineSurface& s, const gp_Pnt2d& start, const gp_Pnt& p) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  s.Bounds(u0, u1, v0, v1);
  double u = start.X(), v = start.Y();
  const double eps_u = 1e-14 * (u1 - u0), eps_v = 1e-14 * (v1 - v0);
  for (int iteration = 0; iteration < 40; ++iteration) {
    gp_Pnt q;
    gp_Vec su, sv, suu, svv, suv;
    s.D2(u, v, q, su, sv, suu, svv, suv);
    const gp_Vec r(p, q);  // q - p
    const double gu = r.Dot(su), gv = r.Dot(sv);
    double huu = su.Dot(su) + r.Dot(suu), hvv = sv.Dot(sv) + r.Dot(svv), huv = su.Dot(sv) + r.Dot(suv);
    if (huu <= 0 || hvv <= 0 || huu * hvv - huv * huv <= 0) {  // not convex here: Gauss-Newton
      huu = su.Dot(su);
      hvv = sv.Dot(sv);
      huv = su.Dot(sv);
    }
    // Variables at a bound with the gradient pushing outward are held; Newton in the others.
    const bool hold_u = (u <= u0 && gu > 0) || (u >= u1 && gu < 0);
    const bool hold_v = (v <= v0 && gv > 0) || (v >= v1 && gv < 0);
    double du = 0, dv = 0;
    if (hold_u && hold_v) break;
    if (hold_u) {
      dv = hvv > 0 ? -gv / hvv : 0;
    } else if (hold_v) {
      du = huu > 0 ? -gu / huu : 0;
    } else {
      const double det = huu * hvv - huv * huv;
      if (!(det > 0)) break;
      du = (-gu * hvv + gv * huv) / det;
      dv = (-gv * huu + gu * huv) / det;
    }
    const double nu = std::clamp(u + du, u0, u1), nv = std::clamp(v + dv, v0, v1);
    const bool converged = std::abs(nu - u) <= eps_u && std::abs(nv - v) <= eps_v;
    u = nu;
    v = nv;
    if (converged) break;
  }
  return s.Value(u, v).Distance(p);
}

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

Deviation measure_deviation(const TopoDS_Shape& shape, const std::vector<Point>& points, const Point& mm,
                            double reach) {
  // A face: its box, and a grid of its points whose nearest gives the projection its start (Newton
  // from there, ShapeAnalysis_Surface::NextValueOfUV, which falls back to a global search).
  constexpr int kGrid = 9;
  struct Candidate {
    Bnd_Box box;
    Handle(Geom_BSplineSurface) surface;
    std::vector<std::pair<gp_Pnt2d, gp_Pnt>> grid;
  };
  std::vector<Candidate> faces;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    Handle(Geom_BSplineSurface) surface = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));
    if (surface.IsNull()) continue;
    Candidate c;
    BRepBndLib::Add(face, c.box);
    c.box.Enlarge(reach);
    c.surface = surface;
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
    const gp_Pnt p(q[0] * mm[0], q[1] * mm[1], q[2] * mm[2]);
    double best = reach;
    for (Candidate& c : faces) {
      if (c.box.IsOut(p)) continue;
      const auto start = std::min_element(c.grid.begin(), c.grid.end(), [&p](const auto& a, const auto& b) {
        return a.second.SquareDistance(p) < b.second.SquareDistance(p);
      });
      best = std::min({best, start->second.Distance(p), distance_in_rectangle(*c.surface, start->first, p)});
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
