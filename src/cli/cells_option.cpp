#include "cli/cells_option.h"

#include "cli/number_list.h"
#include "surfaces/input_error.h"
#include "validate/block_checks.h"

#include <fmt/format.h>

#include <sstream>
#include <vector>

namespace offsetgen {

std::array<int, 3> parse_cells(const std::string& text) {
  std::vector<int> n;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, 'x')) {
    size_t used = 0;
    int value = 0;
    try {
      value = std::stoi(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (part.empty() || used != part.size())
      throw InputError(fmt::format("--cells '{}': expected NX, NXxNY or NXxNYxNZ (positive integers)", text));
    if (value < 1) throw InputError(fmt::format("--cells '{}': {} is not a positive number of cells", text, value));
    n.push_back(value);
  }
  if (n.empty() || n.size() > 3 || text.back() == 'x')
    throw InputError(fmt::format("--cells '{}': expected NX, NXxNY or NXxNYxNZ (positive integers)", text));
  while (n.size() < 3) n.push_back(n.back());
  return {n[0], n[1], n[2]};
}

std::array<double, 3> parse_cell_size(const std::string& text) {
  const auto sizes = parse_number_list(text);
  if (!sizes || (sizes->size() != 1 && sizes->size() != 3))
    throw InputError(
        fmt::format("--cell-size '{}': expected MM (a cube cell) or X,Y,Z (a box cell, mm along x, y and z)", text));
  const std::vector<double>& v = *sizes;
  const std::array<double, 3> size =
      v.size() == 1 ? std::array<double, 3>{v[0], v[0], v[0]} : std::array<double, 3>{v[0], v[1], v[2]};
  check_cell_size(size);
  return size;
}

}  // namespace offsetgen
