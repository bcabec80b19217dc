// The offset methods offsetgen knows. A new method is one file defining its OffsetMethod, plus one
// line here.
#include "offset/method.h"

#include <fmt/format.h>

namespace offsetgen {

const OffsetMethod& richardson_method();  // richardson_method.cpp
const OffsetMethod& projection_method();  // projection_method.cpp

const std::vector<const OffsetMethod*>& offset_methods() {
  static const std::vector<const OffsetMethod*> methods = {&richardson_method(), &projection_method()};
  return methods;
}

const OffsetMethod& offset_method(const std::string& name) {
  std::string known;
  for (const OffsetMethod* m : offset_methods()) {
    if (m->name() == name) return *m;
    known += (known.empty() ? "" : ", ") + m->name();
  }
  throw InputError(fmt::format("unknown method '{}': offsetgen knows {}", name, known));
}

}  // namespace offsetgen
