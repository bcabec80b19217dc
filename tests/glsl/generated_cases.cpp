#include "generated_cases.h"

#include <filesystem>

namespace offsetgen::glsl_test {

double graded_thickness(double x, double /*y*/, double /*z*/) { return 0.02 + 0.04 * x; }

std::vector<SnippetFile> all_snippet_files() {
  std::vector<SnippetFile> out;
  for (const GeneratedCase& c : generated_cases()) out.push_back({c.prefix, c.snippet});
  out.push_back({graded_case().prefix, graded_case().snippet});
  for (const std::string& path : expression_snippet_paths()) {
    out.push_back({std::filesystem::path(path).stem().string(), path});
  }
  return out;
}

void PrintTo(const GeneratedCase& c, std::ostream* os) { *os << c.prefix << " (" << c.snippet << ")"; }

void PrintTo(const SnippetFile& f, std::ostream* os) { *os << f.path; }

}  // namespace offsetgen::glsl_test
