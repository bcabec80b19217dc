// Runtime nested forward-mode automatic differentiation of the offset chain: the straightforward
// alternative to generated code that a user might write (issue 6, "nested AD" peer).
//
// Dual3<T> carries a value and its gradient in (x, y, z). Nesting it K deep gives exact derivatives
// up to order K at run time: psi_K = psi_{K-1} - s |grad psi_{K-1}| evaluates psi_{K-1} on Dual3<T>
// to get its gradient, recursively down to the field F. Then phi^(m) = sum_j w_j psi_j^(j) with the
// closed-form Richardson weights, exactly as METHOD.md writes it -- no safeguard, no F - h*G form,
// no sharing between the chains. A Dual3 nested K deep holds 4^K numbers.
#pragma once

#include <cmath>

namespace offsetgen::bench {

template <class T>
struct Dual3 {
  T v{};
  T d[3]{};

  Dual3() = default;
  Dual3(double c) : v(c) {}  // NOLINT: constants convert implicitly, as in any AD library
  Dual3(const T& value, const T& d0, const T& d1, const T& d2) : v(value), d{d0, d1, d2} {}
  static Dual3 variable(const T& value, int axis) {
    Dual3 r(value, T(0.0), T(0.0), T(0.0));
    r.d[axis] = T(1.0);
    return r;
  }
};

template <class T> Dual3<T> operator+(const Dual3<T>& a, const Dual3<T>& b) {
  return {a.v + b.v, a.d[0] + b.d[0], a.d[1] + b.d[1], a.d[2] + b.d[2]};
}
template <class T> Dual3<T> operator-(const Dual3<T>& a, const Dual3<T>& b) {
  return {a.v - b.v, a.d[0] - b.d[0], a.d[1] - b.d[1], a.d[2] - b.d[2]};
}
template <class T> Dual3<T> operator-(const Dual3<T>& a) { return {-a.v, -a.d[0], -a.d[1], -a.d[2]}; }
template <class T> Dual3<T> operator*(const Dual3<T>& a, const Dual3<T>& b) {
  return {a.v * b.v, a.d[0] * b.v + a.v * b.d[0], a.d[1] * b.v + a.v * b.d[1], a.d[2] * b.v + a.v * b.d[2]};
}
template <class T> Dual3<T> operator*(double c, const Dual3<T>& a) { return {c * a.v, c * a.d[0], c * a.d[1], c * a.d[2]}; }
template <class T> Dual3<T> operator*(const Dual3<T>& a, double c) { return c * a; }
template <class T> Dual3<T> operator+(const Dual3<T>& a, double c) { return {a.v + c, a.d[0], a.d[1], a.d[2]}; }
template <class T> Dual3<T> operator-(double c, const Dual3<T>& a) { return {c - a.v, -a.d[0], -a.d[1], -a.d[2]}; }

template <class T> Dual3<T> sin(const Dual3<T>& a) {
  using std::cos;
  using std::sin;
  const T s = sin(a.v), c = cos(a.v);
  return {s, c * a.d[0], c * a.d[1], c * a.d[2]};
}
template <class T> Dual3<T> cos(const Dual3<T>& a) {
  using std::cos;
  using std::sin;
  const T s = sin(a.v), c = cos(a.v);
  return {c, -s * a.d[0], -s * a.d[1], -s * a.d[2]};
}
template <class T> Dual3<T> sqrt(const Dual3<T>& a) {
  using std::sqrt;
  const T r = sqrt(a.v);
  const T k = 0.5 / r;
  return {r, k * a.d[0], k * a.d[1], k * a.d[2]};
}
template <class T> Dual3<T> operator/(const Dual3<T>& a, const Dual3<T>& b) {
  const T q = a.v / b.v;
  return {q, (a.d[0] - q * b.d[0]) / b.v, (a.d[1] - q * b.d[1]) / b.v, (a.d[2] - q * b.d[2]) / b.v};
}
template <class T> Dual3<T> operator/(double c, const Dual3<T>& a) { return Dual3<T>(c) / a; }

// The fields, in cell coordinates (cell length 1, k = 2*pi), for any (nested) number type.
struct Gyroid {
  template <class T> T operator()(const T& x, const T& y, const T& z) const {
    using std::cos;
    using std::sin;
    const double k = 6.283185307179586;
    return sin(k * x) * cos(k * y) + sin(k * y) * cos(k * z) + sin(k * z) * cos(k * x);
  }
};
struct SchwarzP {
  template <class T> T operator()(const T& x, const T& y, const T& z) const {
    using std::cos;
    const double k = 6.283185307179586;
    return cos(k * x) + cos(k * y) + cos(k * z);
  }
};
struct Neovius {
  template <class T> T operator()(const T& x, const T& y, const T& z) const {
    using std::cos;
    const double k = 6.283185307179586;
    const T cx = cos(k * x), cy = cos(k * y), cz = cos(k * z);
    return 3.0 * (cx + cy + cz) + 4.0 * (cx * cy * cz);
  }
};
struct Diamond {
  template <class T> T operator()(const T& x, const T& y, const T& z) const {
    using std::cos;
    using std::sin;
    const double k = 6.283185307179586;
    const T sx = sin(k * x), sy = sin(k * y), sz = sin(k * z), cx = cos(k * x), cy = cos(k * y), cz = cos(k * z);
    return sx * sy * sz + sx * cy * cz + cx * sy * cz + cx * cy * sz;
  }
};

// psi_K of one chain with step s, evaluated on number type T.
template <int K, class Field>
struct Chain {
  template <class T>
  static T psi(const T& x, const T& y, const T& z, double s) {
    using std::sqrt;
    using D = Dual3<T>;
    const D p = Chain<K - 1, Field>::psi(D::variable(x, 0), D::variable(y, 1), D::variable(z, 2), s);
    return p.v - s * sqrt(p.d[0] * p.d[0] + p.d[1] * p.d[1] + p.d[2] * p.d[2]);
  }
};
template <class Field>
struct Chain<0, Field> {
  template <class T>
  static T psi(const T& x, const T& y, const T& z, double) { return Field{}(x, y, z); }
};

inline double richardson_weight(int m, int j) {
  double w = (m - j) % 2 == 0 ? 1.0 : -1.0;
  for (int i = 0; i < m - 1; ++i) w *= j;
  for (int i = 2; i < j; ++i) w /= i;
  for (int i = 2; i <= m - j; ++i) w /= i;
  return w;
}

// phi^(M)(x, h) = sum_{j=1..M} w_j psi_j with step h/j.
template <int M, class Field, int J = M>
struct Offset {
  static double eval(double x, double y, double z, double h) {
    return richardson_weight(M, J) * Chain<J, Field>::psi(x, y, z, h / J) + Offset<M, Field, J - 1>::eval(x, y, z, h);
  }
};
template <int M, class Field>
struct Offset<M, Field, 0> {
  static double eval(double, double, double, double) { return 0.0; }
};

}  // namespace offsetgen::bench
