#include "slice/coverage_raster.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::slice {

CoverageRaster::CoverageRaster(int width, int height)
    : width_(width), height_(height), acc_(static_cast<size_t>(width + 2) * static_cast<size_t>(height), 0.0) {}

void CoverageRaster::add_edge(std::array<double, 2> a, std::array<double, 2> b) {
  if (a[1] == b[1]) return;  // horizontal: no height, no area
  // The parameters where the edge crosses a pixel row or column.
  std::vector<double> cuts{0.0, 1.0};
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = std::min(a[axis], b[axis]), hi = std::max(a[axis], b[axis]);
    const double d = b[axis] - a[axis];
    if (d == 0) continue;
    for (double k = std::floor(lo) + 1; k < hi; k += 1) cuts.push_back((k - a[axis]) / d);
  }
  std::sort(cuts.begin(), cuts.end());
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double t0 = cuts[k], t1 = cuts[k + 1];
    if (t1 <= t0) continue;
    const double u0 = a[0] + t0 * (b[0] - a[0]), u1 = a[0] + t1 * (b[0] - a[0]);
    const double v0 = a[1] + t0 * (b[1] - a[1]), v1 = a[1] + t1 * (b[1] - a[1]);
    const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
    const int r = static_cast<int>(std::floor(vm));
    if (r < 0 || r >= height_) continue;
    const double dv = v1 - v0;
    int c = static_cast<int>(std::floor(um));
    double m = um - c;
    if (c < 0) {  // left of the image: all of it covers the row from column 0
      c = -1;
      m = 1;
    }
    if (c >= width_) continue;  // right of the image: covers nothing in it
    double* row = &acc_[static_cast<size_t>(r) * static_cast<size_t>(width_ + 2)];
    row[c + 1] += dv * (1 - m);  // columns shifted by one: index 0 is column -1
    row[c + 2] += dv * m;
  }
}

void CoverageRaster::row(int r, double sign, std::vector<uint8_t>& out) const {
  out.resize(static_cast<size_t>(width_));
  const double* row = &acc_[static_cast<size_t>(r) * static_cast<size_t>(width_ + 2)];
  double sum = row[0];
  for (int c = 0; c < width_; ++c) {
    sum += row[c + 1];
    const double cover = std::clamp(sign * sum, 0.0, 1.0);
    out[static_cast<size_t>(c)] = static_cast<uint8_t>(cover * 255 + 0.5);  // rounded: cover >= 0
  }
}

double CoverageRaster::area(double sign) const {
  double total = 0;
  for (int r = 0; r < height_; ++r) {
    const double* row = &acc_[static_cast<size_t>(r) * static_cast<size_t>(width_ + 2)];
    double sum = row[0];
    for (int c = 0; c < width_; ++c) {
      sum += row[c + 1];
      total += std::clamp(sign * sum, 0.0, 1.0);
    }
  }
  return total;
}

}  // namespace offsetgen::slice
