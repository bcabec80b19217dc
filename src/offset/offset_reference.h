// Every emitted function evaluated at high precision (CLN, 40 digits by default) from the symbolic
// construction itself, without lowering: what the emitted code is checked against. Cell units
// outside, as in the emitted functions.
#pragma once

#include "offset/method.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>

#include <vector>

namespace offsetgen {

class OffsetReference {
 public:
  using CellPoint = std::vector<GiNaC::numeric>;

  OffsetReference(const Surface& surface, const OffsetConstruction& construction, int digits = 40);

  GiNaC::numeric field(const CellPoint& x);
  std::vector<GiNaC::numeric> field_gradient(const CellPoint& x);  // d F / d x (cell units)
  GiNaC::numeric offset(const CellPoint& x, const GiNaC::numeric& h);
  GiNaC::numeric shell(const CellPoint& x, const GiNaC::numeric& t);
  std::vector<GiNaC::numeric> normal(const CellPoint& x, const GiNaC::numeric& h);
  // The graded wall's shell for a total thickness t(x, y, z) in cell units.
  GiNaC::numeric graded(const CellPoint& x, const GiNaC::ex& thickness);

  int digits() const { return digits_; }

 private:
  std::vector<GiNaC::numeric> natural(const CellPoint& x) const;

  const Surface& surface_;
  const OffsetConstruction& construction_;
  int digits_;
  GiNaC::numeric scale_;
};

}  // namespace offsetgen
