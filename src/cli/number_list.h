// Comma-separated numbers on the command line ("10,10,15", "1.5,-2,0"): one reader for every option
// that takes them, so that they all refuse the same malformed text.
#pragma once

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace offsetgen {

// The finite numbers of `text`, or nothing when a part is empty, not wholly a number, or not finite.
inline std::optional<std::vector<double>> parse_number_list(const std::string& text) {
  std::vector<double> numbers;
  if (text.empty() || text.back() == ',') return std::nullopt;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(part, &used);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (part.empty() || used != part.size() || !std::isfinite(value)) return std::nullopt;
    numbers.push_back(value);
  }
  return numbers;
}

}  // namespace offsetgen
