// The solid to mesh as a level set: w(p) < 0 inside the wall between the offset surfaces at -t/2
// and +t/2. w is evaluated through the functions a user gets: the C header of `generate` (batch
// API, <prefix>_offset_n), compiled with the system C compiler and loaded with dlopen (run/c_library.h) as `check`
// does.
#pragma once

#include "lowering/program.h"
#include "pipeline/generate.h"
#include "run/c_library.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::wall {

struct WallRequest {
  GenerationRequest generation;  // surface or expression, params, method, order; or density, density_field
  std::string thickness;         // total wall thickness: a number or an expression of x, y, z (cell units)
                                 // (empty when generation.density or .density_field sets it)
  // The network (skeletal) solid phi(p, h) < 0 instead of the sheet: `thickness` is then the offset h
  // (cell units, either sign; h > 0 grows the network), and generation.density the network's density.
  bool network = false;
};

// What the mesher sizes its voxels and its F bound by, in cell units over a box of cells: the thinnest
// feature of the solid (a sheet's thickness; a network's narrowest neck, about 2 (h_max - |h|), which
// closes where |h| reaches the curvature limit h_max), and how far from F = 0 its surface reaches
// (t / 2; |h|).
struct WallExtent {
  double thinnest = 0;
  double reach = 0;
};

class WallField {
 public:
  // Generates the header and reads the thickness. Throws InputError for bad input (unknown surface,
  // a 2D surface, a bad thickness).
  explicit WallField(const WallRequest& request);
  // Compiles the header and loads it (walls() and field() need it). Throws InputError when there is
  // no C compiler, std::runtime_error when it fails.
  void compile();
  ~WallField();
  WallField(const WallField&) = delete;
  WallField& operator=(const WallField&) = delete;

  // Per-thread scratch space (the thickness evaluator is not reentrant).
  class Worker {
   public:
    explicit Worker(const WallField& field);
    ~Worker();

   private:
    friend class WallField;
    std::unique_ptr<Evaluator> thickness;
    std::vector<double> input, plus, minus, h_plus, h_minus;
  };

  // w at n points (cell coordinates): max(phi(p, t/2), -phi(p, -t/2)) / (k M), so roughly a distance
  // in cell units, negative inside the wall; for a network phi(p, h) / (k M). Thread-safe with one
  // Worker per thread.
  void walls(size_t n, const double* x, const double* y, const double* z, double* w, Worker& worker) const;
  // F(p) (the emitted _field), and a bound of |grad F| in cell units: k M.
  double field(double x, double y, double z) const { return field_(x, y, z); }
  // phi(p, h) at n points, h per point (cell units): the emitted _offset_n; its zero set at h is the
  // offset surface (the wall's faces are those at h = +t/2 and -t/2).
  void offsets(size_t n, const double* x, const double* y, const double* z, const double* h, double* out) const {
    offset_n_(n, x, y, z, h, out);
  }
  double field_lipschitz() const { return lipschitz_; }

  // The thickness (a network's offset h) at one point, and its smallest and largest value sampled over
  // a box of cells (8 samples per cell and axis). Throws InputError where a thickness is not positive
  // and finite, or an offset beyond the surface's curvature limit.
  double thickness_at(double x, double y, double z, Worker& worker) const;
  std::array<double, 2> thickness_range(const std::array<int, 3>& cells) const;
  std::array<double, 2> thickness_range(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const;
  // The thinnest feature and the reach over a box of cells (from thickness_range).
  WallExtent extent(const std::array<double, 2>& thickness_range) const;
  // The relative density of a uniform wall or network (docs/density.md), where the surface has a
  // density model.
  std::optional<double> uniform_density() const;
  bool graded() const { return graded_; }
  bool network() const { return network_; }

  const Generation& generation() const { return generation_; }
  double generate_seconds() const { return generate_seconds_; }
  double compile_seconds() const { return compile_seconds_; }
  const std::string& compile_flags() const { return compile_flags_; }

 private:
  Generation generation_;
  bool graded_ = false, network_ = false;
  std::optional<density::DensityModel> density_;  // the surface's, where it has one
  double uniform_thickness_ = 0;
  // Throws InputError for a network offset that is not finite or beyond the curvature limit; `at`: where.
  void check_offset(double h, const double* at) const;
  Program thickness_program_;
  double lipschitz_ = 0, distance_scale_ = 0;
  double generate_seconds_ = 0, compile_seconds_ = 0;
  std::string compile_flags_;
  std::unique_ptr<run::SharedObject> library_;  // run/c_library.h
  using OffsetN = void (*)(size_t, const double*, const double*, const double*, const double*, double*);
  using Field = double (*)(double, double, double);
  OffsetN offset_n_ = nullptr;
  Field field_ = nullptr;
};

}  // namespace offsetgen::wall
