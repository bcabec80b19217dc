#include "body/body_distance.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace offsetgen::body {
namespace {

constexpr int64_t kKeyOffset = int64_t(1) << 20;

int64_t key3(int64_t x, int64_t y, int64_t z) {
  return ((x + kKeyOffset) << 42) | ((y + kKeyOffset) << 21) | (z + kKeyOffset);
}
int64_t key2(int64_t x, int64_t y) { return ((x + kKeyOffset) << 21) | (y + kKeyOffset); }
int64_t cell_of(double x, double cell) { return static_cast<int64_t>(std::floor(x / cell)); }

// The index's cell sides (voxels): about twice the typical facet, so that a cell holds a few facets
// of each sheet of the surface through it; the 3D cells no smaller than a block, which gathers them.
double cell_side(std::vector<double> extents, double smallest) {
  if (extents.empty()) return 16;
  std::nth_element(extents.begin(), extents.begin() + static_cast<long>(extents.size() / 2), extents.end());
  return std::clamp(2 * extents[extents.size() / 2], smallest, 32.0);
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The squared distance from p to the triangle abc (the closest point by its Voronoi regions).
double point_triangle_distance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  auto dist2 = [&](const Vec3& q) {
    const Vec3 e = sub(p, q);
    return dot(e, e);
  };
  if (d1 <= 0 && d2 <= 0) return dot(ap, ap);
  const Vec3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dot(bp, bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return dist2({a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]});
  }
  const Vec3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dot(cp, cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return dist2({a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return dist2({b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2])});
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return dist2({a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w});
}

// The edge function of the edge u -> v at p in the (x, y) plane, computed from the edge's ends in
// lexicographic order so that the two facets sharing the edge get exactly opposite values.
bool before(const Vec3& u, const Vec3& v) { return u[0] != v[0] ? u[0] < v[0] : u[1] < v[1]; }
double edge_function(const Vec3& u, const Vec3& v, double x, double y) {
  if (before(u, v)) return (v[0] - u[0]) * (y - u[1]) - (v[1] - u[1]) * (x - u[0]);
  return -((u[0] - v[0]) * (y - v[1]) - (u[1] - v[1]) * (x - v[0]));
}

struct Entry {
  int64_t key;
  uint32_t facet;
  bool operator<(const Entry& o) const { return key != o.key ? key < o.key : facet < o.facet; }
};

void compress(std::vector<Entry>& entries, std::vector<int64_t>& keys, std::vector<uint32_t>& starts,
              std::vector<uint32_t>& facets) {
  std::sort(entries.begin(), entries.end());
  facets.reserve(entries.size());
  for (size_t i = 0; i < entries.size(); ++i) {
    if (i == 0 || entries[i].key != entries[i - 1].key) {
      keys.push_back(entries[i].key);
      starts.push_back(static_cast<uint32_t>(facets.size()));
    }
    facets.push_back(entries[i].facet);
  }
  starts.push_back(static_cast<uint32_t>(facets.size()));
}

}  // namespace

void BodyDistance::CellIndex::lookup(int64_t key, const uint32_t*& first, const uint32_t*& last) const {
  const auto it = std::lower_bound(keys.begin(), keys.end(), key);
  if (it == keys.end() || *it != key) {
    first = last = nullptr;
    return;
  }
  const size_t k = static_cast<size_t>(it - keys.begin());
  first = facets.data() + starts[k];
  last = facets.data() + starts[k + 1];
}

BodyDistance::BodyDistance(std::vector<Vec3> points, const std::vector<std::array<uint32_t, 3>>& triangles,
                           double inside_reach, double outside_reach, Interval free)
    : points_(std::move(points)),
      triangles_(triangles),
      inside_reach_(inside_reach),
      outside_reach_(outside_reach),
      free_(free) {
  std::vector<Entry> cells, columns;
  std::vector<double> extents, xy_extents;  // of the facets' boxes, in 3D and seen from above
  extents.reserve(triangles_.size());
  for (const auto& t : triangles_) {
    std::array<double, 3> extent{};
    for (size_t k = 0; k < 3; ++k)
      extent[k] = std::max({points_[t[0]][k], points_[t[1]][k], points_[t[2]][k]}) -
                  std::min({points_[t[0]][k], points_[t[1]][k], points_[t[2]][k]});
    extents.push_back(std::max({extent[0], extent[1], extent[2]}));
    if (edge_function(points_[t[0]], points_[t[1]], points_[t[2]][0], points_[t[2]][1]) != 0)
      xy_extents.push_back(std::max(extent[0], extent[1]));
  }
  cells_.cell = cell_side(extents, kDistanceBlock);
  columns_.cell = cell_side(xy_extents, 2);
  balls_.reserve(triangles_.size());
  for (uint32_t f = 0; f < triangles_.size(); ++f) {
    const Vec3 &a = points_[triangles_[f][0]], &b = points_[triangles_[f][1]], &c = points_[triangles_[f][2]];
    const Vec3 centroid = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
    double radius = 0;
    for (const Vec3* corner : {&a, &b, &c})
      radius = std::max(radius, std::sqrt(dot(sub(*corner, centroid), sub(*corner, centroid))));
    balls_.emplace_back(centroid, radius * (1 + 1e-12));
    std::array<int64_t, 3> lo{}, hi{};
    const double side = cells_.cell;
    for (size_t k = 0; k < 3; ++k) {
      lo[k] = cell_of(std::min({a[k], b[k], c[k]}), side);
      hi[k] = cell_of(std::max({a[k], b[k], c[k]}), side);
    }
    // The cells along the facet's plane: over the two axes it spans most, the range of the third
    // that the plane takes over each cell (a large tilted facet fills a sheet of cells, not its box).
    const Vec3 n = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                    (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    size_t across = 0;
    for (size_t k = 1; k < 3; ++k)
      if (std::abs(n[k]) > std::abs(n[across])) across = k;
    const size_t u = (across + 1) % 3, v = (across + 2) % 3;
    for (int64_t i = lo[u]; i <= hi[u]; ++i)
      for (int64_t j = lo[v]; j <= hi[v]; ++j) {
        int64_t first = lo[across], last = hi[across];
        if (n[across] != 0) {
          // The plane's coordinate `across` over the cell's four corners.
          double min_t = HUGE_VAL, max_t = -HUGE_VAL;
          for (int corner = 0; corner < 4; ++corner) {
            const double pu = double(i + (corner & 1)) * side, pv = double(j + (corner >> 1)) * side;
            const double t = a[across] - (n[u] * (pu - a[u]) + n[v] * (pv - a[v])) / n[across];
            min_t = std::min(min_t, t);
            max_t = std::max(max_t, t);
          }
          first = std::max(first, cell_of(min_t, side));
          last = std::min(last, cell_of(max_t, side));
        }
        for (int64_t k = first; k <= last; ++k) {
          std::array<int64_t, 3> at{};
          at[u] = i;
          at[v] = j;
          at[across] = k;
          cells.push_back({key3(at[0], at[1], at[2]), f});
        }
      }
    // Facets seen edge-on from above cover no column.
    if (edge_function(a, b, c[0], c[1]) != 0) {
      const double column = columns_.cell;
      for (int64_t i = cell_of(std::min({a[0], b[0], c[0]}), column);
           i <= cell_of(std::max({a[0], b[0], c[0]}), column); ++i)
        for (int64_t j = cell_of(std::min({a[1], b[1], c[1]}), column);
             j <= cell_of(std::max({a[1], b[1], c[1]}), column); ++j)
          columns.push_back({key2(i, j), f});
    }
  }
  compress(cells, cells_.keys, cells_.starts, cells_.facets);
  compress(columns, columns_.keys, columns_.starts, columns_.facets);
}

BodyDistance::Query::Query(const BodyDistance& body) : stamp(body.triangles_.size(), 0) {}

size_t BodyDistance::memory_bytes() const {
  return points_.size() * sizeof(Vec3) + triangles_.size() * sizeof(triangles_[0]) +
         (cells_.keys.size() + columns_.keys.size()) * 12 + (cells_.facets.size() + columns_.facets.size()) * 4;
}

double BodyDistance::facet_distance2(const Vec3& p, uint32_t facet) const {
  const auto& t = triangles_[facet];
  return point_triangle_distance2(p, points_[t[0]], points_[t[1]], points_[t[2]]);
}

void BodyDistance::gather(const Vec3& lo, const Vec3& hi, Query& q) const {
  q.candidates.clear();
  if (++q.generation == 0) {
    std::fill(q.stamp.begin(), q.stamp.end(), 0);
    q.generation = 1;
  }
  const double side = cells_.cell;
  for (int64_t i = cell_of(lo[0], side); i <= cell_of(hi[0], side); ++i)
    for (int64_t j = cell_of(lo[1], side); j <= cell_of(hi[1], side); ++j)
      for (int64_t k = cell_of(lo[2], side); k <= cell_of(hi[2], side); ++k) {
        const uint32_t *first = nullptr, *last = nullptr;
        cells_.lookup(key3(i, j, k), first, last);
        for (; first != last; ++first)
          if (q.stamp[*first] != q.generation) {
            q.stamp[*first] = q.generation;
            q.candidates.push_back(*first);
          }
      }
}

int BodyDistance::winding(double x, double y, Query& q) const {
  q.crossings.clear();
  const uint32_t *first = nullptr, *last = nullptr;
  columns_.lookup(key2(cell_of(x, columns_.cell), cell_of(y, columns_.cell)), first, last);
  int total = 0;
  for (; first != last; ++first) {
    const auto& t = triangles_[*first];
    const Vec3 &a = points_[t[0]], &b = points_[t[1]], &c = points_[t[2]];
    const double area = edge_function(a, b, c[0], c[1]);
    if (area == 0) continue;
    const int o = area > 0 ? 1 : -1;
    // Each edge's function, positive on the facet's side; on the edge itself the point belongs to the
    // facet if the facet lies left of the edge taken in lexicographic order.
    const std::array<std::pair<const Vec3*, const Vec3*>, 3> edges = {{{&b, &c}, {&c, &a}, {&a, &b}}};
    std::array<double, 3> weight{};
    bool covered = true;
    for (size_t k = 0; k < 3 && covered; ++k) {
      const Vec3 &u = *edges[k].first, &v = *edges[k].second;
      weight[k] = o * edge_function(u, v, x, y);
      covered = weight[k] > 0 || (weight[k] == 0 && (o > 0) == before(u, v));
    }
    if (!covered) continue;
    const double sum = weight[0] + weight[1] + weight[2];
    if (!(sum > 0)) continue;
    q.crossings.emplace_back((weight[0] * a[2] + weight[1] * b[2] + weight[2] * c[2]) / sum, o);
    total += o;
  }
  std::sort(q.crossings.begin(), q.crossings.end());
  return total;
}

bool BodyDistance::inside(const Vec3& p, Query& q) const {
  winding(p[0], p[1], q);
  int above = 0;
  for (const auto& [z, o] : q.crossings)
    if (z > p[2]) above += o;
  return above != 0;
}

void BodyDistance::prepare(const Vec3& centre, double radius, Query& q) const {
  const double r = radius + std::max(inside_reach_, outside_reach_);
  gather({centre[0] - r, centre[1] - r, centre[2] - r}, {centre[0] + r, centre[1] + r, centre[2] + r}, q);
  q.near.clear();
  for (uint32_t f : q.candidates) {
    const double dc = std::sqrt(facet_distance2(centre, f));
    if (dc < r) q.near.push_back({dc, f, balls_[f].first, balls_[f].second});
  }
  std::sort(q.near.begin(), q.near.end());
}

double BodyDistance::scan(const Vec3& p, bool inside, double offset, const Query& q) const {
  const double cap = inside ? inside_reach_ : outside_reach_;
  double best2 = cap * cap;
  const bool has_free = inside && free_.hi > free_.lo;
  for (const auto& n : q.near) {
    const double bound = n.centre_distance - offset;  // no facet from here on is closer than this
    if (bound > 0) {
      if (bound * bound >= best2) break;
      // Nothing nearer than free.lo is left, and the nearest so far is within the free interval.
      if (has_free && bound >= free_.lo && best2 <= free_.hi * free_.hi) break;
    }
    const Vec3 e = sub(p, n.ball);
    const double ball = std::sqrt(dot(e, e)) - n.radius;
    if (ball > 0 && ball * ball >= best2) continue;
    best2 = std::min(best2, facet_distance2(p, n.facet));
  }
  const double value = std::sqrt(best2);
  return inside ? -value : value;
}

void BodyDistance::distances(const std::vector<Vec3>& points, double* d, Query& q) const {
  // By block: the facets near one block serve all its points.
  std::vector<std::pair<std::array<int64_t, 3>, uint32_t>> order(points.size());
  for (uint32_t i = 0; i < points.size(); ++i)
    order[i] = {{static_cast<int64_t>(std::floor(points[i][0] / kDistanceBlock)),
                 static_cast<int64_t>(std::floor(points[i][1] / kDistanceBlock)),
                 static_cast<int64_t>(std::floor(points[i][2] / kDistanceBlock))},
                i};
  std::sort(order.begin(), order.end());
  const double half = 0.5 * kDistanceBlock, radius = half * std::sqrt(3.0);
  for (size_t k = 0; k < order.size();) {
    const auto cell = order[k].first;
    const Vec3 centre = {double(cell[0]) * kDistanceBlock + half, double(cell[1]) * kDistanceBlock + half,
                         double(cell[2]) * kDistanceBlock + half};
    prepare(centre, radius, q);
    for (; k < order.size() && order[k].first == cell; ++k) {
      const Vec3& p = points[order[k].second];
      const Vec3 e = sub(p, centre);
      d[order[k].second] = scan(p, inside(p, q), std::sqrt(dot(e, e)), q);
    }
  }
}

bool BodyDistance::block(const std::array<int, 3>& origin, double* d, Query& q) const {
  const double half = 0.5 * (kDistanceBlock - 1);
  const Vec3 centre = {origin[0] + half, origin[1] + half, origin[2] + half};
  prepare(centre, half * std::sqrt(3.0), q);
  if (q.near.empty()) return false;
  for (int i = 0; i < kDistanceBlock; ++i)
    for (int j = 0; j < kDistanceBlock; ++j) {
      const double x = origin[0] + i, y = origin[1] + j;
      winding(x, y, q);
      // The winding number above each voxel of the column, from the top down.
      size_t next = q.crossings.size();
      int above = 0;
      for (int l = kDistanceBlock - 1; l >= 0; --l) {
        const Vec3 p = {x, y, double(origin[2] + l)};
        while (next > 0 && q.crossings[next - 1].first > p[2]) above += q.crossings[--next].second;
        const Vec3 e = sub(p, centre);
        d[distance_block_offset(i, j, l)] = scan(p, above != 0, std::sqrt(dot(e, e)), q);
      }
    }
  return true;
}

bool BodyDistance::plane_block(const std::array<int, 2>& origin, double z, double* d, Query& q) const {
  const double half = 0.5 * (kDistanceBlock - 1);
  const Vec3 centre = {origin[0] + half, origin[1] + half, z};
  prepare(centre, half * std::sqrt(2.0), q);
  if (q.near.empty()) return false;
  for (int i = 0; i < kDistanceBlock; ++i)
    for (int j = 0; j < kDistanceBlock; ++j) {
      const Vec3 p = {double(origin[0] + i), double(origin[1] + j), z};
      const Vec3 e = sub(p, centre);
      d[i * kDistanceBlock + j] = scan(p, inside(p, q), std::sqrt(dot(e, e)), q);
    }
  return true;
}

}  // namespace offsetgen::body
