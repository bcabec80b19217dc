#include "batch_cases.h"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace offsetgen::batch_test {

const Cases& all_cases() {
  static const Cases cases = [] {
    Cases c;
    add_gyroid_o4(c);
    add_gyroid_o4_omp(c);
    add_gyroid_o4_generic(c);
    add_gyroid_o6(c);
    add_neovius_o3(c);
    add_schwarzp_o2(c);
    add_wave2d_o3(c);
    add_expo_o2(c);
    return c;
  }();
  return cases;
}

HeaderFacts header_facts(const std::string& header) {
  const std::string path = std::string(OFFSETGEN_BATCH_HEADER_DIR) + "/" + header + ".h";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  HeaderFacts facts;
  std::smatch m;
  if (!std::regex_search(s, m, std::regex("\"gradient_bound\":([-0-9.eE+]+)")))
    throw std::runtime_error("no gradient_bound in " + path);
  facts.gradient_bound = std::stod(m[1].str());
  if (std::regex_search(s, m, std::regex("\"scale\":([-0-9.eE+]+)"))) facts.scale = std::stod(m[1].str());
  return facts;
}

}  // namespace offsetgen::batch_test
