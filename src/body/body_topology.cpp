#include "body/body_topology.h"

#include "body/disjoint_sets.h"
#include "support/point.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace offsetgen::body {
namespace {

using Triangle = std::array<uint32_t, 3>;

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
constexpr size_t kMaxHoleEdges = 1000;
constexpr size_t kMaxNestedShells = 10000;
constexpr double kPi = 3.14159265358979323846;
// A shell enclosing less than this times its bounding box diagonal cubed encloses nothing (a sheet).
constexpr double kFlatVolume = 1e-9;

bool distinct(const Triangle& t) { return t[0] != t[1] && t[1] != t[2] && t[0] != t[2]; }

Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Point& a) { return std::sqrt(dot(a, a)); }

Point normal(const BodyMesh& mesh, const Triangle& t) {
  const Point& a = mesh.points[t[0]];
  return cross(sub(mesh.points[t[1]], a), sub(mesh.points[t[2]], a));
}

bool zero_area(const BodyMesh& mesh, const Triangle& t) {
  const Point n = normal(mesh, t);
  return n[0] == 0 && n[1] == 0 && n[2] == 0;
}

Point midpoint(const BodyMesh& mesh, uint32_t a, uint32_t b) {
  const Point& p = mesh.points[a];
  const Point& q = mesh.points[b];
  return {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};
}

double triangle_volume(const BodyMesh& mesh, const Triangle& t) {
  return dot(mesh.points[t[0]], cross(mesh.points[t[1]], mesh.points[t[2]])) / 6.0;
}

// One triangle's use of an undirected edge (lo, hi), filed under lo.
struct HalfEdge {
  uint32_t other;  // hi
  uint32_t code;   // triangle << 1 | 1 when the triangle runs lo -> hi
};
uint32_t triangle_of(const HalfEdge& h) { return h.code >> 1; }
bool runs_up(const HalfEdge& h) { return h.code & 1; }

// The edges of the triangles with three distinct points, grouped by (lo, hi): a bucket per lo point
// (counting sort), each sorted by hi. No hash map and no global sort, so a million triangles take a
// few tens of milliseconds.
class EdgeTable {
 public:
  explicit EdgeTable(const BodyMesh& mesh) : start_(mesh.points.size() + 1, 0) {
    const auto& tris = mesh.triangles;
    for (const Triangle& t : tris)
      if (distinct(t))
        for (size_t k = 0; k < 3; ++k) ++start_[std::min(t[k], t[(k + 1) % 3]) + size_t(1)];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    entries_.resize(start_.back());
    std::vector<size_t> fill(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < tris.size(); ++i) {
      const Triangle& t = tris[i];
      if (!distinct(t)) continue;
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t a = t[k], b = t[(k + 1) % 3];
        const uint32_t lo = std::min(a, b);
        entries_[fill[lo]++] = {std::max(a, b), static_cast<uint32_t>(i << 1) | (a < b ? 1u : 0u)};
      }
    }
    const auto less = [](const HalfEdge& x, const HalfEdge& y) {
      return x.other != y.other ? x.other < y.other : x.code < y.code;
    };
    for (size_t lo = 0; lo + 1 < start_.size(); ++lo) {
      HalfEdge* begin = entries_.data() + start_[lo];
      HalfEdge* end = entries_.data() + start_[lo + 1];
      if (end - begin > 16) {
        std::sort(begin, end, less);
      } else if (end - begin > 1) {
        for (HalfEdge* i = begin + 1; i < end; ++i)  // insertion sort: buckets are small
          for (HalfEdge* j = i; j > begin && less(*j, *(j - 1)); --j) std::swap(*j, *(j - 1));
      }
    }
  }

  // f(lo, hi, begin, end) for every edge, in (lo, hi) order.
  template <typename F>
  void for_each_edge(F&& f) const {
    for (size_t lo = 0; lo + 1 < start_.size(); ++lo) {
      const HalfEdge* i = entries_.data() + start_[lo];
      const HalfEdge* end = entries_.data() + start_[lo + 1];
      while (i < end) {
        const HalfEdge* j = i + 1;
        while (j < end && j->other == i->other) ++j;
        f(static_cast<uint32_t>(lo), i->other, i, j);
        i = j;
      }
    }
  }

  // The triangles using edge {a, b}.
  std::pair<const HalfEdge*, const HalfEdge*> edge(uint32_t a, uint32_t b) const {
    const uint32_t lo = std::min(a, b), hi = std::max(a, b);
    const HalfEdge* begin = entries_.data() + start_[lo];
    const HalfEdge* end = entries_.data() + start_[lo + 1];
    const HalfEdge* first = std::lower_bound(begin, end, hi, [](const HalfEdge& h, uint32_t v) { return h.other < v; });
    const HalfEdge* last = first;
    while (last < end && last->other == hi) ++last;
    return {first, last};
  }
  bool has_edge(uint32_t a, uint32_t b) const {
    const auto [first, last] = edge(a, b);
    return first != last;
  }

 private:
  std::vector<size_t> start_;
  std::vector<HalfEdge> entries_;
};

// A triangle's points in increasing order, and whether the triangle is an even permutation of them
// (faces the same way).
struct CornerKey {
  Triangle sorted;
  uint32_t index;
  bool even;
};

CornerKey corner_key(const Triangle& t, uint32_t index) {
  const size_t m = static_cast<size_t>(std::min_element(t.begin(), t.end()) - t.begin());
  const uint32_t p = t[(m + 1) % 3], q = t[(m + 2) % 3];
  return {{t[m], std::min(p, q), std::max(p, q)}, index, p < q};
}

// Calls f(begin, end) for each group of two or more triangles with the same three points, in index
// order. Copies share every edge, so each group is among the triangles on the edge of its two smallest
// points: no sort of all the triangles.
template <typename F>
void for_each_duplicate_group(const BodyMesh& mesh, const EdgeTable& table, F&& f) {
  std::vector<CornerKey> keys;
  table.for_each_edge([&](uint32_t lo, uint32_t hi, const HalfEdge* begin, const HalfEdge* end) {
    if (end - begin < 2) return;
    keys.clear();
    for (const HalfEdge* h = begin; h != end; ++h) {
      const CornerKey key = corner_key(mesh.triangles[triangle_of(*h)], triangle_of(*h));
      if (key.sorted[0] == lo && key.sorted[1] == hi) keys.push_back(key);
    }
    if (keys.size() < 2) return;
    std::sort(keys.begin(), keys.end(), [](const CornerKey& a, const CornerKey& b) {
      return a.sorted[2] != b.sorted[2] ? a.sorted[2] < b.sorted[2] : a.index < b.index;
    });
    for (size_t i = 0; i < keys.size();) {
      size_t j = i + 1;
      while (j < keys.size() && keys[j].sorted[2] == keys[i].sorted[2]) ++j;
      if (j - i > 1) f(keys.data() + i, keys.data() + j);
      i = j;
    }
  });
}

template <typename Keep>
size_t erase_triangles(BodyMesh& mesh, Keep keep) {
  size_t out = 0;
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    if (keep(i)) mesh.triangles[out++] = mesh.triangles[i];
  const size_t removed = mesh.triangles.size() - out;
  mesh.triangles.resize(out);
  return removed;
}

// ---- repair steps ----

// Zero-area triangles (all three points distinct, so the third lies inside the longest edge): the
// triangle across the long edge is split at the third point, which closes the gap the sliver leaves
// without moving anything. Chains of slivers take a few rounds; what remains after them is removed.
size_t remove_slivers(BodyMesh& mesh) {
  auto& tris = mesh.triangles;
  size_t removed = 0;
  for (int round = 0;; ++round) {
    std::vector<uint32_t> slivers;
    for (size_t i = 0; i < tris.size(); ++i)
      if (zero_area(mesh, tris[i])) slivers.push_back(static_cast<uint32_t>(i));
    if (slivers.empty()) return removed;
    std::vector<uint8_t> remove(tris.size(), 0);
    if (round == 8) {
      for (uint32_t s : slivers) remove[s] = 1;
      return removed + erase_triangles(mesh, [&](size_t i) { return !remove[i]; });
    }
    const EdgeTable table(mesh);
    // Points of triangles changed in this round: the table is stale around them until the next.
    std::vector<uint8_t> dirty(mesh.points.size(), 0);
    for (uint32_t s : slivers) {
      const Triangle sliver = tris[s];
      if (dirty[sliver[0]] || dirty[sliver[1]] || dirty[sliver[2]]) continue;
      size_t k = 0;
      double longest = -1;
      for (size_t e = 0; e < 3; ++e) {
        const Point d = sub(mesh.points[sliver[(e + 1) % 3]], mesh.points[sliver[e]]);
        if (dot(d, d) > longest) longest = dot(d, d), k = e;
      }
      const uint32_t a = sliver[k], b = sliver[(k + 1) % 3], c = sliver[(k + 2) % 3];
      const auto [first, last] = table.edge(a, b);
      uint32_t across = kNone;
      for (const HalfEdge* h = first; h != last; ++h)
        if (triangle_of(*h) != s) across = across == kNone ? triangle_of(*h) : kNone - 1;
      if (across < kNone - 1) {
        const Triangle t = tris[across];
        size_t j = 0;
        while (j < 2 && !((t[j] == a || t[j] == b) && (t[(j + 1) % 3] == a || t[(j + 1) % 3] == b))) ++j;
        const uint32_t x = t[j], y = t[(j + 1) % 3], d = t[(j + 2) % 3];
        if (d != c) {
          tris[across] = {x, c, d};
          tris.push_back({c, y, d});
          remove.push_back(0);
          dirty[d] = 1;
        }
      }
      remove[s] = 1;
      dirty[a] = dirty[b] = dirty[c] = 1;
    }
    removed += erase_triangles(mesh, [&](size_t i) { return !remove[i]; });
  }
}

size_t remove_duplicates(BodyMesh& mesh, const EdgeTable& table) {
  std::vector<uint8_t> remove(mesh.triangles.size(), 0);
  bool any = false;
  for_each_duplicate_group(mesh, table, [&](const CornerKey* begin, const CornerKey* end) {
    any = true;
    const auto even = std::count_if(begin, end, [](const CornerKey& k) { return k.even; });
    const auto odd = (end - begin) - even;
    // Opposite facings cancel in pairs (a wall inside two touching solids); one of the rest stays.
    const CornerKey* keep = even > odd   ? std::find_if(begin, end, [](const CornerKey& k) { return k.even; })
                            : odd > even ? std::find_if(begin, end, [](const CornerKey& k) { return !k.even; })
                                         : end;
    for (const CornerKey* k = begin; k != end; ++k)
      if (k != keep) remove[k->index] = 1;
  });
  if (!any) return 0;
  return erase_triangles(mesh, [&](size_t i) { return !remove[i]; });
}

// Breadth-first over edges with exactly two triangles: a neighbour that runs the shared edge the same
// way is flipped relative to this one. Per component the smaller side is flipped.
size_t make_consistent(BodyMesh& mesh, const EdgeTable& table) {
  auto& tris = mesh.triangles;
  const size_t n = tris.size();
  std::vector<std::array<uint32_t, 3>> neighbours(n, {kNone, kNone, kNone});  // other << 1 | same way
  std::vector<uint8_t> count(n, 0);
  table.for_each_edge([&](uint32_t, uint32_t, const HalfEdge* begin, const HalfEdge* end) {
    if (end - begin != 2) return;
    const uint32_t t = triangle_of(begin[0]), u = triangle_of(begin[1]);
    const uint32_t same = runs_up(begin[0]) == runs_up(begin[1]) ? 1 : 0;
    neighbours[t][count[t]++] = u << 1 | same;
    neighbours[u][count[u]++] = t << 1 | same;
  });
  std::vector<int8_t> flip(n, -1);
  std::vector<uint32_t> component;
  size_t flipped = 0;
  for (size_t seed = 0; seed < n; ++seed) {
    if (flip[seed] >= 0 || !distinct(tris[seed])) continue;
    component.assign(1, static_cast<uint32_t>(seed));
    flip[seed] = 0;
    size_t ones = 0;
    for (size_t head = 0; head < component.size(); ++head) {
      const uint32_t t = component[head];
      for (size_t k = 0; k < count[t]; ++k) {
        const uint32_t u = neighbours[t][k] >> 1;
        if (flip[u] >= 0) continue;  // seen (a non-orientable shell keeps its misoriented edges)
        flip[u] = static_cast<int8_t>(flip[t] ^ int8_t(neighbours[t][k] & 1));
        ones += size_t(flip[u]);
        component.push_back(u);
      }
    }
    const int8_t side = 2 * ones > component.size() ? 0 : 1;  // flip the smaller side
    for (uint32_t t : component)
      if (flip[t] == side) {
        std::swap(tris[t][1], tris[t][2]);
        ++flipped;
      }
  }
  return flipped;
}

// A polygon of points (in the order its triangles are to run) as triangles: ear clipping in the plane
// of its Newell normal, refusing diagonals that are edges of the mesh already; a fan of what is left
// when no ear is found (a loop that is not simple in that plane).
std::vector<Triangle> triangulate_hole(const BodyMesh& mesh, const std::vector<uint32_t>& polygon,
                                       const EdgeTable& table) {
  const size_t n = polygon.size();
  std::vector<Triangle> out;
  out.reserve(n - 2);
  Point centre{0, 0, 0};
  for (uint32_t v : polygon)
    for (size_t k = 0; k < 3; ++k) centre[k] += mesh.points[v][k] / double(n);
  Point newell{0, 0, 0};
  for (size_t i = 0; i < n; ++i) {
    const Point p = sub(mesh.points[polygon[i]], centre), q = sub(mesh.points[polygon[(i + 1) % n]], centre);
    const Point c = cross(p, q);
    for (size_t k = 0; k < 3; ++k) newell[k] += c[k];
  }
  std::vector<size_t> prev(n), next(n);
  for (size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  size_t remaining = n, i = 0;
  const double length = norm(newell);
  if (n > 3 && length > 0 && std::isfinite(length)) {
    // (u, v, normal) right-handed, so the polygon turns counter-clockwise in (u, v).
    const Point w{newell[0] / length, newell[1] / length, newell[2] / length};
    const size_t axis = std::abs(w[0]) <= std::abs(w[1]) && std::abs(w[0]) <= std::abs(w[2]) ? 0
                        : std::abs(w[1]) <= std::abs(w[2])                                   ? 1
                                                                                             : 2;
    Point e{0, 0, 0};
    e[axis] = 1;
    Point u = cross(w, e);
    const double u_length = norm(u);
    for (double& x : u) x /= u_length;
    const Point v = cross(w, u);
    std::vector<std::array<double, 2>> flat(n);
    for (size_t j = 0; j < n; ++j) {
      const Point p = sub(mesh.points[polygon[j]], centre);
      flat[j] = {dot(p, u), dot(p, v)};
    }
    const auto turn = [&](size_t a, size_t b, size_t c) {
      return (flat[b][0] - flat[a][0]) * (flat[c][1] - flat[a][1]) -
             (flat[b][1] - flat[a][1]) * (flat[c][0] - flat[a][0]);
    };
    const auto is_ear = [&](size_t j) {
      const size_t a = prev[j], c = next[j];
      if (!(turn(a, j, c) > 0) || table.has_edge(polygon[a], polygon[c])) return false;
      for (size_t r = next[c]; r != a; r = next[r])
        if (turn(a, j, r) >= 0 && turn(j, c, r) >= 0 && turn(c, a, r) >= 0) return false;
      return true;
    };
    size_t stalled = 0;
    while (remaining > 3 && stalled < remaining) {
      if (is_ear(i)) {
        out.push_back({polygon[prev[i]], polygon[i], polygon[next[i]]});
        next[prev[i]] = next[i];
        prev[next[i]] = prev[i];
        i = next[i];
        --remaining;
        stalled = 0;
      } else {
        i = next[i];
        ++stalled;
      }
    }
  }
  // A fan of the rest (all of a triangle; of a polygon with no ear left, the best there is).
  for (size_t j = next[i]; next[j] != i; j = next[j]) out.push_back({polygon[i], polygon[j], polygon[next[j]]});
  return out;
}

// Triangles added to fill one hole, and a triangle of the hole's rim.
struct Patch {
  uint32_t rim;
  size_t begin, end;
};

std::vector<Patch> fill_holes(BodyMesh& mesh, const EdgeTable& table, RepairReport& report) {
  std::vector<Patch> patches;
  struct Boundary {
    uint32_t from, to;
  };
  std::vector<Boundary> edges;  // in the direction their triangle runs them
  table.for_each_edge([&](uint32_t lo, uint32_t hi, const HalfEdge* begin, const HalfEdge* end) {
    if (end - begin == 1) edges.push_back(runs_up(*begin) ? Boundary{lo, hi} : Boundary{hi, lo});
  });
  if (edges.empty()) return patches;
  std::unordered_map<uint32_t, uint32_t> out_edge, out_count, in_count;
  for (size_t e = 0; e < edges.size(); ++e) {
    out_edge[edges[e].from] = static_cast<uint32_t>(e);
    ++out_count[edges[e].from];
    ++in_count[edges[e].to];
  }
  std::vector<uint8_t> visited(edges.size(), 0);
  std::vector<uint32_t> loop;
  for (size_t start = 0; start < edges.size(); ++start) {
    if (visited[start]) continue;
    loop.clear();
    bool simple = true;
    for (size_t e = start;;) {
      visited[e] = 1;
      loop.push_back(edges[e].from);
      const uint32_t v = edges[e].to;
      // A point where the boundary touches itself (a pinch) makes the loop ambiguous: left open.
      if (out_count[v] != 1 || in_count[v] != 1 || loop.size() > kMaxHoleEdges) {
        simple = false;
        break;
      }
      e = out_edge[v];
      if (e == start) break;
      if (visited[e]) {
        simple = false;
        break;
      }
    }
    if (!simple) continue;
    // The filling runs each boundary edge the other way from the triangle that has it.
    std::reverse(loop.begin(), loop.end());
    const std::vector<Triangle> patch = triangulate_hole(mesh, loop, table);
    const HalfEdge* rim = table.edge(edges[start].from, edges[start].to).first;
    patches.push_back({triangle_of(*rim), mesh.triangles.size(), mesh.triangles.size() + patch.size()});
    mesh.triangles.insert(mesh.triangles.end(), patch.begin(), patch.end());
    ++report.holes_filled;
    report.hole_triangles += patch.size();
  }
  return patches;
}

// Takes back the patches that closed a shell enclosing no volume: a loose sheet, a stray triangle or
// an unwelded triangle soup would otherwise become closed "pillows" of zero volume, and the body
// would pass as a solid. Left open, it is refused.
void unfill_flat_shells(BodyMesh& mesh, const EdgeTable& table, const std::vector<Patch>& patches,
                        RepairReport& report) {
  const auto& tris = mesh.triangles;
  DisjointSets sets(tris.size());
  table.for_each_edge([&](uint32_t, uint32_t, const HalfEdge* begin, const HalfEdge* end) {
    for (const HalfEdge* h = begin + 1; h < end; ++h) sets.unite(triangle_of(*begin), triangle_of(*h));
  });
  struct Stats {
    double volume = 0;
    std::array<Point, 2> box;
  };
  std::unordered_map<uint32_t, Stats> shells;
  for (const Patch& patch : patches) {
    const uint32_t root = sets.find(patch.rim);
    if (!shells.count(root)) shells[root].box = {mesh.points[tris[patch.rim][0]], mesh.points[tris[patch.rim][0]]};
  }
  for (size_t t = 0; t < tris.size(); ++t) {
    const auto shell = shells.find(sets.find(static_cast<uint32_t>(t)));
    if (shell == shells.end()) continue;
    shell->second.volume += triangle_volume(mesh, tris[t]);
    for (uint32_t v : tris[t])
      for (size_t k = 0; k < 3; ++k) {
        shell->second.box[0][k] = std::min(shell->second.box[0][k], mesh.points[v][k]);
        shell->second.box[1][k] = std::max(shell->second.box[1][k], mesh.points[v][k]);
      }
  }
  std::vector<uint8_t> remove(tris.size(), 0);
  bool any = false;
  for (const Patch& patch : patches) {
    const Stats& shell = shells[sets.find(patch.rim)];
    const double diagonal = norm(sub(shell.box[1], shell.box[0]));
    if (std::abs(shell.volume) > kFlatVolume * diagonal * diagonal * diagonal) continue;
    std::fill(remove.begin() + static_cast<std::ptrdiff_t>(patch.begin),
              remove.begin() + static_cast<std::ptrdiff_t>(patch.end), 1);
    --report.holes_filled;
    report.hole_triangles -= patch.end - patch.begin;
    any = true;
  }
  if (any) erase_triangles(mesh, [&](size_t i) { return !remove[i]; });
}

// Winding number of a closed shell around p (generalised: the solid angles of its triangles over
// 4 pi, van Oosterom and Strackee), about +-1 inside, 0 outside.
double winding_number(const BodyMesh& mesh, const uint32_t* begin, const uint32_t* end, const Point& p) {
  double sum = 0;
  for (const uint32_t* t = begin; t != end; ++t) {
    const Triangle& tri = mesh.triangles[*t];
    const Point a = sub(mesh.points[tri[0]], p), b = sub(mesh.points[tri[1]], p), c = sub(mesh.points[tri[2]], p);
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    sum += 2 * std::atan2(numerator, denominator);
  }
  return sum / (4 * kPi);
}

void orient_shells(BodyMesh& mesh, const EdgeTable& table, RepairReport& report) {
  auto& tris = mesh.triangles;
  const size_t n = tris.size();
  DisjointSets sets(n);
  table.for_each_edge([&](uint32_t, uint32_t, const HalfEdge* begin, const HalfEdge* end) {
    for (const HalfEdge* h = begin + 1; h < end; ++h) sets.unite(triangle_of(*begin), triangle_of(*h));
  });
  std::vector<uint8_t> open_root(n, 0);
  table.for_each_edge([&](uint32_t, uint32_t, const HalfEdge* begin, const HalfEdge* end) {
    if (end - begin != 2 || runs_up(begin[0]) == runs_up(begin[1]))
      for (const HalfEdge* h = begin; h < end; ++h) open_root[sets.find(triangle_of(*h))] = 1;
  });

  // The closed shells, numbered in order of their first triangle, and their triangles (counting sort).
  struct Shell {
    double volume = 0;
    std::array<Point, 2> box;
    Point sample{};  // the centre of its largest triangle, inside no other shell's surface
    double sample_area = -1;
  };
  std::vector<uint32_t> shell_of_root(n, kNone), shell_of(n, kNone);
  std::vector<Shell> shells;
  for (size_t t = 0; t < n; ++t) {
    const uint32_t root = sets.find(static_cast<uint32_t>(t));
    if (open_root[root] || !distinct(tris[t])) continue;
    if (shell_of_root[root] == kNone) {
      shell_of_root[root] = static_cast<uint32_t>(shells.size());
      shells.emplace_back();
      shells.back().box = {mesh.points[tris[t][0]], mesh.points[tris[t][0]]};
    }
    Shell& shell = shells[shell_of_root[root]];
    shell_of[t] = shell_of_root[root];
    shell.volume += triangle_volume(mesh, tris[t]);
    for (uint32_t v : tris[t])
      for (size_t k = 0; k < 3; ++k) {
        shell.box[0][k] = std::min(shell.box[0][k], mesh.points[v][k]);
        shell.box[1][k] = std::max(shell.box[1][k], mesh.points[v][k]);
      }
    const double area = norm(normal(mesh, tris[t]));
    if (area > shell.sample_area) {
      shell.sample_area = area;
      for (size_t k = 0; k < 3; ++k)
        shell.sample[k] = (mesh.points[tris[t][0]][k] + mesh.points[tris[t][1]][k] + mesh.points[tris[t][2]][k]) / 3.0;
    }
  }
  if (shells.empty()) return;
  std::vector<size_t> first(shells.size() + 1, 0);
  for (uint32_t s : shell_of)
    if (s != kNone) ++first[s + size_t(1)];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<uint32_t> members(first.back());
  {
    std::vector<size_t> fill(first.begin(), first.end() - 1);
    for (size_t t = 0; t < n; ++t)
      if (shell_of[t] != kNone) members[fill[shell_of[t]]++] = static_cast<uint32_t>(t);
  }

  const auto inside_box = [](const std::array<Point, 2>& inner, const std::array<Point, 2>& outer) {
    for (size_t k = 0; k < 3; ++k)
      if (inner[0][k] < outer[0][k] || inner[1][k] > outer[1][k]) return false;
    return true;
  };
  for (size_t a = 0; a < shells.size(); ++a) {
    size_t depth = 0;  // closed shells around this one: odd for the wall of a cavity
    if (shells.size() <= kMaxNestedShells)
      for (size_t b = 0; b < shells.size(); ++b)
        if (b != a && inside_box(shells[a].box, shells[b].box) &&
            std::abs(winding_number(mesh, members.data() + first[b], members.data() + first[b + 1], shells[a].sample)) >
                0.5)
          ++depth;
    const bool outward = depth % 2 == 0;
    if ((outward && shells[a].volume < 0) || (!outward && shells[a].volume > 0)) {
      for (size_t i = first[a]; i < first[a + 1]; ++i) std::swap(tris[members[i]][1], tris[members[i]][2]);
      ++report.shells_flipped;
    }
  }
  report.oriented_outward_flipped_all = report.shells_flipped == shells.size();
}

void compact_points(BodyMesh& mesh) {
  std::vector<uint32_t> renumber(mesh.points.size(), kNone);
  for (const Triangle& t : mesh.triangles)
    for (uint32_t v : t) renumber[v] = 0;
  uint32_t next = 0;
  for (size_t i = 0; i < mesh.points.size(); ++i)
    if (renumber[i] != kNone) {
      mesh.points[next] = mesh.points[i];
      renumber[i] = next++;
    }
  mesh.points.resize(next);
  for (Triangle& t : mesh.triangles)
    for (uint32_t& v : t) v = renumber[v];
}

std::string counted(size_t n, const char* noun) { return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s"); }

std::string first_at(const std::optional<Point>& p) {
  if (!p) return "";
  return fmt::format(" (the first at ({:g}, {:g}, {:g}) mm)", (*p)[0], (*p)[1], (*p)[2]);
}

}  // namespace

bool TopologyReport::closed() const { return open_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0; }

std::string TopologyReport::describe() const {
  return fmt::format(
      "{}{}, {}{}, {}{}, {} degenerate and {} duplicate triangles; {} in {}", counted(open_edges, "open edge"),
      first_at(first_open_edge), counted(nonmanifold_edges, "non-manifold edge"), first_at(first_nonmanifold_edge),
      counted(misoriented_edges, "misoriented edge"), first_at(first_misoriented_edge), degenerate_triangles,
      duplicate_triangles, counted(triangles, "triangle"), counted(shells, "shell"));
}

TopologyReport analyse_topology(const BodyMesh& mesh) {
  TopologyReport report;
  const auto& tris = mesh.triangles;
  report.triangles = tris.size();
  report.points = mesh.points.size();
  for (const Triangle& t : tris)
    if (!distinct(t) || zero_area(mesh, t)) ++report.degenerate_triangles;

  const EdgeTable table(mesh);
  DisjointSets sets(tris.size());
  table.for_each_edge([&](uint32_t lo, uint32_t hi, const HalfEdge* begin, const HalfEdge* end) {
    const auto uses = end - begin;
    if (uses == 1) {
      if (report.open_edges++ == 0) report.first_open_edge = midpoint(mesh, lo, hi);
    } else if (uses > 2) {
      if (report.nonmanifold_edges++ == 0) report.first_nonmanifold_edge = midpoint(mesh, lo, hi);
    } else if (runs_up(begin[0]) == runs_up(begin[1])) {
      if (report.misoriented_edges++ == 0) report.first_misoriented_edge = midpoint(mesh, lo, hi);
    }
    for (const HalfEdge* h = begin + 1; h < end; ++h) sets.unite(triangle_of(*begin), triangle_of(*h));
  });
  for (size_t t = 0; t < tris.size(); ++t)
    if (distinct(tris[t]) && sets.find(static_cast<uint32_t>(t)) == t) ++report.shells;

  for_each_duplicate_group(mesh, table, [&](const CornerKey* begin, const CornerKey* end) {
    report.duplicate_triangles += static_cast<size_t>(end - begin) - 1;
  });
  return report;
}

std::string RepairReport::describe() const {
  std::vector<std::string> parts;
  if (removed_degenerate && removed_duplicate)
    parts.push_back(
        fmt::format("removed {} degenerate and {} duplicate triangles", removed_degenerate, removed_duplicate));
  else if (removed_degenerate)
    parts.push_back("removed " + counted(removed_degenerate, "degenerate triangle"));
  else if (removed_duplicate)
    parts.push_back("removed " + counted(removed_duplicate, "duplicate triangle"));
  if (flipped) parts.push_back(fmt::format("flipped {} to agree with their neighbours", flipped));
  if (holes_filled)
    parts.push_back(
        fmt::format("filled {} with {}", counted(holes_filled, "hole"), counted(hole_triangles, "triangle")));
  if (oriented_outward_flipped_all)
    parts.push_back("turned the whole mesh outward (it faced inward)");
  else if (shells_flipped)
    parts.push_back(fmt::format("turned {} to face away from the material", counted(shells_flipped, "shell")));
  if (parts.empty()) return "nothing to repair";
  std::string out = parts[0];
  for (size_t i = 1; i < parts.size(); ++i) out += ", " + parts[i];
  return out;
}

RepairReport repair_body(BodyMesh& mesh) {
  RepairReport report;
  report.removed_degenerate = erase_triangles(mesh, [&](size_t i) { return distinct(mesh.triangles[i]); });
  report.removed_degenerate += remove_slivers(mesh);
  EdgeTable table(mesh);
  report.removed_duplicate = remove_duplicates(mesh, table);
  if (report.removed_duplicate) table = EdgeTable(mesh);
  report.flipped = make_consistent(mesh, table);
  if (report.flipped) table = EdgeTable(mesh);  // the table holds each triangle's direction
  const std::vector<Patch> patches = fill_holes(mesh, table, report);
  if (!patches.empty()) {
    table = EdgeTable(mesh);
    unfill_flat_shells(mesh, table, patches, report);
    // Ear clipping makes no zero-area triangle, but the fan of a loop without ears (three points in a
    // line, say) can: split across like any sliver.
    report.hole_triangles -= std::min(report.hole_triangles, remove_slivers(mesh));
    table = EdgeTable(mesh);
  }
  orient_shells(mesh, table, report);
  compact_points(mesh);
  return report;
}

double winding_number(const BodyMesh& mesh, const std::array<double, 3>& p) {
  std::vector<uint32_t> all(mesh.triangles.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<uint32_t>(i);
  return winding_number(mesh, all.data(), all.data() + all.size(), p);
}

}  // namespace offsetgen::body
