#include "mesh/box_domain.h"

#include "mesh/narrow_band.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::mesh {
namespace {

// Box distance along one axis: max(-x, x - length), negative inside [0, length].
double axis_distance(double x, double length) { return std::max(-x, x - length); }

class BoxReader : public DomainReader {
 public:
  BoxReader(const std::array<int, 3>& cells, double voxel) : voxel_(voxel) {
    for (int a = 0; a < 3; ++a) length_[a] = cells[static_cast<size_t>(a)];
  }

  BlockPlace read_block(const std::array<int, 3>& origin, double margin, double* d) override {
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = (origin[static_cast<size_t>(a)] + 0.5) * voxel_;
      hi[a] = (origin[static_cast<size_t>(a)] + kBlock - 0.5) * voxel_;
    }
    // The block's voxel nearest the box, outside by more than the margin?
    double nearest = -HUGE_VAL;
    for (int a = 0; a < 3; ++a)
      nearest = std::max(nearest, axis_distance(std::clamp(0.5 * length_[a], lo[a], hi[a]), length_[a]));
    if (nearest > margin * voxel_) return BlockPlace::Outside;
    for (int i = 0; i < kBlock; ++i)
      for (int j = 0; j < kBlock; ++j)
        for (int l = 0; l < kBlock; ++l) {
          const double p[3] = {(origin[0] + i + 0.5) * voxel_, (origin[1] + j + 0.5) * voxel_,
                               (origin[2] + l + 0.5) * voxel_};
          const double box = std::max(
              {axis_distance(p[0], length_[0]), axis_distance(p[1], length_[1]), axis_distance(p[2], length_[2])});
          d[block_offset(i, j, l)] = box / voxel_;
        }
    return BlockPlace::Mixed;
  }

 private:
  double voxel_;
  double length_[3] = {0, 0, 0};
};

}  // namespace

BoxDomain::BoxDomain(const std::array<int, 3>& cells, double voxel) : cells_(cells), voxel_(voxel) {}

std::unique_ptr<DomainReader> BoxDomain::reader() const { return std::make_unique<BoxReader>(cells_, voxel_); }

std::array<std::array<int, 3>, 2> BoxDomain::block_range() const {
  // Voxel indices [-2, N + 2) on each axis, aligned to multiples of kBlock.
  std::array<std::array<int, 3>, 2> range{};
  for (size_t a = 0; a < 3; ++a) {
    const int n = static_cast<int>(std::lround(cells_[a] / voxel_));
    range[0][a] = -kBlock;
    range[1][a] = ((n + 2 + kBlock - 1) / kBlock) * kBlock;
  }
  return range;
}

}  // namespace offsetgen::mesh
