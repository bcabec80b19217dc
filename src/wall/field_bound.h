// Where F alone decides the wall, so it need not be evaluated: a point q with |F(q)| > L reach is
// beyond the solid's surface (both offsets, or a network's one, have the sign of F there: the methods'
// safeguards guarantee it, see the headers' SAFETY notes), so a box or square of points within
// `radius` of a centre with |F(centre)| > L (reach + margin + radius) is outside the sheet's wall, or
// inside the network where F < 0, with all its neighbours within `margin`. L = k M bounds |grad F|
// only where M was computed: the unit cell, so everywhere for periodic (catalog) surfaces. Cell units.
#pragma once

#include "wall/wall_field.h"

#include <cmath>

namespace offsetgen::wall {

class FieldBound {
 public:
  enum class Far { No, Outside, Inside };

  // lipschitz 0 disables the bound (M does not hold where the points lie).
  FieldBound(const WallField& field, double lipschitz, double reach, double margin)
      : field_(field), lipschitz_(lipschitz), far_(lipschitz * (reach + margin)), network_(field.network()) {}

  Far far_from_walls(const double* centre, double radius) const {
    if (lipschitz_ <= 0) return Far::No;
    const double f = field_.field(centre[0], centre[1], centre[2]);
    if (std::abs(f) <= far_ + lipschitz_ * radius) return Far::No;
    return network_ && f < 0 ? Far::Inside : Far::Outside;
  }

 private:
  const WallField& field_;
  double lipschitz_, far_;
  bool network_;
};

}  // namespace offsetgen::wall
