// The naive baseline for generation time: phi^(m) built with GiNaC's own diff() on the explicit
// chain, as a user of GiNaC would write it (no jets, no memoisation, no CSE), in cell coordinates
// (sin(2*Pi*x), ...). Prints one JSON line: {"surface", "order", "seconds", "process_cpu_seconds", "nodes"}:
// the construction's wall time, and the CPU time of the whole process (startup included, as for the
// CLI runs it is compared with). Printing, CSE or lowering the result would come on top.
//   bench_naive_ginac --surface gyroid --order 5
#include "offset/richardson.h"
#include "surfaces/catalog.h"

#include <ginac/ginac.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

// Number of nodes of the expression tree (shared subtrees counted every time they occur).
double tree_size(const GiNaC::ex& e) {
  double n = 1;
  for (size_t i = 0; i < e.nops(); ++i) n += tree_size(e.op(i));
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  std::string surface = "gyroid";
  int order = 1;
  bool count_nodes = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--surface") && i + 1 < argc) surface = argv[++i];
    else if (!std::strcmp(argv[i], "--order") && i + 1 < argc) order = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--count-nodes")) count_nodes = true;
    else {
      std::fprintf(stderr, "usage: %s --surface NAME --order M [--count-nodes]\n", argv[0]);
      return 2;
    }
  }
  const offsetgen::Surface s = offsetgen::catalog_surface(surface);
  const auto& sym = offsetgen::Symbols::get();
  GiNaC::lst to_cell;
  for (int i = 0; i < s.dims; ++i) to_cell.append(sym.natural(i) == s.scale * sym.cell(i));
  GiNaC::symbol h("h");

  const auto start = std::chrono::steady_clock::now();
  const GiNaC::ex field = s.field.subs(to_cell);
  const auto weights = offsetgen::richardson_weights(order);
  GiNaC::ex phi = 0;
  for (int j = 1; j <= order; ++j) {
    GiNaC::ex psi = field;
    for (int k = 0; k < j; ++k) {
      GiNaC::ex norm2 = 0;
      for (int i = 0; i < s.dims; ++i) norm2 += GiNaC::pow(psi.diff(sym.cell(i)), 2);
      psi = psi - h / j * GiNaC::sqrt(norm2);
    }
    phi += weights[static_cast<size_t>(j - 1)] * psi;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double nodes = count_nodes ? tree_size(phi) : -1.0;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double cpu = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                     1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  std::printf("{\"surface\": \"%s\", \"order\": %d, \"seconds\": %.6f, \"process_cpu_seconds\": %.6f, \"nodes\": %.0f}\n",
              surface.c_str(), order, seconds, cpu, nodes);
  return 0;
}
