#include "step/bspline_fit.h"

#include <cmath>
#include <memory>
#include <stdexcept>

namespace offsetgen::step {
namespace {

// A small dense symmetric positive definite system, solved by Cholesky for several right-hand sides.
class Cholesky {
 public:
  explicit Cholesky(std::vector<double> a, int n) : l_(std::move(a)), n_(n) {
    for (int j = 0; j < n; ++j) {
      double d = l_[idx(j, j)];
      for (int k = 0; k < j; ++k) d -= l_[idx(j, k)] * l_[idx(j, k)];
      if (!(d > 0)) throw std::runtime_error("B-spline fit: the normal equations are singular (too few samples)");
      l_[idx(j, j)] = std::sqrt(d);
      for (int i = j + 1; i < n; ++i) {
        double s = l_[idx(i, j)];
        for (int k = 0; k < j; ++k) s -= l_[idx(i, k)] * l_[idx(j, k)];
        l_[idx(i, j)] = s / l_[idx(j, j)];
      }
    }
  }
  void solve(std::vector<double>& b) const {
    for (int i = 0; i < n_; ++i) {
      double s = b[static_cast<size_t>(i)];
      for (int k = 0; k < i; ++k) s -= l_[idx(i, k)] * b[static_cast<size_t>(k)];
      b[static_cast<size_t>(i)] = s / l_[idx(i, i)];
    }
    for (int i = n_ - 1; i >= 0; --i) {
      double s = b[static_cast<size_t>(i)];
      for (int k = i + 1; k < n_; ++k) s -= l_[idx(k, i)] * b[static_cast<size_t>(k)];
      b[static_cast<size_t>(i)] = s / l_[idx(i, i)];
    }
  }

 private:
  size_t idx(int i, int j) const { return flat(i, n_, j); }
  std::vector<double> l_;
  int n_;
};

// The basis matrix (m samples x n functions) at t = k/(m-1), and the Cholesky factor of the normal
// equations of its interior columns 1..n-2.
struct Basis1D {
  Basis1D(int samples, int functions) : m(samples), n(functions), values(flat(samples, functions, 0)) {
    CubicKnots knots(n);
    for (int k = 0; k < m; ++k) {
      std::vector<double> b = knots.basis(double(k) / (m - 1));
      for (int j = 0; j < n; ++j) values[flat(k, n, j)] = b[static_cast<size_t>(j)];
    }
    const int ni = n - 2;
    std::vector<double> normal(flat(ni, ni, 0), 0.0);
    for (int a = 0; a < ni; ++a)
      for (int b = 0; b < ni; ++b) {
        double s = 0;
        for (int k = 0; k < m; ++k) s += at(k, a + 1) * at(k, b + 1);
        normal[flat(a, ni, b)] = s;
      }
    factor = std::make_unique<Cholesky>(std::move(normal), ni);
  }
  double at(int k, int j) const { return values[flat(k, n, j)]; }
  // The interior coefficients (n-2) minimising sum_k (sum_j N_j(t_k) c_j - r_k)^2 over interior j.
  std::vector<double> interior_fit(const std::vector<double>& r) const {
    std::vector<double> rhs(static_cast<size_t>(n - 2), 0.0);
    for (int a = 0; a < n - 2; ++a) {
      double s = 0;
      for (int k = 0; k < m; ++k) s += at(k, a + 1) * r[static_cast<size_t>(k)];
      rhs[static_cast<size_t>(a)] = s;
    }
    factor->solve(rhs);
    return rhs;
  }
  int m, n;
  std::vector<double> values;
  std::unique_ptr<Cholesky> factor;
};

// A boundary curve: n control points from m samples, the ends interpolated. Each coordinate is fitted
// by the same operations, so equal coordinates of the samples (x = y on a mirror plane) stay equal.
std::vector<Point> fit_curve(const Basis1D& basis, const std::vector<Point>& samples) {
  const int m = basis.m, n = basis.n;
  std::vector<Point> c(static_cast<size_t>(n));
  c.front() = samples.front();
  c.back() = samples.back();
  for (size_t a = 0; a < 3; ++a) {
    std::vector<double> r(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k)
      r[static_cast<size_t>(k)] =
          samples[static_cast<size_t>(k)][a] - basis.at(k, 0) * c.front()[a] - basis.at(k, n - 1) * c.back()[a];
    std::vector<double> x = basis.interior_fit(r);
    for (int j = 1; j < n - 1; ++j) c[static_cast<size_t>(j)][a] = x[static_cast<size_t>(j - 1)];
  }
  return c;
}

}  // namespace

CubicKnots::CubicKnots(int n) : control_points(n) {
  if (n < 4) throw std::invalid_argument("a cubic B-spline needs at least 4 control points");
  const int spans = n - 3;
  for (int k = 0; k <= spans; ++k) {
    distinct.push_back(double(k) / spans);
    multiplicities.push_back(k == 0 || k == spans ? 4 : 1);
  }
}

std::vector<double> CubicKnots::basis(double t) const {
  const int n = control_points, spans = n - 3;
  // The full knot vector u_0..u_{n+3}.
  std::vector<double> u;
  for (size_t k = 0; k < distinct.size(); ++k)
    for (int r = 0; r < multiplicities[k]; ++r) u.push_back(distinct[k]);
  int span = std::min(spans - 1, std::max(0, static_cast<int>(std::floor(t * spans))));
  const size_t i = static_cast<size_t>(span) + 3;  // u_i <= t < u_{i+1}
  // Cox-de Boor, the non-zero functions N_{i-3..i}.
  std::array<double, 4> nb{1, 0, 0, 0}, left{}, right{};
  for (size_t j = 1; j <= 3; ++j) {
    left[j] = t - u[i + 1 - j];
    right[j] = u[i + j] - t;
    double saved = 0;
    for (size_t r = 0; r < j; ++r) {
      const double temp = nb[r] / (right[r + 1] + left[j - r]);
      nb[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    nb[j] = saved;
  }
  std::vector<double> out(static_cast<size_t>(n), 0.0);
  for (size_t r = 0; r < 4; ++r) out[i - 3 + r] = nb[r];
  return out;
}

Point CubicPatch::evaluate(double u, double v) const {
  CubicKnots knots(n);
  const std::vector<double> bu = knots.basis(u), bv = knots.basis(v);
  Point p{0, 0, 0};
  for (int i = 0; i < n; ++i) {
    if (bu[static_cast<size_t>(i)] == 0) continue;
    for (int j = 0; j < n; ++j) {
      const double w = bu[static_cast<size_t>(i)] * bv[static_cast<size_t>(j)];
      for (size_t a = 0; a < 3; ++a) p[a] += w * at(i, j)[a];
    }
  }
  return p;
}

CubicPatch fit_patch(const std::vector<Point>& samples, int m, int n) {
  if (m < n) throw std::invalid_argument("fit_patch: fewer samples than control points");
  const Basis1D basis(m, n);
  auto sample = [&](int i, int j) -> const Point& { return samples[flat(i, m, j)]; };
  CubicPatch patch;
  patch.n = n;
  patch.control.assign(flat(n, n, 0), Point{0, 0, 0});

  // The four boundary curves, each from its own samples.
  std::vector<Point> row(static_cast<size_t>(m));
  for (int side = 0; side < 4; ++side) {
    for (int k = 0; k < m; ++k) {
      row[static_cast<size_t>(k)] = side == 0   ? sample(0, k)       // u = 0
                                    : side == 1 ? sample(m - 1, k)   // u = 1
                                    : side == 2 ? sample(k, 0)       // v = 0
                                                : sample(k, m - 1);  // v = 1
    }
    const std::vector<Point> c = fit_curve(basis, row);
    for (int k = 0; k < n; ++k) {
      Point& target = side == 0   ? patch.at(0, k)
                      : side == 1 ? patch.at(n - 1, k)
                      : side == 2 ? patch.at(k, 0)
                                  : patch.at(k, n - 1);
      target = c[static_cast<size_t>(k)];
    }
  }

  // The interior: the residual of the samples after the boundary's share, fitted separably (the
  // least-squares problem of a tensor grid is a Kronecker product: fit along v, then along u).
  auto boundary = [&](int i, int j) { return i == 0 || j == 0 || i == n - 1 || j == n - 1; };
  for (size_t a = 0; a < 3; ++a) {
    std::vector<double> residual(flat(m, m, 0));
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        double s = sample(i, j)[a];
        for (int k = 0; k < n; ++k) {
          const double bk = basis.at(i, k);
          if (bk == 0) continue;
          for (int l = 0; l < n; ++l)
            if (boundary(k, l)) s -= bk * basis.at(j, l) * patch.at(k, l)[a];
        }
        residual[flat(i, m, j)] = s;
      }
    // Along v for every sample row i: m x (n-2).
    std::vector<double> along_v(flat(m, n - 2, 0));
    std::vector<double> r(static_cast<size_t>(m));
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) r[static_cast<size_t>(j)] = residual[flat(i, m, j)];
      const std::vector<double> x = basis.interior_fit(r);
      for (int l = 0; l < n - 2; ++l) along_v[flat(i, n - 2, l)] = x[static_cast<size_t>(l)];
    }
    // Then along u for every interior column l.
    for (int l = 0; l < n - 2; ++l) {
      for (int i = 0; i < m; ++i) r[static_cast<size_t>(i)] = along_v[flat(i, n - 2, l)];
      const std::vector<double> x = basis.interior_fit(r);
      for (int k = 0; k < n - 2; ++k) patch.at(k + 1, l + 1)[a] = x[static_cast<size_t>(k)];
    }
  }
  return patch;
}

}  // namespace offsetgen::step
