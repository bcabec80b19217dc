#include "wall/part_value.h"

#include <algorithm>
#include <cmath>

namespace offsetgen::wall {
namespace {

// Quadratic smooth minimum: min(a, b) lowered by at most r / 4 where a and b are within r.
double smooth_min(double a, double b, double r) {
  if (r <= 0) return std::min(a, b);
  const double overlap = std::max(r - std::abs(a - b), 0.0);
  return std::min(a, b) - overlap * overlap / (4 * r);
}

}  // namespace

double part_value(double d, double w, double skin, double fillet) {
  if (skin <= 0) return std::max(w, d);
  const double core = d + skin;
  const double shell = std::max(d, -core);
  return smooth_min(shell, std::max(w, core), fillet);
}

double part_value_without_wall(double d, double skin, double band, double background) {
  if (skin <= 0) return background;
  const double shell = std::max(d, -(d + skin));
  return shell < band ? shell : background;
}

bool wall_matters(double d, double skin, double fillet, double margin) {
  return skin > 0 ? d + skin < margin + fillet : d < margin;
}

}  // namespace offsetgen::wall
