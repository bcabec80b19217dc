// The snippets offsetgen generates at build time (tests/glsl/CMakeLists.txt): every catalog surface
// at orders 1-4 as a .glsl snippet plus its C header (double and float), and one graded-thickness
// snippet. Each case carries the header's functions, so the GLSL output of a surface/order is
// compared with the C output of the same lowered program.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace offsetgen::glsl_test {

struct GeneratedCase {
  const char* surface;  // catalog name, e.g. "gyroid"
  int order;            // 1..4 (richardson), 2..8 (projection)
  const char* method;   // the offset method, e.g. "richardson"
  const char* prefix;   // function prefix, e.g. "gyroid_o4", "gyroid_proj_o4"
  const char* header;   // absolute path of the generated .h
  const char* snippet;  // absolute path of the generated .glsl
  double (*field)(double, double, double);
  double (*offset)(double, double, double, double);
  double (*shell)(double, double, double, double);
  void (*normal)(double, double, double, double, double*);
  double (*graded)(double, double, double);  // nullptr unless generated with --thickness
  float (*fieldf)(float, float, float);
  float (*offsetf)(float, float, float, float);
  float (*shellf)(float, float, float, float);
  void (*normalf)(float, float, float, float, float*);
  float (*gradedf)(float, float, float);
};

// Catalog surfaces x orders 1-4 (richardson), then x orders 2-8 (projection), in CMake's order.
const std::vector<GeneratedCase>& generated_cases();
// gyroid order 4 generated with --thickness graded_thickness_expression().
const GeneratedCase& graded_case();
const char* graded_thickness_expression();
// The same t(x, y, z) written in C++; GradedCase.MatchesShellWithThickness ties the two together.
double graded_thickness(double x, double y, double z);

// The surface names the build generates; must equal `offsetgen list`.
std::vector<std::string> catalog_surfaces_under_test();
// Snippets generated from --expr (compiled and linted only): a 2D one and one with a --param.
std::vector<std::string> expression_snippet_paths();
// generated/*.glsl of the source tree at configure time (CONFIGURE_DEPENDS glob), sorted.
std::vector<std::string> golden_snippet_paths();

// A snippet file the compile and convention tests cover.
struct SnippetFile {
  std::string label;  // test-name friendly: "gyroid_o4", "gyroid_graded_o4", "expr_circle_o2"
  std::string path;
};
// Generated cases, the graded snippet and the expression snippets (the golden snippets are
// byte-identical to generated cases: GoldenSnippets.AreTheBuildTimeSnippets).
std::vector<SnippetFile> all_snippet_files();

// GoogleTest prints parameters with these (instead of a byte dump).
void PrintTo(const GeneratedCase& c, std::ostream* os);
void PrintTo(const SnippetFile& f, std::ostream* os);

}  // namespace offsetgen::glsl_test
