#include "validate/names.h"

#include "surfaces/surface.h"

#include <fmt/format.h>

namespace offsetgen {

void require_usable_prefix(const std::string& prefix, const std::vector<const Backend*>& languages) {
  for (const Backend* language : languages) {
    for (const auto& identifier : language->declared_identifiers(prefix)) {
      if (auto why = language->reserved(identifier))
        throw InputError(fmt::format("the prefix '{}' cannot be used in {}: it would declare {}, and {}", prefix,
                                     language->title(), identifier, *why));
    }
  }
}

}  // namespace offsetgen
