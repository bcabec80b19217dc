#include "validate/share_range.h"

#include "emit/file_writer.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <cctype>
#include <exception>
#include <stdexcept>

namespace offsetgen {

std::pair<int, int> parse_share(const std::string& text, const std::string& option) {
  const auto bad = [&] {
    return InputError(
        fmt::format("{} '{}': expected I/N with 0 <= I < N (share I of N, counted from 0)", option, text));
  };
  const size_t slash = text.find('/');
  if (slash == std::string::npos) throw bad();
  auto number = [&](const std::string& part) {
    size_t used = 0;
    int value = -1;
    try {
      value = std::stoi(part, &used);
    } catch (const std::exception&) {
      throw bad();
    }
    if (part.empty() || used != part.size() || !std::isdigit(static_cast<unsigned char>(part[0]))) throw bad();
    return value;
  };
  const int index = number(text.substr(0, slash)), count = number(text.substr(slash + 1));
  if (count < 1 || index >= count) throw bad();
  return {index, count};
}

std::pair<size_t, size_t> share_of(size_t total, int index, int count) {
  const auto share = [&](int i) { return total * static_cast<size_t>(i) / static_cast<size_t>(count); };
  return {share(index), share(index + 1)};
}

void check_merge_paths(const std::vector<std::string>& parts, const std::string& output) {
  if (parts.empty()) throw InputError("--merge: no parts given");
  std::vector<std::string> all = parts;
  all.push_back(output);
  try {
    require_distinct(all);
  } catch (const std::runtime_error& e) {
    throw InputError(std::string("--merge: ") + e.what());
  }
}

}  // namespace offsetgen
