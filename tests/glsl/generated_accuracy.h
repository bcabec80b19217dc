// Accuracy of a generated surface/order in float32 (GLSL on llvmpipe, or the C float variant)
// against the double-precision C header of the same lowered program.
//
// Metrics, over N random points p in [0,1]^3 with h uniform in [-0.05, 0.05] (t = 2|h|).
// "Near the zero set" means: estimated distance |phi_d| / |grad F| <= 0.05 cell lengths, at points
// with |grad F| >= 10% of its sample maximum (|grad F| by central differences of the double field).
//   field     max |F_f - F_d| over all points                                      units of F
//   offset    max |phi_f(p,h) - phi_d(p,h)| near the zero set of phi_d             units of F
//             The float zero set lies between the double level sets -E and +E: the
//             requirement "float32 zero set within 2e-5, in units of F" reads offset < 2e-5.
//   offset (all)  the same max over all points (informative: far from the surface, near the
//             critical points of F where |grad F| -> 0, the 1/|grad F| terms of orders >= 2
//             amplify rounding; the sign there is F's, so no zero set is affected)
//   zero set  max |phi_f - phi_d| / |grad phi_d| near the zero set: how far, in cell lengths,
//             the float zero set moves (grad phi_d by central differences of the double offset)
//   shell     max |S_f - S_d| / (|phi_d(p,t/2)| + |phi_d(p,-t/2)| + 1e-3) where either wall face
//             is near (min |phi_d(p,+-t/2)| / |grad F| <= 0.05): the error of the vanishing factor,
//             units of F
//   normal    max |n_f - n_d| (Euclidean distance of unit vectors) near the zero set
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "generated_cases.h"
#include "run/glsl_executor.h"

namespace offsetgen::glsl_test {

// Double-precision values of one case at the sample points (inputs are float, as the GPU sees them).
struct DoubleReference {
  std::vector<glsl::Sample> points;                               // x, y, z, h
  std::vector<double> field, offset, shell, phi_plus, phi_minus;  // shell at t = 2|h|
  std::vector<double> normal;                                     // 3 per point
  std::vector<double> grad_len;                                   // |grad phi_d(p, h)|
  std::vector<double> field_grad;                                 // |grad F(p)|
  double gradient_floor = 0.0;                                    // 10% of the largest |grad F| of the sample
};

DoubleReference make_reference(const GeneratedCase& c, std::size_t n, std::uint32_t seed);

// Float results at the same points: field, offset, shell (1 per point), normal (3 per point).
struct FloatResults {
  std::vector<float> field, offset, shell, normal;
};

struct Accuracy {
  double field = 0.0, offset = 0.0, offset_all = 0.0, zero_set = 0.0, shell = 0.0, normal = 0.0;
  std::size_t near_points = 0;   // points near the zero set of phi (offset, zero set, normal)
  std::size_t shell_points = 0;  // points near a wall face
  std::size_t worst_offset = 0;  // index of the worst offset point near the zero set
};

// Whether point i of `ref` is near the zero set of phi_d(p, h).
bool near_zero_set(const DoubleReference& ref, std::size_t i);

Accuracy measure(const DoubleReference& ref, const FloatResults& got);

// One line with every metric.
std::string describe(const Accuracy& a);

}  // namespace offsetgen::glsl_test
