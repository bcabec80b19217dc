#include "validate/names.h"

#include "emit/c_names.h"
#include "emit/emitted_api.h"
#include "emit/glsl_names.h"
#include "surfaces/surface.h"

#include <fmt/format.h>

#include <optional>
#include <vector>

namespace offsetgen {
namespace {

const char* const kSuffixes[] = {"field", "offset", "shell", "normal", "graded"};

std::vector<std::string> c_identifiers(const std::string& prefix) {
  std::vector<std::string> names;
  for (const char* suffix : kSuffixes) {
    const std::string name = prefix + "_" + suffix;
    names.insert(names.end(), {name, name + "f", name + "_n", name + "f_n"});
  }
  names.push_back(prefix + "_glsl");  // offsetgen_generate(LANG glsl_string)
  names.push_back(guard_name(prefix, "h"));
  return names;
}

std::vector<std::string> glsl_identifiers(const std::string& prefix) {
  std::vector<std::string> names;
  for (const char* suffix : kSuffixes) names.push_back(prefix + "_" + suffix);
  names.push_back(guard_name(prefix, "glsl"));
  return names;
}

}  // namespace

void require_usable_prefix(const std::string& prefix, bool c, bool glsl) {
  struct Language {
    bool wanted;
    const char* name;
    std::vector<std::string> identifiers;
    std::optional<std::string> (*reserved)(const std::string&);
  };
  const Language languages[] = {
      {c, "C", c ? c_identifiers(prefix) : std::vector<std::string>{}, c_names::reserved},
      {glsl, "GLSL", glsl ? glsl_identifiers(prefix) : std::vector<std::string>{}, glsl_names::reserved}};
  for (const auto& language : languages) {
    if (!language.wanted) continue;
    for (const auto& identifier : language.identifiers) {
      if (auto why = language.reserved(identifier))
        throw InputError(fmt::format("the prefix '{}' cannot be used in {}: it would declare {}, and {}", prefix,
                                     language.name, identifier, *why));
    }
  }
}

}  // namespace offsetgen
