#include "step/box_patch.h"

#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <stdexcept>
#include <thread>
#include <unordered_map>

namespace offsetgen::step {
namespace {

// Samples per box edge: a box's face is scanned on a grid of kSamples x kSamples squares.
constexpr int kSamples = 24;
// Central differences for gradients (cell units).
constexpr double kStep = 1e-6;

Point add(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point scale(const Point& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Point& a) { return std::sqrt(dot(a, a)); }
Point unit(const Point& a) { return scale(a, 1 / norm(a)); }

// g at many points at once.
std::vector<double> evaluate(const LevelFunction& g, const std::vector<Point>& points) {
  const size_t n = points.size();
  std::vector<double> x(n), y(n), z(n), out(n);
  for (size_t i = 0; i < n; ++i) {
    x[i] = points[i][0];
    y[i] = points[i][1];
    z[i] = points[i][2];
  }
  if (n > 0) g(n, x.data(), y.data(), z.data(), out.data());
  return out;
}

// The gradients of g at the points, by central differences; only the axes in `axes` (the others 0).
std::vector<Point> gradients(const LevelFunction& g, const std::vector<Point>& points, std::array<bool, 3> axes) {
  std::vector<Point> probes;
  probes.reserve(points.size() * 6);
  for (const Point& p : points)
    for (size_t a = 0; a < 3; ++a) {
      Point lo = p, hi = p;
      lo[a] -= kStep;
      hi[a] += kStep;
      probes.push_back(lo);
      probes.push_back(hi);
    }
  const std::vector<double> v = evaluate(g, probes);
  std::vector<Point> out(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t a = 0; a < 3; ++a) out[i][a] = axes[a] ? (v[i * 6 + 2 * a + 1] - v[i * 6 + 2 * a]) / (2 * kStep) : 0.0;
  return out;
}

// Roots of g on segments lo + s (hi - lo) with a sign change between s = 0 and 1 (values f0, f1
// given), by the Illinois variant of regula falsi, all at once: a point each.
struct Bracket {
  Point lo, hi;
  double f0, f1;
};
std::vector<Point> refine(const LevelFunction& g, const std::vector<Bracket>& brackets) {
  const size_t n = brackets.size();
  std::vector<double> a(n, 0.0), b(n, 1.0), fa(n), fb(n);
  std::vector<int> side(n, 0);
  for (size_t i = 0; i < n; ++i) {
    fa[i] = brackets[i].f0;
    fb[i] = brackets[i].f1;
  }
  auto at = [&](size_t i, double s) { return add(brackets[i].lo, scale(sub(brackets[i].hi, brackets[i].lo), s)); };
  std::vector<size_t> active(n);
  for (size_t i = 0; i < n; ++i) active[i] = i;
  for (int pass = 0; pass < 80 && !active.empty(); ++pass) {
    std::vector<double> s(active.size());
    std::vector<Point> p(active.size());
    for (size_t k = 0; k < active.size(); ++k) {
      const size_t i = active[k];
      // Regula falsi, with a bisection every fourth pass so that the bracket always shrinks.
      double c = pass % 4 == 3 ? 0.5 * (a[i] + b[i]) : (a[i] * fb[i] - b[i] * fa[i]) / (fb[i] - fa[i]);
      if (!(c > a[i] && c < b[i])) c = 0.5 * (a[i] + b[i]);
      s[k] = c;
      p[k] = at(i, c);
    }
    const std::vector<double> f = evaluate(g, p);
    std::vector<size_t> next;
    for (size_t k = 0; k < active.size(); ++k) {
      const size_t i = active[k];
      if (f[k] == 0) {
        a[i] = b[i] = s[k];
        continue;
      }
      if ((f[k] < 0) == (fa[i] < 0)) {
        a[i] = s[k];
        fa[i] = f[k];
        if (side[i] == -1) fb[i] *= 0.5;
        side[i] = -1;
      } else {
        b[i] = s[k];
        fb[i] = f[k];
        if (side[i] == 1) fa[i] *= 0.5;
        side[i] = 1;
      }
      if (b[i] - a[i] > 1e-15) next.push_back(i);
    }
    active.swap(next);
  }
  std::vector<Point> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = at(i, 0.5 * (a[i] + b[i]));
  return out;
}

// The grid of box corners: n[a] boxes along axis a, side h (a power of two, so i * h is exact).
struct Grid {
  std::array<int, 3> n{};
  double h = 1;
  int vertex_count() const { return (n[0] + 1) * (n[1] + 1) * (n[2] + 1); }
  int vertex(const std::array<int, 3>& i) const { return (i[0] * (n[1] + 1) + i[1]) * (n[2] + 1) + i[2]; }
  std::array<int, 3> index(int v) const {
    const int l = v % (n[2] + 1), rest = v / (n[2] + 1);
    return {rest / (n[1] + 1), rest % (n[1] + 1), l};
  }
  Point at(const std::array<int, 3>& i) const { return {i[0] * h, i[1] * h, i[2] * h}; }
  // Edge (axis, vertex) and face (normal axis, vertex) ids.
  int id(int axis, int v) const { return axis * vertex_count() + v; }
  // Sample k of the edge from vertex i along axis.
  Point sample(const std::array<int, 3>& i, int axis, int k) const {
    Point p = at(i);
    p[static_cast<size_t>(axis)] += h * k / kSamples;
    return p;
  }
  bool has_edge(const std::array<int, 3>& i, int axis) const {
    return i[static_cast<size_t>(axis)] < n[static_cast<size_t>(axis)];
  }
};

std::array<int, 3> step(std::array<int, 3> i, int axis, int by = 1) {
  i[static_cast<size_t>(axis)] += by;
  return i;
}

std::string where(const Point& p) { return fmt::format("({:.4f}, {:.4f}, {:.4f})", p[0], p[1], p[2]); }

class Builder {
 public:
  Builder(const std::array<LevelFunction, 2>& g, const std::vector<std::array<LevelFunction, 2>>& more,
          const std::function<bool(const Point&)>& inside_wall, const std::array<int, 3>& cells, int k)
      : g_(g), more_(more), inside_(inside_wall) {
    grid_.n = {cells[0] * k, cells[1] * k, cells[2] * k};
    grid_.h = 1.0 / k;
    out_.boxes_per_cell = k;
  }

  BoxPartition run(double target, int max_side) {
    find_crossings();
    orient_sheets();
    trace_faces();
    for (int sheet = 0; sheet < 2; ++sheet) build_loops(sheet);
    fit_patches(target, max_side);
    build_caps();
    return std::move(out_);
  }

 private:
  // Edge samples and crossings. Each edge is scanned once; its faces reuse its samples, so a face's
  // boundary agrees with the crossings found on the edge.
  void find_crossings() {
    const int edges = 3 * grid_.vertex_count();
    for (int sheet = 0; sheet < 2; ++sheet) {
      samples_[sheet].assign(static_cast<size_t>(edges) * (kSamples + 1), 0.0);
      std::vector<Point> points;
      std::vector<int> ids;
      for (int v = 0; v < grid_.vertex_count(); ++v)
        for (int axis = 0; axis < 3; ++axis) {
          const auto i = grid_.index(v);
          if (!grid_.has_edge(i, axis)) continue;
          ids.push_back(grid_.id(axis, v));
          for (int s = 0; s <= kSamples; ++s) points.push_back(grid_.sample(i, axis, s));
        }
      const std::vector<double> values = evaluate(g_[sheet], points);
      std::vector<Bracket> brackets;
      std::vector<long> keys;
      for (size_t e = 0; e < ids.size(); ++e) {
        const int id = ids[e];
        for (int s = 0; s <= kSamples; ++s) {
          const double f = values[e * (kSamples + 1) + static_cast<size_t>(s)];
          if (f == 0)
            throw InputError(fmt::format("a sheet of the wall passes exactly through the point {} of the boxes' grid",
                                         where(points[e * (kSamples + 1) + static_cast<size_t>(s)])));
          samples_[sheet][static_cast<size_t>(id) * (kSamples + 1) + static_cast<size_t>(s)] = f;
        }
        for (int s = 0; s < kSamples; ++s) {
          const size_t at = e * (kSamples + 1) + static_cast<size_t>(s);
          if ((values[at] < 0) == (values[at + 1] < 0)) continue;
          brackets.push_back({points[at], points[at + 1], values[at], values[at + 1]});
          keys.push_back(crossing_key(id, s));
        }
      }
      const std::vector<Point> roots = refine(g_[sheet], brackets);
      for (size_t b = 0; b < roots.size(); ++b) {
        crossing_[sheet][keys[b]] = static_cast<int>(out_.vertices.size());
        out_.vertices.push_back(roots[b]);
        crossing_sheet_.push_back(sheet);
      }
    }
  }

  static long crossing_key(int edge, int s) { return long(edge) * (kSamples + 1) + s; }

  int crossing(int sheet, int edge, int s) const {
    const auto it = crossing_[sheet].find(crossing_key(edge, s));
    if (it == crossing_[sheet].end()) throw std::logic_error("box patches: a face crossing with no edge crossing");
    return it->second;
  }

  // Which way each sheet's gradient points: out of the wall or into it.
  void orient_sheets() {
    for (int sheet = 0; sheet < 2; ++sheet) {
      int out = 0, in = 0;
      std::vector<Point> points;
      for (size_t v = 0; v < out_.vertices.size() && points.size() < 16; ++v)
        if (crossing_sheet_[v] == sheet) points.push_back(out_.vertices[v]);
      if (points.empty()) throw InputError("a sheet of the wall does not cross the block's boxes");
      const std::vector<Point> grad = gradients(g_[sheet], points, {true, true, true});
      for (size_t i = 0; i < points.size(); ++i) {
        const Point probe = add(points[i], scale(unit(grad[i]), 1e-5));
        (inside_(probe) ? in : out) += 1;
      }
      if (in != 0 && out != 0)
        throw std::logic_error("box patches: a sheet's gradient points both ways out of the wall");
      outward_[sheet] = out > 0 ? 1.0 : -1.0;
    }
  }

  // The curves on every box face that a sheet crosses: marching squares on the face's sample grid for
  // the topology, then points evenly spaced along it, moved onto the sheet within the face's plane.
  void trace_faces() {
    for (int sheet = 0; sheet < 2; ++sheet) {
      struct Face {
        int axis, v;
        std::vector<double> values;  // (kSamples + 1)^2, [i * (kSamples + 1) + j], i along b, j along c
      };
      std::vector<Face> faces;
      std::vector<Point> interior;
      for (int v = 0; v < grid_.vertex_count(); ++v)
        for (int axis = 0; axis < 3; ++axis) {
          const auto i = grid_.index(v);
          const int b = (axis + 1) % 3, c = (axis + 2) % 3;
          if (!grid_.has_edge(i, b) || !grid_.has_edge(i, c)) continue;
          Face face{axis, v, std::vector<double>(static_cast<size_t>((kSamples + 1) * (kSamples + 1)))};
          bool crossed = false;
          auto edge = [&](const std::array<int, 3>& from, int along, int s) {
            return samples_[sheet][static_cast<size_t>(grid_.id(along, grid_.vertex(from))) * (kSamples + 1) +
                                   static_cast<size_t>(s)];
          };
          for (int s = 0; s <= kSamples; ++s) {
            face.values[index(s, 0)] = edge(i, b, s);
            face.values[index(s, kSamples)] = edge(step(i, c), b, s);
            face.values[index(0, s)] = edge(i, c, s);
            face.values[index(kSamples, s)] = edge(step(i, b), c, s);
          }
          for (int s = 0; s < kSamples; ++s)
            crossed = crossed || differ(face.values, index(s, 0), index(s + 1, 0)) ||
                      differ(face.values, index(s, kSamples), index(s + 1, kSamples)) ||
                      differ(face.values, index(0, s), index(0, s + 1)) ||
                      differ(face.values, index(kSamples, s), index(kSamples, s + 1));
          if (!crossed) continue;
          for (int a = 1; a < kSamples; ++a)
            for (int d = 1; d < kSamples; ++d) interior.push_back(face_point(axis, v, a, d));
          faces.push_back(std::move(face));
        }
      const std::vector<double> values = evaluate(g_[sheet], interior);
      size_t next = 0;
      std::vector<std::vector<Point>> polylines;
      for (Face& face : faces) {
        for (int a = 1; a < kSamples; ++a)
          for (int d = 1; d < kSamples; ++d) face.values[index(a, d)] = values[next++];
        march(sheet, face.axis, face.v, face.values, polylines);
      }
      place_curve_points(sheet, polylines);
    }
  }

  static size_t index(int i, int j) { return flat(i, kSamples + 1, j); }
  static bool differ(const std::vector<double>& v, size_t a, size_t b) { return (v[a] < 0) != (v[b] < 0); }

  Point face_point(int axis, int v, double a, double d) const {
    Point p = grid_.at(grid_.index(v));
    p[static_cast<size_t>((axis + 1) % 3)] += grid_.h * a / kSamples;
    p[static_cast<size_t>((axis + 2) % 3)] += grid_.h * d / kSamples;
    return p;
  }

  // Marching squares on one face: the chains of sample-grid crossings from one boundary crossing to
  // another, each a new curve (its points still rough, on the grid's lines).
  void march(int sheet, int axis, int v, const std::vector<double>& f, std::vector<std::vector<Point>>& polylines) {
    constexpr int S = kSamples;
    // Nodes: crossings of the grid's lines. H(i, j) on (i, j)-(i+1, j), V(i, j) on (i, j)-(i, j+1).
    const int nh = S * (S + 1);
    auto h_node = [&](int i, int j) { return j * S + i; };
    auto v_node = [&](int i, int j) { return nh + i * S + j; };
    std::vector<std::array<int, 2>> link(static_cast<size_t>(2 * nh), {-1, -1});
    auto connect = [&](int p, int q) {
      for (int r : {p, q}) {
        auto& l = link[static_cast<size_t>(r)];
        (l[0] < 0 ? l[0] : l[1]) = r == p ? q : p;
      }
    };
    auto hx = [&](int i, int j) { return differ(f, index(i, j), index(i + 1, j)); };
    auto vx = [&](int i, int j) { return differ(f, index(i, j), index(i, j + 1)); };
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) {
        std::vector<int> nodes;
        if (hx(i, j)) nodes.push_back(h_node(i, j));
        if (vx(i + 1, j)) nodes.push_back(v_node(i + 1, j));
        if (hx(i, j + 1)) nodes.push_back(h_node(i, j + 1));
        if (vx(i, j)) nodes.push_back(v_node(i, j));
        if (nodes.size() == 2) connect(nodes[0], nodes[1]);
        if (nodes.size() == 4) {
          // A saddle: the centre's sign decides which corners the curves cut off.
          const double centre =
              0.25 * (f[index(i, j)] + f[index(i + 1, j)] + f[index(i + 1, j + 1)] + f[index(i, j + 1)]);
          if ((centre < 0) == (f[index(i, j)] < 0)) {
            connect(h_node(i, j), v_node(i + 1, j));
            connect(h_node(i, j + 1), v_node(i, j));
          } else {
            connect(h_node(i, j), v_node(i, j));
            connect(v_node(i + 1, j), h_node(i, j + 1));
          }
        }
      }
    auto position = [&](int node) {
      if (node < nh) {
        const int i = node % S, j = node / S;
        const double t = f[index(i, j)] / (f[index(i, j)] - f[index(i + 1, j)]);
        return face_point(axis, v, i + t, j);
      }
      const int i = (node - nh) / S, j = (node - nh) % S;
      const double t = f[index(i, j)] / (f[index(i, j)] - f[index(i, j + 1)]);
      return face_point(axis, v, i, j + t);
    };
    const auto corner = grid_.index(v);
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    // The vertex of a boundary node: the crossing found on the box's edge.
    auto boundary_vertex = [&](int node) -> int {
      if (node < nh) {
        const int i = node % S, j = node / S;
        if (j == 0) return crossing(sheet, grid_.id(b, v), i);
        if (j == S) return crossing(sheet, grid_.id(b, grid_.vertex(step(corner, c))), i);
        return -1;
      }
      const int i = (node - nh) / S, j = (node - nh) % S;
      if (i == 0) return crossing(sheet, grid_.id(c, v), j);
      if (i == S) return crossing(sheet, grid_.id(c, grid_.vertex(step(corner, b))), j);
      return -1;
    };
    std::vector<bool> seen(link.size(), false);
    for (int start = 0; start < 2 * nh; ++start) {
      const auto& l = link[static_cast<size_t>(start)];
      if (seen[static_cast<size_t>(start)] || l[0] < 0 || l[1] >= 0 || boundary_vertex(start) < 0) continue;
      std::vector<Point> line;
      int prev = -1, node = start;
      for (;;) {
        seen[static_cast<size_t>(node)] = true;
        line.push_back(position(node));
        const auto& ln = link[static_cast<size_t>(node)];
        const int nxt = ln[0] != prev ? ln[0] : ln[1];
        if (nxt < 0 || (node != start && ln[1] < 0)) break;
        prev = node;
        node = nxt;
      }
      const int from = boundary_vertex(start), to = boundary_vertex(node);
      if (to < 0 || node == start) throw std::logic_error("box patches: a curve on a box's face ends inside the face");
      line.front() = out_.vertices[static_cast<size_t>(from)];
      line.back() = out_.vertices[static_cast<size_t>(to)];
      BoxCurve curve;
      curve.sheet = sheet;
      curve.from = from;
      curve.to = to;
      face_curves_[sheet][grid_.id(axis, v)].push_back(static_cast<int>(out_.curves.size()));
      curve_axis_.push_back(axis);
      out_.curves.push_back(std::move(curve));
      polylines.push_back(std::move(line));
    }
    for (size_t node = 0; node < link.size(); ++node)
      if (link[node][0] >= 0 && !seen[node])
        throw InputError(fmt::format(
            "a sheet of the wall closes into a loop inside a face of the boxes (near {}): it touches the face there; "
            "the boxes cannot cut it",
            where(position(static_cast<int>(node)))));
  }

  // Even spacing along each rough polyline, then each inner point moved onto the sheet within its
  // face's plane (Newton steps along the in-plane gradient).
  void place_curve_points(int sheet, const std::vector<std::vector<Point>>& polylines) {
    const size_t first = out_.curves.size() - polylines.size();
    std::vector<size_t> owner;
    std::vector<Point> points;
    for (size_t k = 0; k < polylines.size(); ++k) {
      const std::vector<Point>& line = polylines[k];
      std::vector<double> length{0};
      for (size_t i = 1; i < line.size(); ++i) length.push_back(length.back() + norm(sub(line[i], line[i - 1])));
      const int pieces = std::clamp(static_cast<int>(std::ceil(length.back() / (grid_.h / 16))), 3, 48);
      BoxCurve& curve = out_.curves[first + k];
      curve.points.push_back(line.front());
      size_t at = 1;
      for (int p = 1; p < pieces; ++p) {
        const double s = length.back() * p / pieces;
        while (at + 1 < line.size() && length[at] < s) ++at;
        const double w = (s - length[at - 1]) / std::max(length[at] - length[at - 1], 1e-300);
        curve.points.push_back(add(line[at - 1], scale(sub(line[at], line[at - 1]), w)));
        owner.push_back(first + k);
        points.push_back(curve.points.back());
      }
      curve.points.push_back(line.back());
    }
    for (int iteration = 0; iteration < 4; ++iteration) {
      std::vector<Point> moved = points;
      // Each curve's plane: its face's normal axis has a zero gradient component.
      std::vector<double> f = evaluate(g_[sheet], points);
      std::vector<Point> grad = gradients(g_[sheet], points, {true, true, true});
      for (size_t i = 0; i < points.size(); ++i) {
        Point gp = grad[i];
        gp[static_cast<size_t>(curve_axis_[owner[i]])] = 0;
        const double g2 = dot(gp, gp);
        if (!(g2 > 0))
          throw InputError(fmt::format("a sheet of the wall is tangent to a box's face at {}", where(points[i])));
        moved[i] = sub(points[i], scale(gp, f[i] / g2));
      }
      points.swap(moved);
    }
    const std::vector<double> f = evaluate(g_[sheet], points);
    const std::vector<Point> grad = gradients(g_[sheet], points, {true, true, true});
    size_t next = 0;
    for (size_t k = 0; k < polylines.size(); ++k) {
      BoxCurve& curve = out_.curves[first + k];
      for (size_t i = 1; i + 1 < curve.points.size(); ++i, ++next) {
        if (!(std::abs(f[next]) <= 1e-9 * norm(grad[next])))
          throw InputError(
              fmt::format("a curve where a sheet of the wall crosses a box's face could not be traced near {}",
                          where(points[next])));
        curve.points[i] = points[next];
      }
    }
  }

  // The loops of one sheet in each box: its curves on the box's six faces meet two by two at the
  // crossings on the box's edges.
  void build_loops(int sheet) {
    for (int v = 0; v < grid_.vertex_count(); ++v) {
      const auto i = grid_.index(v);
      if (!grid_.has_edge(i, 0) || !grid_.has_edge(i, 1) || !grid_.has_edge(i, 2)) continue;
      std::vector<int> curves;
      for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
          const auto it = face_curves_[sheet].find(grid_.id(axis, grid_.vertex(step(i, axis, side))));
          if (it != face_curves_[sheet].end()) curves.insert(curves.end(), it->second.begin(), it->second.end());
        }
      if (curves.empty()) continue;
      std::map<int, std::vector<int>> at;  // vertex -> the curves ending there
      for (int c : curves) {
        at[out_.curves[static_cast<size_t>(c)].from].push_back(c);
        at[out_.curves[static_cast<size_t>(c)].to].push_back(c);
      }
      for (const auto& [vertex, list] : at)
        if (list.size() != 2)
          throw InputError(
              fmt::format("a sheet of the wall crosses a box's edge at {} in a way the boxes cannot follow",
                          where(out_.vertices[static_cast<size_t>(vertex)])));
      std::map<int, bool> used;
      for (int c0 : curves) {
        if (used[c0]) continue;
        std::vector<LoopEdge> loop;
        int c = c0, from = out_.curves[static_cast<size_t>(c0)].from;
        for (;;) {
          used[c] = true;
          const BoxCurve& curve = out_.curves[static_cast<size_t>(c)];
          const bool forward = curve.from == from;
          const int to = forward ? curve.to : curve.from;
          loop.push_back({c, forward, from, to});
          const std::vector<int>& there = at[to];
          const int nxt = there[0] == c ? there[1] : there[0];
          from = to;
          c = nxt;
          if (c == c0) break;
        }
        BoxPatch patch;
        patch.sheet = sheet;
        patch.loop = std::move(loop);
        out_.patches.push_back(std::move(patch));
      }
    }
  }

  // The points of a loop, in order, each once.
  std::vector<Point> loop_points(const std::vector<LoopEdge>& loop) const {
    std::vector<Point> out;
    for (const LoopEdge& e : loop) {
      if (e.curve < 0) {
        out.push_back(out_.vertices[static_cast<size_t>(e.from)]);
        continue;
      }
      const std::vector<Point>& p = out_.curves[static_cast<size_t>(e.curve)].points;
      if (e.forward)
        out.insert(out.end(), p.begin(), p.end() - 1);
      else
        out.insert(out.end(), p.rbegin(), p.rend() - 1);
    }
    return out;
  }

  static void reverse_loop(std::vector<LoopEdge>& loop) {
    std::reverse(loop.begin(), loop.end());
    for (LoopEdge& e : loop) {
      e.forward = !e.forward;
      std::swap(e.from, e.to);
    }
  }

  // Each patch on its own: on one thread per evaluator, patches i, i + threads, ... each. Where several
  // fail, the first patch's reason is the one reported, as on one thread.
  void fit_patches(double target, int max_side) {
    const size_t threads = 1 + more_.size(), count = out_.patches.size();
    std::vector<std::pair<size_t, std::exception_ptr>> failed(threads, {count, nullptr});
    auto work = [&](size_t t) {
      const std::array<LevelFunction, 2>& g = t == 0 ? g_ : more_[t - 1];
      for (size_t i = t; i < count; i += threads) {
        try {
          fit_patch_in_box(out_.patches[i], g[static_cast<size_t>(out_.patches[i].sheet)], target, max_side);
        } catch (...) {
          failed[t] = {i, std::current_exception()};
          return;
        }
      }
    };
    std::vector<std::thread> pool;
    for (size_t t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& thread : pool) thread.join();
    const auto first =
        std::min_element(failed.begin(), failed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (first->second) std::rethrow_exception(first->second);
    for (const BoxPatch& patch : out_.patches) {
      out_.largest_side = std::max(out_.largest_side, patch.patch.n);
      out_.fit_error = std::max(out_.fit_error, patch.error);
    }
  }

  // The frame across the piece's mean outward normal, the loop counterclockwise in it, the height
  // samples, and the fit.
  void fit_patch_in_box(BoxPatch& patch, const LevelFunction& g, double target, int max_side) const {
    std::vector<Point> ring = loop_points(patch.loop);
    const std::vector<Point> grad = gradients(g, ring, {true, true, true});
    Point mean{};
    for (const Point& n : grad) mean = add(mean, scale(unit(n), outward_[patch.sheet]));
    const Point normal = unit(mean);
    double worst = 1;
    for (const Point& n : grad) worst = std::min(worst, dot(scale(unit(n), outward_[patch.sheet]), normal));
    if (!(worst > 0.2))
      throw InputError(
          fmt::format("a piece of a sheet of the wall in one box (near {}) turns too far to be a graph over one plane",
                      where(ring.front())));
    size_t least = 0;
    for (size_t a = 1; a < 3; ++a)
      if (std::abs(normal[a]) < std::abs(normal[least])) least = a;
    Point axis{};
    axis[least] = 1;
    patch.normal = normal;
    patch.e1 = unit(sub(axis, scale(normal, normal[least])));
    patch.e2 = cross(normal, patch.e1);
    Point centre{};
    for (const Point& p : ring) centre = add(centre, p);
    patch.origin = scale(centre, 1.0 / double(ring.size()));
    // Plane coordinates and heights of the loop.
    std::vector<std::array<double, 3>> uvs;
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const Point& p : ring) {
      const Point d = sub(p, patch.origin);
      uvs.push_back({dot(d, patch.e1), dot(d, patch.e2), dot(d, normal)});
      u0 = std::min(u0, uvs.back()[0]);
      u1 = std::max(u1, uvs.back()[0]);
      v0 = std::min(v0, uvs.back()[1]);
      v1 = std::max(v1, uvs.back()[1]);
    }
    double area = 0;
    for (size_t k = 0; k < uvs.size(); ++k) {
      const auto& p = uvs[k];
      const auto& q = uvs[(k + 1) % uvs.size()];
      area += p[0] * q[1] - q[0] * p[1];
    }
    if (area < 0) {
      reverse_loop(patch.loop);
      std::reverse(uvs.begin(), uvs.end());
    }
    const double margin = 0.03 * std::max(u1 - u0, v1 - v0) + 1e-6;
    patch.u0 = u0 - margin;
    patch.u1 = u1 + margin;
    patch.v0 = v0 - margin;
    patch.v1 = v1 + margin;
    const std::array<double, 6> guess = quadratic_heights(uvs);
    for (int n : kPatchSides) {
      if (n > max_side) break;
      const int m = 3 * n + 1;
      std::vector<std::array<double, 2>> ab;
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) ab.push_back({double(i) / (m - 1), double(j) / (m - 1)});
      Heights heights = heights_at(patch, g, ab, uvs, guess);
      extend_outside(heights, m, std::max(patch.u1 - patch.u0, patch.v1 - patch.v0) / (m - 1));
      std::vector<Point> samples;
      for (size_t k = 0; k < ab.size(); ++k) {
        const double h = heights.h[k];
        samples.push_back(plane_point(patch, ab[k][0], ab[k][1], std::isfinite(h) ? h : guess_at(guess, patch, ab[k])));
      }
      patch.patch = fit_patch(samples, m, n);
      // The check: the midpoints of the sample grid inside the loop.
      std::vector<std::array<double, 2>> mid;
      for (int i = 0; i + 1 < m; ++i)
        for (int j = 0; j + 1 < m; ++j) mid.push_back({(i + 0.5) / (m - 1), (j + 0.5) / (m - 1)});
      const Heights exact = heights_at(patch, g, mid, uvs, guess);
      patch.error = 0;
      for (size_t k = 0; k < mid.size(); ++k) {
        if (!exact.inside[k]) continue;  // trimmed away
        const Point p = patch.patch.evaluate(mid[k][0], mid[k][1]);
        patch.error = std::max(patch.error, std::abs(dot(sub(p, patch.origin), normal) - exact.h[k]));
      }
      if (patch.error <= target) break;
    }
  }

  static double guess_at(const std::array<double, 6>& c, const BoxPatch& patch, const std::array<double, 2>& ab) {
    const double u = patch.u0 + ab[0] * (patch.u1 - patch.u0), v = patch.v0 + ab[1] * (patch.v1 - patch.v0);
    return c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
  }

  static Point plane_point(const BoxPatch& patch, double a, double b, double height) {
    const double u = patch.u0 + a * (patch.u1 - patch.u0), v = patch.v0 + b * (patch.v1 - patch.v0);
    return add(add(patch.origin, add(scale(patch.e1, u), scale(patch.e2, v))), scale(patch.normal, height));
  }

  // The least-squares quadratic height h(u, v) = c0 + c1 u + c2 v + c3 u^2 + c4 uv + c5 v^2 of the
  // loop: the first guess of the piece's height inside it.
  static std::array<double, 6> quadratic_heights(const std::vector<std::array<double, 3>>& uvs) {
    double a[6][7] = {};
    for (const auto& p : uvs) {
      const double row[6] = {1, p[0], p[1], p[0] * p[0], p[0] * p[1], p[1] * p[1]};
      for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) a[r][c] += row[r] * row[c];
        a[r][6] += row[r] * p[2];
      }
    }
    // A small ridge keeps a loop of few points (or a straight one) solvable.
    for (int r = 0; r < 6; ++r) a[r][r] += 1e-12 + (r > 2 ? 1e-9 : 0.0);
    for (int c = 0; c < 6; ++c) {
      int pivot = c;
      for (int r = c + 1; r < 6; ++r)
        if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
      for (int k = 0; k < 7; ++k) std::swap(a[c][k], a[pivot][k]);
      for (int r = 0; r < 6; ++r) {
        if (r == c) continue;
        const double f = a[r][c] / a[c][c];
        for (int k = c; k < 7; ++k) a[r][k] -= f * a[c][k];
      }
    }
    std::array<double, 6> out{};
    for (int r = 0; r < 6; ++r) out[static_cast<size_t>(r)] = a[r][6] / a[r][r];
    return out;
  }

  static bool inside_loop(const std::vector<std::array<double, 3>>& uvs, double u, double v) {
    bool in = false;
    for (size_t k = 0, l = uvs.size() - 1; k < uvs.size(); l = k++) {
      const auto &p = uvs[k], &q = uvs[l];
      if ((p[1] > v) != (q[1] > v) && u < (q[0] - p[0]) * (v - p[1]) / (q[1] - p[1]) + p[0]) in = !in;
    }
    return in;
  }

  // The exact heights of the sheet at patch parameters (a, b): the root along the line across the
  // plane nearest the quadratic guess, within half a box of it (NaN where there is none), and whether
  // (a, b) lies inside the loop. Inside it, a line with no root means the piece is no graph.
  struct Heights {
    std::vector<double> h;
    std::vector<bool> inside;
  };
  Heights heights_at(const BoxPatch& patch, const LevelFunction& g, const std::vector<std::array<double, 2>>& ab,
                     const std::vector<std::array<double, 3>>& uvs, const std::array<double, 6>& c) const {
    constexpr int kScan = 8;
    const double reach = 0.5 * grid_.h;
    std::vector<Point> probes;
    std::vector<double> guess(ab.size());
    Heights out{std::vector<double>(ab.size(), std::nan("")), std::vector<bool>(ab.size())};
    for (size_t k = 0; k < ab.size(); ++k) {
      const double u = patch.u0 + ab[k][0] * (patch.u1 - patch.u0), v = patch.v0 + ab[k][1] * (patch.v1 - patch.v0);
      guess[k] = guess_at(c, patch, ab[k]);
      out.inside[k] = inside_loop(uvs, u, v);
      for (int s = 0; s <= kScan; ++s)
        probes.push_back(plane_point(patch, ab[k][0], ab[k][1], guess[k] - reach + 2 * reach * s / kScan));
    }
    const std::vector<double> f = evaluate(g, probes);
    std::vector<Bracket> brackets;
    std::vector<size_t> owner;
    for (size_t k = 0; k < ab.size(); ++k) {
      int best = -1;
      double best_distance = 1e300;
      for (int s = 0; s < kScan; ++s) {
        const size_t at = k * (kScan + 1) + static_cast<size_t>(s);
        if ((f[at] < 0) == (f[at + 1] < 0)) continue;
        const double distance = std::abs(-reach + 2 * reach * (s + 0.5) / kScan);
        if (distance < best_distance) {
          best_distance = distance;
          best = s;
        }
      }
      if (best < 0) {
        if (out.inside[k])
          throw InputError(
              fmt::format("a piece of a sheet of the wall in one box (near {}) is not a graph over its plane",
                          where(plane_point(patch, ab[k][0], ab[k][1], guess[k]))));
        continue;
      }
      const size_t at = k * (kScan + 1) + static_cast<size_t>(best);
      brackets.push_back({probes[at], probes[at + 1], f[at], f[at + 1]});
      owner.push_back(k);
    }
    const std::vector<Point> roots = refine(g, brackets);
    for (size_t b = 0; b < roots.size(); ++b) out.h[owner[b]] = dot(sub(roots[b], patch.origin), patch.normal);
    return out;
  }

  // The heights of an m x m sample grid outside the loop, where the patch is trimmed away: grown
  // outwards from the samples inside it, ring by ring, each sample predicted linearly from its
  // neighbours; the sheet's own height where it continues that smoothly (within one grid step), the
  // prediction where it does not (no root, or another fold of the sheet beyond the box). A jump there
  // would cost the fit inside the loop many control points.
  static void extend_outside(Heights& heights, int m, double spacing) {
    std::vector<double>& h = heights.h;
    const size_t total = h.size();
    std::vector<bool> fixed = heights.inside;
    std::vector<size_t> layer;
    for (size_t k = 0; k < total; ++k)
      if (fixed[k]) layer.push_back(k);
    if (layer.empty()) return;  // a loop between the samples: nothing to grow from
    auto at = [m](int i, int j) { return flat(i, m, j); };
    for (;;) {
      std::vector<size_t> next;
      std::vector<bool> queued(total, false);
      for (size_t k : layer) {
        const int i = static_cast<int>(k) / m, j = static_cast<int>(k) % m;
        for (const auto& d : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int a = i + d[0], b = j + d[1];
          if (a < 0 || b < 0 || a >= m || b >= m || fixed[at(a, b)] || queued[at(a, b)]) continue;
          queued[at(a, b)] = true;
          next.push_back(at(a, b));
        }
      }
      if (next.empty()) break;
      std::sort(next.begin(), next.end());
      std::vector<double> value(next.size());
      for (size_t q = 0; q < next.size(); ++q) {
        const int i = static_cast<int>(next[q]) / m, j = static_cast<int>(next[q]) % m;
        double sum = 0;
        int count = 0;
        for (const auto& d : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int a = i + d[0], b = j + d[1];
          if (a < 0 || b < 0 || a >= m || b >= m || !fixed[at(a, b)]) continue;
          const int a2 = a + d[0], b2 = b + d[1];
          const bool second = a2 >= 0 && b2 >= 0 && a2 < m && b2 < m && fixed[at(a2, b2)];
          sum += second ? 2 * h[at(a, b)] - h[at(a2, b2)] : h[at(a, b)];
          ++count;
        }
        const double predicted = sum / count;
        const double own = h[next[q]];
        value[q] = std::isfinite(own) && std::abs(own - predicted) <= spacing ? own : predicted;
      }
      for (size_t q = 0; q < next.size(); ++q) {
        h[next[q]] = value[q];
        fixed[next[q]] = true;
      }
      layer.swap(next);
    }
  }

  // The caps: on each box face in the block's faces, the parts inside the wall, bounded by the
  // sheets' curves on it and by segments of its edges.
  void build_caps() {
    for (int v = 0; v < grid_.vertex_count(); ++v)
      for (int axis = 0; axis < 3; ++axis) {
        const auto i = grid_.index(v);
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        const int at = i[static_cast<size_t>(axis)];
        if (!grid_.has_edge(i, b) || !grid_.has_edge(i, c)) continue;
        if (at != 0 && at != grid_.n[static_cast<size_t>(axis)]) continue;
        cap_face(axis, v, at == 0 ? -1 : 1);
      }
  }

  int corner_vertex(int v) {
    const auto it = corner_.find(v);
    if (it != corner_.end()) return it->second;
    const int id = static_cast<int>(out_.vertices.size());
    out_.vertices.push_back(grid_.at(grid_.index(v)));
    corner_[v] = id;
    return id;
  }

  void cap_face(int axis, int v, int outward) {
    const auto i = grid_.index(v);
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    // The perimeter q0 -> q1 -> q2 -> q3 runs counterclockwise about +axis.
    const std::array<std::array<int, 3>, 4> q{i, step(i, b), step(step(i, b), c), step(i, c)};
    struct Event {
      int vertex;
      int sheet;  // -1 for a corner
    };
    std::vector<Event> events;
    auto edge_crossings = [&](const std::array<int, 3>& from, int along, bool backward) {
      std::vector<Event> list;
      const int edge = grid_.id(along, grid_.vertex(from));
      for (int s = 0; s < kSamples; ++s)
        for (int sheet = 0; sheet < 2; ++sheet) {
          const auto it = crossing_[sheet].find(crossing_key(edge, s));
          if (it != crossing_[sheet].end()) list.push_back({it->second, sheet});
        }
      // Within one sample interval both sheets may cross: order by position along the edge.
      std::stable_sort(list.begin(), list.end(), [&](const Event& x, const Event& y) {
        return out_.vertices[static_cast<size_t>(x.vertex)][static_cast<size_t>(along)] <
               out_.vertices[static_cast<size_t>(y.vertex)][static_cast<size_t>(along)];
      });
      if (backward) std::reverse(list.begin(), list.end());
      return list;
    };
    auto append = [&](const std::vector<Event>& list) { events.insert(events.end(), list.begin(), list.end()); };
    events.push_back({corner_vertex(grid_.vertex(q[0])), -1});
    append(edge_crossings(q[0], b, false));
    events.push_back({corner_vertex(grid_.vertex(q[1])), -1});
    append(edge_crossings(q[1], c, false));
    events.push_back({corner_vertex(grid_.vertex(q[2])), -1});
    append(edge_crossings(q[3], b, true));
    events.push_back({corner_vertex(grid_.vertex(q[3])), -1});
    append(edge_crossings(q[0], c, true));
    if (outward < 0) std::reverse(events.begin(), events.end());
    const size_t m = events.size();
    // Whether the perimeter from event k to k + 1 lies inside the wall.
    std::vector<bool> in(m);
    for (size_t k = 0; k < m; ++k) {
      const Point& p = out_.vertices[static_cast<size_t>(events[k].vertex)];
      const Point& r = out_.vertices[static_cast<size_t>(events[(k + 1) % m].vertex)];
      in[k] = inside_(scale(add(p, r), 0.5));
    }
    // The partner of each crossing: the other end of its curve on this face.
    std::map<int, int> partner;
    std::map<int, std::pair<int, bool>> curve_of;  // vertex -> (curve, forward from it)
    for (int sheet = 0; sheet < 2; ++sheet) {
      const auto it = face_curves_[sheet].find(grid_.id(axis, v));
      if (it == face_curves_[sheet].end()) continue;
      for (int cv : it->second) {
        const BoxCurve& curve = out_.curves[static_cast<size_t>(cv)];
        partner[curve.from] = curve.to;
        partner[curve.to] = curve.from;
        curve_of[curve.from] = {cv, true};
        curve_of[curve.to] = {cv, false};
      }
    }
    std::map<int, size_t> event_at;
    for (size_t k = 0; k < m; ++k) event_at[events[k].vertex] = k;
    std::vector<bool> used(m, false);
    for (size_t start = 0; start < m; ++start) {
      if (!in[start] || used[start]) continue;
      BoxCap cap;
      cap.axis = axis;
      cap.offset = grid_.at(i)[static_cast<size_t>(axis)];
      cap.outward = outward;
      size_t k = start;
      for (size_t guard = 0; guard <= 2 * m; ++guard) {
        used[k] = true;
        cap.loop.push_back({-1, true, events[k].vertex, events[(k + 1) % m].vertex});
        size_t next = (k + 1) % m;
        if (events[next].sheet >= 0) {
          // Along the sheet's curve to its partner, then on along the perimeter.
          const int from = events[next].vertex, to = partner.at(from);
          const auto [cv, forward] = curve_of.at(from);
          cap.loop.push_back({cv, forward, from, to});
          next = event_at.at(to);
          if (!in[next])
            throw InputError(fmt::format("the wall's cap on the block's face near {} could not be closed",
                                         where(out_.vertices[static_cast<size_t>(to)])));
        }
        k = next;
        if (k == start) break;
      }
      if (k != start) throw std::logic_error("box patches: a cap's loop does not close");
      out_.caps.push_back(std::move(cap));
    }
  }

  const std::array<LevelFunction, 2>& g_;
  const std::vector<std::array<LevelFunction, 2>>& more_;
  const std::function<bool(const Point&)>& inside_;
  Grid grid_;
  BoxPartition out_;
  std::array<std::vector<double>, 2> samples_;
  std::array<std::unordered_map<long, int>, 2> crossing_;
  std::vector<int> crossing_sheet_;
  std::array<std::unordered_map<int, std::vector<int>>, 2> face_curves_;
  std::vector<int> curve_axis_;
  std::array<double, 2> outward_{1, 1};
  std::map<int, int> corner_;
};

}  // namespace

std::array<double, 2> BoxPatch::parameters(const Point& p) const {
  const Point d = sub(p, origin);
  return {(dot(d, e1) - u0) / (u1 - u0), (dot(d, e2) - v0) / (v1 - v0)};
}

BoxPartition partition_wall(const std::array<LevelFunction, 2>& g, const std::function<bool(const Point&)>& inside_wall,
                            const std::array<int, 3>& cells, int boxes_per_cell, double target, int max_side,
                            const std::vector<std::array<LevelFunction, 2>>& more) {
  if (boxes_per_cell < 1 || (boxes_per_cell & (boxes_per_cell - 1)) != 0)
    throw std::logic_error("partition_wall: boxes per cell must be a power of two");
  Builder builder(g, more, inside_wall, cells, boxes_per_cell);
  return builder.run(target, max_side);
}

}  // namespace offsetgen::step
