#include "step/cell_symmetry.h"

#include <algorithm>

namespace offsetgen::step {

Point CellImage::apply(const Point& p) const {
  Point q{};
  for (size_t a = 0; a < 3; ++a) {
    const double value = p[static_cast<size_t>(from[a])];
    q[a] = mirror[a] ? 1 - value : value;
  }
  return q;
}

bool CellImage::reverses() const {
  int parity = 0;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = a + 1; b < 3; ++b)
      if (from[a] > from[b]) ++parity;
  for (bool m : mirror) parity += m ? 1 : 0;
  return parity % 2 == 1;
}

int CellImage::face_axis() const { return static_cast<int>(std::find(from.begin(), from.end(), 2) - from.begin()); }

int CellImage::face_side() const { return mirror[static_cast<size_t>(face_axis())] ? 1 : 0; }

const std::vector<CellImage>& cell_images() {
  static const std::vector<CellImage> images = [] {
    std::vector<CellImage> all;
    std::array<int, 3> perm{0, 1, 2};
    do {
      for (int flags = 0; flags < 8; ++flags) {
        CellImage image;
        image.from = perm;
        for (size_t a = 0; a < 3; ++a) image.mirror[a] = ((flags >> a) & 1) != 0;
        all.push_back(image);
      }
    } while (std::next_permutation(perm.begin(), perm.end()));
    return all;
  }();
  return images;
}

}  // namespace offsetgen::step
