#include "mesh/mesh_audit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace offsetgen::mesh {
namespace {

// LSD radix sort of 64-bit words, 16 bits a pass: a tile's millions of edges in four linear passes.
void radix_sort(std::vector<uint64_t>& words) {
  std::vector<uint64_t> buffer(words.size());
  std::vector<size_t> start(size_t(1) << 16);
  for (int shift = 0; shift < 64; shift += 16) {
    std::fill(start.begin(), start.end(), 0);
    for (uint64_t w : words) ++start[(w >> shift) & 0xffff];
    if (std::count(start.begin(), start.end(), 0) == static_cast<long>(start.size()) - 1) continue;  // one digit
    size_t sum = 0;
    for (size_t& c : start) sum += std::exchange(c, sum);
    for (uint64_t w : words) buffer[start[(w >> shift) & 0xffff]++] = w;
    words.swap(buffer);
  }
}

uint32_t position_hash(const std::array<float, 3>& p) {
  uint32_t bits[3];
  std::memcpy(bits, p.data(), sizeof(bits));
  uint64_t h = 1469598103934665603ull;
  for (uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
  return static_cast<uint32_t>(h ^ (h >> 32));
}

// Each point's welded id: the smallest index of the points at its position, as a reader welds them.
// Sorted by (hash of the position, index); points whose hashes collide are told apart exactly.
std::vector<uint32_t> weld_ids(const std::vector<std::array<float, 3>>& points) {
  std::vector<uint64_t> order(points.size());
  for (uint32_t i = 0; i < points.size(); ++i) order[i] = (uint64_t(position_hash(points[i])) << 32) | i;
  radix_sort(order);
  std::vector<uint32_t> id(points.size());
  for (size_t k = 0; k < order.size();) {
    size_t end = k;
    while (end < order.size() && (order[end] >> 32) == (order[k] >> 32)) ++end;
    for (size_t a = k; a < end; ++a) {  // in index order: the first at each position is its id
      const auto i = static_cast<uint32_t>(order[a]);
      id[i] = i;
      for (size_t b = k; b < a; ++b) {
        const auto j = static_cast<uint32_t>(order[b]);
        if (points[j] == points[i]) {
          id[i] = id[j];
          break;
        }
      }
    }
    k = end;
  }
  return id;
}

// A facet's edge as one word: the smaller id, the larger id, and whether the facet crosses it from the
// smaller to the larger (ids below 2^31), so that sorting words groups each edge's uses.
uint64_t directed_edge(uint32_t from, uint32_t to) {
  const uint32_t lo = std::min(from, to), hi = std::max(from, to);
  return (uint64_t(lo) << 32) | (uint64_t(hi) << 1) | (from == lo ? 1u : 0u);
}

}  // namespace

MeshAudit::EdgeKey MeshAudit::edge_key(const Position& first, const Position& second) {
  uint32_t bits[6];
  std::memcpy(bits, first.data(), 12);
  std::memcpy(bits + 3, second.data(), 12);
  uint64_t a = 1469598103934665603ull, b = 0x9e3779b97f4a7c15ull;  // FNV-1a, and a multiply-xorshift mix
  for (uint32_t x : bits) {
    a = (a ^ x) * 1099511628211ull;
    b = (b ^ x) * 0xbf58476d1ce4e5b9ull;
    b ^= b >> 31;
  }
  return {a ^ (a >> 29), b};
}

std::string AuditReport::describe() const {
  return fmt::format("{} open edges, {} non-manifold edges, {} misoriented edges, {} degenerate facets", open_edges,
                     nonmanifold_edges, misoriented_edges, degenerate_facets);
}

void MeshAudit::judge(int forward, int backward) {
  if (forward + backward == 1) {
    ++report_.open_edges;
  } else if (forward + backward > 2) {
    ++report_.nonmanifold_edges;
  } else if (forward != 1) {
    ++report_.misoriented_edges;
  }
}

void MeshAudit::add(const TriangleMesh& mesh) {
  add(mesh, std::vector<uint8_t>(mesh.points.size(), 0), std::vector<uint8_t>(mesh.points.size(), 0));
}

void MeshAudit::add(const TriangleMesh& mesh, const std::vector<uint8_t>& seam,
                    const std::vector<uint8_t>& outside_run) {
  const std::vector<uint32_t> id = weld_ids(mesh.points);
  // A welded point is on a seam when any point at its position is.
  std::vector<uint8_t> on_seam(mesh.points.size(), 0), outside(mesh.points.size(), 0);
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    on_seam[id[i]] |= seam[i];
    outside[id[i]] |= outside_run[i];
  }
  if (mesh.points.size() >= (size_t(1) << 31)) throw std::length_error("mesh audit: too many points in one tile");
  std::vector<uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const uint32_t a = id[t[0]], b = id[t[1]], c = id[t[2]];
    if (a == b || b == c || a == c) {
      ++report_.degenerate_facets;
      continue;
    }
    edges.insert(edges.end(), {directed_edge(a, b), directed_edge(b, c), directed_edge(c, a)});
  }
  radix_sort(edges);
  for (size_t k = 0; k < edges.size();) {
    size_t end = k;
    int forward = 0, backward = 0;
    for (; end < edges.size() && (edges[end] >> 1) == (edges[k] >> 1); ++end) (edges[end] & 1 ? forward : backward)++;
    const auto lo = static_cast<uint32_t>(edges[k] >> 32), hi = static_cast<uint32_t>((edges[k] >> 1) & 0x7fffffffu);
    if (on_seam[lo] && on_seam[hi]) {
      // Held by position: the neighbour's facets name the same positions, not the same ids.
      const bool swap = mesh.points[hi] < mesh.points[lo];
      const EdgeKey key =
          swap ? edge_key(mesh.points[hi], mesh.points[lo]) : edge_key(mesh.points[lo], mesh.points[hi]);
      SeamEdge& e = seam_edges_[key];
      const int f = e.forward + (swap ? backward : forward), bk = e.backward + (swap ? forward : backward);
      e.forward = static_cast<uint8_t>(std::min(f, 255));
      e.backward = static_cast<uint8_t>(std::min(bk, 255));
      e.outside_run = e.outside_run || outside[lo] || outside[hi];
      // Complete: no later tile can add to it without a third facet, which shows as an open edge.
      if (e.forward == 1 && e.backward == 1) seam_edges_.erase(key);
    } else {
      judge(forward, backward);
    }
    k = end;
  }
}

AuditReport MeshAudit::finish() {
  for (const auto& [key, e] : seam_edges_) {
    if (e.outside_run && e.forward + e.backward == 1) {
      ++report_.unmatched_seam_edges;
    } else {
      judge(e.forward, e.backward);
    }
  }
  seam_edges_.clear();
  return report_;
}

}  // namespace offsetgen::mesh
