#include "mesh/triangle_mesh.h"

#include "body/disjoint_sets.h"

#include <algorithm>
#include <numeric>

namespace offsetgen::mesh {
namespace {

double triangle_volume(const TriangleMesh& mesh, const std::array<uint32_t, 3>& t) {
  const auto& a = mesh.points[t[0]];
  const auto& b = mesh.points[t[1]];
  const auto& c = mesh.points[t[2]];
  // a . (b x c) / 6, in double.
  const double bx = b[0], by = b[1], bz = b[2], cx = c[0], cy = c[1], cz = c[2];
  return (a[0] * (by * cz - bz * cy) + a[1] * (bz * cx - bx * cz) + a[2] * (bx * cy - by * cx)) / 6.0;
}

// Keeps the triangles whose piece is kept, in their order, and the points they use in order of
// first use.
void compact(TriangleMesh& mesh, const std::vector<uint32_t>& piece, const std::vector<uint8_t>& keep) {
  std::vector<uint32_t> renumber(mesh.points.size(), UINT32_MAX);
  TriangleMesh out;
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    if (!keep[piece[t[0]]]) continue;
    std::array<uint32_t, 3> u{};
    for (int k = 0; k < 3; ++k) {
      uint32_t& r = renumber[t[static_cast<size_t>(k)]];
      if (r == UINT32_MAX) {
        r = static_cast<uint32_t>(out.points.size());
        out.points.push_back(mesh.points[t[static_cast<size_t>(k)]]);
      }
      u[static_cast<size_t>(k)] = r;
    }
    out.triangles.push_back(u);
  }
  mesh = std::move(out);
}

}  // namespace

double signed_volume(const TriangleMesh& mesh) {
  double v = 0;
  for (const auto& t : mesh.triangles) v += triangle_volume(mesh, t);
  return v;
}

std::vector<uint32_t> point_pieces(const TriangleMesh& mesh) {
  DisjointSets sets(mesh.points.size());
  for (const auto& t : mesh.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[0], t[2]);
  }
  std::vector<uint32_t> pieces(mesh.points.size());
  for (size_t i = 0; i < pieces.size(); ++i) pieces[i] = sets.find(static_cast<uint32_t>(i));
  return pieces;
}

std::vector<double> piece_volumes(const TriangleMesh& mesh, const std::vector<uint32_t>& pieces) {
  std::vector<double> volume(mesh.points.size(), 0.0);
  for (const auto& t : mesh.triangles) volume[pieces[t[0]]] += triangle_volume(mesh, t);
  return volume;
}

size_t weld_points(TriangleMesh& mesh) {
  std::vector<uint32_t> order(mesh.points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return mesh.points[a] < mesh.points[b]; });
  // Each point's representative: the first occurrence of its position.
  std::vector<uint32_t> same(mesh.points.size());
  size_t merged = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    const bool repeat = i > 0 && mesh.points[order[i]] == mesh.points[order[i - 1]];
    same[order[i]] = repeat ? same[order[i - 1]] : order[i];
    merged += repeat ? 1 : 0;
  }
  if (merged == 0) return 0;
  for (auto& t : mesh.triangles)
    for (uint32_t& i : t) i = same[i];
  std::vector<uint32_t> piece(mesh.points.size(), 0);
  compact(mesh, piece, std::vector<uint8_t>{1});
  return merged;
}

void flip(TriangleMesh& mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

std::pair<int, double> drop_small_inner_pieces(TriangleMesh& mesh, const std::array<std::array<float, 3>, 2>& inner,
                                               double min_volume) {
  const std::vector<uint32_t> piece = point_pieces(mesh);
  const std::vector<double> volume = piece_volumes(mesh, piece);
  std::vector<uint8_t> keep(mesh.points.size(), 0);
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    const auto& p = mesh.points[i];
    for (size_t a = 0; a < 3; ++a)
      if (p[a] < inner[0][a] || p[a] > inner[1][a]) keep[piece[i]] = 1;  // reaches a seam
  }
  int dropped = 0;
  double dropped_volume = 0;
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    if (piece[i] != i || keep[i]) continue;
    if (volume[i] < 0 || volume[i] >= min_volume) {
      keep[i] = 1;
    } else {
      ++dropped;
      dropped_volume += volume[i];
    }
  }
  if (dropped > 0) compact(mesh, piece, keep);
  return {dropped, dropped_volume};
}

PieceReport keep_large_pieces(TriangleMesh& mesh, double min_fraction) {
  PieceReport report;
  if (signed_volume(mesh) < 0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);

  // Connected surfaces: triangles sharing a point.
  const std::vector<uint32_t> piece = point_pieces(mesh);
  const std::vector<double> volume = piece_volumes(mesh, piece);
  std::vector<uint8_t> has_triangles(mesh.points.size(), 0);
  for (const auto& t : mesh.triangles) has_triangles[piece[t[0]]] = 1;
  double largest = 0;
  for (double v : volume) largest = std::max(largest, v);
  std::vector<uint8_t> keep(mesh.points.size(), 1);
  for (size_t root = 0; root < volume.size(); ++root) {
    if (!has_triangles[root]) continue;
    const double v = volume[root];
    if (v >= 0 && v < min_fraction * largest) {  // includes flat debris enclosing nothing
      keep[root] = 0;
      ++report.dropped;
      report.dropped_volume += v;
    } else if (v > 0) {
      ++report.kept;
    } else if (v < 0) {
      ++report.cavities;
    }
  }

  compact(mesh, piece, keep);
  report.volume = signed_volume(mesh);
  return report;
}

}  // namespace offsetgen::mesh
