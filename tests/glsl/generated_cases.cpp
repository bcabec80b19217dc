#include "generated_cases.h"

#include <filesystem>
#include <regex>

namespace offsetgen::glsl_test {

double graded_thickness(double x, double /*y*/, double /*z*/) { return 0.02 + 0.04 * x; }

std::string offsetgen_executable() { return OFFSETGEN_EXE; }

std::vector<SnippetFile> all_snippet_files() {
  std::vector<SnippetFile> out;
  for (const GeneratedCase& c : generated_cases()) out.push_back({c.prefix, c.snippet});
  out.push_back({graded_case().prefix, graded_case().snippet});
  for (const std::string& path : expression_snippet_paths()) {
    out.push_back({std::filesystem::path(path).stem().string(), path});
  }
  for (const std::string& path : golden_snippet_paths()) {
    out.push_back({"golden_" + std::filesystem::path(path).stem().string(), path});
  }
  return out;
}

std::string snippet_prefix(const std::string& snippet, const std::string& fallback) {
  static const std::regex kPrefix(R"re(offsetgen-metadata \{[^\n]*"prefix":"([A-Za-z_]\w*)")re");
  std::smatch m;
  return std::regex_search(snippet, m, kPrefix) ? m[1].str() : fallback;
}

void PrintTo(const GeneratedCase& c, std::ostream* os) { *os << c.prefix << " (" << c.snippet << ")"; }

void PrintTo(const SnippetFile& f, std::ostream* os) { *os << f.path; }

}  // namespace offsetgen::glsl_test
