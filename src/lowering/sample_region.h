// Where the stages sample F before building (bounds of its derivatives, definedness, the thickness):
// one cell [0, k]^d for a periodic surface; for a mapped one (surface.h) its domain box, less the
// points within the clearance of the map's singular set.
#pragma once

#include "lowering/program.h"
#include "surfaces/surface.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace offsetgen {

class SampleRegion {
 public:
  explicit SampleRegion(const Surface& surface);
  SampleRegion(const SampleRegion& other);
  SampleRegion& operator=(const SampleRegion&) = delete;
  ~SampleRegion();

  int dims() const { return dims_; }
  // The box, in natural coordinates.
  double lo(int axis) const { return lo_[static_cast<size_t>(axis)]; }
  double hi(int axis) const { return hi_[static_cast<size_t>(axis)]; }
  // The point of the box at fractions t in [0, 1] along each axis.
  std::vector<double> at(const std::vector<double>& t) const;
  // Whether a natural point is sampled: inside the box and outside the singular clearance.
  bool contains(const std::vector<double>& p);
  // The smallest singular measure at p (infinity when the surface has none).
  double singular_measure(const std::vector<double>& p);
  bool has_singular_measures() const { return measures_ != nullptr; }
  // A mapped domain spans many cells of varying size: its searches sample more densely.
  bool mapped() const { return mapped_; }
  // "the cell [0, 1]^3" or "the domain [0, 10] x [-5, 5] x [0, 20]", for messages.
  std::string describe() const;

 private:
  int dims_ = 3;
  bool mapped_ = false;
  double clearance_ = 0;
  std::vector<double> lo_, hi_;
  std::unique_ptr<Program> measures_;
  std::unique_ptr<Evaluator> evaluate_;
};

// The maximum of f over the region's points (grid, then compass refinement from the 8 best samples;
// non-finite values are skipped), and where it is if `argmax` is given. Throws std::runtime_error
// naming `what` when f is finite nowhere.
double maximum_over_region(SampleRegion& region, const std::function<double(const std::vector<double>&)>& f,
                           const std::string& what, std::vector<double>* argmax = nullptr);

// A point as "(x, y, z) = (0.5, 0, 2)".
std::string point_text(const std::vector<double>& p);

}  // namespace offsetgen
