// The nested-AD peer, instantiated for the surfaces and orders the benchmark compares.
#include "eval_registry.h"
#include "nested_dual.h"

namespace offsetgen::bench {
namespace {

template <int M, class Field>
double ad_offset(double x, double y, double z, double h) {
  return Offset<M, Field>::eval(x, y, z, h);
}

const bool registered = [] {
  register_ad("gyroid", 1, &ad_offset<1, Gyroid>);
  register_ad("gyroid", 2, &ad_offset<2, Gyroid>);
  register_ad("gyroid", 3, &ad_offset<3, Gyroid>);
  register_ad("gyroid", 4, &ad_offset<4, Gyroid>);
  register_ad("gyroid", 5, &ad_offset<5, Gyroid>);
  register_ad("schwarzp", 4, &ad_offset<4, SchwarzP>);
  register_ad("neovius", 4, &ad_offset<4, Neovius>);
  register_ad("diamond", 4, &ad_offset<4, Diamond>);
  return true;
}();

}  // namespace
}  // namespace offsetgen::bench
