// Helpers of the mesh tests: run `offsetgen mesh`, read binary STL, ask admesh, and the exact walls
// of a catalog surface through its generated header (compiled at -O2 and loaded).
#pragma once

#include "mesh/triangle_mesh.h"
#include "offsetgen_test_support.h"
#include "run/c_library.h"

#include <array>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace offsetgen::mesh::testing {

// The runners every test folder shares (tests/support).
using CliRun = test_support::CommandResult;
using test_support::run_offsetgen;
using test_support::scratch_dir;

// A part meshed with --cells 3 --cell-size 10 plus `args` (surface and wall).
struct Case {
  std::string name;
  std::vector<std::string> args;
};
inline void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// Meshes the case and expects admesh to find no hole, no disconnected facet, no backwards edge and
// one part, and the facets to face outward.
void expect_clean_part(const Case& c);

// Facets of a binary STL (3 vertices each); throws when the file is not one.
std::vector<std::array<std::array<float, 3>, 3>> read_stl(const std::string& path);
double stl_volume(const std::vector<std::array<std::array<float, 3>, 3>>& facets);

// admesh's report of a file, as "name" -> number, from its (default: check and fix all) run:
// "parts", "backwards edges", "disconnected facets" (before fixing), "facets added" (holes filled),
// "degenerate facets", "facets removed", "facets reversed", "edges fixed", "facets" (before fixing).
std::map<std::string, double> admesh_report(const std::string& stl, std::string* raw = nullptr);

// The walls of a catalog surface: phi(p, +t/2) and phi(p, -t/2) of the generated header.
class ExactWalls {
 public:
  ExactWalls(const std::string& surface, int order, double thickness);
  // max(phi(p, t/2), -phi(p, -t/2)): <= 0 in the wall.
  double w(const double p[3]) const;
  double phi(const double p[3], double h) const;
  double thickness() const { return t_; }

 private:
  std::unique_ptr<run::CompileResult> compiled_;
  double t_;
};

// Bodies whose insides are known in closed form, for --body.
// An icosphere of radius r about c: the icosahedron, each triangle split in 4 `levels` times.
TriangleMesh sphere(double r, const std::array<double, 3>& c, int levels);
// A torus about the z axis through c: major radius big, minor radius small, n x m quads.
TriangleMesh torus(double big, double small, const std::array<double, 3>& c, int n, int m);
void write_stl(const TriangleMesh& m, const std::string& path);
inline std::string read_bytes(const std::string& path) { return test_support::read_file(path); }
// "key: ... <number> ..." -> the first number after `label` in the summary.
double summary_number(const std::string& summary, const std::string& label);
// admesh counts every closed surface as a part: the outer one and each cavity the skin closes
// (cavities < 0: not checked). Expects no hole, backwards edge or disconnected facet.
void expect_admesh_clean(const std::string& stl, double cavities);

}  // namespace offsetgen::mesh::testing
