// ns per point of the emitted functions (scalar and batch, double and float), of SymPy's C and of
// nested AD, all compiled with this executable's flags (bench/CMakeLists.txt builds one executable
// per flag set). Benchmark names: <mode>/<impl>/<surface>/o<order>/<function>/<precision>.
// Before measuring, the implementations are checked against each other at random points.
#include "eval_registry.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace offsetgen::bench {

Registry& registry() {
  static Registry r;
  return r;
}

namespace {

constexpr std::size_t kPoints = 4096;  // per iteration, scalar and batch
constexpr std::size_t kAdPoints = 64;  // nested AD is ~1e4 times slower

template <class T>
struct Points {
  std::vector<T> x, y, z, w;
  std::vector<T> out;
};

template <class T>
Points<T> make(bool shell) {
  std::mt19937 rng(shell ? 2u : 1u);
  std::uniform_real_distribution<double> unit(0.0, 1.0), w(shell ? 0.0 : -0.05, shell ? 0.1 : 0.05);
  Points<T> p;
  for (std::size_t i = 0; i < kPoints; ++i) {
    p.x.push_back(static_cast<T>(unit(rng)));
    p.y.push_back(static_cast<T>(unit(rng)));
    p.z.push_back(static_cast<T>(unit(rng)));
    p.w.push_back(static_cast<T>(w(rng)));
  }
  p.out.resize(kPoints);
  return p;
}

// Random points in the unit cell; w is h in [-0.05, 0.05] (offset) or t in [0, 0.1] (shell).
template <class T>
const Points<T>& points(bool shell) {
  static const Points<T> sets[2] = {make<T>(false), make<T>(true)};
  return sets[shell ? 1 : 0];
}

template <class T, class F>
void run_scalar(benchmark::State& state, F f, bool shell, std::size_t n) {
  Points<T> p = points<T>(shell);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) p.out[i] = f(p.x[i], p.y[i], p.z[i], p.w[i]);
    benchmark::DoNotOptimize(p.out.data());
    benchmark::ClobberMemory();
  }
  state.counters["points"] = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(n));
}

template <class T, class B>
void run_batch(benchmark::State& state, B f, bool shell) {
  Points<T> p = points<T>(shell);
  for (auto _ : state) {
    f(kPoints, p.x.data(), p.y.data(), p.z.data(), p.w.data(), p.out.data());
    benchmark::DoNotOptimize(p.out.data());
    benchmark::ClobberMemory();
  }
  state.counters["points"] = static_cast<double>(kPoints);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(kPoints));
}

std::string name(const char* mode, const char* impl, const Key& key, const char* function, const char* precision) {
  return std::string(mode) + "/" + impl + "/" + key.first + "/o" + std::to_string(key.second) + "/" + function + "/" +
         precision;
}

void register_ours(const char* impl, const Key& key, const OursFunctions& f) {
  benchmark::RegisterBenchmark(name("scalar", impl, key, "offset", "double").c_str(),
                               [f = f.offset](benchmark::State& s) { run_scalar<double>(s, f, false, kPoints); });
  benchmark::RegisterBenchmark(name("scalar", impl, key, "shell", "double").c_str(),
                               [f = f.shell](benchmark::State& s) { run_scalar<double>(s, f, true, kPoints); });
  benchmark::RegisterBenchmark(name("batch", impl, key, "offset", "double").c_str(),
                               [f = f.offset_n](benchmark::State& s) { run_batch<double>(s, f, false); });
  benchmark::RegisterBenchmark(name("batch", impl, key, "shell", "double").c_str(),
                               [f = f.shell_n](benchmark::State& s) { run_batch<double>(s, f, true); });
  benchmark::RegisterBenchmark(name("scalar", impl, key, "offset", "float").c_str(),
                               [f = f.offsetf](benchmark::State& s) { run_scalar<float>(s, f, false, kPoints); });
  benchmark::RegisterBenchmark(name("scalar", impl, key, "shell", "float").c_str(),
                               [f = f.shellf](benchmark::State& s) { run_scalar<float>(s, f, true, kPoints); });
  benchmark::RegisterBenchmark(name("batch", impl, key, "offset", "float").c_str(),
                               [f = f.offsetf_n](benchmark::State& s) { run_batch<float>(s, f, false); });
  benchmark::RegisterBenchmark(name("batch", impl, key, "shell", "float").c_str(),
                               [f = f.shellf_n](benchmark::State& s) { run_batch<float>(s, f, true); });
}

void register_benchmarks() {
  const Registry& r = registry();
  // The offset methods side by side: benchmark names say the method where others say "ours".
  for (const auto& [method_key, f] : r.methods) register_ours(method_key.first.c_str(), method_key.second, f);
  for (const auto& [key, f] : r.ours) register_ours("ours", key, f);
  // SymPy's pipeline has no shell: a user calls its offset twice.
  for (const auto& [key, f] : r.sympy) {
    benchmark::RegisterBenchmark(name("scalar", "sympy", key, "offset", "double").c_str(),
                                 [f = f](benchmark::State& s) { run_scalar<double>(s, f, false, kPoints); });
    benchmark::RegisterBenchmark(name("scalar", "sympy", key, "shell", "double").c_str(), [f = f](benchmark::State& s) {
      run_scalar<double>(
          s, [f](double x, double y, double z, double t) { return f(x, y, z, 0.5 * t) * f(x, y, z, -0.5 * t); }, true,
          kPoints);
    });
  }
  for (const auto& [key, f] : r.libm_trig) {
    benchmark::RegisterBenchmark(name("scalar", "libm_trig", key, "offset", "double").c_str(),
                                 [f = f.first](benchmark::State& s) { run_scalar<double>(s, f, false, kPoints); });
    benchmark::RegisterBenchmark(name("scalar", "libm_trig", key, "shell", "double").c_str(),
                                 [f = f.second](benchmark::State& s) { run_scalar<double>(s, f, true, kPoints); });
  }
  for (const auto& [key, f] : r.ad) {
    benchmark::RegisterBenchmark(name("scalar", "ad", key, "offset", "double").c_str(),
                                 [f = f](benchmark::State& s) { run_scalar<double>(s, f, false, kAdPoints); });
  }
}

double scaled_difference(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1.0); }

// Every implementation computes the same phi^(m): compare at random points of the cell, away from
// the lattice of critical points (there the safeguard and the raw formulas legitimately differ).
int cross_check() {
  const Registry& r = registry();
  const Points<double>& p = points<double>(false);
  int failures = 0;
  auto check = [&](const char* what, const Key& key, Scalar other, double tolerance, std::size_t n) {
    const Scalar ours = r.ours.at(key).offset;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = ours(p.x[i], p.y[i], p.z[i], p.w[i]), b = other(p.x[i], p.y[i], p.z[i], p.w[i]);
      if (!(scaled_difference(a, b) <= tolerance)) {
        std::fprintf(stderr, "cross-check: %s %s o%d differs from ours at (%g, %g, %g, %g): %.17g vs %.17g\n", what,
                     key.first.c_str(), key.second, p.x[i], p.y[i], p.z[i], p.w[i], b, a);
        ++failures;
        return;
      }
    }
  };
  for (const auto& [key, f] : r.sympy)
    if (r.ours.count(key)) check("sympy", key, f, 1e-9, 256);
  for (const auto& [key, f] : r.ad)
    if (r.ours.count(key)) check("nested AD", key, f, 1e-9, 16);
  for (const auto& [key, f] : r.libm_trig)
    if (r.ours.count(key)) check("libm sin/cos build", key, f.first, 1e-12, 1024);
  for (const auto& [key, f] : r.ours) {
    std::vector<double> out(kPoints);
    f.offset_n(kPoints, p.x.data(), p.y.data(), p.z.data(), p.w.data(), out.data());
    for (std::size_t i = 0; i < kPoints; ++i) {
      if (!(scaled_difference(out[i], f.offset(p.x[i], p.y[i], p.z[i], p.w[i])) <= 1e-12)) {
        std::fprintf(stderr, "cross-check: batch %s o%d differs from scalar at point %zu\n", key.first.c_str(),
                     key.second, i);
        ++failures;
        break;
      }
    }
  }
  // Each method's batch loop against its own scalar function. (The methods are not compared with each
  // other: they share the zero set to their order, not the values off it.)
  for (const auto& [method_key, f] : r.methods) {
    const auto& [method, key] = method_key;
    std::vector<double> out(kPoints);
    f.offset_n(kPoints, p.x.data(), p.y.data(), p.z.data(), p.w.data(), out.data());
    for (std::size_t i = 0; i < kPoints; ++i) {
      if (!(scaled_difference(out[i], f.offset(p.x[i], p.y[i], p.z[i], p.w[i])) <= 1e-10)) {
        std::fprintf(stderr, "cross-check: batch %s %s o%d differs from scalar at point %zu\n", method.c_str(),
                     key.first.c_str(), key.second, i);
        ++failures;
        break;
      }
    }
  }
  return failures;
}

}  // namespace
}  // namespace offsetgen::bench

int main(int argc, char** argv) {
  if (int failures = offsetgen::bench::cross_check(); failures > 0) {
    std::fprintf(stderr, "%d cross-check failure(s): not benchmarking functions that disagree\n", failures);
    return 2;
  }
  offsetgen::bench::register_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
